#include "gl_renderer.hpp"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstddef>
#include <stdexcept>
#include <string>

namespace impetus::samples {
namespace {

constexpr const char* vertexSource = R"(#version 330 core
layout(location = 0) in vec2 position;
layout(location = 1) in vec4 color;
layout(location = 2) in float size;
uniform mat4 projection;
out vec4 vertexColor;
void main() {
  gl_Position = projection * vec4(position, 0.0, 1.0);
  gl_PointSize = size;
  vertexColor = color;
}
)";

constexpr const char* fragmentSource = R"(#version 330 core
in vec4 vertexColor;
uniform int roundPoints;
out vec4 fragColor;
void main() {
  if (roundPoints == 1 && length(gl_PointCoord - vec2(0.5)) > 0.5) {
    discard;
  }
  fragColor = vertexColor;
}
)";

GLuint compile(GLenum kind, const char* source) {
  const GLuint shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok == 0) {
    char log[1024] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw std::runtime_error(std::string("OpenGL shader does not compile: ") + log);
  }
  return shader;
}

} // namespace

GlRenderer::GlRenderer() {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertexSource);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, fragmentSource);
  program_ = glCreateProgram();
  glAttachShader(program_, vs);
  glAttachShader(program_, fs);
  glLinkProgram(program_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (ok == 0) {
    char log[1024] = {};
    glGetProgramInfoLog(program_, sizeof log, nullptr, log);
    glDeleteProgram(program_);
    throw std::runtime_error(std::string("OpenGL program does not link: ") + log);
  }
  projectionLocation_ = glGetUniformLocation(program_, "projection");
  roundPointsLocation_ = glGetUniformLocation(program_, "roundPoints");

  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  constexpr auto stride = static_cast<GLsizei>(sizeof(DrawVertex));
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(DrawVertex, x)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(DrawVertex, color)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(DrawVertex, size)));
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

GlRenderer::~GlRenderer() {
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
  glDeleteProgram(program_);
}

void GlRenderer::render(const DrawBatch& batch, const Camera& camera, float pixelScale, int drawableHeight) {
  const auto px = [pixelScale](int v) { return static_cast<GLint>(static_cast<float>(v) * pixelScale + 0.5f); };
  const GLint vx = px(camera.x());
  const GLint vw = px(camera.width());
  const GLint vh = px(camera.height());
  const GLint vy = drawableHeight - px(camera.y()) - vh;
  glViewport(vx, vy, vw, vh);
  glEnable(GL_SCISSOR_TEST);
  glScissor(vx, vy, vw, vh);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_PROGRAM_POINT_SIZE);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);

  glUseProgram(program_);
  const std::array<float, 16> projection = camera.projection();
  glUniformMatrix4fv(projectionLocation_, 1, GL_FALSE, projection.data());
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  const auto drawList = [&](const std::vector<DrawVertex>& vertices, GLenum mode, int round) {
    if (vertices.empty()) {
      return;
    }
    glUniform1i(roundPointsLocation_, round);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(DrawVertex)), vertices.data(),
                 GL_STREAM_DRAW);
    glDrawArrays(mode, 0, static_cast<GLsizei>(vertices.size()));
  };
  drawList(batch.triangles(), GL_TRIANGLES, 0);
  drawList(batch.lines(), GL_LINES, 0);
  drawList(batch.points(), GL_POINTS, 1);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glUseProgram(0);
  glDisable(GL_SCISSOR_TEST);
}

} // namespace impetus::samples
