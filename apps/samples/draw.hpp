// DebugDraw: how samples draw, in world coordinates (m), independent of any physics world and of
// the graphics API. A renderer implements four primitives (segment, triangle, point, text); the
// shapes every engine debug view needs (polylines, polygons solid and outlined, circles, capsules,
// arrows, boxes, transforms) are built from them here, once. The 2D worlds draw through it today
// (rigid2d_draw.hpp, particle_draw.hpp); the 3D world can draw through it too, after projecting
// its points onto the view plane.
#pragma once

#include <impetus/math/transform2.hpp>

#include <span>
#include <string_view>

namespace impetus::samples {

/// Linear RGBA in [0, 1].
struct Color {
  float r = 1.0f;
  float g = 1.0f;
  float b = 1.0f;
  float a = 1.0f;

  /// The same colour with another opacity.
  [[nodiscard]] constexpr Color withAlpha(float alpha) const noexcept { return {r, g, b, alpha}; }
  /// Darker (factor < 1) or lighter (factor > 1), clamped to [0, 1].
  [[nodiscard]] Color scaled(float factor) const noexcept;
};

/// The palette the samples share, so that the same thing looks the same everywhere.
namespace palette {
inline constexpr Color background{0.10f, 0.11f, 0.13f, 1.0f};
inline constexpr Color grid{0.18f, 0.19f, 0.22f, 1.0f};
inline constexpr Color awake{0.95f, 0.65f, 0.30f, 1.0f};      ///< dynamic body, awake
inline constexpr Color asleep{0.55f, 0.55f, 0.62f, 1.0f};     ///< dynamic body, asleep
inline constexpr Color staticBody{0.45f, 0.80f, 0.45f, 1.0f}; ///< never moves
inline constexpr Color kinematic{0.50f, 0.60f, 0.95f, 1.0f};  ///< moved by its velocity only
inline constexpr Color bullet{0.95f, 0.35f, 0.35f, 1.0f};     ///< continuous collision
inline constexpr Color sensor{0.90f, 0.90f, 0.30f, 1.0f};
inline constexpr Color joint{0.40f, 0.85f, 0.85f, 1.0f};
inline constexpr Color contact{1.00f, 0.30f, 0.30f, 1.0f};
inline constexpr Color normal{0.35f, 0.90f, 0.35f, 1.0f};
inline constexpr Color contactForce{0.95f, 0.85f, 0.35f, 1.0f};  ///< along the contact normal
inline constexpr Color frictionForce{0.95f, 0.50f, 0.85f, 1.0f}; ///< along the contact tangent
inline constexpr Color aabb{0.80f, 0.40f, 0.80f, 1.0f};
inline constexpr Color centerOfMass{0.95f, 0.95f, 0.95f, 1.0f};
inline constexpr Color text{0.92f, 0.92f, 0.92f, 1.0f};
inline constexpr Color trajectory{0.40f, 0.75f, 1.00f, 1.0f};
inline constexpr Color reference{0.95f, 0.85f, 0.35f, 1.0f}; ///< closed form, exact solution
inline constexpr Color warning{1.00f, 0.45f, 0.25f, 1.0f};
inline constexpr Color particle{0.55f, 0.80f, 1.00f, 1.0f};
/// Distinct colours for several series (integrators, craft, shots).
inline constexpr Color series[] = {{0.95f, 0.40f, 0.35f, 1.0f}, {0.40f, 0.80f, 0.40f, 1.0f},
                                   {0.40f, 0.65f, 1.00f, 1.0f}, {0.95f, 0.80f, 0.30f, 1.0f},
                                   {0.80f, 0.50f, 0.95f, 1.0f}, {0.40f, 0.90f, 0.90f, 1.0f}};
} // namespace palette

class DebugDraw {
public:
  virtual ~DebugDraw() = default;

  // The primitives a renderer implements.
  virtual void segment(const Vec2f& a, const Vec2f& b, const Color& color) = 0;
  /// A filled triangle (any winding).
  virtual void triangle(const Vec2f& a, const Vec2f& b, const Vec2f& c, const Color& color) = 0;
  /// A round dot `sizePixels` across, whatever the zoom.
  virtual void point(const Vec2f& p, float sizePixels, const Color& color) = 0;
  /// A text label whose top-left corner is at the world point p (screen-aligned, fixed size).
  virtual void text(const Vec2f& p, std::string_view label, const Color& color) = 0;
  /// Screen pixels from one line of text to the next (the panels' 15 px font and its spacing):
  /// a second line goes textLinePixels * pixelSize() metres below the first.
  static constexpr float textLinePixels = 18.0f;
  /// The world length of one pixel at the current zoom, m: for sizes that should look the same
  /// on screen (arrow heads, axis lengths).
  [[nodiscard]] virtual float pixelSize() const = 0;

  // Shapes built from the primitives.
  /// Open polyline through the points.
  void polyline(std::span<const Vec2f> points, const Color& color);
  /// Closed outline.
  void polygon(std::span<const Vec2f> points, const Color& color);
  /// Convex polygon, filled with `fill` (a fan from the first point) and outlined with `outline`.
  void solidPolygon(std::span<const Vec2f> points, const Color& fill, const Color& outline);
  void circle(const Vec2f& center, float radius, const Color& color);
  /// A filled circle with a radius line at `angle` (rad) so its rotation shows.
  void solidCircle(const Vec2f& center, float radius, float angle, const Color& fill, const Color& outline);
  /// A stadium: the points within `radius` of the segment p1-p2.
  void solidCapsule(const Vec2f& p1, const Vec2f& p2, float radius, const Color& fill, const Color& outline);
  /// A rounded convex polygon (the polygon inflated by radius), outlined.
  void roundedPolygon(std::span<const Vec2f> points, float radius, const Color& fill, const Color& outline);
  /// An arrow from `from` to `to` with a head `headPixels` long.
  void arrow(const Vec2f& from, const Vec2f& to, const Color& color, float headPixels = 8.0f);
  /// An axis-aligned box outline.
  void box(const Vec2f& lower, const Vec2f& upper, const Color& color);
  /// A frame: its x axis red, its y axis green, `axisPixels` long.
  void transform(const Transform2f& xf, float axisPixels = 20.0f);
  /// A cross of `sizePixels`.
  void cross(const Vec2f& p, float sizePixels, const Color& color);
  /// Lines every `spacing` metres across the box, and the axes brighter: the ground truth of scale.
  void grid(const Vec2f& lower, const Vec2f& upper, float spacing, const Color& color);
};

/// A DebugDraw that forwards to another with every point moved by `offset` (m): to draw two worlds
/// side by side in one view.
class OffsetDraw final : public DebugDraw {
public:
  OffsetDraw(DebugDraw& target, const Vec2f& offset) : target_(target), offset_(offset) {}
  void segment(const Vec2f& a, const Vec2f& b, const Color& color) override {
    target_.segment(a + offset_, b + offset_, color);
  }
  void triangle(const Vec2f& a, const Vec2f& b, const Vec2f& c, const Color& color) override {
    target_.triangle(a + offset_, b + offset_, c + offset_, color);
  }
  void point(const Vec2f& p, float sizePixels, const Color& color) override {
    target_.point(p + offset_, sizePixels, color);
  }
  void text(const Vec2f& p, std::string_view label, const Color& color) override {
    target_.text(p + offset_, label, color);
  }
  [[nodiscard]] float pixelSize() const override { return target_.pixelSize(); }

private:
  DebugDraw& target_;
  Vec2f offset_;
};

} // namespace impetus::samples
