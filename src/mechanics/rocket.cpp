#include <impetus/error.hpp>
#include <impetus/mechanics/rocket.hpp>

#include <algorithm>
#include <cmath>

namespace impetus {
namespace {

void validate(const VerticalRocket& r) {
  requirePositive(r.initialMass, "initialMass");
  requirePositive(r.propellantMass, "propellantMass");
  if (!(r.propellantMass < r.initialMass)) {
    throwInvalid("propellantMass", r.propellantMass,
                 "must be less than the initial mass (the rocket's structure has mass)");
  }
  requirePositive(r.burnRate, "burnRate");
  requirePositive(r.exhaustVelocity, "exhaustVelocity");
  requirePositive(r.gravity, "gravity");
  requireFinite(r.initialVelocity, "initialVelocity");
  requireFinite(r.initialAltitude, "initialAltitude");
}

/// x + (1 - x) ln(1 - x) for 0 <= x < 1, accurate near 0: the series sum_{k>=2} x^k/(k(k-1))
/// below x = 0.05 (25 terms: error below 0.05^26), the direct form above it.
double burnIntegral(double x) {
  if (x >= 0.05) {
    return x + (1.0 - x) * std::log1p(-x);
  }
  double power = x * x;
  double sum = 0.0;
  for (int k = 2; k <= 26; ++k) {
    sum += power / static_cast<double>(k * (k - 1));
    power *= x;
  }
  return sum;
}

/// The powered flight from lift-off: time since lift-off tau, lift-off mass ml.
struct Powered {
  double velocity;
  double altitude;
};
Powered powered(const VerticalRocket& r, double ml, double tau) {
  const double x = r.burnRate * tau / ml;  // fraction of the lift-off mass burnt
  const double logRatio = -std::log1p(-x); // ln(ml / m)
  const double u = r.exhaustVelocity;
  const double g = r.gravity;
  // u tau - (u m/mdot) ln(ml/m) = (u ml/mdot) (x + (1 - x) ln(1 - x))
  const double thrustTerm = u * ml / r.burnRate * burnIntegral(x);
  return {r.initialVelocity + u * logRatio - g * tau,
          r.initialAltitude + r.initialVelocity * tau + thrustTerm - 0.5 * g * tau * tau};
}

/// When the rocket leaves the pad: 0 unless it starts at rest with thrust <= weight; then the
/// moment m(t) g = thrust. Returns burn-out time or later when it never does.
double liftoffTime(const VerticalRocket& r) {
  if (r.initialVelocity != 0.0) {
    return 0.0;
  }
  const double hoverMass = r.burnRate * r.exhaustVelocity / r.gravity; // thrust / g
  if (hoverMass > r.initialMass) {
    return 0.0;
  }
  return (r.initialMass - hoverMass) / r.burnRate;
}

} // namespace

double rocketDeltaV(double exhaustVelocity, double initialMass, double finalMass) {
  requirePositive(exhaustVelocity, "exhaustVelocity");
  requirePositive(initialMass, "initialMass");
  requirePositive(finalMass, "finalMass");
  if (finalMass > initialMass) {
    throwInvalid("finalMass", finalMass, "must not exceed the initial mass");
  }
  return exhaustVelocity * std::log(initialMass / finalMass);
}

double rocketThrust(double burnRate, double exhaustVelocity) {
  requireNonNegative(burnRate, "burnRate");
  requireNonNegative(exhaustVelocity, "exhaustVelocity");
  return burnRate * exhaustVelocity;
}

RocketState verticalRocketStateAt(const VerticalRocket& r, double time) {
  validate(r);
  requireNonNegative(time, "time");
  const double tb = r.propellantMass / r.burnRate;
  const double tl = liftoffTime(r);
  const double thrust = r.burnRate * r.exhaustVelocity;
  RocketState s;
  s.time = time;
  s.burning = time < tb;
  s.mass = s.burning ? r.initialMass - r.burnRate * time : r.initialMass - r.propellantMass;
  if (tl >= tb || time < tl) { // held on the pad (until lift-off, or for good)
    s.velocity = 0.0;
    s.altitude = r.initialAltitude;
    s.acceleration = 0.0;
    return s;
  }
  const double ml = r.initialMass - r.burnRate * tl;
  if (s.burning) {
    const Powered p = powered(r, ml, time - tl);
    s.velocity = p.velocity;
    s.altitude = p.altitude;
    s.acceleration = thrust / s.mass - r.gravity;
    return s;
  }
  const Powered b = powered(r, ml, tb - tl);
  const double dt = time - tb;
  s.velocity = b.velocity - r.gravity * dt;
  s.altitude = b.altitude + b.velocity * dt - 0.5 * r.gravity * dt * dt;
  s.acceleration = -r.gravity;
  return s;
}

RocketFlight verticalRocketFlight(const VerticalRocket& r) {
  validate(r);
  RocketFlight f;
  f.thrust = r.burnRate * r.exhaustVelocity;
  f.liftoffThrustToWeight = f.thrust / (r.initialMass * r.gravity);
  f.burnoutTime = r.propellantMass / r.burnRate;
  f.burnoutMass = r.initialMass - r.propellantMass;
  f.idealDeltaV = r.exhaustVelocity * std::log(r.initialMass / f.burnoutMass);
  const double tl = liftoffTime(r);
  f.liftsOff = tl < f.burnoutTime;
  f.liftoffTime = f.liftsOff ? tl : f.burnoutTime;
  if (!f.liftsOff) {
    f.burnoutVelocity = 0.0;
    f.burnoutAltitude = r.initialAltitude;
    f.peakAltitude = r.initialAltitude;
    f.peakTime = 0.0;
    return f;
  }
  const RocketState burnout = verticalRocketStateAt(r, f.burnoutTime);
  f.burnoutVelocity = burnout.velocity;
  f.burnoutAltitude = burnout.altitude;

  // Candidates for the highest point: the start, the first time v falls through 0 during the
  // burn (v is convex in t while burning, so there is at most one such fall), and the coast apex.
  f.peakAltitude = r.initialAltitude;
  f.peakTime = 0.0;
  const auto consider = [&](double t) {
    const RocketState s = verticalRocketStateAt(r, t);
    if (s.altitude > f.peakAltitude) {
      f.peakAltitude = s.altitude;
      f.peakTime = t;
    }
  };
  if (r.initialVelocity > 0.0) {
    // v decreases until thrust = m g (t* = (m0 - thrust/g)/mdot), then increases.
    const double tMin = std::clamp((r.initialMass - f.thrust / r.gravity) / r.burnRate, 0.0, f.burnoutTime);
    if (verticalRocketStateAt(r, tMin).velocity < 0.0) {
      double lo = 0.0;
      double hi = tMin;
      for (int i = 0; i < 200 && hi - lo > 1e-15 * (1.0 + hi); ++i) {
        const double mid = 0.5 * (lo + hi);
        (verticalRocketStateAt(r, mid).velocity > 0.0 ? lo : hi) = mid;
      }
      consider(0.5 * (lo + hi));
    }
  }
  if (burnout.velocity > 0.0) {
    consider(f.burnoutTime + burnout.velocity / r.gravity);
  } else {
    consider(f.burnoutTime);
  }
  return f;
}

} // namespace impetus
