// Follows lighting.glsl, which has the #version line and the shared lighting.
uniform vec3 lineColor;
out vec4 fragColor;
void main() {
  fragColor = vec4(lineColor, 1.0);
}
