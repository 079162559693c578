// Follows lighting.glsl, which has the #version line and the shared lighting.
in vec3 worldPosition;
in vec3 worldNormal;
in vec3 baseColor;
out vec4 fragColor;
void main() {
  vec3 shaded = shade(baseColor, worldNormal, worldPosition, 24.0, 0.18);
  fragColor = vec4(fadeBeyondBounds(shaded, worldPosition), 1.0);
}
