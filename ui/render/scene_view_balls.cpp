// SceneView's balls: their radii, colours and positions in GL buffers, sorted nearest first
// each picture, and drawn as squares or point sprites, whole or a range at a time.

#include "ui/render/gl_util.h"
#include "ui/render/scene_view.h"
#include "ui/render/view_vertices.h"

#include "sim/core/prefault.h"

#include <QOpenGLShaderProgram>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
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

// The element buffer, which belongs to the balls' vertex array object (bound), lists the balls'
// squares nearest first.
void SceneView::sortBallsFrontToBack(const QVector3D& eye, double pixelAngle) {
  const std::size_t count = static_cast<std::size_t>(uploadedBallCount_);
  const Vec3 eyePoint(eye.x(), eye.y(), eye.z());
  std::vector<std::pair<float, GLuint>>& order = ballOrderScratch_;
  resizePrefaulted(order, count);
  for (std::size_t i = 0; i < count; ++i)
    order[i] = {static_cast<float>((ballPositions_[i] - eyePoint).squaredNorm()),
                static_cast<GLuint>(i)};
  sortNearestFirst(order, ballSortScratch_);
  // A sprite is the outline's diameter in pixels and three more for the soft edge (ball.vert);
  // a ball whose sprite would not fit, or that holds the eye, stays a square.
  const bool sprites = static_cast<int>(count) >= kPointSpriteBalls;
  const double largestDiameter = (largestPointSize_ - 3.0) * pixelAngle;
  const auto fitsSprite = [&](float distance2, GLuint ball) {
    const double r = scene_->ballRadii[ball];
    const double beyond2 = distance2 - r * r;
    return beyond2 > 0.0 && 4.0 * r * r < largestDiameter * largestDiameter * beyond2;
  };
  std::vector<GLuint>& indices = ballIndexScratch_;
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
  uploadReusingStorage(GL_ELEMENT_ARRAY_BUFFER, indices, ballIndexBytes_);
}

void SceneView::markBallAttributesDirty() {
  ballAttributesDirty_ = true;
  attributesUploaded_ = 0;
}

// A ball's radius and colour, with the colour's alpha 0 when it is highlighted, for each of its
// vertices. When only highlights changed, only their balls are uploaded: the whole buffer of a
// million balls took 170-270 ms to build and upload at each change of the selection, in one
// 32 MB array. Whole uploads go through a small array, a piece at a time.
bool SceneView::uploadBallAttributes(std::size_t mostBalls) {
  const std::size_t count = scene_ ? scene_->ballRadii.size() : 0;
  const std::vector<bool> highlighted = membership(highlightedBalls_, count);
  const auto attributes = [&](std::size_t ball, BallAttributes* vertices) {
    const QColor color =
        ball < scene_->ballColors.size() ? scene_->ballColors[ball] : QColor(Qt::gray);
    PackedColor packed = pack(color);
    if (highlighted[ball]) packed.a = 0;
    std::fill_n(vertices, kVerticesPerBall,
                BallAttributes{static_cast<float>(scene_->ballRadii[ball]), packed});
    uploadedBallHighlights_[ball] = highlighted[ball];
  };
  constexpr auto kBallBytes = static_cast<GLsizeiptr>(kVerticesPerBall * sizeof(BallAttributes));
  glBindBuffer(GL_ARRAY_BUFFER, ballAttributeBuffer_);
  if (!ballAttributesDirty_ && uploadedBallHighlights_.size() == count) {
    std::array<BallAttributes, kVerticesPerBall> vertices;
    for (std::size_t ball = 0; ball < count; ++ball) {
      if (highlighted[ball] == uploadedBallHighlights_[ball]) continue;
      attributes(ball, vertices.data());
      glBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(ball) * kBallBytes, kBallBytes,
                      vertices.data());
    }
    return true;
  }
  if (attributesUploaded_ == 0) {
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(count) * kBallBytes, nullptr,
                 GL_STATIC_DRAW);
    uploadedBallHighlights_.assign(count, false);
  }
  constexpr std::size_t kBallsAtOnce = 16'384;
  std::vector<BallAttributes> part(kVerticesPerBall * std::min(count, kBallsAtOnce));
  const std::size_t end =
      count - attributesUploaded_ > mostBalls ? attributesUploaded_ + mostBalls : count;
  while (attributesUploaded_ < end) {
    const std::size_t balls = std::min(kBallsAtOnce, end - attributesUploaded_);
    for (std::size_t k = 0; k < balls; ++k)
      attributes(attributesUploaded_ + k, part.data() + kVerticesPerBall * k);
    glBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(attributesUploaded_) * kBallBytes,
                    static_cast<GLsizeiptr>(balls) * kBallBytes, part.data());
    attributesUploaded_ += balls;
  }
  if (attributesUploaded_ < count) return false;
  ballAttributesDirty_ = false;
  attributesUploaded_ = 0;
  return true;
}

