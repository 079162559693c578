// Follows lighting.glsl, which has the #version line and the shared lighting.
in vec2 outline;
flat in float spriteScale;  // 0 for squares
flat in vec3 light;
flat in vec3 halfway;
flat in vec3 worldUp;
flat in vec3 baseColor;
flat in float edgePixels;
flat in float selected;
out vec4 fragColor;
void main() {
  // A sprite's coordinates run from its top left corner.
  vec2 at = spriteScale > 0.0 ? (2.0 * gl_PointCoord - 1.0) * vec2(spriteScale, -spriteScale)
                              : outline;
  float fromCenter2 = dot(at, at);
  // Coverage of this pixel by the outline, which alpha-to-coverage turns into samples.
  float coverage = clamp((1.0 - sqrt(fromCenter2)) * edgePixels + 0.5, 0.0, 1.0);
  if (coverage <= 0.0) discard;
  // Pixels of the soft edge just outside take the outline's normal.
  vec3 n = vec3(at, sqrt(max(1.0 - fromCenter2, 0.0)));
  vec3 ambient = mix(groundAmbient, skyAmbient, 0.5 + 0.5 * dot(n, worldUp));
  float diffuse = max(dot(n, light), 0.0);
  // The shininess of 40 by squaring, far cheaper than pow() in a software renderer.
  float h = max(dot(n, halfway), 0.0);
  float h2 = h * h, h4 = h2 * h2, h8 = h4 * h4, h16 = h8 * h8, h32 = h16 * h16;
  float highlight = diffuse > 0.0 ? h32 * h8 : 0.0;
  // A selected ball wears a bright ring around its outline.
  vec3 base = selected > 0.5 && fromCenter2 > 0.6 ? selectionColor : baseColor;
  fragColor = vec4(base * (ambient + diffuseStrength * diffuse) + vec3(0.35 * highlight),
                   coverage);
}
