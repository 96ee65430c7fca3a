// ParticleWorld: storage, ids, the step's order, emitters and energies.
#include "particles/particle_world_impl.hpp"

#include <impetus/core/state_hash.hpp>
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/validate.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace impetus {

struct ParticleWorld::Impl : detail::ParticleWorldState {};

namespace detail {

std::uint32_t ParticleWorldState::dense(ParticleId id) const {
  particleIds.requireValid(id, "particle id", "particle");
  return slotToDense[id.index];
}

} // namespace detail

namespace {

void validateSettings(const ParticleWorldSettings& s) {
  requireFinite(s.gravity, "gravity");
  requireFinite(s.wind, "wind");
  if (s.substeps < 1 || s.substeps > 1000) {
    throwInvalid("substeps", s.substeps, "must be between 1 and 1000");
  }
  if (s.constraintIterations < 1 || s.constraintIterations > 1000) {
    throwInvalid("constraintIterations", s.constraintIterations, "must be between 1 and 1000");
  }
  requireNonNegative(s.linearDrag, "linearDrag");
  requireNonNegative(s.dragCoefficient, "dragCoefficient");
  requireNonNegative(s.airDensity, "airDensity");
  requireNonNegative(s.restThreshold, "restThreshold");
  // A cast integer would select no integrator: the particles would never move.
  if (s.integrator != ParticleIntegrator::semiImplicitEuler && s.integrator != ParticleIntegrator::explicitEuler &&
      s.integrator != ParticleIntegrator::velocityVerlet && s.integrator != ParticleIntegrator::rk4) {
    throwInvalid("integrator", static_cast<int>(s.integrator), "unknown ParticleIntegrator");
  }
  const float e = s.particleRestitution;
  if (!(e >= 0.0f && e <= 1.0f)) {
    throwInvalid("particleRestitution", e, "must be in [0, 1]");
  }
}

void validateMaterial(const SurfaceMaterial& m) {
  if (!(m.restitution >= 0.0f && m.restitution <= 1.0f)) {
    throwInvalid("restitution", m.restitution, "must be in [0, 1]");
  }
  requireNonNegative(m.friction, "friction");
}

/// Uniform in [lo, hi) from the generator's raw output (the standard's distributions are not
/// bit-identical across library implementations; mt19937 is).
float uniform(std::mt19937& rng, float lo, float hi) {
  return lo + (hi - lo) * static_cast<float>(static_cast<double>(rng()) / 4294967296.0);
}

/// A unit vector within `cone` radians of the unit vector `axis`.
Vec3f directionInCone(std::mt19937& rng, const Vec3f& axis, float cone, bool planar) {
  if (planar) {
    const float angle = std::atan2(axis.y, axis.x) + uniform(rng, -cone, cone);
    return {std::cos(angle), std::sin(angle), 0.0f};
  }
  // Uniform on the spherical cap: cos(theta) uniform in [cos(cone), 1].
  const float cosTheta = uniform(rng, std::cos(cone), 1.0f);
  const float sinTheta = std::sqrt(std::fmax(0.0f, 1.0f - cosTheta * cosTheta));
  const float phi = uniform(rng, 0.0f, 2.0f * pi<float>);
  const Vec3f helper = std::abs(axis.x) < 0.9f ? Vec3f::unitX() : Vec3f::unitY();
  const Vec3f u = normalize(cross(axis, helper));
  const Vec3f w = cross(axis, u);
  return axis * cosTheta + (u * std::cos(phi) + w * std::sin(phi)) * sinTheta;
}

} // namespace

ParticleWorld::ParticleWorld(const ParticleWorldSettings& settings) : impl_(std::make_unique<Impl>()) {
  validateSettings(settings);
  impl_->settings = settings;
  // The ids it hands out record it: another world refuses them.
  const std::uint32_t number = nextWorldNumber();
  for (IdPool* pool :
       {&impl_->particleIds, &impl_->obstacleIds, &impl_->springIds, &impl_->constraintIds, &impl_->emitterIds}) {
    *pool = IdPool(number);
  }
}
ParticleWorld::~ParticleWorld() = default;
ParticleWorld::ParticleWorld(ParticleWorld&&) noexcept = default;
ParticleWorld& ParticleWorld::operator=(ParticleWorld&&) noexcept = default;

const ParticleWorldSettings& ParticleWorld::settings() const noexcept { return impl_->settings; }
void ParticleWorld::setSettings(const ParticleWorldSettings& settings) {
  validateSettings(settings);
  impl_->settings = settings;
}
float ParticleWorld::time() const noexcept { return impl_->time; }

ParticleId ParticleWorld::createParticle(const ParticleDef& def) {
  requireFinite(def.position, "position");
  requireFinite(def.velocity, "velocity");
  requirePositive(def.mass, "mass");
  requirePositive(def.radius, "radius");
  if (!(def.lifetime > 0.0f)) {
    throwInvalid("lifetime", def.lifetime, "must be positive (infiniteLifetime for a permanent particle)");
  }
  Impl& w = *impl_;
  const ParticleId id = w.particleIds.allocateId<ParticleTag>();
  if (w.slotToDense.size() <= id.index) {
    w.slotToDense.resize(id.index + 1);
  }
  detail::ParticleStore& p = w.particles;
  w.slotToDense[id.index] = static_cast<std::uint32_t>(p.size());
  p.position.push_back(def.position);
  p.velocity.push_back(def.velocity);
  p.userForce.emplace_back();
  p.mass.push_back(def.mass);
  p.inverseMass.push_back(def.pinned ? 0.0f : 1.0f / def.mass);
  p.radius.push_back(def.radius);
  p.age.push_back(0.0f);
  p.lifetime.push_back(def.lifetime);
  p.userData.push_back(def.userData);
  p.id.push_back(id);
  return id;
}

void ParticleWorld::destroyParticle(ParticleId id) {
  Impl& w = *impl_;
  const std::uint32_t i = w.dense(id);
  // Connections to it go first (in order, so the rest keep their relative order).
  std::erase_if(w.springs, [&](const detail::Spring& s) {
    const bool attached = s.a == id || s.b == id;
    if (attached) {
      w.springIds.freeId(s.id);
    }
    return attached;
  });
  std::erase_if(w.constraints, [&](const detail::DistanceConstraint& c) {
    const bool attached = c.a == id || c.b == id;
    if (attached) {
      w.constraintIds.freeId(c.id);
    }
    return attached;
  });
  detail::ParticleStore& p = w.particles;
  const std::uint32_t last = static_cast<std::uint32_t>(p.size() - 1);
  const auto moveLast = [&](auto& array) {
    array[i] = array[last];
    array.pop_back();
  };
  w.slotToDense[p.id[last].index] = i;
  moveLast(p.position);
  moveLast(p.velocity);
  moveLast(p.userForce);
  moveLast(p.mass);
  moveLast(p.inverseMass);
  moveLast(p.radius);
  moveLast(p.age);
  moveLast(p.lifetime);
  moveLast(p.userData);
  moveLast(p.id);
  w.particleIds.freeId(id);
}

bool ParticleWorld::isValid(ParticleId id) const noexcept { return impl_->particleIds.isValidId(id); }
std::size_t ParticleWorld::particleCount() const noexcept { return impl_->particles.size(); }
Vec3f ParticleWorld::position(ParticleId id) const { return impl_->particles.position[impl_->dense(id)]; }
Vec3f ParticleWorld::velocity(ParticleId id) const { return impl_->particles.velocity[impl_->dense(id)]; }
float ParticleWorld::mass(ParticleId id) const { return impl_->particles.mass[impl_->dense(id)]; }
float ParticleWorld::radius(ParticleId id) const { return impl_->particles.radius[impl_->dense(id)]; }
float ParticleWorld::age(ParticleId id) const { return impl_->particles.age[impl_->dense(id)]; }
float ParticleWorld::lifetime(ParticleId id) const { return impl_->particles.lifetime[impl_->dense(id)]; }

void ParticleWorld::setPosition(ParticleId id, const Vec3f& position) {
  impl_->particles.position[impl_->dense(id)] = requireFinite(position, "position");
}
void ParticleWorld::setVelocity(ParticleId id, const Vec3f& velocity) {
  impl_->particles.velocity[impl_->dense(id)] = requireFinite(velocity, "velocity");
}
void ParticleWorld::setPinned(ParticleId id, bool pinned) {
  const std::uint32_t i = impl_->dense(id);
  impl_->particles.inverseMass[i] = pinned ? 0.0f : 1.0f / impl_->particles.mass[i];
  if (pinned) {
    impl_->particles.velocity[i] = {};
  }
}
void ParticleWorld::applyForce(ParticleId id, const Vec3f& force) {
  impl_->particles.userForce[impl_->dense(id)] += requireFinite(force, "force");
}
void ParticleWorld::applyImpulse(ParticleId id, const Vec3f& impulse) {
  const std::uint32_t i = impl_->dense(id);
  impl_->particles.velocity[i] += requireFinite(impulse, "impulse") * impl_->particles.inverseMass[i];
}

std::span<const Vec3f> ParticleWorld::positions() const noexcept { return impl_->particles.position; }
std::span<const Vec3f> ParticleWorld::velocities() const noexcept { return impl_->particles.velocity; }
std::span<const ParticleId> ParticleWorld::ids() const noexcept { return impl_->particles.id; }

std::uint64_t ParticleWorld::stateHash() const {
  StateHash hash;
  const auto& p = impl_->particles;
  for (std::size_t i = 0; i < p.id.size(); ++i) {
    hash.add(p.id[i].index);
    hash.add(p.id[i].generation);
    for (const Vec3f* v : {&p.position[i], &p.velocity[i]}) {
      hash.add(v->x);
      hash.add(v->y);
      hash.add(v->z);
    }
  }
  return hash.value();
}

namespace {

template <class Shape>
ObstacleId addShape(detail::ParticleWorldState& w, const Shape& shape, const SurfaceMaterial& m) {
  validateMaterial(m);
  const ObstacleId id = w.obstacleIds.allocateId<ObstacleTag>();
  w.obstacles.push_back({shape, m, id});
  return id;
}

template <class T, class IdT> void removeById(std::vector<T>& items, IdPool& pool, IdT id, const char* what) {
  const auto it = std::find_if(items.begin(), items.end(), [&](const T& item) { return item.id == id; });
  if (it == items.end()) {
    throwInvalid(std::string(what) + " id", static_cast<double>(id.index), "does not exist");
  }
  items.erase(it);
  pool.freeId(id);
}

} // namespace

ObstacleId ParticleWorld::addObstacle(const PlaneObstacle& plane, const SurfaceMaterial& material) {
  requireFinite(plane.normal, "normal");
  requireFinite(plane.offset, "offset");
  if (!(lengthSquared(plane.normal) > 0.0f)) {
    throwInvalid("normal", 0.0, "plane normal must be non-zero");
  }
  return addShape(*impl_, PlaneObstacle{normalize(plane.normal), plane.offset}, material);
}
ObstacleId ParticleWorld::addObstacle(const SphereObstacle& sphere, const SurfaceMaterial& material) {
  requireFinite(sphere.center, "center");
  requirePositive(sphere.radius, "radius");
  return addShape(*impl_, sphere, material);
}
ObstacleId ParticleWorld::addObstacle(const BoxObstacle& box, const SurfaceMaterial& material) {
  requireFinite(box.center, "center");
  requirePositive(box.halfExtents.x, "halfExtents.x");
  requirePositive(box.halfExtents.y, "halfExtents.y");
  requirePositive(box.halfExtents.z, "halfExtents.z");
  if (!isFinite(box.rotation) || !(lengthSquared(box.rotation) > 0.0f)) {
    throwInvalid("rotation", std::sqrt(lengthSquared(box.rotation)), "must be a finite, non-zero quaternion");
  }
  return addShape(*impl_, BoxObstacle{box.center, box.halfExtents, normalize(box.rotation)}, material);
}
ObstacleId ParticleWorld::addObstacle(const CapsuleObstacle& capsule, const SurfaceMaterial& material) {
  requireFinite(capsule.pointA, "pointA");
  requireFinite(capsule.pointB, "pointB");
  requirePositive(capsule.radius, "radius");
  return addShape(*impl_, capsule, material);
}
void ParticleWorld::removeObstacle(ObstacleId id) { removeById(impl_->obstacles, impl_->obstacleIds, id, "obstacle"); }
std::size_t ParticleWorld::obstacleCount() const noexcept { return impl_->obstacles.size(); }

SpringId ParticleWorld::addSpring(const SpringDef& def) {
  Impl& w = *impl_;
  const Vec3f pa = w.particles.position[w.dense(def.a)];
  const Vec3f pb = def.b.isNull() ? requireFinite(def.anchor, "anchor") : w.particles.position[w.dense(def.b)];
  if (def.a == def.b) {
    throwInvalid("b", static_cast<double>(def.b.index), "a spring needs two different particles");
  }
  requireNonNegative(def.stiffness, "stiffness");
  requireNonNegative(def.damping, "damping");
  requireFinite(def.restLength, "restLength");
  const float rest = def.restLength < 0.0f ? distance(pa, pb) : def.restLength;
  const SpringId id = w.springIds.allocateId<SpringTag>();
  w.springs.push_back({def.a, def.b, def.anchor, def.stiffness, def.damping, rest, id});
  return id;
}
void ParticleWorld::removeSpring(SpringId id) { removeById(impl_->springs, impl_->springIds, id, "spring"); }

ConstraintId ParticleWorld::addDistanceConstraint(const DistanceConstraintDef& def) {
  Impl& w = *impl_;
  const Vec3f pa = w.particles.position[w.dense(def.a)];
  const Vec3f pb = def.b.isNull() ? requireFinite(def.anchor, "anchor") : w.particles.position[w.dense(def.b)];
  if (def.a == def.b) {
    throwInvalid("b", static_cast<double>(def.b.index), "a constraint needs two different particles");
  }
  requireNonNegative(def.compliance, "compliance");
  requireFinite(def.length, "length");
  const float length = def.length < 0.0f ? distance(pa, pb) : def.length;
  const ConstraintId id = w.constraintIds.allocateId<ConstraintTag>();
  w.constraints.push_back({def.a, def.b, def.anchor, length, def.compliance, def.maxOnly, id});
  return id;
}
void ParticleWorld::removeDistanceConstraint(ConstraintId id) {
  removeById(impl_->constraints, impl_->constraintIds, id, "constraint");
}
std::size_t ParticleWorld::springCount() const noexcept { return impl_->springs.size(); }
std::size_t ParticleWorld::constraintCount() const noexcept { return impl_->constraints.size(); }

void ParticleWorld::addAttractor(const Attractor& attractor) {
  requireFinite(attractor.position, "position");
  requireFinite(attractor.strength, "strength");
  requirePositive(attractor.softening, "softening");
  impl_->attractors.push_back(attractor);
}

EmitterId ParticleWorld::addEmitter(const EmitterDef& def) {
  requireFinite(def.position, "position");
  requireFinite(def.direction, "direction");
  if (!(lengthSquared(def.direction) > 0.0f)) {
    throwInvalid("direction", 0.0, "must be non-zero");
  }
  requireNonNegative(def.coneAngle, "coneAngle");
  requireNonNegative(def.minSpeed, "minSpeed");
  if (!(def.maxSpeed >= def.minSpeed) || !std::isfinite(def.maxSpeed)) {
    throwInvalid("maxSpeed", def.maxSpeed, "must be finite and >= minSpeed");
  }
  // The step converts the particles due (rate * dt) to an int: beyond 1e9 per second that
  // overflows (undefined behaviour), and no effect needs that many.
  if (!(def.rate >= 0.0f && def.rate <= 1e9f)) {
    throwInvalid("rate", def.rate, "must be between 0 and 1e9 particles per second");
  }
  if (def.burst < 0 || def.burst > 1'000'000) {
    throwInvalid("burst", def.burst, "must be between 0 and 1000000");
  }
  if (!(def.duration >= 0.0f)) {
    throwInvalid("duration", def.duration, "must be non-negative");
  }
  requirePositive(def.minLifetime, "minLifetime");
  // Finite: a lifetime drawn uniformly from [minLifetime, inf) is inf, or NaN (inf * 0) when the
  // generator draws 0, and a NaN lifetime would make the step throw.
  if (!(def.maxLifetime >= def.minLifetime) || !std::isfinite(def.maxLifetime)) {
    throwInvalid("maxLifetime", def.maxLifetime, "must be finite and >= minLifetime");
  }
  requirePositive(def.mass, "mass");
  requirePositive(def.radius, "radius");
  EmitterDef stored = def;
  stored.direction = normalize(def.direction);
  const EmitterId id = impl_->emitterIds.allocateId<EmitterTag>();
  impl_->emitters.push_back({stored, id, std::mt19937(def.seed)});
  return id;
}
void ParticleWorld::removeEmitter(EmitterId id) { removeById(impl_->emitters, impl_->emitterIds, id, "emitter"); }

namespace {

void spawn(ParticleWorld& world, detail::Emitter& e, int count) {
  const EmitterDef& d = e.def;
  for (int i = 0; i < count; ++i) {
    const Vec3f dir = directionInCone(e.rng, d.direction, d.coneAngle, d.planar);
    const float speed = uniform(e.rng, d.minSpeed, d.maxSpeed);
    const float life = uniform(e.rng, d.minLifetime, d.maxLifetime);
    ParticleDef p;
    p.position = d.position;
    p.velocity = dir * speed;
    p.mass = d.mass;
    p.radius = d.radius;
    p.lifetime = life;
    world.createParticle(p);
  }
}

} // namespace

void ParticleWorld::step(float dt) {
  if (!(dt > 0.0f && dt <= 1.0f)) {
    throwInvalid("dt", dt, "time step must be in (0, 1] s");
  }
  Impl& w = *impl_;
  // Emission first: new particles start at age 0 and this step advances them like the others.
  for (detail::Emitter& e : w.emitters) {
    if (!e.burstDone) {
      e.burstDone = true;
      spawn(*this, e, e.def.burst);
    }
    const float active = std::fmin(dt, std::fmax(0.0f, e.def.duration - e.elapsed));
    e.elapsed += dt;
    e.carry += e.def.rate * active;
    const int count = static_cast<int>(e.carry);
    e.carry -= static_cast<float>(count);
    spawn(*this, e, count);
  }

  const float h = dt / static_cast<float>(w.settings.substeps);
  for (int s = 0; s < w.settings.substeps; ++s) {
    detail::integrate(w, h);
    if (!w.constraints.empty()) {
      detail::solveConstraints(w, h);
    }
    // Particle pairs first, then the obstacles: the static walls have the last word, so a pile
    // pressing on a wall cannot push its particles into it.
    if (w.settings.particleCollisions) {
      detail::collideParticles(w);
    }
    detail::collideObstacles(w, h);
    w.time += h;
  }
  std::fill(w.particles.userForce.begin(), w.particles.userForce.end(), Vec3f{});
  // Ageing and expiry last, so that between steps every particle's age is the time it has been
  // simulated for (its position is where it got to in that time) and is below its lifetime.
  for (float& a : w.particles.age) {
    a += dt;
  }
  for (std::size_t i = w.particles.size(); i-- > 0;) {
    if (w.particles.age[i] >= w.particles.lifetime[i]) {
      destroyParticle(w.particles.id[i]);
    }
  }
}

double ParticleWorld::kineticEnergy() const noexcept {
  const detail::ParticleStore& p = impl_->particles;
  double e = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.inverseMass[i] > 0.0f) {
      e += 0.5 * p.mass[i] * static_cast<double>(lengthSquared(p.velocity[i]));
    }
  }
  return e;
}

