#pragma once
// What the scene view and its renderers share: a packed vertex type, buffer uploads, vertex
// layouts and shader programs from the built-in resources (resources/shaders).

#include "sim/model/scene.h"
#include "ui/render/frame_camera.h"

#include <QOpenGLFunctions_3_3_Core>

#include <cstddef>
#include <memory>
#include <vector>

class QOpenGLShaderProgram;

namespace carom::render {

struct Float3 {
  float x, y, z;
};

inline Float3 toFloat3(const Vec3& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

// Replaces the contents of an array buffer, which stays bound.
template <typename T>
void uploadBuffer(QOpenGLFunctions_3_3_Core* gl, GLuint buffer, const std::vector<T>& data,
                  GLenum usage) {
  gl->glBindBuffer(GL_ARRAY_BUFFER, buffer);
  gl->glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(T)),
                   data.empty() ? nullptr : data.data(), usage);
}

// One vertex attribute from the bound buffer: floats as they are, bytes as 0..1; per-instance
// attributes advance once per instance.
void vertexAttribute(QOpenGLFunctions_3_3_Core* gl, GLuint location, GLint components, GLenum type,
                     GLsizei stride, std::size_t offset, bool perInstance);

// The program of ":/shaders/<name>.vert" and ":/shaders/<name>.frag". A shader that cannot be
// read, compiled or linked is logged, and the program comes back unlinked.
std::unique_ptr<QOpenGLShaderProgram> buildProgram(const char* name,
                                                   const char* fragmentName = nullptr);

// Binds `program` and gives it the frame's camera and light.
void useProgram(QOpenGLShaderProgram& program, const FrameCamera& frame);

}  // namespace carom::render
