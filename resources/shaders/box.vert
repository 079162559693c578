#version 330 core
// A unit cube from -1 to 1, placed per instance by its centre and its three half axes (the
// box's turned axes times its half extents). Drawn with plane.frag: textured like the walls.
layout(location = 0) in vec3 local;
layout(location = 1) in vec3 localNormal;  // one of the six axis directions
layout(location = 2) in vec3 center;
layout(location = 3) in vec3 halfX;
layout(location = 4) in vec3 halfY;
layout(location = 5) in vec3 halfZ;
layout(location = 6) in vec4 color;
uniform mat4 viewProjection;
uniform float gridSpacing;  // metres per cell of the texture
out vec3 worldPosition;
out vec3 worldNormal;
out vec2 grid;
out vec3 baseColor;
void main() {
  vec3 offset = local.x * halfX + local.y * halfY + local.z * halfZ;
  worldPosition = center + offset;
  worldNormal = normalize(localNormal.x * halfX + localNormal.y * halfY + localNormal.z * halfZ);
  // The face's own two directions, so that its cells line up with its edges.
  vec3 across = normalize(localNormal.x != 0.0 ? halfY : halfX);
  vec3 along = normalize(localNormal.z != 0.0 ? halfY : halfZ);
  grid = vec2(dot(offset, across), dot(offset, along)) / gridSpacing;
  baseColor = color.rgb;
  gl_Position = viewProjection * vec4(worldPosition, 1.0);
}
