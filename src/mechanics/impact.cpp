#include <impetus/error.hpp>
#include <impetus/math/symmetric_eigen.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/mechanics/impact.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace impetus {
namespace {

void requireRestitution(double restitution) {
  if (!(restitution >= 0.0 && restitution <= 1.0)) {
    throwInvalid("restitution", restitution, "must be between 0 and 1");
  }
}

/// A mass that may be +infinity (an immovable body): returns 1/m, 0 for infinity.
double inverseOfMass(double mass, std::string_view field) {
  if (!(mass > 0.0) || std::isnan(mass)) {
    throwInvalid(field, mass, "must be positive (inf for an immovable body)");
  }
  return std::isinf(mass) ? 0.0 : 1.0 / mass;
}

/// The unit normal; throws when it has no direction.
template <class V> V unitNormal(const V& normal) {
  requireFinite(normal, "normal");
  const V n = normalize(normal);
  if (lengthSquared(n) == 0.0) {
    throwInvalid("normal", length(normal), "must have a non-zero length");
  }
  return n;
}

/// I^-1 must be what the inverse of an inertia tensor can be: finite, symmetric and positive
/// semi-definite (zero along an axis the body cannot turn about). The triangle inequality of
/// inertia tensors does not carry over to their inverses, so it is not checked here.
void requireInverseInertia(const Mat33d& m, const std::string& field) {
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      requireFinite(m(r, c), field + "(" + std::to_string(r) + "," + std::to_string(c) + ")");
    }
  }
  // Relative tolerance: a tensor rotated into world axes (R D R^T) is symmetric only to rounding.
  const double scale = std::fabs(m(0, 0)) + std::fabs(m(1, 1)) + std::fabs(m(2, 2));
  const double tol = 1e-9 * scale;
  for (int r = 0; r < 3; ++r) {
    for (int c = r + 1; c < 3; ++c) {
      if (std::fabs(m(r, c) - m(c, r)) > tol) {
        throwInvalid(field + "(" + std::to_string(r) + "," + std::to_string(c) + ")", m(r, c), "must be symmetric");
      }
    }
  }
  const double smallest = symmetricEigen(m).values.x;
  if (smallest < -tol) {
    throwInvalid(field + " eigenvalue", smallest, "must be non-negative (positive semi-definite)");
  }
}

void requireBody(const ImpactBody& body, const std::string& name) {
  requireNonNegative(body.inverseMass, name + ".inverseMass");
  requireInverseInertia(body.inverseInertiaWorld, name + ".inverseInertiaWorld");
  requireFinite(body.velocity, name + ".velocity");
  requireFinite(body.angularVelocity, name + ".angularVelocity");
  requireFinite(body.offset, name + ".offset");
}

void requireBody(const ImpactBody2D& body, const std::string& name) {
  requireNonNegative(body.inverseMass, name + ".inverseMass");
  requireNonNegative(body.inverseInertia, name + ".inverseInertia");
  requireFinite(body.velocity, name + ".velocity");
  requireFinite(body.angularVelocity, name + ".angularVelocity");
  requireFinite(body.offset, name + ".offset");
}

bool isImmovable(const ImpactBody& body) {
  return body.inverseMass == 0.0 && body.inverseInertiaWorld == Mat33d::zero();
}

/// Velocity of the contact point: v_P = v + w x r.
Vec3d contactVelocity(const ImpactBody& body) { return body.velocity + cross(body.angularVelocity, body.offset); }

/// 1/m + d . ((I^-1 (r x d)) x r) = 1/m + (r x d) . I^-1 (r x d): the inverse of the effective
/// mass the body shows at its contact point to an impulse along the unit direction d.
double inverseEffectiveMass(const ImpactBody& body, const Vec3d& d) {
  const Vec3d rxd = cross(body.offset, d);
  return body.inverseMass + dot(rxd, body.inverseInertiaWorld * rxd);
}

/// Applies the impulse p at the contact point (body 1 receives +p, body 2 receives -p).
void applyImpulse(ImpactBody& body1, ImpactBody& body2, const Vec3d& p) {
  body1.velocity += p * body1.inverseMass;
  body1.angularVelocity += body1.inverseInertiaWorld * cross(body1.offset, p);
  body2.velocity -= p * body2.inverseMass;
  body2.angularVelocity -= body2.inverseInertiaWorld * cross(body2.offset, p);
}

