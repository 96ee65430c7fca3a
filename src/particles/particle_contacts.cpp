// Particle contacts: static obstacles (plane, sphere, box, capsule) and particle pairs found
// through a spatial hash grid.
#include "particles/particle_world_impl.hpp"

#include <algorithm>
#include <array>

namespace impetus::detail {
namespace {

/// Where a particle touches an obstacle: the outward normal and the signed distance from the
/// obstacle's surface to the particle's centre (penetration when below the particle's radius).
struct SurfacePoint {
  Vec3f normal;
  float distance;
};

SurfacePoint closest(const PlaneObstacle& plane, const Vec3f& x) {
  return {plane.normal, dot(plane.normal, x) - plane.offset};
}

/// Distance from a point: the normal points from `point` to x (up when they coincide).
SurfacePoint fromPoint(const Vec3f& point, const Vec3f& x, float inflate) {
  const Vec3f d = x - point;
  const float len = length(d);
  return {len > 0.0f ? d / len : Vec3f::unitY(), len - inflate};
}

SurfacePoint closest(const SphereObstacle& sphere, const Vec3f& x) {
  return fromPoint(sphere.center, x, sphere.radius);
}

SurfacePoint closest(const CapsuleObstacle& capsule, const Vec3f& x) {
  const Vec3f ab = capsule.pointB - capsule.pointA;
  const float ab2 = lengthSquared(ab);
  const float t = ab2 > 0.0f ? std::clamp(dot(x - capsule.pointA, ab) / ab2, 0.0f, 1.0f) : 0.0f;
  return fromPoint(capsule.pointA + ab * t, x, capsule.radius);
}

SurfacePoint closest(const BoxObstacle& box, const Vec3f& x) {
  const Vec3f local = inverseRotate(box.rotation, x - box.center);
  const Vec3f h = box.halfExtents;
  const Vec3f q = abs(local) - h; // per axis: > 0 outside that slab
  if (q.x > 0.0f || q.y > 0.0f || q.z > 0.0f) {
    // Outside: the closest point is the clamped one.
    const Vec3f clamped{std::clamp(local.x, -h.x, h.x), std::clamp(local.y, -h.y, h.y), std::clamp(local.z, -h.z, h.z)};
    const SurfacePoint s = fromPoint(clamped, local, 0.0f);
    return {rotate(box.rotation, s.normal), s.distance};
  }
  // Inside: leave through the nearest face.
  int axis = 0;
  if (q.y > q[axis]) {
    axis = 1;
  }
  if (q.z > q[axis]) {
    axis = 2;
  }
  Vec3f n{};
  n[axis] = local[axis] < 0.0f ? -1.0f : 1.0f;
  return {rotate(box.rotation, n), q[axis]};
}

/// Reflects the normal velocity with restitution (no bounce below the rest threshold) and
/// applies Coulomb friction: the tangential speed drops by at most mu times the normal speed
/// change, never reversing.
Vec3f respond(const Vec3f& v, const Vec3f& n, float restitution, float friction, float restThreshold) {
  const float vn = dot(v, n);
  if (vn >= 0.0f) {
    return v;
  }
  const float vnAfter = -vn > restThreshold ? -restitution * vn : 0.0f;
  const float normalChange = vnAfter - vn;
  Vec3f vt = v - n * vn;
  const float vtLength = length(vt);
  const float frictionChange = friction * normalChange;
  vt = vtLength <= frictionChange ? Vec3f{} : vt * (1.0f - frictionChange / vtLength);
  return vt + n * vnAfter;
}

} // namespace

void collideObstacles(ParticleWorldState& w) {
  ParticleStore& p = w.particles;
  const float threshold = w.settings.restThreshold;
  for (const ObstacleShape& o : w.obstacles) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.inverseMass[i] == 0.0f) {
        continue;
      }
      const SurfacePoint s = std::visit([&](const auto& shape) { return closest(shape, p.position[i]); }, o.shape);
      const float penetration = p.radius[i] - s.distance;
      if (penetration > 0.0f) {
        p.position[i] += s.normal * penetration;
        p.velocity[i] = respond(p.velocity[i], s.normal, o.material.restitution, o.material.friction, threshold);
      }
    }
  }
}

