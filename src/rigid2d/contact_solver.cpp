// The soft-step contact solver (after Erin Catto's Solver2D "soft step" and Box2D v3): soft
// contact constraints with a stiffness in hertz, sub-stepping, warm starting, a relax pass and
// a restitution pass.
#include "rigid2d/world_impl.hpp"

#include <impetus/math/scalar.hpp>

#include <algorithm>

namespace impetus::rigid2d::detail {
namespace {

/// Soft constraint coefficients for a spring of `hertz` and damping ratio `zeta` over a
/// substep h: the bias rate (1/s) that turns a position error into a velocity target, and the
/// mass and impulse scales that make the constraint a spring-damper instead of rigid.
struct Softness {
  float biasRate = 0.0f;
  float massScale = 1.0f;
  float impulseScale = 0.0f;
};

Softness makeSoft(float hertz, float zeta, float h) {
  if (hertz == 0.0f) {
    return {};
  }
  const float omega = 2.0f * pi<float> * hertz;
  const float a1 = 2.0f * zeta + h * omega;
  const float a2 = h * omega * a1;
  const float a3 = 1.0f / (1.0f + a2);
  return {omega / a1, a2 * a3, a3};
}

struct ConstraintPoint {
  Vec2f rA, rB; ///< anchors relative to the centres of mass, world axes
  float adjustedSeparation = 0.0f;
  float normalImpulse = 0.0f;
  float tangentImpulse = 0.0f;
  float maxNormalImpulse = 0.0f;
  float normalMass = 0.0f;
  float tangentMass = 0.0f;
  float relativeVelocity = 0.0f; ///< normal approach speed before the step, for restitution
};

struct Constraint {
  std::uint32_t bodyA = 0, bodyB = 0;
  float mA = 0.0f, iA = 0.0f, mB = 0.0f, iB = 0.0f;
  Vec2f normal;
  float friction = 0.0f;
  float restitution = 0.0f;
  Softness softness;
  int pointCount = 0;
  std::array<ConstraintPoint, 2> points{};
  Contact* contact = nullptr;
};

Vec2f velocityAt(const BodyState& s, const Vec2f& r) { return s.v + cross(s.w, r); }

void applyImpulse(BodyState& a, BodyState& b, const Constraint& c, const ConstraintPoint& p, const Vec2f& impulse) {
  a.v -= impulse * c.mA;
  a.w -= c.iA * cross(p.rA, impulse);
  b.v += impulse * c.mB;
  b.w += c.iB * cross(p.rB, impulse);
}

void solve(std::vector<Constraint>& constraints, std::vector<BodyState>& states, float inverseH, float pushSpeed,
           bool useBias) {
  for (Constraint& c : constraints) {
    BodyState& a = states[c.bodyA];
    BodyState& b = states[c.bodyB];
    const Vec2f dp = b.dp - a.dp;
    for (int k = 0; k < c.pointCount; ++k) {
      ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
      // Current separation from the deltas: the anchors turn with their bodies.
      const Vec2f d = dp + rotate(b.dq, p.rB) - rotate(a.dq, p.rA);
      const float s = dot(d, c.normal) + p.adjustedSeparation;
      float bias = 0.0f;
      float massScale = 1.0f;
      float impulseScale = 0.0f;
      if (s > 0.0f) {
        bias = s * inverseH; // speculative: may close the gap this substep, no more
      } else if (useBias) {
        bias = std::max(c.softness.biasRate * s, -pushSpeed);
        massScale = c.softness.massScale;
        impulseScale = c.softness.impulseScale;
      }
      const float vn = dot(velocityAt(b, p.rB) - velocityAt(a, p.rA), c.normal);
      if (useBias && s <= 0.0f) {
        // The approach speed at impact, for restitution: gravity may have sped the bodies up
        // since the step began (2% of e^2 h in a dropped ball's rebound).
        p.relativeVelocity = std::min(p.relativeVelocity, vn);
      }
      const float impulse = -p.normalMass * massScale * (vn + bias) - impulseScale * p.normalImpulse;
      const float total = std::max(p.normalImpulse + impulse, 0.0f);
      const float applied = total - p.normalImpulse;
      p.normalImpulse = total;
      p.maxNormalImpulse = std::max(p.maxNormalImpulse, applied);
      applyImpulse(a, b, c, p, c.normal * applied);
    }
    const Vec2f tangent{c.normal.y, -c.normal.x};
    for (int k = 0; k < c.pointCount; ++k) {
      ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
      const float vt = dot(velocityAt(b, p.rB) - velocityAt(a, p.rA), tangent);
      const float limit = c.friction * p.normalImpulse;
      const float total = std::clamp(p.tangentImpulse - p.tangentMass * vt, -limit, limit);
      const float applied = total - p.tangentImpulse;
      p.tangentImpulse = total;
      applyImpulse(a, b, c, p, tangent * applied);
    }
  }
}

} // namespace

void solveContacts(WorldState& w, float dt) {
  const int substeps = w.def.substeps;
  const float h = dt / static_cast<float>(substeps);
  const float inverseH = 1.0f / h;
  // Stiffer than a quarter of the substep rate cannot be resolved by the substeps.
  const float hertz = std::min(w.def.contactHertz, 0.25f * inverseH);
  const Softness soft = makeSoft(hertz, w.def.contactDampingRatio, h);
  const Softness staticSoft = makeSoft(2.0f * hertz, w.def.contactDampingRatio, h);

  // Prepare: one constraint per touching contact that involves a moving body.
  std::vector<Constraint> constraints;
  constraints.reserve(w.contacts.size());
  for (auto& [key, contact] : w.contacts) {
    const Manifold& m = contact.manifold;
    const Shape& sa = w.shapes[contact.shapeA];
    const Shape& sb = w.shapes[contact.shapeB];
    if (m.pointCount == 0 || sa.sensor || sb.sensor) {
      continue;
    }
    const Body& a = w.bodies[sa.body];
    const Body& b = w.bodies[sb.body];
    if (!a.moving() && !b.moving()) {
      continue; // asleep (the world wakes a sleeper touched by a moving body before the solve)
    }
    Constraint c;
    c.bodyA = sa.body;
    c.bodyB = sb.body;
    c.mA = a.inverseMass;
    c.iA = a.inverseInertia;
    c.mB = b.inverseMass;
    c.iB = b.inverseInertia;
    c.normal = m.normal;
    c.friction = contact.friction;
    c.restitution = contact.restitution;
    c.softness = (c.mA == 0.0f || c.mB == 0.0f) ? staticSoft : soft;
    c.pointCount = m.pointCount;
    c.contact = &contact;
    const Vec2f tangent{m.normal.y, -m.normal.x};
    const Vec2f offsetA = a.center - a.transform.p;
    const Vec2f offsetB = b.center - b.transform.p;
    for (int k = 0; k < m.pointCount; ++k) {
      const ManifoldPoint& mp = m.points[static_cast<std::size_t>(k)];
      ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
      p.rA = mp.anchorA - offsetA;
      p.rB = mp.anchorB - offsetB;
      p.adjustedSeparation = mp.separation - dot(p.rB - p.rA, m.normal);
      p.normalImpulse = mp.normalImpulse;
      p.tangentImpulse = mp.tangentImpulse;
      const float rnA = cross(p.rA, m.normal);
      const float rnB = cross(p.rB, m.normal);
      const float kNormal = c.mA + c.mB + c.iA * rnA * rnA + c.iB * rnB * rnB;
      p.normalMass = kNormal > 0.0f ? 1.0f / kNormal : 0.0f;
      const float rtA = cross(p.rA, tangent);
      const float rtB = cross(p.rB, tangent);
      const float kTangent = c.mA + c.mB + c.iA * rtA * rtA + c.iB * rtB * rtB;
      p.tangentMass = kTangent > 0.0f ? 1.0f / kTangent : 0.0f;
      const BodyState& stA = w.states[c.bodyA];
      const BodyState& stB = w.states[c.bodyB];
      p.relativeVelocity = dot(velocityAt(stB, p.rB) - velocityAt(stA, p.rA), m.normal);
    }
    constraints.push_back(c);
  }

  const Vec2f gravity = w.def.gravity;
  const float maxSpeed = w.def.maxLinearSpeed;
  for (int step = 0; step < substeps; ++step) {
    // Integrate velocities.
    for (Body& body : w.bodies) {
      if (!body.moving() || body.type != BodyType::dynamicBody) {
        continue;
      }
      BodyState& s = w.states[body.id.index];
      Vec2f v = s.v + (body.force * body.inverseMass + gravity * body.gravityScale) * h;
      float av = s.w + body.inverseInertia * body.torque * h;
      // Implicit damping: stable for any coefficient.
      v *= 1.0f / (1.0f + h * body.linearDamping);
      av *= 1.0f / (1.0f + h * body.angularDamping);
      if (lengthSquared(v) > maxSpeed * maxSpeed) {
        v = normalize(v) * maxSpeed;
      }
      s.v = v;
      s.w = av;
    }
    // Warm start with last substep's (or last step's) impulses.
    for (Constraint& c : constraints) {
      const Vec2f tangent{c.normal.y, -c.normal.x};
      for (int k = 0; k < c.pointCount; ++k) {
        const ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
        applyImpulse(w.states[c.bodyA], w.states[c.bodyB], c, p,
                     c.normal * p.normalImpulse + tangent * p.tangentImpulse);
      }
    }
    solve(constraints, w.states, inverseH, w.def.maxContactPushSpeed, true);
    // Integrate positions (as deltas).
    for (Body& body : w.bodies) {
      if (!body.moving()) {
        continue;
      }
      BodyState& s = w.states[body.id.index];
      s.dp += s.v * h;
      const float angle = s.w * h;
      s.dq = normalize(Rot2f{s.dq.c - angle * s.dq.s, s.dq.s + angle * s.dq.c});
    }
    solve(constraints, w.states, inverseH, w.def.maxContactPushSpeed, false); // relax
  }

  // Restitution, once: for points that approached faster than the threshold.
  const float threshold = w.def.restitutionThreshold;
  for (Constraint& c : constraints) {
    if (c.restitution == 0.0f) {
      continue;
    }
    BodyState& a = w.states[c.bodyA];
    BodyState& b = w.states[c.bodyB];
    for (int k = 0; k < c.pointCount; ++k) {
      ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
      if (p.relativeVelocity > -threshold || p.maxNormalImpulse == 0.0f) {
        continue;
      }
      const float vn = dot(velocityAt(b, p.rB) - velocityAt(a, p.rA), c.normal);
      const float impulse = -p.normalMass * (vn + c.restitution * p.relativeVelocity);
      const float total = std::max(p.normalImpulse + impulse, 0.0f);
      const float applied = total - p.normalImpulse;
      p.normalImpulse = total;
      applyImpulse(a, b, c, p, c.normal * applied);
    }
  }

  // Keep the impulses for the next step's warm start; note the fastest impact for hit events.
  for (const Constraint& c : constraints) {
    c.contact->approachSpeed = 0.0f;
    for (int k = 0; k < c.pointCount; ++k) {
      const ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
      if (p.maxNormalImpulse > 0.0f && -p.relativeVelocity > c.contact->approachSpeed) {
        c.contact->approachSpeed = -p.relativeVelocity;
        c.contact->fastestPoint = k;
      }
    }
    for (int k = 0; k < c.pointCount; ++k) {
      ManifoldPoint& mp = c.contact->manifold.points[static_cast<std::size_t>(k)];
      mp.normalImpulse = c.points[static_cast<std::size_t>(k)].normalImpulse;
      mp.tangentImpulse = c.points[static_cast<std::size_t>(k)].tangentImpulse;
    }
  }
}

} // namespace impetus::rigid2d::detail
