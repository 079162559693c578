#version 330 core
// Balls are impostors: one camera-facing square per ball, just large enough to hold the
// sphere's outline, and the fragment shader finds the sphere's surface and depth inside it.
// Software renderers set the budget:
// - Four vertices a ball instead of a mesh, drawn as plain indexed triangles: llvmpipe pays a
//   fixed cost for each instance of an instanced draw.
// - Everything that is the same across a ball (the light and the view in the ball's own frame)
//   is worked out per vertex, and the surface is the sphere seen head-on. That is exact at the
//   centre of the view and off by the perspective across one ball elsewhere, which the eye
//   does not see; it halved the time for 1,000 balls against ray casting each pixel.
// - The depth is the square's own, a disc through the centre, not the sphere's surface: then
//   the depth test runs before the shading, and with the balls drawn nearest first, hidden
//   pixels are never shaded (5,000 balls: 15.6 -> 11.9 ms a frame). The disc lies inside the
//   ball, so a plane, cylinder or ball that does not cut into the ball is drawn in front of it
//   exactly where it is in front of the sphere, except that two balls overlapping on the
//   screen are ordered by their centres.
// - In scenes of very many balls (SceneView::kPointSpriteBalls), balls small on the screen are
//   point sprites instead: one vertex a ball rather than four and two triangles, with the same
//   shading in the fragment shader. The ball's frame then takes the screen's axes, which are the
//   sprite's.
layout(location = 1) in vec3 center;
layout(location = 2) in float radius;
layout(location = 3) in vec4 color;
uniform mat4 viewProjection;
uniform vec3 eyePosition;
uniform vec3 lightDirection;
uniform float pixelAngle;  // view height over distance, per device pixel
uniform bool pointSprites;
out vec2 outline;          // position in the square; the sphere's outline is the unit circle
flat out float spriteScale;  // point sprites: the sprite's half size over the outline's radius
// In the ball's frame: x right, y up, z towards the eye.
flat out vec3 light;
flat out vec3 halfway;
flat out vec3 worldUp;
flat out vec3 baseColor;
flat out float edgePixels;  // outline radius in pixels
flat out float selected;    // the colour's alpha is 0 for a selected ball
void main() {
  // The square's corner in [-1, 1]^2 from the vertex's place among its ball's four.
  vec2 corner = vec2((gl_VertexID & 1) != 0 ? 1.0 : -1.0, (gl_VertexID & 2) != 0 ? 1.0 : -1.0);
  vec3 toCenter = center - eyePosition;
  float distance = length(toCenter);
  baseColor = color.rgb;
  selected = color.a < 0.5 ? 1.0 : 0.0;
  if (distance <= radius * 1.0001) {  // the eye is inside: nothing sensible to draw
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    return;
  }
  vec3 forward = toCenter / distance;
  vec3 right;
  if (pointSprites) {
    // The view's right: the first row of the view matrix, which the projection only scales.
    vec3 screenRight = vec3(viewProjection[0][0], viewProjection[1][0], viewProjection[2][0]);
    right = normalize(screenRight - dot(screenRight, forward) * forward);
  } else {
    vec3 helper = abs(forward.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    right = normalize(cross(forward, helper));
  }
  vec3 up = cross(right, forward);
  mat3 toBall = transpose(mat3(right, up, -forward));
  light = toBall * lightDirection;
  halfway = normalize(light + vec3(0.0, 0.0, 1.0));
  worldUp = toBall * vec3(0.0, 1.0, 0.0);

  // The cone of rays touching the sphere cuts the plane through its centre in this circle.
  float outlineRadius = radius * distance / sqrt(distance * distance - radius * radius);
  edgePixels = outlineRadius / (pixelAngle * distance);
  // Plus a pixel and a half, for the soft edge.
  float halfSize = outlineRadius + 1.5 * pixelAngle * distance;
  if (pointSprites) {
    spriteScale = halfSize / outlineRadius;
    outline = vec2(0.0);
    gl_PointSize = 2.0 * halfSize / (pixelAngle * distance);
    gl_Position = viewProjection * vec4(center, 1.0);
    return;
  }
  spriteScale = 0.0;
  outline = corner * (halfSize / outlineRadius);
  gl_Position = viewProjection * vec4(center + halfSize * (corner.x * right + corner.y * up), 1.0);
}
