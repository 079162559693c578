#pragma once
// The camera as every shader program of the view takes it in a frame.

#include <QMatrix4x4>
#include <QVector3D>

namespace carom::render {

// What every program is given in a frame.
struct FrameCamera {
  QMatrix4x4 viewProjection;
  QVector3D eye;
  QVector3D light;  // towards the light, unit length
};

}  // namespace carom::render
