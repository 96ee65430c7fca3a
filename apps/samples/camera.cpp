#include "camera.hpp"

#include <algorithm>

namespace impetus::samples {

void Camera::setViewport(int x, int y, int width, int height) {
  x_ = x;
  y_ = y;
  width_ = std::max(width, 1);
  height_ = std::max(height, 1);
}

void Camera::setView(const CameraView& view) {
  view_ = view;
  const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
  view_.halfHeight = std::clamp(std::max(view.halfHeight, view.halfWidth / aspect), 1e-3f, 1e5f);
  view_.halfWidth = 0.0f;
}

float Camera::pixelSize() const { return 2.0f * view_.halfHeight / static_cast<float>(height_); }

Vec2f Camera::screenToWorld(const Vec2f& screen) const {
  const float s = pixelSize();
  const float cx = static_cast<float>(x_) + 0.5f * static_cast<float>(width_);
  const float cy = static_cast<float>(y_) + 0.5f * static_cast<float>(height_);
  return {view_.center.x + (screen.x - cx) * s, view_.center.y - (screen.y - cy) * s};
}

Vec2f Camera::worldToScreen(const Vec2f& world) const {
  const float s = pixelSize();
  const float cx = static_cast<float>(x_) + 0.5f * static_cast<float>(width_);
  const float cy = static_cast<float>(y_) + 0.5f * static_cast<float>(height_);
  return {cx + (world.x - view_.center.x) / s, cy - (world.y - view_.center.y) / s};
}

std::array<Vec2f, 2> Camera::visibleBox() const {
  const float halfWidth = view_.halfHeight * static_cast<float>(width_) / static_cast<float>(height_);
  return {view_.center - Vec2f{halfWidth, view_.halfHeight}, view_.center + Vec2f{halfWidth, view_.halfHeight}};
}

void Camera::pan(const Vec2f& screenDelta) {
  const float s = pixelSize();
  view_.center += Vec2f{-screenDelta.x * s, screenDelta.y * s};
}

void Camera::zoomAt(const Vec2f& screen, float factor) {
  if (!(factor > 0.0f)) {
    return;
  }
  const Vec2f before = screenToWorld(screen);
  view_.halfHeight = std::clamp(view_.halfHeight / factor, 1e-3f, 1e5f);
  const Vec2f after = screenToWorld(screen);
  view_.center += before - after;
}

std::array<float, 16> Camera::projection() const {
  const auto [lower, upper] = visibleBox();
  const float sx = 2.0f / (upper.x - lower.x);
  const float sy = 2.0f / (upper.y - lower.y);
  return {sx,
          0.0f,
          0.0f,
          0.0f, //
          0.0f,
          sy,
          0.0f,
          0.0f, //
          0.0f,
          0.0f,
          -1.0f,
          0.0f, //
          -(upper.x + lower.x) * 0.5f * sx,
          -(upper.y + lower.y) * 0.5f * sy,
          0.0f,
          1.0f};
}

} // namespace impetus::samples