double ParticleWorld::potentialEnergy() const noexcept {
  const detail::ParticleStore& p = impl_->particles;
  const Vec3f& g = impl_->settings.gravity;
  double e = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.inverseMass[i] > 0.0f) {
      e -= static_cast<double>(p.mass[i]) * static_cast<double>(dot(g, p.position[i]));
    }
  }
  return e;
}

double ParticleWorld::springEnergy() const noexcept {
  const Impl& w = *impl_;
  double e = 0.0;
  for (const detail::Spring& s : w.springs) {
    const Vec3f pa = w.particles.position[w.slotToDense[s.a.index]];
    const Vec3f pb = s.b.isNull() ? s.anchor : w.particles.position[w.slotToDense[s.b.index]];
    const double stretch = static_cast<double>(distance(pa, pb) - s.restLength);
    e += 0.5 * s.stiffness * stretch * stretch;
  }
  return e;
}

Vec3d ParticleWorld::momentum() const noexcept {
  const detail::ParticleStore& p = impl_->particles;
  Vec3d m{};
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.inverseMass[i] > 0.0f) {
      const Vec3f& v = p.velocity[i];
      m += Vec3d{v.x, v.y, v.z} * static_cast<double>(p.mass[i]);
    }
  }
  return m;
}

} // namespace impetus
