// The 3D world's step: the stages of the soft step (after Erin Catto's Solver2D and Box2D v3),
// in order. Collide at the step's start; prepare the bodies and contacts; then, substep after
// substep: integrate velocities, warm start the contacts with their impulses, solve them with
// bias (overlap pushed apart softly), integrate positions (within the speed caps), relax (solve
// again without bias, taking back the velocity the push added, and friction); then restitution,
// and the impulses and results stored.
#include "rigid3d/world_impl.hpp"

#include <impetus/math/scalar.hpp>

#include <algorithm>
#include <cmath>

namespace impetus::rigid3d::detail {

namespace {

/// How many Newton iterations the gyroscopic step makes: the residual falls quadratically from
/// (h |w|)^2 and, within the spin cap (h |w| <= pi/4), two bring it under float rounding.
constexpr int gyroscopicNewtonIterations = 2;

/// Solves J x = b by Cramer's rule; false when J is not comfortably invertible (det <= 0: the
/// gyroscopic Jacobian is I plus a perturbation of order h |w| |I|, so its determinant only
/// reaches zero far beyond the spin cap).
bool solve3(const Mat33f& j, const Vec3f& b, Vec3f& x) {
  const float det = dot(j.cx, cross(j.cy, j.cz));
  if (!(det > 0.0f)) {
    return false;
  }
  const float inv = 1.0f / det;
  x = Vec3f{dot(b, cross(j.cy, j.cz)), dot(j.cx, cross(b, j.cz)), dot(j.cx, cross(j.cy, b))} * inv;
  return true;
}

/// A substep of a dynamic body's velocities: gravity and force, torque, the gyroscopic torque,
/// damping (implicit: stable for any coefficient), then the locks.
void integrateVelocity(BodyState& s, const BodySim& sim, float h) {
  const Quatf q = normalize(s.dq * sim.rotation);
  s.v = (s.v + sim.acceleration * h) * (1.0f / (1.0f + h * sim.linearDamping));
  const Vec3f w = s.w + worldInverseInertia(q, sim.inertia, sim.inverseInertia, sim.locks) * (sim.torque * h);
  const GyroscopicStep gyroscopic = gyroscopicStep(q, sim.inertia, w, h);
  s.gyroscopicLag = gyroscopic.lag;
  s.w = (w + gyroscopic.change) * (1.0f / (1.0f + h * sim.angularDamping));
  s.v = withoutLockedLinear(s.v, sim.locks);
  s.w = withoutLockedAngular(s.w, sim.locks);
}

/// Holds a body's speeds within the world's caps: the linear speed cap, and a quarter
/// turn a substep unless the body allows fast rotation.
void capVelocity(BodyState& s, const BodySim& sim, const StepContext& context) {
  if (const float v2 = lengthSquared(s.v); v2 > context.maxLinearSpeed * context.maxLinearSpeed) {
    s.v = s.v * (context.maxLinearSpeed / std::sqrt(v2));
  }
  if (!sim.allowFastRotation) {
    if (const float w2 = lengthSquared(s.w); w2 > context.maxAngularSpeed * context.maxAngularSpeed) {
      s.w = s.w * (context.maxAngularSpeed / std::sqrt(w2));
    }
  }
}

/// A substep of a body's position: the centre along v, the rotation by the substep's mean spin
/// (q += h/2 (0, w - gyroscopicLag) q, normalised: the Cayley rotation of the midpoint rule's
/// mean spin, with which a torque-free body's angular momentum stays fixed in the world).
void integratePosition(BodyState& s, float h) {
  s.dp += s.v * h;
  const Quatf spin = Quatf{0.0f, s.w - s.gyroscopicLag} * s.dq;
  s.dq = normalize(s.dq + spin * (0.5f * h));
}

StepContext makeStepContext(const WorldState& w, float dt) {
  StepContext c;
  c.dt = dt;
  c.substeps = w.def.substeps;
  c.h = dt / static_cast<float>(c.substeps);
  c.inverseH = 1.0f / c.h;
  c.maxLinearSpeed = w.def.maxLinearSpeed;
  c.maxAngularSpeed = maxRotationPerSubstep * c.inverseH;
  c.maxContactPushSpeed = w.def.maxContactPushSpeed;
  // A spring stiffer than a quarter of the substep rate is more than the substep can follow.
  const float hertz = std::min(w.def.contactHertz, 0.25f * c.inverseH);
  c.contactSoftness = solver::makeSoft(hertz, w.def.contactDampingRatio, c.h);
  c.staticContactSoftness = solver::makeSoft(2.0f * hertz, w.def.contactDampingRatio, c.h);
  return c;
}

/// The solver's arrays from the awake bodies: states and sims in solver order.
void prepareBodies(WorldState& w) {
  w.awakeBodySet.compact();
  const auto awake = w.awakeBodySet.items();
  w.awakeBodies.assign(awake.begin(), awake.end());
  const auto n = w.awakeBodies.size();
  w.states.resize(n + 1);
  w.sims.resize(n);
  w.states[n] = BodyState{}; // the static bodies' state: at rest, never written
  for (std::size_t i = 0; i < n; ++i) {
    Body& b = w.bodies[w.awakeBodies[i]];
    b.solverIndex = static_cast<std::uint32_t>(i);
    w.states[i] = BodyState{b.linearVelocity, b.angularVelocity, {}, Quatf::identity(), {}};
    BodySim& sim = w.sims[i];
    sim.dynamic = b.type == BodyType::dynamicBody;
    sim.rotation = b.transform.q;
    sim.inertia = b.inertia;
    sim.inverseInertia = b.inverseInertia;
    sim.acceleration = sim.dynamic ? w.def.gravity * b.gravityScale + b.force * b.inverseMass : Vec3f{};
    sim.torque = sim.dynamic ? b.torque : Vec3f{};
    sim.linearDamping = b.linearDamping;
    sim.angularDamping = b.angularDamping;
    sim.locks = b.locks;
    sim.allowFastRotation = b.allowFastRotation;
  }
}

/// The step's results into the bodies: velocities, the new pose; forces cleared.
void finalizeBodies(WorldState& w) {
  for (std::size_t i = 0; i < w.awakeBodies.size(); ++i) {
    Body& b = w.bodies[w.awakeBodies[i]];
    const BodyState& s = w.states[i];
    b.linearVelocity = s.v;
    b.angularVelocity = s.w;
    b.center += s.dp;
    const Quatf q = normalize(s.dq * b.transform.q);
    b.transform = {b.center - rotate(q, b.localCenter), q};
    b.force = {};
    b.torque = {};
  }
}

} // namespace

GyroscopicStep gyroscopicStep(const Quatf& rotation, const Mat33f& inertia, const Vec3f& worldSpin, float h) {
  // In the body frame the inertia is constant: I (w2 - w1) + h wm x (I wm) = 0, wm = (w1 + w2)/2,
  // by Newton on g(w2), dg/dw2 = I + h/2 (skew(wm) I - skew(I wm)).
  const Vec3f w1 = inverseRotate(rotation, worldSpin);
  Vec3f w2 = w1;
  for (int iteration = 0; iteration < gyroscopicNewtonIterations; ++iteration) {
    const Vec3f wm = (w1 + w2) * 0.5f;
    const Vec3f lm = inertia * wm;
    const Vec3f g = inertia * (w2 - w1) + cross(wm, lm) * h;
    const Mat33f jacobian = inertia + (skew(wm) * inertia - skew(lm)) * (0.5f * h);
    Vec3f step;
    if (!solve3(jacobian, g, step)) {
      break; // beyond any spin the substeps can follow: the last iterate stands
    }
    w2 -= step;
  }
  // The body turns this substep at the mean spin wm, by the Cayley rotation of h wm (what the
  // position update's q += h/2 (0, wm) q, normalised, is): the new spin is w2 expressed in the
  // turned frame, that rotation of R w2. Every term is a change, added to the world spin rather
  // than a world spin rebuilt from the body frame's, whose rounding would scale the whole spin
  // every substep (an energy drift of 1e-7 a substep).
  const Vec3f halfChange = rotate(rotation, w2 - w1) * 0.5f;
  const Vec3f meanSpin = worldSpin + halfChange;
  const Vec3f u = meanSpin * (0.5f * h);
  const Vec3f spun = worldSpin + halfChange * 2.0f;
  const Vec3f turn = (cross(u, spun) + cross(u, cross(u, spun))) * (2.0f / (1.0f + lengthSquared(u)));
  return {halfChange * 2.0f + turn, halfChange + turn};
}

void solve(WorldState& w, float dt) {
  const StepContext context = makeStepContext(w, dt);
  updateContacts(w); // first: a contact that begins may wake bodies into this step
  prepareBodies(w);
  prepareContacts(w, context);
  const std::size_t n = w.sims.size();
  for (int substep = 0; substep < context.substeps; ++substep) {
    for (std::size_t i = 0; i < n; ++i) {
      if (w.sims[i].dynamic) {
        integrateVelocity(w.states[i], w.sims[i], context.h);
      }
    }
    warmStartContacts(w);
    solveContacts(w, context, true);
    for (std::size_t i = 0; i < n; ++i) {
      if (w.sims[i].dynamic) {
        capVelocity(w.states[i], w.sims[i], context);
      }
      integratePosition(w.states[i], context.h);
    }
    solveContacts(w, context, false);
  }
  applyRestitution(w);
  storeImpulses(w);
  sweepFastBodies(w);
  finalizeBodies(w);
  updateSleep(w, dt);
}

} // namespace impetus::rigid3d::detail
