#include "particle_draw.hpp"

#include <algorithm>
#include <cmath>

namespace impetus::samples {

void drawParticles(const ParticleWorld& world, DebugDraw& draw, const Color& color) {
  const auto positions = world.positions();
  const auto ids = world.ids();
  const float pixel = draw.pixelSize();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const float diameterPixels = 2.0f * world.radius(ids[i]) / pixel;
    draw.point({positions[i].x, positions[i].y}, std::max(diameterPixels, 3.0f), color);
  }
}

void drawObstacle(DebugDraw& draw, const PlaneObstacle& plane, float extent) {
  const Vec2f n = normalize(Vec2f{plane.normal.x, plane.normal.y});
  const float len =
      std::sqrt(plane.normal.x * plane.normal.x + plane.normal.y * plane.normal.y + plane.normal.z * plane.normal.z);
  const Vec2f base = n * (plane.offset / (len > 0.0f ? len : 1.0f));
  const Vec2f along = perp(n);
  const Color c = palette::staticBody;
  draw.segment(base - along * extent, base + along * extent, c);
  const float tick = 0.5f * extent / 20.0f;
  for (int i = -20; i <= 20; ++i) {
    const Vec2f p = base + along * (extent * static_cast<float>(i) / 20.0f);
    draw.segment(p, p - n * tick - along * tick, c.withAlpha(0.5f));
  }
}

void drawObstacle(DebugDraw& draw, const SphereObstacle& sphere) {
  draw.solidCircle({sphere.center.x, sphere.center.y}, sphere.radius, 0.0f,
                   palette::staticBody.scaled(0.5f).withAlpha(0.6f), palette::staticBody);
}

void drawObstacle(DebugDraw& draw, const BoxObstacle& box) {
  const Vec2f c{box.center.x, box.center.y};
  Vec2f corners[4];
  const float sx[] = {-1.0f, 1.0f, 1.0f, -1.0f};
  const float sy[] = {-1.0f, -1.0f, 1.0f, 1.0f};
  for (int i = 0; i < 4; ++i) {
    const Vec3f local{sx[i] * box.halfExtents.x, sy[i] * box.halfExtents.y, 0.0f};
    const Vec3f world = rotate(box.rotation, local);
    corners[i] = c + Vec2f{world.x, world.y};
  }
  draw.solidPolygon(corners, palette::staticBody.scaled(0.5f).withAlpha(0.6f), palette::staticBody);
}

} // namespace impetus::samples
