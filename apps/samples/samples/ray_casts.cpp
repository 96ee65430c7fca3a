// Engine/Ray casts: World::castRayClosest and castRayAll against every kind of shape (boxes,
// circles, capsules, a rounded polygon, a one-sided chain: a ray from behind a chain passes
// through). A ray sweeps around its origin at a steady rate; the closest hit's point and surface
// normal are drawn, and with "bounces" the ray reflects off each surface (d' = d - 2 (d . n) n) as
// a laser would. "All hits" marks every shape the ray crosses, nearest first. The plot is the
// distance to the closest hit (m) as the ray turns: a map of the room as seen from the origin.
// Click on empty space to move the origin; drag bodies to put them in the way.
#include "rigid2d_sample.hpp"
#include "ui.hpp"

#include <imgui.h>

#include <cmath>
#include <impetus/math/scalar.hpp>

namespace impetus::samples {
namespace {

using namespace impetus::rigid2d;

class RayCasts final : public Rigid2dSample {
public:
  void setup() override {
    resetWorld({});
    const BodyId ground = world().createBody({});
    world().createShape(ground, {}, makeOffsetBox(16.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    world().createShape(ground, {}, makeOffsetBox(2.0f, 1.0f, {-9.0f, 6.0f}, 0.4f));
    world().createShape(ground, {}, Circle{{9.0f, 7.0f}, 1.5f});
    world().createShape(ground, {}, Capsule{{-4.0f, 11.0f}, {1.0f, 12.0f}, 0.5f});
    const Vec2f hex[] = {{7.0f, 12.0f}, {9.0f, 11.0f}, {11.0f, 12.0f}, {11.0f, 14.0f}, {9.0f, 15.0f}, {7.0f, 14.0f}};
    world().createShape(ground, {}, makePolygon(hex, 0.3f));
    // A one-sided chain: solid below, free above (listed right to left); rays from below pass.
    ChainDef chain;
    chain.points = {{-5.0f, 15.0f}, {-8.0f, 14.0f}, {-11.0f, 15.5f}, {-14.0f, 14.0f}};
    world().createChain(ground, {}, chain);
    for (int i = 0; i < 5; ++i) {
      BodyDef def;
      def.type = BodyType::dynamicBody;
      def.position = {-6.0f + 3.0f * static_cast<float>(i), 1.0f + 0.5f * static_cast<float>(i % 2)};
      const BodyId body = world().createBody(def);
      if (i % 2 == 0) {
        world().createShape(body, {}, makeBox(0.6f, 0.6f));
      } else {
        world().createShape(body, {}, Circle{{}, 0.7f});
      }
    }
    angle_ = startAngle;
    distance_.clear();
  }
  [[nodiscard]] CameraView initialView() const override { return {{0.0f, 8.0f}, 9.0f, 17.0f}; }
  [[nodiscard]] std::string_view controls() const override {
    return "Click empty space to move the ray's origin; drag bodies into its way.";
  }

  [[nodiscard]] std::string summary() const override {
    const std::optional<RayHit> hit = world().castRayClosest(origin_, direction() * range_);
    char text[96];
    if (hit) {
      std::snprintf(text, sizeof text, "; the ray hits at %.2f m", static_cast<double>(hit->fraction * range_));
    } else {
      std::snprintf(text, sizeof text, "; the ray misses");
    }
    return Rigid2dSample::summary() + text;
  }

  bool mouseDown(const Vec2f& p, MouseButton button) override {
    if (Rigid2dSample::mouseDown(p, button)) {
      return true;
    }
    origin_ = p;
    return true;
  }

protected:
  void afterStep(float dt) override {
    angle_ = std::remainder(angle_ + rate_ * dt, 2.0f * pi<float>);
    const std::optional<RayHit> hit = world().castRayClosest(origin_, direction() * range_);
    distance_.push(hit ? hit->fraction * range_ : range_);
  }

  void drawOverlay(DebugDraw& draw) override {
    draw.point(origin_, 8.0f, palette::warning);
    Vec2f from = origin_;
    Vec2f d = direction();
    float left = range_;
    for (int bounce = 0; bounce <= bounces_ && left > 0.0f; ++bounce) {
      const std::optional<RayHit> hit = world().castRayClosest(from, d * left);
      if (!hit) {
        draw.segment(from, from + d * left, palette::warning.withAlpha(0.6f));
        break;
      }
      draw.segment(from, hit->point, palette::warning);
      draw.point(hit->point, 6.0f, palette::contact);
      draw.arrow(hit->point, hit->point + hit->normal * (24.0f * draw.pixelSize()), palette::normal, 6.0f);
      left -= hit->fraction * left;
      d = d - hit->normal * (2.0f * dot(d, hit->normal)); // mirror reflection
      from = hit->point + d * 1e-3f;                      // leave the surface
    }
    if (allHits_) {
      int n = 0;
      for (const RayHit& h : world().castRayAll(origin_, direction() * range_)) {
        draw.text(h.point + Vec2f{0.2f, 0.6f}, std::to_string(++n), palette::text);
        draw.cross(h.point, 10.0f, palette::reference);
      }
    }
  }

  void parameters() override {
    slider("turning at", &rate_, -2.0f, 2.0f, "%.2f rad/s");
    slider("range", &range_, 1.0f, 60.0f, "%.0f m");
    slider("bounces", &bounces_, 0, 8);
    checkbox("all hits along the first ray (castRayAll)", &allHits_);
    textWrapped("origin (%.1f, %.1f) m, angle %.0f deg", static_cast<double>(origin_.x), static_cast<double>(origin_.y),
                static_cast<double>(angle_ * 57.29578f));
    distance_.plot("distance to the closest hit (m)", "%.2f m", 80.0f, 0.0f, range_);
  }

private:
  [[nodiscard]] Vec2f direction() const { return {std::cos(angle_), std::sin(angle_)}; }

  Vec2f origin_{0.0f, 6.0f};
  /// rad: pointing down to the right, so the ray sweeps the ground, the circle and the hexagon
  /// (all hits, with bounces) in its first two seconds.
  static constexpr float startAngle = -0.55f;
  float angle_ = startAngle; // rad
  float rate_ = 0.6f;        // rad/s
  float range_ = 30.0f;      // m
  int bounces_ = 3;
  bool allHits_ = true;
  History distance_;
};

const SampleRegistrar registrar{"Engine", "Ray casts",
                                "Closest and all-hits ray casts against every shape type, with surface "
                                "normals and reflections; one-sided chains let rays through from behind.",
                                [] { return std::make_unique<RayCasts>(); }};

} // namespace
} // namespace impetus::samples