void SceneView::uploadBallPositions() {
  positionsDirty_ = false;
  const std::size_t count =
      scene_ ? std::min(ballPositions_.size(), scene_->ballRadii.size()) : std::size_t{0};
  std::vector<float>& centers = ballCenterScratch_;
  resizePrefaulted(centers, 3 * kVerticesPerBall * count);
  float* at = centers.data();
  for (std::size_t i = 0; i < count; ++i) {
    const Float3 centre = toFloat3(ballPositions_[i]);
    for (std::size_t corner = 0; corner < kVerticesPerBall; ++corner, at += 3) {
      at[0] = centre.x;
      at[1] = centre.y;
      at[2] = centre.z;
    }
  }
  glBindBuffer(GL_ARRAY_BUFFER, ballPositionBuffer_);
  uploadReusingStorage(GL_ARRAY_BUFFER, centers, ballCenterBytes_);
  uploadedBallCount_ = static_cast<int>(count);
}

void SceneView::drawBalls(const FrameCamera& frame, double pixelHeight) {
  drawBallRange(frame, pixelHeight, 0, prepareBalls(frame, pixelHeight));
}

// Per device pixel, so that the soft edge is a pixel wide on any screen.
double SceneView::pixelAngle(double pixelHeight) const {
  const double viewHeightAtUnitDistance =
      2.0 * std::tan(0.5 * camera_.verticalFov() * std::numbers::pi / 180.0);
  return viewHeightAtUnitDistance / std::max(1.0, pixelHeight);
}

int SceneView::prepareBalls(const FrameCamera& frame, double pixelHeight) {
  if (uploadedBallCount_ == 0) return 0;
  glBindVertexArray(ballVao_);
  sortBallsFrontToBack(frame.eye, pixelAngle(pixelHeight));
  return squareBallCount_ + spriteBallCount_;
}

void SceneView::drawBallRange(const FrameCamera& frame, double pixelHeight, int first, int count) {
  glDisable(GL_CULL_FACE);
  if (count <= 0) return;
  useProgram(*ballProgram_, frame);
  ballProgram_->setUniformValue("pixelAngle", static_cast<float>(pixelAngle(pixelHeight)));
  glBindVertexArray(ballVao_);
  // The squares face the camera by construction; alpha-to-coverage gives the impostor outline
  // the same smooth edge multisampling gives triangles. Alpha itself stays 1 in the image.
  glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  const int end = first + count;
  const auto offset = [](int index) {
    return reinterpret_cast<const void*>(static_cast<std::uintptr_t>(index) * sizeof(GLuint));
  };
  if (first < squareBallCount_) {
    ballProgram_->setUniformValue("pointSprites", false);
    const int squares = std::min(end, squareBallCount_) - first;
    glDrawElements(GL_TRIANGLES, kIndicesPerBall * squares, GL_UNSIGNED_INT,
                   offset(kIndicesPerBall * first));
  }
  if (end > squareBallCount_) {
    glEnable(GL_PROGRAM_POINT_SIZE);
    ballProgram_->setUniformValue("pointSprites", true);
    const int firstSprite = std::max(first, squareBallCount_) - squareBallCount_;
    glDrawElements(GL_POINTS, end - squareBallCount_ - firstSprite, GL_UNSIGNED_INT,
                   offset(kIndicesPerBall * squareBallCount_ + firstSprite));
    glDisable(GL_PROGRAM_POINT_SIZE);
  }
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
}

}  // namespace carom::render
