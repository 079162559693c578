// A faint checker with thin lines on the cell borders. Both fade out where a cell shrinks to a
// few pixels, before they would shimmer.
// Follows lighting.glsl, which has the #version line and the shared lighting.
in vec3 worldPosition;
in vec3 worldNormal;
in vec2 grid;
in vec3 baseColor;
out vec4 fragColor;
void main() {
  vec2 cellsPerPixel = fwidth(grid);
  float fade = 1.0 - smoothstep(0.15, 0.5, max(cellsPerPixel.x, cellsPerPixel.y));
  vec2 fromLine = abs(fract(grid + 0.5) - 0.5);
  vec2 onLine = 1.0 - smoothstep(0.5 * cellsPerPixel, 1.5 * cellsPerPixel, fromLine);
  float line = max(onLine.x, onLine.y);
  float dark = mod(floor(grid.x) + floor(grid.y), 2.0);
  vec3 textured = baseColor * (1.0 - fade * (0.06 * dark + 0.14 * line));
  vec3 shaded = shade(textured, worldNormal, worldPosition, 16.0, 0.04);
  fragColor = vec4(fadeBeyondBounds(shaded, worldPosition), 1.0);
}
