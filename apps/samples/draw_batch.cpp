#include "draw_batch.hpp"

namespace impetus::samples {

void DrawBatch::begin(float pixelSize) {
  lines_.clear();
  triangles_.clear();
  points_.clear();
  labels_.clear();
  pixelSize_ = pixelSize;
  finite_ = true;
}

void DrawBatch::check(const Vec2f& p) noexcept { finite_ = finite_ && isFinite(p); }

void DrawBatch::segment(const Vec2f& a, const Vec2f& b, const Color& color) {
  check(a);
  check(b);
  lines_.push_back({a.x, a.y, color, 1.0f});
  lines_.push_back({b.x, b.y, color, 1.0f});
}

void DrawBatch::triangle(const Vec2f& a, const Vec2f& b, const Vec2f& c, const Color& color) {
  check(a);
  check(b);
  check(c);
  triangles_.push_back({a.x, a.y, color, 1.0f});
  triangles_.push_back({b.x, b.y, color, 1.0f});
  triangles_.push_back({c.x, c.y, color, 1.0f});
}

void DrawBatch::point(const Vec2f& p, float sizePixels, const Color& color) {
  check(p);
  points_.push_back({p.x, p.y, color, sizePixels});
}

void DrawBatch::text(const Vec2f& p, std::string_view label, const Color& color) {
  check(p);
  labels_.push_back({p, std::string(label), color});
}

} // namespace impetus::samples
