#include <impetus/display/stereo.hpp>
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>

#include <cmath>

namespace impetus::display {
namespace {

double requireFov(double fov, std::string_view field) {
  requireFinite(fov, field);
  if (!(fov > 0.0 && fov < pi<double>)) {
    throwInvalid(field, fov, "must be between 0 and pi rad");
  }
  return fov;
}

} // namespace

double screenParallax(double interaxial, double convergence, double depth) {
  requireNonNegative(interaxial, "interaxial");
  requirePositive(convergence, "convergence");
  requirePositive(depth, "depth");
  return interaxial * (1.0 - convergence / depth);
}

double horizontalFov(double verticalFov, double aspect) {
  requireFov(verticalFov, "verticalFov");
  requirePositive(aspect, "aspect");
  return 2.0 * std::atan(aspect * std::tan(0.5 * verticalFov));
}

double convergencePlaneWidth(double convergence, double hfov) {
  requirePositive(convergence, "convergence");
  requireFov(hfov, "horizontalFov");
  return 2.0 * convergence * std::tan(0.5 * hfov);
}

double interaxialFromSeparation(double separation, double convergence, double hfov) {
  requireNonNegative(separation, "separation");
  return separation * convergencePlaneWidth(convergence, hfov);
}

double separationFromInteraxial(double interaxial, double convergence, double hfov) {
  requireNonNegative(interaxial, "interaxial");
  return interaxial / convergencePlaneWidth(convergence, hfov);
}

std::optional<double> perceivedDistance(double parallax, double viewingDistance, double eyeSeparation) {
  requireFinite(parallax, "screenParallax");
  requirePositive(viewingDistance, "viewingDistance");
  requirePositive(eyeSeparation, "eyeSeparation");
  if (parallax >= eyeSeparation) {
    return std::nullopt;
  }
  return viewingDistance * eyeSeparation / (eyeSeparation - parallax);
}

DepthZone depthZone(double depth, double convergence) {
  requirePositive(depth, "depth");
  requirePositive(convergence, "convergence");
  if (depth < 0.5 * convergence) {
    return DepthZone::tooNear;
  }
  if (depth < convergence) {
    return DepthZone::outOfScreen;
  }
  if (depth <= 10.0 * convergence) {
    return DepthZone::action;
  }
  if (depth <= 100.0 * convergence) {
    return DepthZone::background;
  }
  return DepthZone::tooFar;
}

const char* toString(DepthZone zone) noexcept {
  switch (zone) {
  case DepthZone::tooNear:
    return "too near";
  case DepthZone::outOfScreen:
    return "out of the screen";
  case DepthZone::action:
    return "action";
  case DepthZone::background:
    return "background";
  case DepthZone::tooFar:
    return "too far";
  }
  return "?";
}

} // namespace impetus::display
