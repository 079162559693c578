#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 gridCoordinate;  // in grid cells
layout(location = 3) in vec4 color;
uniform mat4 viewProjection;
out vec3 worldPosition;
out vec3 worldNormal;
out vec2 grid;
out vec3 baseColor;
void main() {
  worldPosition = position;
  worldNormal = normal;
  grid = gridCoordinate;
  baseColor = color.rgb;
  gl_Position = viewProjection * vec4(position, 1.0);
}
