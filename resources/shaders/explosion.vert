#version 330 core
// Explosions: per instance, two perpendicular quads. Both contain the view's up direction and
// meet the line of sight at 45 degrees, so neither is ever seen edge-on.
layout(location = 0) in vec3 corner;  // x, y in [-1, 1] across a quad; z: which quad, 0 or 1
layout(location = 1) in vec3 center;
layout(location = 2) in float halfSize;
layout(location = 3) in float alpha;
uniform mat4 viewProjection;
uniform vec3 eyePosition;
out vec2 sparkCoordinate;
out float fade;
void main() {
  vec3 toCenter = center - eyePosition;
  float distance = length(toCenter);
  vec3 forward = distance > 1e-6 ? toCenter / distance : vec3(0.0, 0.0, -1.0);
  vec3 helper = abs(forward.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  vec3 right = normalize(cross(forward, helper));
  vec3 up = cross(right, forward);
  vec3 across = 0.70710678 * (corner.z < 0.5 ? right + forward : right - forward);
  sparkCoordinate = 0.5 + 0.5 * corner.xy;
  fade = alpha;
  gl_Position = viewProjection * vec4(center + halfSize * (corner.x * across + corner.y * up), 1.0);
}
