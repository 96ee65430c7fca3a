// The rope builder: particles along a line, joined by XPBD distance constraints or by the
// book's spring-dampers.
#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/particles/rope.hpp>

#include <cmath>

namespace impetus {

RopeDef RopeDef::along(const Vec3f& start, const Vec3f& direction, float length) {
  requireFinite(direction, "direction");
  if (!(lengthSquared(direction) > 0.0f)) {
    throwInvalid("direction", 0.0, "must be non-zero");
  }
  requirePositive(length, "length");
  RopeDef def;
  def.start = start;
  def.end = start + normalize(direction) * length;
  return def;
}

namespace {

void validate(const RopeDef& def) {
  requireFinite(def.start, "start");
  requireFinite(def.end, "end");
  // Finite too: ends at +-3e38 are finite but their distance is not, and the particles
  // interpolated between them would be NaN.
  if (const float length = distance(def.start, def.end); !(length > 0.0f && std::isfinite(length))) {
    throwInvalid("end", length, "must differ from start by a finite distance (the rope needs a length)");
  }
  if (def.segments < 1 || def.segments > 1'000'000) {
    throwInvalid("segments", def.segments, "must be between 1 and 1000000");
  }
  requirePositive(def.totalMass, "totalMass");
  // Each particle's share must stay a positive float, or the world would refuse the rope half built.
  if (!(def.totalMass / static_cast<float>(def.segments + 1) > 0.0f)) {
    throwInvalid("totalMass", def.totalMass, "too small to share among segments + 1 particles");
  }
  requirePositive(def.particleRadius, "particleRadius");
  requireNonNegative(def.compliance, "compliance");
  requirePositive(def.stiffness, "stiffness");
  requireNonNegative(def.damping, "damping");
}

} // namespace

Rope createRope(ParticleWorld& world, const RopeDef& def) {
  validate(def);
  const int n = def.segments;
  Rope rope;
  rope.particles.reserve(static_cast<std::size_t>(n) + 1);
  const float particleMass = def.totalMass / static_cast<float>(n + 1);
  // Everything is validated: the world's own checks cannot fail from here on (the positions are
  // finite interpolations and the mass and radius positive).
  for (int i = 0; i <= n; ++i) {
    ParticleDef p;
    p.position = lerp(def.start, def.end, static_cast<float>(i) / static_cast<float>(n));
    p.mass = particleMass;
    p.radius = def.particleRadius;
    p.pinned = (i == 0 && def.pinStart) || (i == n && def.pinEnd);
    rope.particles.push_back(world.createParticle(p));
  }
  const float segmentLength = distance(def.start, def.end) / static_cast<float>(n);
  rope.restLength = segmentLength * static_cast<float>(n);
  for (std::size_t i = 0; i + 1 < rope.particles.size(); ++i) {
    const ParticleId a = rope.particles[i];
    const ParticleId b = rope.particles[i + 1];
    if (def.model == RopeModel::xpbd) {
      DistanceConstraintDef c;
      c.a = a;
      c.b = b;
      c.length = segmentLength;
      c.compliance = def.compliance;
      c.maxOnly = true; // a rope resists stretching only: it can go slack
      rope.constraints.push_back(world.addDistanceConstraint(c));
    } else {
      SpringDef s;
      s.a = a;
      s.b = b;
      s.stiffness = def.stiffness;
      s.damping = def.damping;
      s.restLength = segmentLength;
      rope.springs.push_back(world.addSpring(s));
    }
  }
  return rope;
}

float ropeLength(const ParticleWorld& world, const Rope& rope) {
  float total = 0.0f;
  for (std::size_t i = 0; i + 1 < rope.particles.size(); ++i) {
    total += distance(world.position(rope.particles[i]), world.position(rope.particles[i + 1]));
  }
  return total;
}

} // namespace impetus
