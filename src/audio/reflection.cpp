#include <impetus/audio/reflection.hpp>
#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>

#include <cmath>
#include <limits>

namespace impetus::audio {

double echoDelay(double distance, double speedOfSound) {
  requireNonNegative(distance, "distance");
  requirePositive(speedOfSound, "speedOfSound");
  return 2.0 * distance / speedOfSound;
}

double reflectorDistance(double delay, double speedOfSound) {
  requireNonNegative(delay, "delay");
  requirePositive(speedOfSound, "speedOfSound");
  return 0.5 * speedOfSound * delay;
}

double reflectionCoefficient(double absorption) {
  requireFinite(absorption, "absorption");
  if (absorption < 0.0 || absorption > 1.0) {
    throwInvalid("absorption", absorption, "must be a fraction of the incident energy, 0..1");
  }
  return std::sqrt(1.0 - absorption);
}

PlaneReflection reflectOffPlane(const Vec3d& source, const Vec3d& listener, const Vec3d& planePoint,
                                const Vec3d& planeNormal, double coefficient, double speedOfSound) {
  requireFinite(source, "source");
  requireFinite(listener, "listener");
  requireFinite(planePoint, "planePoint");
  requireFinite(planeNormal, "planeNormal");
  requirePositive(speedOfSound, "speedOfSound");
  requireFinite(coefficient, "coefficient");
  if (coefficient < 0.0 || coefficient > 1.0) {
    throwInvalid("coefficient", coefficient, "must be a pressure reflection coefficient, 0..1");
  }
  const double normalLength = length(planeNormal);
  if (!(normalLength > 0.0)) {
    throwInvalid("planeNormal", normalLength, "must have a length");
  }
  const Vec3d n = planeNormal / normalLength;
  const double sourceSide = dot(source - planePoint, n);
  const double listenerSide = dot(listener - planePoint, n);
  if (sourceSide == 0.0) {
    throwInvalid("source", sourceSide, "lies on the plane (signed distance given, m)");
  }
  if (!(sourceSide * listenerSide > 0.0)) {
    throwInvalid("listener", listenerSide, "must be on the source's side of the plane, off it (signed distance, m)");
  }
  PlaneReflection r;
  r.imageSource = source - n * (2.0 * sourceSide);
  // The ray from the image to the listener crosses the plane where the signed distance is 0.
  const double t = -dot(r.imageSource - planePoint, n) / dot(listener - r.imageSource, n);
  r.reflectionPoint = r.imageSource + (listener - r.imageSource) * t;
  r.directPath = distance(source, listener);
  r.reflectedPath = distance(r.imageSource, listener);
  r.directDelay = r.directPath / speedOfSound;
  r.reflectedDelay = r.reflectedPath / speedOfSound;
  r.lag = r.reflectedDelay - r.directDelay;
  if (r.directPath == 0.0) {
    throwInvalid("listener", 0.0, "coincides with the source");
  }
  r.amplitudeRatio = coefficient * r.directPath / r.reflectedPath;
  r.levelDifference =
      r.amplitudeRatio > 0.0 ? 20.0 * std::log10(r.amplitudeRatio) : std::numeric_limits<double>::lowest();
  return r;
}

} // namespace impetus::audio