/// The impact itself, on validated input and a unit normal.
ImpactResult solveImpact(ImpactBody body1, ImpactBody body2, const Vec3d& n, double restitution, double friction) {
  const double kn = inverseEffectiveMass(body1, n) + inverseEffectiveMass(body2, n);
  if (!(kn > 0.0)) {
    throw Error("normal", "normal: neither body can move along it at the contact (zero effective inverse mass)");
  }
  ImpactResult result;
  const Vec3d vrBefore = contactVelocity(body1) - contactVelocity(body2);
  const double vn = dot(vrBefore, n);
  if (vn < 0.0) {
    // Normal impulse.
    const double j = -(1.0 + restitution) * vn / kn;
    applyImpulse(body1, body2, n * j);
    result.normalImpulse = j;
    result.impulse = n * j;

    // Friction opposes the slip that remains after the normal impulse (t from v_r', not v_r-:
    // the normal impulse can change the slip through rotation, and taking t and the cap from
    // the same velocity is what keeps the energy from increasing).
    const Vec3d vr = contactVelocity(body1) - contactVelocity(body2);
    const Vec3d slip = vr - n * dot(vr, n); // (n x v_r) x n
    const double slipSpeed = length(slip);
    if (friction > 0.0 && slipSpeed > 0.0) {
      const Vec3d t = slip / slipSpeed;
      const double kt = inverseEffectiveMass(body1, t) + inverseEffectiveMass(body2, t);
      const double kinetic = friction * j;
      // kt == 0: a tangential impulse cannot change the slip (nor any velocity): no cap.
      const double stick = kt > 0.0 ? slipSpeed / kt : std::numeric_limits<double>::infinity();
      result.sticking = stick <= kinetic;
      result.frictionImpulse = std::min(kinetic, stick);
      applyImpulse(body1, body2, t * -result.frictionImpulse);
      result.impulse -= t * result.frictionImpulse;
    }
    const Vec3d vrAfter = contactVelocity(body1) - contactVelocity(body2);
    // Work of the impulse pair on the two bodies: dKE = P . (v_r- + v_r+) / 2, exact for any
    // impulse because each body's velocity change is linear in it with a symmetric matrix. It
    // is the frame-independent dissipation, also when one body is immovable.
    result.kineticEnergyLost = std::max(0.0, -0.5 * dot(result.impulse, vrBefore + vrAfter));
  }
  result.velocity1 = body1.velocity;
  result.angularVelocity1 = body1.angularVelocity;
  result.velocity2 = body2.velocity;
  result.angularVelocity2 = body2.angularVelocity;
  return result;
}

ImpactBody embed(const ImpactBody2D& b) {
  ImpactBody body;
  body.inverseMass = b.inverseMass;
  body.inverseInertiaWorld = Mat33d::diagonal({0.0, 0.0, b.inverseInertia});
  body.velocity = {b.velocity.x, b.velocity.y, 0.0};
  body.angularVelocity = {0.0, 0.0, b.angularVelocity};
  body.offset = {b.offset.x, b.offset.y, 0.0};
  return body;
}

/// J = -(1 + e)(v_r . n) / (1/m1 + 1/m2) along the unit normal, for 2D or 3D particles.
template <class Result, class Particle, class V>
Result resolveParticles(const Particle& body1, const Particle& body2, const V& normal, double restitution) {
  requireNonNegative(body1.inverseMass, "body1.inverseMass");
  requireNonNegative(body2.inverseMass, "body2.inverseMass");
  const double w = body1.inverseMass + body2.inverseMass;
  if (w == 0.0) {
    throwInvalid("body2.inverseMass", body2.inverseMass, "both bodies are immovable");
  }
  requireFinite(body1.velocity, "body1.velocity");
  requireFinite(body2.velocity, "body2.velocity");
  const V n = unitNormal(normal);
  requireRestitution(restitution);
  const double vn = dot(body1.velocity - body2.velocity, n);
  if (!(vn < 0.0)) {
    return {body1.velocity, body2.velocity, 0.0, 0.0};
  }
  const double j = -(1.0 + restitution) * vn / w;
  return {body1.velocity + n * (j * body1.inverseMass), body2.velocity - n * (j * body2.inverseMass), j,
          0.5 / w * (1.0 - restitution * restitution) * vn * vn};
}

} // namespace

double linearImpulse(double mass, double velocityChange) {
  requirePositive(mass, "mass");
  requireFinite(velocityChange, "velocityChange");
  return mass * velocityChange;
}

double averageImpactForce(double impulse, double duration) {
  requireFinite(impulse, "impulse");
  requirePositive(duration, "duration");
  return impulse / duration;
}

double coefficientOfRestitution(double v1Before, double v2Before, double v1After, double v2After) {
  requireFinite(v1Before, "v1Before");
  requireFinite(v2Before, "v2Before");
  requireFinite(v1After, "v1After");
  requireFinite(v2After, "v2After");
  const double approach = v1Before - v2Before;
  if (approach == 0.0) {
    throwInvalid("v2Before", v2Before,
                 "must differ from the velocity of body 1 before (no relative velocity, no impact)");
  }
  const double e = -(v1After - v2After) / approach;
  if (e < 0.0) {
    throwInvalid("v2After", v2After, "leaves the bodies still approaching each other (negative restitution)");
  }
  return e;
}

