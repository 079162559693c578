#version 330 core
layout(location = 0) in vec3 local;  // unit circle in x, y; 0 to 1 along the axis in z
layout(location = 1) in vec3 localNormal;
layout(location = 2) in vec3 start;
layout(location = 3) in vec3 end;
layout(location = 4) in float radius;
layout(location = 5) in vec4 color;
uniform mat4 viewProjection;
out vec3 worldPosition;
out vec3 worldNormal;
out vec3 baseColor;
void main() {
  vec3 axis = end - start;
  vec3 w = normalize(axis);
  // Any direction across the axis will do; the world axis least like it keeps this stable.
  vec3 helper = abs(w.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  vec3 u = normalize(cross(w, helper));
  vec3 v = cross(w, u);
  worldPosition = start + radius * (local.x * u + local.y * v) + local.z * axis;
  worldNormal = localNormal.x * u + localNormal.y * v + localNormal.z * w;
  baseColor = color.rgb;
  gl_Position = viewProjection * vec4(worldPosition, 1.0);
}
