// Trilateration: the book's circles (spec ch. 22 section 3.6 oracles), the pseudorange solver
// with receiver clock bias recovering a known receiver and bias from exact ranges (the spec's
// 2D case, and a GPS constellation over Paris to 1 m), and geometry that cannot be solved.
#include <impetus/geo/ellipsoid.hpp>
#include <impetus/geo/trilateration.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace impetus::geo {
namespace {

TEST(Trilateration, closed_form_in_the_plane_matches_the_spec) {
  // Satellites (0,0), (10,0), (4,8); the point (3,4): r = 5, sqrt(65), sqrt(17).
  const Vec2d p =
      trilaterate({Vec2d{0.0, 0.0}, Vec2d{10.0, 0.0}, Vec2d{4.0, 8.0}}, {5.0, std::sqrt(65.0), std::sqrt(17.0)});
  EXPECT_NEAR(p.x, 3.0, 1e-12);
  EXPECT_NEAR(p.y, 4.0, 1e-12);
  // Any frame: the same circles moved and turned.
  const double c = std::cos(0.7);
  const double s = std::sin(0.7);
  auto move = [&](Vec2d v) { return Vec2d{c * v.x - s * v.y + 100.0, s * v.x + c * v.y - 50.0}; };
  const Vec2d q =
      trilaterate({move({0.0, 0.0}), move({10.0, 0.0}), move({4.0, 8.0})}, {5.0, std::sqrt(65.0), std::sqrt(17.0)});
  EXPECT_NEAR(q.x, move({3.0, 4.0}).x, 1e-11);
  EXPECT_NEAR(q.y, move({3.0, 4.0}).y, 1e-11);
}

TEST(Trilateration, closed_form_in_space_gives_both_mirror_points) {
  // The same satellites at z = 0, the point (3, 4, 5): r = 7.0711, 9.4868, 6.4807.
  const std::array<Vec3d, 2> p = trilaterate({Vec3d{0.0, 0.0, 0.0}, Vec3d{10.0, 0.0, 0.0}, Vec3d{4.0, 8.0, 0.0}},
                                             {std::sqrt(50.0), std::sqrt(90.0), std::sqrt(42.0)});
  EXPECT_NEAR(distance(p[0], Vec3d{3.0, 4.0, 5.0}), 0.0, 1e-12);
  EXPECT_NEAR(distance(p[1], Vec3d{3.0, 4.0, -5.0}), 0.0, 1e-12);
  expectErrorField(
      [] {
        (void)trilaterate({Vec3d{0.0, 0.0, 0.0}, Vec3d{10.0, 0.0, 0.0}, Vec3d{4.0, 8.0, 0.0}}, {1.0, 1.0, 1.0});
      },
      "ranges");
  expectErrorField(
      [] {
        (void)trilaterate({Vec3d{0.0, 0.0, 0.0}, Vec3d{10.0, 0.0, 0.0}, Vec3d{20.0, 0.0, 0.0}}, {5.0, 5.0, 15.0});
      },
      "centres");
  expectErrorField(
      [] {
        (void)trilaterate({Vec2d{0.0, 0.0}, Vec2d{1.0, 1.0}, Vec2d{2.0, 2.0}}, {1.0, 1.0, 2.0});
      },
      "centres");
  expectErrorField(
      [] {
        (void)trilaterate({Vec2d{0.0, 0.0}, Vec2d{1.0, 0.0}, Vec2d{0.0, 1.0}}, {1.0, -1.0, 2.0});
      },
      "ranges");
}

TEST(Trilateration, gauss_newton_recovers_the_spec_2d_point_and_bias) {
  // Pseudoranges = true ranges + c b with c b = 0.5 (spec: 5.5, 8.5623, 4.6231). From (5, 5, 0)
  // the spec's iteration reaches (3, 4, 0.5) in 4 steps.
  const std::vector<Vec2d> sats{{0.0, 0.0}, {10.0, 0.0}, {4.0, 8.0}};
  const std::vector<double> rho{5.5, std::sqrt(65.0) + 0.5, std::sqrt(17.0) + 0.5};
  PseudorangeOptions options;
  options.initialPosition = {5.0, 5.0, 0.0};
  options.speedOfLight = 1.0; // ranges in the example's units: the clock bias is c b itself
  const PseudorangeFix fix = solvePseudoranges(std::span<const Vec2d>(sats), rho, options);
  EXPECT_NEAR(fix.position.x, 3.0, 1e-10);
  EXPECT_NEAR(fix.position.y, 4.0, 1e-10);
  EXPECT_NEAR(fix.rangeBias, 0.5, 1e-10);
  EXPECT_LE(fix.iterations, 6); // 4 steps plus the vanishing steps that confirm convergence
  EXPECT_LT(fix.residualRms, 1e-10);
  // The default start is the origin, exactly on satellite 1 (the Jacobian row is undefined
  // there): the solver steps off it and still converges.
  const PseudorangeFix fromOrigin = solvePseudoranges(std::span<const Vec2d>(sats), rho);
  EXPECT_NEAR(distance(fromOrigin.position, Vec3d{3.0, 4.0, 0.0}), 0.0, 1e-9);
}

/// Satellites of a GPS-like constellation (orbit radius 26,560 km) spread over the sky of
/// `receiver`, all above its horizon.
std::vector<Vec3d> constellationOver(const GeodeticPosition& receiver) {
  const Vec3d p = geodeticToEcef(receiver);
  const double phi = receiver.point.latitude * std::numbers::pi / 180.0;
  const double lambda = receiver.point.longitude * std::numbers::pi / 180.0;
  const Vec3d up{std::cos(phi) * std::cos(lambda), std::cos(phi) * std::sin(lambda), std::sin(phi)};
  const Vec3d east{-std::sin(lambda), std::cos(lambda), 0.0};
  const Vec3d north = cross(up, east);
  std::vector<Vec3d> sats;
  // (azimuth, elevation) in degrees.
  const double sky[][2] = {{0.0, 80.0}, {40.0, 25.0}, {130.0, 40.0}, {220.0, 15.0}, {300.0, 55.0}, {175.0, 65.0}};
  for (const auto& ae : sky) {
    const double az = ae[0] * std::numbers::pi / 180.0;
    const double el = ae[1] * std::numbers::pi / 180.0;
    const Vec3d dir = up * std::sin(el) + (north * std::cos(az) + east * std::sin(az)) * std::cos(el);
    // The point along dir from the receiver at orbit radius: |p + t dir| = 26,560 km.
    const double orbit = 2.656e7;
    const double b = dot(p, dir);
    const double t = -b + std::sqrt(b * b - (dot(p, p) - orbit * orbit));
    sats.push_back(p + dir * t);
  }
  return sats;
}

TEST(Trilateration, gps_fix_recovers_position_and_clock_bias_to_a_metre) {
  const GeodeticPosition paris{{48.8584, 2.2945}, 35.0};
  const Vec3d truth = geodeticToEcef(paris);
  const double bias = 1.234e-3; // s: the receiver clock is 1.234 ms ahead (370 km of range)
  for (const std::size_t n : {std::size_t{4}, std::size_t{6}}) {
    std::vector<Vec3d> sats = constellationOver(paris);
    sats.resize(n);
    std::vector<double> rho;
    for (const Vec3d& s : sats) {
      rho.push_back(pseudorange(truth, s, bias));
    }
    const PseudorangeFix fix = solvePseudoranges(sats, rho); // from the Earth's centre
    EXPECT_LT(distance(fix.position, truth), 1.0) << n;
    EXPECT_NEAR(fix.clockBias * constants::speedOfLight, bias * constants::speedOfLight, 1.0) << n;
    EXPECT_LT(fix.iterations, 12) << n;
    EXPECT_GT(fix.gdop, 1.0) << n;
    EXPECT_LT(fix.gdop, 20.0) << n;
    const GeodeticPosition back = ecefToGeodetic(fix.position);
    EXPECT_NEAR(back.point.latitude, paris.point.latitude, 1e-7);
    EXPECT_NEAR(back.height, paris.height, 1e-3);
  }
}

TEST(Trilateration, geometry_that_cannot_be_solved_is_reported) {
  // Too few satellites for position and bias.
  const std::vector<Vec3d> three{{2e7, 0.0, 0.0}, {0.0, 2e7, 0.0}, {0.0, 0.0, 2e7}};
  expectErrorField([&] { (void)solvePseudoranges(three, std::vector<double>{2e7, 2e7, 2e7}); }, "satellites");
  // Four satellites in a plane with the receiver: the out-of-plane direction is unobserved.
  const std::vector<Vec3d> planar{{0.0, 0.0, 0.0}, {10.0, 0.0, 0.0}, {4.0, 8.0, 0.0}, {-6.0, 3.0, 0.0}};
  std::vector<double> rho;
  for (const Vec3d& s : planar) {
    rho.push_back(distance(s, Vec3d{3.0, 4.0, 0.0}) + 0.5);
  }
  expectErrorField([&] { (void)solvePseudoranges(planar, rho); }, "satellites");
  // 2D: satellites on a line with the receiver on it.
  const std::vector<Vec2d> line{{0.0, 0.0}, {10.0, 0.0}, {20.0, 0.0}};
  const std::vector<double> lineRho{5.5, 5.5, 15.5}; // receiver at (5, 0), c b = 0.5
  expectErrorField([&] { (void)solvePseudoranges(std::span<const Vec2d>(line), lineRho); }, "satellites");
  // Counts and values.
  const std::vector<Vec3d> four{{2e7, 0.0, 0.0}, {0.0, 2e7, 0.0}, {0.0, 0.0, 2e7}, {-2e7, 0.0, 0.0}};
  expectErrorField([&] { (void)solvePseudoranges(four, std::vector<double>{1.0, 2.0, 3.0}); }, "pseudoranges");
  expectErrorField([&] { (void)solvePseudoranges(four, std::vector<double>{2e7, 2e7, NAN, 2e7}); }, "pseudoranges");
  PseudorangeOptions bad;
  bad.maxIterations = 0;
  expectErrorField(
      [&] {
        (void)solvePseudoranges(four, std::vector<double>{2e7, 2e7, 2e7, 2e7}, bad);
      },
      "maxIterations");
}

} // namespace
} // namespace impetus::geo
