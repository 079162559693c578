// Follows lighting.glsl, which has the #version line and the shared lighting.
in vec3 worldPosition;
in vec3 worldNormal;
in vec3 baseColor;
out vec4 fragColor;
void main() {
  fragColor = vec4(shade(baseColor, worldNormal, worldPosition, 24.0, 0.18), 1.0);
}