double restitutionFromBounce(double dropHeight, double bounceHeight) {
  requirePositive(dropHeight, "dropHeight");
  requireNonNegative(bounceHeight, "bounceHeight");
  if (bounceHeight > dropHeight) {
    throwInvalid("bounceHeight", bounceHeight, "must not exceed the drop height (a passive bounce gains no energy)");
  }
  return std::sqrt(bounceHeight / dropHeight);
}

double impactEnergyLoss(double mass1, double mass2, double normalClosingSpeed, double restitution) {
  const double w1 = inverseOfMass(mass1, "mass1");
  const double w2 = inverseOfMass(mass2, "mass2");
  if (w1 + w2 == 0.0) {
    throwInvalid("mass2", mass2, "both bodies are immovable");
  }
  requireFinite(normalClosingSpeed, "normalClosingSpeed");
  requireRestitution(restitution);
  // mu_red = 1 / (1/m1 + 1/m2): the form that also holds when one mass is infinite.
  return 0.5 / (w1 + w2) * (1.0 - restitution * restitution) * normalClosingSpeed * normalClosingSpeed;
}

Impact1DResult resolveImpact1D(double mass1, double velocity1, double mass2, double velocity2, double restitution) {
  const double w1 = inverseOfMass(mass1, "mass1");
  const double w2 = inverseOfMass(mass2, "mass2");
  if (w1 + w2 == 0.0) {
    throwInvalid("mass2", mass2, "both bodies are immovable");
  }
  requireFinite(velocity1, "velocity1");
  requireFinite(velocity2, "velocity2");
  requireRestitution(restitution);
  const double closing = velocity1 - velocity2;
  if (!(closing > 0.0)) {
    return {velocity1, velocity2, 0.0, 0.0}; // separating or at rest relative to each other
  }
  const double j = (1.0 + restitution) * closing / (w1 + w2);
  return {velocity1 - j * w1, velocity2 + j * w2, j,
          0.5 / (w1 + w2) * (1.0 - restitution * restitution) * closing * closing};
}

ParticleImpactResult resolveParticleImpact(const ImpactParticle& body1, const ImpactParticle& body2,
                                           const Vec3d& normal, double restitution) {
  return resolveParticles<ParticleImpactResult>(body1, body2, normal, restitution);
}

ParticleImpactResult2D resolveParticleImpact(const ImpactParticle2D& body1, const ImpactParticle2D& body2,
                                             const Vec2d& normal, double restitution) {
  return resolveParticles<ParticleImpactResult2D>(body1, body2, normal, restitution);
}

ImpactResult resolveImpact(const ImpactBody& body1, const ImpactBody& body2, const Vec3d& normal, double restitution,
                           double friction) {
  requireBody(body1, "body1");
  requireBody(body2, "body2");
  if (isImmovable(body1) && isImmovable(body2)) {
    throw Error("body2.inverseMass", "body2.inverseMass: body1 and body2 are both immovable (zero inverse mass "
                                     "and inverse inertia)");
  }
  const Vec3d n = unitNormal(normal);
  requireRestitution(restitution);
  requireNonNegative(friction, "friction");
  return solveImpact(body1, body2, n, restitution, friction);
}

ImpactResult2D resolveImpact(const ImpactBody2D& body1, const ImpactBody2D& body2, const Vec2d& normal,
                             double restitution, double friction) {
  requireBody(body1, "body1");
  requireBody(body2, "body2");
  if (body1.inverseMass == 0.0 && body1.inverseInertia == 0.0 && body2.inverseMass == 0.0 &&
      body2.inverseInertia == 0.0) {
    throw Error("body2.inverseMass", "body2.inverseMass: body1 and body2 are both immovable (zero inverse mass "
                                     "and inverse inertia)");
  }
  const Vec2d n2 = unitNormal(normal);
  requireRestitution(restitution);
  requireNonNegative(friction, "friction");
  // The plane problem embedded in 3D (z = 0, spin about z): every product with a zero component
  // is an exact zero, so the angular terms reduce to the scalar (r x n)_z^2 / I of the book.
  const ImpactResult r = solveImpact(embed(body1), embed(body2), {n2.x, n2.y, 0.0}, restitution, friction);
  ImpactResult2D out;
  out.velocity1 = {r.velocity1.x, r.velocity1.y};
  out.angularVelocity1 = r.angularVelocity1.z;
  out.velocity2 = {r.velocity2.x, r.velocity2.y};
  out.angularVelocity2 = r.angularVelocity2.z;
  out.impulse = {r.impulse.x, r.impulse.y};
  out.normalImpulse = r.normalImpulse;
  out.frictionImpulse = r.frictionImpulse;
  out.sticking = r.sticking;
  out.kineticEnergyLost = r.kineticEnergyLost;
  return out;
}

} // namespace impetus
