#pragma once
// The vertex data the scene view's files share: packed colours, the balls' per-vertex
// attributes, which items of a list are selected, the selection's colour and the background.

#include <QColor>
#include <QVector3D>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace carom::render {

// The editor's handles, the selection's tint and the markers of selected balls out of view.
inline const QColor kSelectionColor(255, 140, 13);
// The view's background, which infinite shapes fade into beyond the scene's bounds.
inline const QVector3D kBackground(0.16f, 0.17f, 0.20f);

struct PackedColor {
  std::uint8_t r, g, b, a;
};

inline PackedColor pack(const QColor& color) {
  return {static_cast<std::uint8_t>(color.red()), static_cast<std::uint8_t>(color.green()),
          static_cast<std::uint8_t>(color.blue()), 255};
}

// Whether each of `count` items is among `indices`: one pass, however many are selected.
inline std::vector<bool> membership(const std::vector<int>& indices, std::size_t count) {
  std::vector<bool> member(count, false);
  for (int index : indices)
    if (index >= 0 && static_cast<std::size_t>(index) < count) member[index] = true;
  return member;
}

struct BallAttributes {
  float radius;
  PackedColor color;
};

constexpr std::size_t kVerticesPerBall = 4;  // a square, as two triangles
constexpr int kIndicesPerBall = 6;

}  // namespace carom::render
