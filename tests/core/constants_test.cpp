// Sanity identities between the physical constants and the definitions quoted beside them.
#include <impetus/core/constants.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace impetus {
namespace {

TEST(Constants, speed_of_sound_follows_its_stated_formula) {
  // 331.3 sqrt(1 + T / 273.15) at T = 20 C is 343.2146 m/s; the constant is rounded to 0.01.
  EXPECT_NEAR(constants::speedOfSoundAir20C, 331.3 * std::sqrt(1.0 + 20.0 / 273.15), 0.05);
}

TEST(Constants, ton_of_tnt_is_4_184e9_joules) {
  // 4.184e6 and 4.184e9 are integers below 2^53, so the product is exact.
  EXPECT_EQ(constants::tntSpecificEnergy * 1000.0, 4.184e9);
}

TEST(Constants, earth_surface_gravity_is_close_to_standard_gravity) {
  // GM / R^2 = 9.820 m/s^2; standard gravity 9.80665 also includes the centrifugal term
  // (~0.034 m/s^2 at the equator) and the latitude of its definition: they agree within 0.5 %.
  const double g = constants::earthGravitationalParameter / (constants::earthMeanRadius * constants::earthMeanRadius);
  EXPECT_NEAR(g, constants::standardGravity, 0.005 * constants::standardGravity);
  // GM / G is the Earth's mass, 5.9722e24 kg (IAU 2015 nominal), to the precision of G.
  EXPECT_NEAR(constants::earthGravitationalParameter / constants::gravitationalConstant, 5.9722e24, 1e-3 * 5.9722e24);
}

} // namespace
} // namespace impetus
