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

/// The displacement per unit velocity change that the integrator would have produced had a
/// change at the end of a substep of h come from a force during it: h for semi-implicit Euler
/// (x += v_new h), h/2 for velocity Verlet and RK4 (a constant force moves x by a h^2/2), 0 for
/// explicit Euler (x += v_old h).
float displacementPerVelocity(ParticleIntegrator integrator, float h) {
  switch (integrator) {
  case ParticleIntegrator::semiImplicitEuler:
    return h;
  case ParticleIntegrator::velocityVerlet:
  case ParticleIntegrator::rk4:
    return 0.5f * h;
  case ParticleIntegrator::explicitEuler:
    break;
  }
  return 0.0f;
}

} // namespace

void collideObstacles(ParticleWorldState& w, float h) {
  ParticleStore& p = w.particles;
  const float threshold = w.settings.restThreshold;
  const float share = displacementPerVelocity(w.settings.integrator, h);
  for (const ObstacleShape& o : w.obstacles) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.inverseMass[i] == 0.0f) {
        continue;
      }
      const SurfacePoint s = std::visit([&](const auto& shape) { return closest(shape, p.position[i]); }, o.shape);
      const float penetration = p.radius[i] - s.distance;
      if (penetration > 0.0f) {
        p.position[i] += s.normal * penetration;
        const Vec3f before = p.velocity[i];
        p.velocity[i] = respond(before, s.normal, o.material.restitution, o.material.friction, threshold);
        // Friction acts during the substep, so the tangential distance it prevents is taken back
        // too (the push-out already did this along the normal). Without it a particle held by
        // static friction on a slope creeps down by g sin(theta) h^2 every substep (0.14 m in
        // 10 s at 20 degrees and h = 1/240 s) because it moved before friction stopped it.
        const Vec3f change = p.velocity[i] - before;
        p.position[i] += (change - s.normal * dot(change, s.normal)) * share;
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
  // The bucket of cell (ix, iy, iz): a spatial hash, XOR of one product per axis.
  const auto hashX = [](int ix) { return static_cast<std::uint32_t>(ix) * 92837111U; };
  const auto hashY = [](int iy) { return static_cast<std::uint32_t>(iy) * 689287499U; };
  const auto hashZ = [](int iz) { return static_cast<std::uint32_t>(iz) * 283923481U; };
  const auto cellCoords = [&](const Vec3f& x) {
    // Clamped so that a particle far away (or one an unstable spring has sent to infinity or
    // NaN) still maps to a cell instead of an undefined float-to-int conversion.
    const auto coord = [&](float v) {
      const float c = std::floor(v * inverseCell);
      return c >= -1e9f && c <= 1e9f ? static_cast<int>(c) : 0;
    };
    return std::array<int, 3>{coord(x.x), coord(x.y), coord(x.z)};
  };
  // Counting sort of the particles by bucket (stable: equal buckets keep index order).
  s.cellOfParticle.resize(n);
  s.cellStart.assign(tableSize + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = cellCoords(p.position[i]);
    s.cellOfParticle[i] = (hashX(c[0]) ^ hashY(c[1]) ^ hashZ(c[2])) % tableSize;
    ++s.cellStart[s.cellOfParticle[i] + 1];
  }
  for (std::uint32_t b = 0; b < tableSize; ++b) {
    s.cellStart[b + 1] += s.cellStart[b];
  }
  s.sorted.resize(n + 4); // + padding for the unrolled gathering below
  s.cursor.assign(s.cellStart.begin(), s.cellStart.end() - 1);
  for (std::size_t i = 0; i < n; ++i) {
    s.sorted[s.cursor[s.cellOfParticle[i]]++] = static_cast<std::uint32_t>(i);
  }
  const std::uint32_t* const cellStart = s.cellStart.data();
  const std::uint32_t* const sorted = s.sorted.data();
  Vec3f* const position = p.position.data();
  Vec3f* const velocity = p.velocity.data();
  const float* const inverseMass = p.inverseMass.data();
  const float* const radius = p.radius.data();
  const float e = w.settings.particleRestitution;
  const float threshold = w.settings.restThreshold;
  // Pairs are resolved in a fixed order: particles i ascending; for each, its 27 neighbour
  // buckets in ascending key order, each once; within a bucket, j ascending, j > i only.
  // The loop below keeps that order but avoids data-dependent branches where it can (a sort of
  // the 27 keys, a loop per bucket, a test per candidate): they mispredicted about 90 times per
  // particle and substep and took two thirds of the time of a pile of touching particles.
  constexpr std::uint32_t emptySlot = 0xffffffffU; // no bucket has this key (keys < 2n)
  constexpr std::uint32_t unrolled = 4;            // bucket entries gathered without a branch
  std::array<std::uint32_t, 128> candidates;       // the j > i gathered so far, in order
  std::array<std::uint32_t, 27> buckets{};
  std::array<std::uint32_t, 27> ordered;
  for (std::uint32_t i = 0; i < n; ++i) {
    const auto c = cellCoords(position[i]);
    int count = 0;
    for (int dx = -1; dx <= 1; ++dx) {
      const std::uint32_t hx = hashX(c[0] + dx);
      for (int dy = -1; dy <= 1; ++dy) {
        const std::uint32_t hxy = hx ^ hashY(c[1] + dy);
        for (int dz = -1; dz <= 1; ++dz) {
          buckets[static_cast<std::size_t>(count++)] = (hxy ^ hashZ(c[2] + dz)) % tableSize;
        }
      }
    }
    // The buckets in ascending order, each once (hash collisions can map two neighbour cells to
    // one bucket): a key's rank is the number of smaller keys, so equal keys share a slot and
    // the slots left over stay empty. Branch-free and vectorized, unlike a sort.
    ordered.fill(emptySlot);
    for (std::size_t a = 0; a < buckets.size(); ++a) {
      std::uint32_t rank = 0;
      for (std::size_t b = 0; b < buckets.size(); ++b) {
        rank += buckets[b] < buckets[a] ? 1U : 0U;
      }
      ordered[rank] = buckets[a];
    }
    // Particle i's state stays in registers: every j below is > i, so no write touches it.
    Vec3f xi = position[i];
    Vec3f vi = velocity[i];
    const float wi = inverseMass[i];
    const float ri = radius[i];
    const auto resolve = [&](std::uint32_t j) {
      const float wj = inverseMass[j];
      const float wsum = wi + wj;
      const Vec3f d = position[j] - xi;
      const float reach = ri + radius[j];
      const float dist2 = lengthSquared(d);
      if (wsum == 0.0f || dist2 >= reach * reach) {
        return;
      }
      const float dist = std::sqrt(dist2);
      const Vec3f normal = dist > 0.0f ? d / dist : Vec3f::unitY();
      // Separate in proportion to the inverse masses: the centre of mass does not move.
      const Vec3f push = normal * ((reach - dist) / wsum);
      xi -= push * wi;
      position[j] += push * wj;
      const float approach = dot(velocity[j] - vi, normal);
      if (approach < 0.0f) {
        const float restitution = -approach > threshold ? e : 0.0f;
        const Vec3f impulse = normal * (-(1.0f + restitution) * approach / wsum);
        vi -= impulse * wi;
        velocity[j] += impulse * wj;
      }
    };
    // Candidates are tested in the order gathered; a crowded neighbourhood (more than fit) is
    // tested in batches, which is the same order.
    std::size_t m = 0;
    const auto flush = [&] {
      for (std::size_t t = 0; t < m; ++t) {
        resolve(candidates[t]);
      }
      m = 0;
    };
    for (const std::uint32_t bucket : ordered) {
      if (bucket == emptySlot) {
        continue;
      }
      if (m + unrolled > candidates.size()) {
        flush();
      }
      const std::uint32_t begin = cellStart[bucket];
      const std::uint32_t size = cellStart[bucket + 1] - begin;
      // The first `unrolled` entries, each kept when it is in the bucket and after i (`sorted`
      // is padded, so reading past its end is safe).
      for (std::uint32_t q = 0; q < unrolled; ++q) {
        const std::uint32_t j = sorted[begin + q];
        candidates[m] = j;
        m += (q < size && j > i) ? 1U : 0U;
      }
      for (std::uint32_t q = unrolled; q < size; ++q) {
        if (m == candidates.size()) {
          flush();
        }
        const std::uint32_t j = sorted[begin + q];
        candidates[m] = j;
        m += j > i ? 1U : 0U;
      }
    }
    flush();
    position[i] = xi;
    velocity[i] = vi;
  }
}

} // namespace impetus::detail
