#include <impetus/audio/doppler.hpp>
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/validate.hpp>

#include <algorithm>
#include <cmath>

namespace impetus::audio {

double dopplerFrequency(double frequency, double sourceSpeedTowardListener, double listenerSpeedTowardSource,
                        double speedOfSound) {
  requirePositive(frequency, "frequency");
  requirePositive(speedOfSound, "speedOfSound");
  requireFinite(sourceSpeedTowardListener, "sourceSpeed");
  requireFinite(listenerSpeedTowardSource, "listenerSpeed");
  if (!(sourceSpeedTowardListener < speedOfSound)) {
    throwInvalid("sourceSpeed", sourceSpeedTowardListener,
                 "must be below the speed of sound: at or above it the source outruns its sound (a sonic boom)");
  }
  if (!(listenerSpeedTowardSource > -speedOfSound)) {
    throwInvalid("listenerSpeed", listenerSpeedTowardSource,
                 "must be above minus the speed of sound: a listener receding that fast never hears the source");
  }
  return frequency * (speedOfSound + listenerSpeedTowardSource) / (speedOfSound - sourceSpeedTowardListener);
}

double dopplerFrequency(double frequency, const Vec3d& sourcePosition, const Vec3d& sourceVelocity,
                        const Vec3d& listenerPosition, const Vec3d& listenerVelocity, double speedOfSound) {
  requireFinite(sourcePosition, "sourcePosition");
  requireFinite(sourceVelocity, "sourceVelocity");
  requireFinite(listenerPosition, "listenerPosition");
  requireFinite(listenerVelocity, "listenerVelocity");
  const Vec3d sl = listenerPosition - sourcePosition;
  const double d = length(sl);
  if (!(d > 0.0)) {
    throwInvalid("listenerPosition", d, "coincides with the source: no line of sight to project on");
  }
  const Vec3d u = sl / d; // source toward listener
  return dopplerFrequency(frequency, dot(sourceVelocity, u), -dot(listenerVelocity, u), speedOfSound);
}

double openALDopplerFrequency(double frequency, const Vec3d& sourcePosition, const Vec3d& sourceVelocity,
                              const Vec3d& listenerPosition, const Vec3d& listenerVelocity, double dopplerFactor,
                              double speedOfSound) {
  requirePositive(frequency, "frequency");
  requirePositive(speedOfSound, "speedOfSound");
  requireNonNegative(dopplerFactor, "dopplerFactor");
  requireFinite(sourcePosition, "sourcePosition");
  requireFinite(sourceVelocity, "sourceVelocity");
  requireFinite(listenerPosition, "listenerPosition");
  requireFinite(listenerVelocity, "listenerVelocity");
  const Vec3d sl = listenerPosition - sourcePosition;
  const double mag = length(sl);
  if (dopplerFactor == 0.0 || mag == 0.0) {
    return frequency;
  }
  const double limit = speedOfSound / dopplerFactor;
  const double vls = std::min(dot(sl, listenerVelocity) / mag, limit);
  const double vss = std::min(dot(sl, sourceVelocity) / mag, limit);
  if (vss >= limit) {
    throwInvalid("sourceVelocity", vss,
                 "its component toward the listener reaches the speed of sound over the Doppler factor");
  }
  return frequency * (speedOfSound - dopplerFactor * vls) / (speedOfSound - dopplerFactor * vss);
}

void requireValid(const PassBy& pass) {
  requirePositive(pass.frequency, "frequency");
  requirePositive(pass.speedOfSound, "speedOfSound");
  requireNonNegative(pass.speed, "speed");
  if (!(pass.speed < pass.speedOfSound)) {
    throwInvalid("speed", pass.speed, "must be below the speed of sound (a supersonic source outruns its sound)");
  }
  requirePositive(pass.closestApproach, "closestApproach");
  requireFinite(pass.closestTime, "closestTime");
}

Vec3d passBySourcePosition(const PassBy& pass, double time) {
  requireValid(pass);
  requireFinite(time, "time");
  return {pass.speed * (time - pass.closestTime), pass.closestApproach, 0.0};
}

double passByEmissionTime(const PassBy& pass, double time) {
  requireValid(pass);
  requireFinite(time, "time");
  const double c = pass.speedOfSound;
  const double v = pass.speed;
  const double d = pass.closestApproach;
  const double bigT = time - pass.closestTime;
  const double beta = v / c;
  // u = (c^2 T - c sqrt(v^2 T^2 + (1 - b^2) d^2)) / (c^2 - v^2), written per c^2.
  const double root = std::sqrt(v * v * bigT * bigT + (1.0 - beta) * (1.0 + beta) * d * d);
  const double u = (bigT - root / c) / ((1.0 - beta) * (1.0 + beta));
  return pass.closestTime + u;
}

double passByHeardFrequency(const PassBy& pass, double time) {
  const double tau = passByEmissionTime(pass, time);
  const Vec3d s = passBySourcePosition(pass, tau);
  // The velocity (v, 0, 0) projected on the unit vector from the source toward the listener.
  const double towardListener = pass.speed * (-s.x) / length(s);
  return pass.frequency * pass.speedOfSound / (pass.speedOfSound - towardListener);
}

double passByInstantaneousFrequency(const PassBy& pass, double time) {
  const Vec3d s = passBySourcePosition(pass, time);
  const double towardListener = pass.speed * (-s.x) / length(s);
  return pass.frequency * pass.speedOfSound / (pass.speedOfSound - towardListener);
}

double passByPressure(const PassBy& pass, double time, double amplitudeAt1m) {
  requireFinite(amplitudeAt1m, "amplitudeAt1m");
  const double tau = passByEmissionTime(pass, time);
  const double r = pass.speedOfSound * (time - tau);
  return amplitudeAt1m * std::sin(2.0 * pi<double> * pass.frequency * tau) / r;
}

} // namespace impetus::audio
