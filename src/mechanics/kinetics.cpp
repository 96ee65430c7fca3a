#include <impetus/error.hpp>
#include <impetus/mechanics/kinetics.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace impetus {
namespace {

/// (1 - e^{-x}) / x, with its limit 1 at x = 0 (expm1 keeps full precision for small x).
double phi1(double x) { return x == 0.0 ? 1.0 : -std::expm1(-x) / x; }

/// (x - 1 + e^{-x}) / x^2 for x >= 0, with its limit 1/2 at x = 0. The direct form loses about
/// 2 eps / x to cancellation, so below x = 0.5 the Taylor series sum (-x)^n / (n + 2)! is summed
/// instead (Horner, n = 0..16: the first omitted term is below 0.5^17 / 19! = 6e-23).
double phi2(double x) {
  if (x < 0.5) {
    constexpr int terms = 17;
    double coefficient[terms]{};
    double factorial = 2.0; // (n + 2)!
    for (int n = 0; n < terms; ++n) {
      coefficient[n] = 1.0 / factorial;
      factorial *= n + 3;
    }
    double sum = coefficient[terms - 1];
    for (int n = terms - 2; n >= 0; --n) {
      sum = coefficient[n] - x * sum;
    }
    return sum;
  }
  return (x + std::expm1(-x)) / (x * x);
}

void requireBox(const PushedBox& b) {
  requirePositive(b.mass, "mass");
  requirePositive(b.width, "width");
  requirePositive(b.height, "height");
  requirePositive(b.pushHeight, "pushHeight");
  if (b.pushHeight > b.height) {
    throwInvalid("pushHeight", b.pushHeight, "must not exceed height (the push acts on the box's face)");
  }
  requireNonNegative(b.staticCoefficient, "staticCoefficient");
  requireNonNegative(b.kineticCoefficient, "kineticCoefficient");
  if (b.kineticCoefficient > b.staticCoefficient) {
    throwInvalid("kineticCoefficient", b.kineticCoefficient, "must not exceed staticCoefficient");
  }
  requireNonNegative(b.gravity, "gravity");
}

} // namespace

ShipState shipMotion(double thrust, double mass, double resistanceCoefficient, double time, double initialSpeed) {
  requireFinite(thrust, "thrust");
  requirePositive(mass, "mass");
  requireNonNegative(resistanceCoefficient, "resistanceCoefficient");
  requireNonNegative(time, "time");
  requireFinite(initialSpeed, "initialSpeed");
  const double k = resistanceCoefficient / mass; // 1/s
  const double f = thrust / mass;                // m/s^2
  const double x = k * time;
  const double decay = std::exp(-x);
  const double p1 = phi1(x);
  ShipState s{};
  // v = v0 e^{-kt} + f (1 - e^{-kt}) / k,  s = v0 (1 - e^{-kt}) / k + f (kt - 1 + e^{-kt}) / k^2.
  s.speed = initialSpeed * decay + f * time * p1;
  s.distance = initialSpeed * time * p1 + f * time * time * phi2(x);
  s.acceleration = (f - k * initialSpeed) * decay;
  return s;
}

double shipTerminalSpeed(double thrust, double resistanceCoefficient) {
  return requireFinite(thrust, "thrust") / requirePositive(resistanceCoefficient, "resistanceCoefficient");
}

double shipTimeConstant(double mass, double resistanceCoefficient) {
  return requirePositive(mass, "mass") / requirePositive(resistanceCoefficient, "resistanceCoefficient");
}

BoxSupportReactions boxSupportReactions(const PushedBox& box, double pushForce, bool sliding) {
  requireBox(box);
  const double f = requireNonNegative(pushForce, "pushForce");
  const double w = box.width;
  const double h = box.height;
  const double weight = box.mass * box.gravity;
  BoxSupportReactions r{};
  r.frictionForce = sliding ? box.kineticCoefficient * weight : f;
  r.acceleration = (f - r.frictionForce) / box.mass;
  // Moments about the centre of gravity (alpha = 0), counter-clockwise positive with the push
  // along +x from the trailing face at x = -w/2:
  //   -F (h_p - h/2)  (push)  - F_f h/2  (friction at the floor, h/2 below)
  //   + R1 w/2 - R2 w/2  (reactions at x = +-w/2)  = 0,   with R1 + R2 = m g.
  r.trailingReaction = 0.5 * weight - (f * (box.pushHeight - 0.5 * h) + r.frictionForce * 0.5 * h) / w;
  r.leadingReaction = weight - r.trailingReaction;
  return r;
}

BoxResponse pushBoxAtRest(const PushedBox& box, double pushForce) {
  requireBox(box);
  requireNonNegative(pushForce, "pushForce");
  const bool sliding = pushForce > box.staticCoefficient * box.mass * box.gravity;
  BoxResponse r{};
  r.reactions = boxSupportReactions(box, pushForce, sliding);
  if (r.reactions.trailingReaction < 0.0) {
    r.motion = BoxMotion::tipsForward;
  } else if (r.reactions.leadingReaction < 0.0) {
    r.motion = BoxMotion::tipsBackward;
  } else {
    r.motion = sliding ? BoxMotion::slides : BoxMotion::rests;
  }
  return r;
}

BoxTipping boxTipping(const PushedBox& box) {
  requireBox(box);
  const double weight = box.mass * box.gravity;
  const double w = box.width;
  const double h = box.height;
  const double hp = box.pushHeight;
  BoxTipping t{};
  t.slidingForce = box.staticCoefficient * weight;
  t.tippingForceAtRest = weight * w / (2.0 * hp);
  t.criticalPushHeight =
      box.staticCoefficient > 0.0 ? w / (2.0 * box.staticCoefficient) : std::numeric_limits<double>::infinity();
  t.tipsFirst = t.tippingForceAtRest <= t.slidingForce;
  if (2.0 * hp > h) {
    t.tippingForceWhileSliding = std::max(0.0, weight * (w - box.kineticCoefficient * h) / (2.0 * hp - h));
  }
  if (2.0 * hp < h) {
    t.backwardTippingForceWhileSliding = weight * (w + box.kineticCoefficient * h) / (h - 2.0 * hp);
  }
  return t;
}

} // namespace impetus
