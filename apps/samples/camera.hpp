// The 2D camera: which part of the world (m) the viewport shows. Pan with the right mouse button,
// zoom with the wheel about the pointer; screen pixels have y down, the world has y up.
#pragma once

#include <impetus/math/vec2.hpp>

#include <array>

namespace impetus::samples {

/// What a sample asks the camera to show when it starts: a centre and the half-height of the view.
struct CameraView {
  Vec2f center{0.0f, 0.0f}; ///< m
  float halfHeight = 20.0f; ///< m, > 0
  float halfWidth = 0.0f;   ///< m: when > 0, the view is widened (zoomed out) until this much fits too
};

class Camera {
public:
  /// The viewport, in window pixels: where the scene is drawn (the rest of the window holds panels).
  void setViewport(int x, int y, int width, int height);
  /// Shows `view` in the current viewport: its half-height, or more when its half-width needs it.
  void setView(const CameraView& view);
  [[nodiscard]] const CameraView& view() const noexcept { return view_; }

  [[nodiscard]] Vec2f screenToWorld(const Vec2f& screen) const;
  [[nodiscard]] Vec2f worldToScreen(const Vec2f& world) const;
  /// The world length of one pixel, m.
  [[nodiscard]] float pixelSize() const;
  /// The world box the viewport shows: lower-left and upper-right corners.
  [[nodiscard]] std::array<Vec2f, 2> visibleBox() const;

  /// Moves the view by a pointer displacement in pixels (the world follows the pointer).
  void pan(const Vec2f& screenDelta);
  /// Zooms by `factor` (> 1: closer) keeping the world point under `screen` in place.
  void zoomAt(const Vec2f& screen, float factor);

  /// Column-major orthographic projection from world coordinates to the viewport's clip space.
  [[nodiscard]] std::array<float, 16> projection() const;

  [[nodiscard]] int x() const noexcept { return x_; }
  [[nodiscard]] int y() const noexcept { return y_; }
  [[nodiscard]] int width() const noexcept { return width_; }
  [[nodiscard]] int height() const noexcept { return height_; }

private:
  CameraView view_;
  int x_ = 0;
  int y_ = 0;
  int width_ = 1280;
  int height_ = 800;
};

} // namespace impetus::samples
