// The OpenGL 3.3 core renderer of a DrawBatch: one shader, one vertex buffer, three draw calls a
// frame (triangles, then lines, then round points). Create it with a current GL context.
#pragma once

#include "camera.hpp"
#include "draw_batch.hpp"

namespace impetus::samples {

class GlRenderer {
public:
  /// Compiles the shader and makes the buffers; throws std::runtime_error with the GL log when a
  /// shader does not compile or link.
  GlRenderer();
  ~GlRenderer();
  GlRenderer(const GlRenderer&) = delete;
  GlRenderer& operator=(const GlRenderer&) = delete;

  /// Draws the batch into the camera's viewport. `pixelScale` is drawable pixels per window pixel
  /// (HiDPI); `drawableHeight` the framebuffer's height, for GL's bottom-up viewport.
  void render(const DrawBatch& batch, const Camera& camera, float pixelScale, int drawableHeight);

private:
  unsigned program_ = 0;
  unsigned vao_ = 0;
  unsigned vbo_ = 0;
  int projectionLocation_ = -1;
  int roundPointsLocation_ = -1;
};

} // namespace impetus::samples
