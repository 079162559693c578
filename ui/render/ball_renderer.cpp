#include "ui/render/ball_renderer.h"

#include "ui/render/gl_util.h"
#include "ui/render/view_vertices.h"

#include "sim/core/prefault.h"

#include <QOpenGLShaderProgram>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <utility>

namespace carom::render {
namespace {

// Sorts by distance, then by ball, as std::sort would, in linear time: a million balls took 170 ms
// a frame with std::sort. Squared distances are never negative, so their bits sort as integers.
void sortNearestFirst(std::vector<std::pair<float, GLuint>>& order,
                      std::vector<std::pair<float, GLuint>>& scratch) {
  constexpr int kDigitBits = 11;
  constexpr std::uint32_t kDigits = 1u << kDigitBits;
  resizePrefaulted(scratch, order.size());
  std::vector<std::pair<float, GLuint>>* from = &order;
  std::vector<std::pair<float, GLuint>>* to = &scratch;
  for (int shift = 0; shift < 32; shift += kDigitBits) {
    std::array<std::size_t, kDigits + 1> start{};
    const auto digit = [&](float key) {
      return (std::bit_cast<std::uint32_t>(key) >> shift) & (kDigits - 1);
    };
    for (const auto& entry : *from) ++start[digit(entry.first) + 1];
    for (std::uint32_t d = 0; d < kDigits; ++d) start[d + 1] += start[d];
    for (const auto& entry : *from) (*to)[start[digit(entry.first)]++] = entry;  // stable
    std::swap(from, to);
  }
  if (from != &order) order.swap(*from);
}

}  // namespace

BallRenderer::BallRenderer(QOpenGLFunctions_3_3_Core* gl, int pointSpriteBalls)
    : gl_(gl), pointSpriteBalls_(pointSpriteBalls), program_(buildProgram("ball")) {
  std::array<GLfloat, 2> pointSizes{1.0f, 1.0f};
  gl_->glGetFloatv(GL_POINT_SIZE_RANGE, pointSizes.data());
  largestPointSize_ = pointSizes[1];
  createBuffers();
}

BallRenderer::~BallRenderer() {
  program_.reset();
  const std::array<GLuint, 3> buffers = {indexBuffer_, positionBuffer_, attributeBuffer_};
  gl_->glDeleteBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  gl_->glDeleteVertexArrays(1, &vao_);
}

// Four vertices each, with a centre (updated every frame) and a radius and colour (set once per
// scene) from two buffers, so that a frame uploads only the centres.
void BallRenderer::createBuffers() {
  std::array<GLuint, 3> buffers{};
  gl_->glGenBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  indexBuffer_ = buffers[0];
  positionBuffer_ = buffers[1];
  attributeBuffer_ = buffers[2];
  gl_->glGenVertexArrays(1, &vao_);
  gl_->glBindVertexArray(vao_);
  gl_->glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
  gl_->glBindBuffer(GL_ARRAY_BUFFER, positionBuffer_);
  vertexAttribute(gl_, 1, 3, GL_FLOAT, sizeof(Float3), 0, false);
  gl_->glBindBuffer(GL_ARRAY_BUFFER, attributeBuffer_);
  vertexAttribute(gl_, 2, 1, GL_FLOAT, sizeof(BallAttributes), offsetof(BallAttributes, radius),
                  false);
  vertexAttribute(gl_, 3, 4, GL_UNSIGNED_BYTE, sizeof(BallAttributes),
                  offsetof(BallAttributes, color), false);
  gl_->glBindVertexArray(0);
  gl_->glBindBuffer(GL_ARRAY_BUFFER, 0);
}

// The element buffer, which belongs to the balls' vertex array object (bound), lists the balls'
// squares nearest first.
void BallRenderer::sortFrontToBack(const RenderScene& scene, const std::vector<Vec3>& positions,
                                   const QVector3D& eye, double pixelAngle) {
  const std::size_t count = static_cast<std::size_t>(uploadedBallCount_);
  const Vec3 eyePoint(eye.x(), eye.y(), eye.z());
  std::vector<std::pair<float, GLuint>>& order = orderScratch_;
  resizePrefaulted(order, count);
  for (std::size_t i = 0; i < count; ++i)
    order[i] = {static_cast<float>((positions[i] - eyePoint).squaredNorm()),
                static_cast<GLuint>(i)};
  sortNearestFirst(order, sortScratch_);
  // A sprite is the outline's diameter in pixels and three more for the soft edge (ball.vert);
  // a ball whose sprite would not fit, or that holds the eye, stays a square.
  const bool sprites = static_cast<int>(count) >= pointSpriteBalls_;
  const double largestDiameter = (largestPointSize_ - 3.0) * pixelAngle;
  const auto fitsSprite = [&](float distance2, GLuint ball) {
    const double r = scene.ballRadii[ball];
    const double beyond2 = distance2 - r * r;
    return beyond2 > 0.0 && 4.0 * r * r < largestDiameter * largestDiameter * beyond2;
  };
  std::vector<GLuint>& indices = indexScratch_;
  resizePrefaulted(indices, kIndicesPerBall * count);
  // Squares from the front of the buffer, sprites from its back (they cannot meet: a sprite
  // takes one index, a square six), then the sprites moved to just after the squares, nearest
  // first again.
  GLuint* square = indices.data();
  GLuint* sprite = indices.data() + indices.size();
  squareBallCount_ = spriteBallCount_ = 0;
  for (const auto& [distance2, ball] : order) {
    const auto first = static_cast<GLuint>(kVerticesPerBall * ball);
    if (sprites && fitsSprite(distance2, ball)) {
      ++spriteBallCount_;
      *--sprite = first;
      continue;
    }
    ++squareBallCount_;
    for (GLuint corner : {0u, 1u, 2u, 2u, 1u, 3u}) *square++ = first + corner;
  }
  square = std::reverse_copy(sprite, indices.data() + indices.size(), square);
  indices.resize(static_cast<std::size_t>(square - indices.data()));
  uploadReusingStorage(GL_ELEMENT_ARRAY_BUFFER, indices, indexBytes_);
}

void BallRenderer::markAttributesDirty() {
  attributesDirty_ = true;
  attributesUploaded_ = 0;
}

// A ball's radius and colour, with the colour's alpha 0 when it is highlighted, for each of its
// vertices. When only highlights changed, only their balls are uploaded: the whole buffer of a
// million balls took 170-270 ms to build and upload at each change of the selection, in one
// 32 MB array. Whole uploads go through a small array, a piece at a time.
bool BallRenderer::uploadAttributes(const RenderScene* scene,
                                    const std::vector<int>& highlightedBalls,
                                    std::size_t mostBalls) {
  const std::size_t count = scene ? scene->ballRadii.size() : 0;
  const std::vector<bool> highlighted = membership(highlightedBalls, count);
  const auto attributes = [&](std::size_t ball, BallAttributes* vertices) {
    const QColor color =
        ball < scene->ballColors.size() ? scene->ballColors[ball] : QColor(Qt::gray);
    PackedColor packed = pack(color);
    if (highlighted[ball]) packed.a = 0;
    std::fill_n(vertices, kVerticesPerBall,
                BallAttributes{static_cast<float>(scene->ballRadii[ball]), packed});
    uploadedHighlights_[ball] = highlighted[ball];
  };
  constexpr auto kBallBytes = static_cast<GLsizeiptr>(kVerticesPerBall * sizeof(BallAttributes));
  gl_->glBindBuffer(GL_ARRAY_BUFFER, attributeBuffer_);
  if (!attributesDirty_ && uploadedHighlights_.size() == count) {
    std::array<BallAttributes, kVerticesPerBall> vertices;
    for (std::size_t ball = 0; ball < count; ++ball) {
      if (highlighted[ball] == uploadedHighlights_[ball]) continue;
      attributes(ball, vertices.data());
      gl_->glBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(ball) * kBallBytes, kBallBytes,
                           vertices.data());
    }
    return true;
  }
  if (attributesUploaded_ == 0) {
    gl_->glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(count) * kBallBytes, nullptr,
                      GL_STATIC_DRAW);
    uploadedHighlights_.assign(count, false);
  }
  constexpr std::size_t kBallsAtOnce = 16'384;
  std::vector<BallAttributes> part(kVerticesPerBall * std::min(count, kBallsAtOnce));
  const std::size_t end =
      count - attributesUploaded_ > mostBalls ? attributesUploaded_ + mostBalls : count;
  while (attributesUploaded_ < end) {
    const std::size_t balls = std::min(kBallsAtOnce, end - attributesUploaded_);
    for (std::size_t k = 0; k < balls; ++k)
      attributes(attributesUploaded_ + k, part.data() + kVerticesPerBall * k);
    gl_->glBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(attributesUploaded_) * kBallBytes,
                         static_cast<GLsizeiptr>(balls) * kBallBytes, part.data());
    attributesUploaded_ += balls;
  }
  if (attributesUploaded_ < count) return false;
  attributesDirty_ = false;
  attributesUploaded_ = 0;
  return true;
}

