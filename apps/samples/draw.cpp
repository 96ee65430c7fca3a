// The composite shapes of DebugDraw, from its four primitives.
#include "draw.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <impetus/math/scalar.hpp>
#include <vector>

namespace impetus::samples {
namespace {

constexpr int circleSegments = 32;
constexpr float twoPi = 2.0f * pi<float>;

/// Unit circle points, computed once.
const std::array<Vec2f, circleSegments>& unitCircle() {
  static const std::array<Vec2f, circleSegments> points = [] {
    std::array<Vec2f, circleSegments> p{};
    for (int i = 0; i < circleSegments; ++i) {
      const float a = twoPi * static_cast<float>(i) / static_cast<float>(circleSegments);
      p[static_cast<std::size_t>(i)] = {std::cos(a), std::sin(a)};
    }
    return p;
  }();
  return points;
}

} // namespace

Color Color::scaled(float factor) const noexcept {
  return {std::clamp(r * factor, 0.0f, 1.0f), std::clamp(g * factor, 0.0f, 1.0f), std::clamp(b * factor, 0.0f, 1.0f),
          a};
}

void DebugDraw::polyline(std::span<const Vec2f> points, const Color& color) {
  for (std::size_t i = 1; i < points.size(); ++i) {
    segment(points[i - 1], points[i], color);
  }
}

void DebugDraw::polygon(std::span<const Vec2f> points, const Color& color) {
  if (points.size() < 2) {
    return;
  }
  polyline(points, color);
  segment(points.back(), points.front(), color);
}

void DebugDraw::solidPolygon(std::span<const Vec2f> points, const Color& fill, const Color& outline) {
  for (std::size_t i = 2; i < points.size(); ++i) {
    triangle(points[0], points[i - 1], points[i], fill);
  }
  polygon(points, outline);
}

void DebugDraw::circle(const Vec2f& center, float radius, const Color& color) {
  const auto& unit = unitCircle();
  for (std::size_t i = 0; i < unit.size(); ++i) {
    segment(center + unit[i] * radius, center + unit[(i + 1) % unit.size()] * radius, color);
  }
}

void DebugDraw::solidCircle(const Vec2f& center, float radius, float angle, const Color& fill, const Color& outline) {
  const auto& unit = unitCircle();
  for (std::size_t i = 0; i < unit.size(); ++i) {
    triangle(center, center + unit[i] * radius, center + unit[(i + 1) % unit.size()] * radius, fill);
  }
  circle(center, radius, outline);
  segment(center, center + Vec2f{std::cos(angle), std::sin(angle)} * radius, outline);
}

void DebugDraw::solidCapsule(const Vec2f& p1, const Vec2f& p2, float radius, const Color& fill, const Color& outline) {
  const Vec2f axis = normalize(p2 - p1);
  if (lengthSquared(axis) == 0.0f) {
    solidCircle(p1, radius, 0.0f, fill, outline);
    return;
  }
  // Half circles around each end, joined by the two straight sides.
  const float start = std::atan2(axis.y, axis.x);
  constexpr int half = circleSegments / 2;
  std::vector<Vec2f> outlinePoints;
  outlinePoints.reserve(2 * (half + 1));
  for (int end = 0; end < 2; ++end) {
    const Vec2f c = end == 0 ? p2 : p1;
    const float from = start - twoPi / 4.0f + (end == 0 ? 0.0f : twoPi / 2.0f);
    for (int i = 0; i <= half; ++i) {
      const float a = from + twoPi / 2.0f * static_cast<float>(i) / static_cast<float>(half);
      outlinePoints.push_back(c + Vec2f{std::cos(a), std::sin(a)} * radius);
    }
  }
  solidPolygon(outlinePoints, fill, outline);
  segment(p1, p2, outline);
}

void DebugDraw::roundedPolygon(std::span<const Vec2f> points, float radius, const Color& fill, const Color& outline) {
  if (radius <= 0.0f) {
    solidPolygon(points, fill, outline);
    return;
  }
  // Each vertex becomes an arc between its two edges' outward normals (counter-clockwise points).
  std::vector<Vec2f> outlinePoints;
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2f prev = points[(i + n - 1) % n];
    const Vec2f cur = points[i];
    const Vec2f next = points[(i + 1) % n];
    const Vec2f n1 = normalize(Vec2f{cur.y - prev.y, prev.x - cur.x});
    const Vec2f n2 = normalize(Vec2f{next.y - cur.y, cur.x - next.x});
    const float a1 = std::atan2(n1.y, n1.x);
    float a2 = std::atan2(n2.y, n2.x);
    if (a2 < a1) {
      a2 += twoPi;
    }
    constexpr int steps = 4;
    for (int s = 0; s <= steps; ++s) {
      const float a = a1 + (a2 - a1) * static_cast<float>(s) / static_cast<float>(steps);
      outlinePoints.push_back(cur + Vec2f{std::cos(a), std::sin(a)} * radius);
    }
  }
  solidPolygon(outlinePoints, fill, outline);
}

void DebugDraw::arrow(const Vec2f& from, const Vec2f& to, const Color& color, float headPixels) {
  segment(from, to, color);
  const Vec2f d = normalize(to - from);
  if (lengthSquared(d) == 0.0f) {
    return;
  }
  const float head = std::min(headPixels * pixelSize(), 0.5f * distance(from, to));
  const Vec2f back = to - d * head;
  const Vec2f side = perp(d) * (0.5f * head);
  segment(to, back + side, color);
  segment(to, back - side, color);
}

void DebugDraw::box(const Vec2f& lower, const Vec2f& upper, const Color& color) {
  const Vec2f corners[] = {lower, {upper.x, lower.y}, upper, {lower.x, upper.y}};
  polygon(corners, color);
}

void DebugDraw::transform(const Transform2f& xf, float axisPixels) {
  const float len = axisPixels * pixelSize();
  segment(xf.p, transformPoint(xf, Vec2f{len, 0.0f}), {0.95f, 0.3f, 0.3f, 1.0f});
  segment(xf.p, transformPoint(xf, Vec2f{0.0f, len}), {0.3f, 0.95f, 0.3f, 1.0f});
}

void DebugDraw::cross(const Vec2f& p, float sizePixels, const Color& color) {
  const float h = 0.5f * sizePixels * pixelSize();
  segment(p - Vec2f{h, 0.0f}, p + Vec2f{h, 0.0f}, color);
  segment(p - Vec2f{0.0f, h}, p + Vec2f{0.0f, h}, color);
}

void DebugDraw::grid(const Vec2f& lower, const Vec2f& upper, float spacing, const Color& color) {
  if (!(spacing > 0.0f)) {
    return;
  }
  const Color axes = color.scaled(1.6f);
  const auto lines = [&](float lo, float hi, auto&& line) {
    const long first = static_cast<long>(std::ceil(lo / spacing));
    const long last = static_cast<long>(std::floor(hi / spacing));
    for (long i = first; i <= last && i - first < 400; ++i) {
      line(static_cast<float>(i) * spacing, i == 0);
    }
  };
  lines(lower.x, upper.x, [&](float x, bool axis) { segment({x, lower.y}, {x, upper.y}, axis ? axes : color); });
  lines(lower.y, upper.y, [&](float y, bool axis) { segment({lower.x, y}, {upper.x, y}, axis ? axes : color); });
}

} // namespace impetus::samples
