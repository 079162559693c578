// Follows lighting.glsl, which has the #version line and the shared lighting.
uniform sampler2D spark;
uniform vec3 sparkColor;
in vec2 sparkCoordinate;
in float fade;
out vec4 fragColor;
void main() {
  // With additive blending this adds sparkColor times the spark's brightness and the fade.
  fragColor = vec4(sparkColor, texture(spark, sparkCoordinate).r * fade);
}