void BallRenderer::uploadPositions(const RenderScene* scene, const std::vector<Vec3>& positions) {
  const std::size_t count =
      scene ? std::min(positions.size(), scene->ballRadii.size()) : std::size_t{0};
  std::vector<float>& centers = centerScratch_;
  resizePrefaulted(centers, 3 * kVerticesPerBall * count);
  float* at = centers.data();
  for (std::size_t i = 0; i < count; ++i) {
    const Float3 centre = toFloat3(positions[i]);
    for (std::size_t corner = 0; corner < kVerticesPerBall; ++corner, at += 3) {
      at[0] = centre.x;
      at[1] = centre.y;
      at[2] = centre.z;
    }
  }
  gl_->glBindBuffer(GL_ARRAY_BUFFER, positionBuffer_);
  uploadReusingStorage(GL_ARRAY_BUFFER, centers, centerBytes_);
  uploadedBallCount_ = static_cast<int>(count);
}

int BallRenderer::prepare(const RenderScene* scene, const std::vector<Vec3>& positions,
                          const FrameCamera& frame, double pixelAngle) {
  if (uploadedBallCount_ == 0) return 0;
  gl_->glBindVertexArray(vao_);
  sortFrontToBack(*scene, positions, frame.eye, pixelAngle);
  return preparedBalls();
}

