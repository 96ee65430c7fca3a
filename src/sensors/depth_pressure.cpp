#include <impetus/error.hpp>
#include <impetus/mechanics/forces.hpp>
#include <impetus/sensors/depth_pressure.hpp>

namespace impetus::sensors {

DepthPressure depthPressure(double depth, double density, double gravity, double surfacePressure,
                            double internalPressure) {
  requireNonNegative(depth, "depth");
  requireNonNegative(density, "density");
  requireNonNegative(gravity, "gravity");
  requireNonNegative(surfacePressure, "surfacePressure");
  requireNonNegative(internalPressure, "internalPressure");
  DepthPressure p;
  p.gauge = hydrostaticPressure(density, depth, gravity, 0.0); // mechanics: P0 + rho g h
  p.absolute = surfacePressure + p.gauge;
  p.differential = p.absolute - internalPressure;
  return p;
}

double depthForPressure(double gauge, double density, double gravity) {
  requireNonNegative(gauge, "gauge");
  requirePositive(density, "density");
  requirePositive(gravity, "gravity");
  return gauge / (density * gravity);
}

} // namespace impetus::sensors
