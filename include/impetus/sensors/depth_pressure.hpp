// Pressure at depth (ch. 23): what a pressure sensor (or a sealed hull) feels under a fluid.
//
// Pressure is force per area, P = F / A (1 Pa = 1 N/m^2), and acts normal to every surface. In a
// fluid at rest the weight of the column above adds rho g h: the gauge pressure at depth h is
//   P_gauge = rho g h,   P_absolute = P_surface + rho g h.
// The book's example: a steel ball sealed at the surface (inside P_atm = 101,000 Pa) sunk to the
// bottom of the Mariana trench, 10,900 m. Outside it is P_atm + rho g h, inside still P_atm, so the
// net pressure on the shell is exactly rho g h: 1.096e8 Pa (about 1,082 atm) with rho = 1025 kg/m^3
// of sea water and g = 9.81. (Subtracting P_atm from rho g h again would treat the gauge pressure
// as absolute.) An open ball has no differential: only its material is squeezed.
// Sea water is compressed by about 5 % at that depth, so with the surface density the pressure at
// the bottom comes out about 2 % low (the column's mean density is higher); pass the mean density
// of the column where that matters.
#pragma once

#include <impetus/core/constants.hpp>

namespace impetus::sensors {

struct DepthPressure {
  double gauge = 0.0;        ///< rho g h, Pa
  double absolute = 0.0;     ///< P_surface + rho g h, Pa
  double differential = 0.0; ///< absolute - internal: the net push inwards on a sealed hull, Pa
};

/// depth h >= 0 m, density rho >= 0 kg/m^3, gravity >= 0 m/s^2, surfacePressure and
/// internalPressure >= 0 Pa (internal: what the hull was sealed at). Throws impetus::Error naming
/// the field.
[[nodiscard]] DepthPressure depthPressure(double depth, double density = constants::seaWaterDensity,
                                          double gravity = constants::standardGravity,
                                          double surfacePressure = constants::standardAtmosphere,
                                          double internalPressure = constants::standardAtmosphere);

/// The depth at which the gauge pressure reaches `gauge` Pa: h = P / (rho g). density and gravity
/// > 0.
[[nodiscard]] double depthForPressure(double gauge, double density = constants::seaWaterDensity,
                                      double gravity = constants::standardGravity);

} // namespace impetus::sensors
