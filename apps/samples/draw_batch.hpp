// DrawBatch: a DebugDraw that records a frame's primitives as vertex lists (world coordinates),
// for the renderer to upload in three draw calls (triangles, lines, points) and for the app to
// check: every vertex a sample draws must be finite, like its state.
#pragma once

#include "draw.hpp"

#include <string>
#include <vector>

namespace impetus::samples {

struct DrawVertex {
  float x = 0.0f;
  float y = 0.0f;
  Color color;
  float size = 1.0f; ///< pixels (points only)
};

struct DrawLabel {
  Vec2f position; ///< world, m
  std::string text;
  Color color;
};

class DrawBatch final : public DebugDraw {
public:
  /// Empties the batch for a new frame drawn at `pixelSize` metres per pixel.
  void begin(float pixelSize);

  void segment(const Vec2f& a, const Vec2f& b, const Color& color) override;
  void triangle(const Vec2f& a, const Vec2f& b, const Vec2f& c, const Color& color) override;
  void point(const Vec2f& p, float sizePixels, const Color& color) override;
  void text(const Vec2f& p, std::string_view label, const Color& color) override;
  [[nodiscard]] float pixelSize() const override { return pixelSize_; }

  [[nodiscard]] const std::vector<DrawVertex>& lines() const noexcept { return lines_; }
  [[nodiscard]] const std::vector<DrawVertex>& triangles() const noexcept { return triangles_; }
  [[nodiscard]] const std::vector<DrawVertex>& points() const noexcept { return points_; }
  [[nodiscard]] const std::vector<DrawLabel>& labels() const noexcept { return labels_; }
  /// Whether every coordinate drawn is finite (NaN in a drawing is NaN in the state).
  [[nodiscard]] bool finite() const noexcept { return finite_; }

private:
  void check(const Vec2f& p) noexcept;

  std::vector<DrawVertex> lines_;
  std::vector<DrawVertex> triangles_;
  std::vector<DrawVertex> points_;
  std::vector<DrawLabel> labels_;
  float pixelSize_ = 0.05f;
  bool finite_ = true;
};

} // namespace impetus::samples
