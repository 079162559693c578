#version 330 core
// The start of every fragment shader (SceneView's buildProgram puts it in front), so they have
// no #version line of their own.
// One sun-like light plus a sky/ground ambient term, so faces turned away from the light still
// show their shape.
uniform vec3 eyePosition;
uniform vec3 lightDirection;  // towards the light, unit length
const vec3 groundAmbient = vec3(0.30, 0.28, 0.27);
const vec3 skyAmbient = vec3(0.46, 0.48, 0.52);
const float diffuseStrength = 0.62;
const vec3 selectionColor = vec3(1.0, 0.55, 0.05);

vec3 shade(vec3 base, vec3 normal, vec3 position, float shininess, float specularStrength) {
  vec3 n = normalize(normal);
  vec3 toEye = normalize(eyePosition - position);
  vec3 ambient = mix(groundAmbient, skyAmbient, 0.5 + 0.5 * n.y);
  float diffuse = max(dot(n, lightDirection), 0.0);
  vec3 halfway = normalize(lightDirection + toEye);
  float highlight = diffuse > 0.0 ? pow(max(dot(n, halfway), 0.0), shininess) : 0.0;
  return base * (ambient + diffuseStrength * diffuse) + vec3(specularStrength * highlight);
}

// Infinite planes and cylinders fade into the background beyond the scene's bounds, so that
// their far parts read as distance rather than as an edge (render::kFadeRadii).
uniform vec3 boundsMin;
uniform vec3 boundsMax;
uniform float fadeLength;  // metres beyond the bounds to fade by e^-1; 0 for no fading
uniform vec3 backgroundColor;

vec3 fadeBeyondBounds(vec3 color, vec3 position) {
  if (fadeLength <= 0.0) return color;
  vec3 outside = max(max(boundsMin - position, position - boundsMax), vec3(0.0));
  return mix(backgroundColor, color, exp(-length(outside) / fadeLength));
}