void collideParticles(ParticleWorldState& w) {
  ParticleStore& p = w.particles;
  Scratch& s = w.scratch;
  const std::size_t n = p.size();
  if (n < 2) {
    return;
  }
  float maxRadius = 0.0f;
  for (float r : p.radius) {
    maxRadius = std::max(maxRadius, r);
  }
  // Cells of two radii: touching particles are in the same or adjacent cells.
  const float cell = 2.0f * maxRadius;
  const float inverseCell = 1.0f / cell;
  const std::uint32_t tableSize = static_cast<std::uint32_t>(2 * n);
  const auto cellKey = [&](int ix, int iy, int iz) {
    const std::uint32_t h = (static_cast<std::uint32_t>(ix) * 92837111U) ^
                            (static_cast<std::uint32_t>(iy) * 689287499U) ^
                            (static_cast<std::uint32_t>(iz) * 283923481U);
    return h % tableSize;
  };
  const auto cellCoords = [&](const Vec3f& x) {
    return std::array<int, 3>{static_cast<int>(std::floor(x.x * inverseCell)),
                              static_cast<int>(std::floor(x.y * inverseCell)),
                              static_cast<int>(std::floor(x.z * inverseCell))};
  };
  // Counting sort of the particles by bucket (stable: equal buckets keep index order).
  s.cellOfParticle.resize(n);
  s.cellStart.assign(tableSize + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = cellCoords(p.position[i]);
    s.cellOfParticle[i] = cellKey(c[0], c[1], c[2]);
    ++s.cellStart[s.cellOfParticle[i] + 1];
  }
  for (std::uint32_t b = 0; b < tableSize; ++b) {
    s.cellStart[b + 1] += s.cellStart[b];
  }
  s.sorted.resize(n);
  s.cursor.assign(s.cellStart.begin(), s.cellStart.end() - 1);
  for (std::size_t i = 0; i < n; ++i) {
    s.sorted[s.cursor[s.cellOfParticle[i]]++] = static_cast<std::uint32_t>(i);
  }
  const float e = w.settings.particleRestitution;
  const float threshold = w.settings.restThreshold;
  std::array<std::uint32_t, 27> buckets{};
  for (std::uint32_t i = 0; i < n; ++i) {
    const auto c = cellCoords(p.position[i]);
    int count = 0;
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          buckets[static_cast<std::size_t>(count++)] = cellKey(c[0] + dx, c[1] + dy, c[2] + dz);
        }
      }
    }
    // Hash collisions can map two neighbour cells to one bucket: visit each bucket once.
    std::sort(buckets.begin(), buckets.end());
    const auto last = std::unique(buckets.begin(), buckets.end());
    for (auto b = buckets.begin(); b != last; ++b) {
      for (std::uint32_t k = s.cellStart[*b]; k < s.cellStart[*b + 1]; ++k) {
        const std::uint32_t j = s.sorted[k];
        if (j <= i) {
          continue;
        }
        const float wi = p.inverseMass[i];
        const float wj = p.inverseMass[j];
        const float wsum = wi + wj;
        const Vec3f d = p.position[j] - p.position[i];
        const float reach = p.radius[i] + p.radius[j];
        const float dist2 = lengthSquared(d);
        if (wsum == 0.0f || dist2 >= reach * reach) {
          continue;
        }
        const float dist = std::sqrt(dist2);
        const Vec3f normal = dist > 0.0f ? d / dist : Vec3f::unitY();
        // Separate in proportion to the inverse masses: the centre of mass does not move.
        const Vec3f push = normal * ((reach - dist) / wsum);
        p.position[i] -= push * wi;
        p.position[j] += push * wj;
        const float approach = dot(p.velocity[j] - p.velocity[i], normal);
        if (approach < 0.0f) {
          const float restitution = -approach > threshold ? e : 0.0f;
          const Vec3f impulse = normal * (-(1.0f + restitution) * approach / wsum);
          p.velocity[i] -= impulse * wi;
          p.velocity[j] += impulse * wj;
        }
      }
    }
  }
}

} // namespace impetus::detail
