#include "ui/render/gl_util.h"

#include <QFile>
#include <QOpenGLShaderProgram>
#include <QString>

namespace carom::render {
namespace {

// A resource file's text. A missing one reads as empty, with a warning: compiling it then fails
// like any broken shader, and the program is left as after any other failure.
QByteArray shaderFile(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) {
    qWarning("SceneView: shader program failed: cannot read %s", qPrintable(path));
    return {};
  }
  return file.readAll();
}

}  // namespace

void vertexAttribute(QOpenGLFunctions_3_3_Core* gl, GLuint location, GLint components, GLenum type,
                     GLsizei stride, std::size_t offset, bool perInstance) {
  gl->glEnableVertexAttribArray(location);
  gl->glVertexAttribPointer(location, components, type, type == GL_FLOAT ? GL_FALSE : GL_TRUE,
                            stride, reinterpret_cast<void*>(offset));
  if (perInstance) gl->glVertexAttribDivisor(location, 1);
}

std::unique_ptr<QOpenGLShaderProgram> buildProgram(const char* name, const char* fragmentName) {
  auto program = std::make_unique<QOpenGLShaderProgram>();
  const QString path = QStringLiteral(":/shaders/") + QLatin1String(name);
  const QString fragmentPath =
      fragmentName ? QStringLiteral(":/shaders/") + QLatin1String(fragmentName) : path;
  // GLSL has no #include: every fragment shader is the shared lighting with its own text after.
  const QByteArray fragment =
      shaderFile(QStringLiteral(":/shaders/lighting.glsl")) + shaderFile(fragmentPath + ".frag");
  if (!program->addCacheableShaderFromSourceCode(QOpenGLShader::Vertex,
                                                 shaderFile(path + ".vert")) ||
      !program->addCacheableShaderFromSourceCode(QOpenGLShader::Fragment, fragment) ||
      !program->link()) {
    qWarning("SceneView: shader program failed: %s", qPrintable(program->log()));
  }
  return program;
}

void useProgram(QOpenGLShaderProgram& program, const FrameCamera& frame) {
  program.bind();
  program.setUniformValue("viewProjection", frame.viewProjection);
  program.setUniformValue("eyePosition", frame.eye);
  program.setUniformValue("lightDirection", frame.light);
}

}  // namespace carom::render