void BallRenderer::drawRange(const FrameCamera& frame, double pixelAngle, int first, int count) {
  gl_->glDisable(GL_CULL_FACE);
  if (count <= 0) return;
  useProgram(*program_, frame);
  program_->setUniformValue("pixelAngle", static_cast<float>(pixelAngle));
  gl_->glBindVertexArray(vao_);
  // The squares face the camera by construction; alpha-to-coverage gives the impostor outline
  // the same smooth edge multisampling gives triangles. Alpha itself stays 1 in the image.
  gl_->glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  gl_->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  const int end = first + count;
  const auto offset = [](int index) {
    return reinterpret_cast<const void*>(static_cast<std::uintptr_t>(index) * sizeof(GLuint));
  };
  if (first < squareBallCount_) {
    program_->setUniformValue("pointSprites", false);
    const int squares = std::min(end, squareBallCount_) - first;
    gl_->glDrawElements(GL_TRIANGLES, kIndicesPerBall * squares, GL_UNSIGNED_INT,
                        offset(kIndicesPerBall * first));
  }
  if (end > squareBallCount_) {
    gl_->glEnable(GL_PROGRAM_POINT_SIZE);
    program_->setUniformValue("pointSprites", true);
    const int firstSprite = std::max(first, squareBallCount_) - squareBallCount_;
    gl_->glDrawElements(GL_POINTS, end - squareBallCount_ - firstSprite, GL_UNSIGNED_INT,
                        offset(kIndicesPerBall * squareBallCount_ + firstSprite));
    gl_->glDisable(GL_PROGRAM_POINT_SIZE);
  }
  gl_->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gl_->glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
}

}  // namespace carom::render
