// Optical tracking (ch. 25) against references the library did not produce: derivatives of
// closed-form motions (x = 4.9 t^2, sin t), the spec's oracles (and the book's divide-by-h
// value), the error falling as h or h^2 as each method's order says, Savitzky and Golay's 1964
// coefficient tables, and the noise gain of a convolution, sqrt(sum c^2) sigma / h.
#include <impetus/math/scalar.hpp>
#include <impetus/sensors/finite_difference.hpp>
#include <impetus/sensors/optical_tracking.hpp>
#include <impetus/sensors/savitzky_golay.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <vector>

namespace impetus::sensors {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// ---- Finite differences --------------------------------------------------------------------------

TEST(FiniteDifference, falling_body_oracles_and_the_books_divide_by_h) {
  // x = 4.9 t^2 sampled at 30 Hz around t = 1: v = 9.8 t = 9.8, a = 9.8.
  const double h = 1.0 / 30.0;
  const auto x = [](double t) { return 4.9 * t * t; };
  EXPECT_NEAR(backwardDifference(x(1.0 - h), x(1.0), h), 9.63667, 5e-6);
  EXPECT_NEAR(forwardDifference(x(1.0), x(1.0 + h), h), 9.96333, 5e-6);
  EXPECT_NEAR(centralDifference(x(1.0 - h), x(1.0 + h), h), 9.8, 1e-12); // exact for a parabola
  EXPECT_NEAR(secondDifference(x(1.0 - h), x(1.0), x(1.0 + h), h), 9.8, 1e-10);
  // The book's findAcceleration divides by h: 9.8 h = 0.326667 (and in m/s, not m/s^2).
  EXPECT_NEAR(bookFindAcceleration(x(1.0 - h), x(1.0), x(1.0 + h), h), 0.326667, 5e-7);
}

TEST(FiniteDifference, sine_oracles) {
  // x = sin t at t = 0.5, h = 0.1: exact v = 0.877583, a = -0.479426.
  const double t = 0.5, h = 0.1;
  EXPECT_NEAR(backwardDifference(std::sin(t - h), std::sin(t), h), 0.900072, 5e-7);
  EXPECT_NEAR(forwardDifference(std::sin(t), std::sin(t + h), h), 0.852169, 5e-7);
  EXPECT_NEAR(centralDifference(std::sin(t - h), std::sin(t + h), h), 0.876121, 5e-7);
  EXPECT_NEAR(secondDifference(std::sin(t - h), std::sin(t), std::sin(t + h), h), -0.479026, 5e-7);
}

/// log2 of the error ratio between steps h and h/2: the observed order of accuracy.
double observedOrder(const std::function<double(double)>& error, double h) {
  return std::log2(std::abs(error(h)) / std::abs(error(0.5 * h)));
}

TEST(FiniteDifference, error_falls_as_h_or_h_squared_as_each_order_says) {
  // x = exp(sin t) at t = 0.3 (no derivative vanishes near there).
  const auto x = [](double t) { return std::exp(std::sin(t)); };
  const double t = 0.3;
  const double v = std::cos(t) * x(t);
  const double a = (std::cos(t) * std::cos(t) - std::sin(t)) * x(t);
  const auto backward = [&](double h) { return backwardDifference(x(t - h), x(t), h) - v; };
  const auto forward = [&](double h) { return forwardDifference(x(t), x(t + h), h) - v; };
  const auto central = [&](double h) { return centralDifference(x(t - h), x(t + h), h) - v; };
  const auto second = [&](double h) { return secondDifference(x(t - h), x(t), x(t + h), h) - a; };
  // Uneven steps (h and 1.6 h): the three-point velocity stays second order.
  const auto uneven = [&](double h) { return centralDifferenceUneven(x(t - h), x(t), x(t + 1.6 * h), h, 1.6 * h) - v; };
  const auto unevenSecond = [&](double h) {
    return secondDifferenceUneven(x(t - h), x(t), x(t + 1.6 * h), h, 1.6 * h) - a;
  };
  for (const double h : {0.1, 0.05, 0.02}) {
    EXPECT_NEAR(observedOrder(backward, h), 1.0, 0.05) << h;
    EXPECT_NEAR(observedOrder(forward, h), 1.0, 0.05) << h;
    EXPECT_NEAR(observedOrder(central, h), 2.0, 0.05) << h;
    EXPECT_NEAR(observedOrder(second, h), 2.0, 0.05) << h;
    EXPECT_NEAR(observedOrder(uneven, h), 2.0, 0.05) << h;
  }
  // The leading terms themselves: backward -h x''/2, central h^2 x'''/6.
  const double h = 1e-3;
  const double x3 = (-std::sin(t) * std::cos(t) * 3.0 - std::cos(t) + std::pow(std::cos(t), 3)) * x(t);
  EXPECT_NEAR(backward(h) / (-0.5 * h * a), 1.0, 2e-3);
  EXPECT_NEAR(central(h) / (h * h * x3 / 6.0), 1.0, 2e-3);
  // With uneven steps the second difference drops to first order: error (h2 - h1) x''' / 3.
  EXPECT_NEAR(unevenSecond(h) / (0.6 * h * x3 / 3.0), 1.0, 1e-2);
  EXPECT_NEAR(observedOrder(unevenSecond, 0.002), 1.0, 0.05);
}

TEST(FiniteDifference, motion_at_the_sampling_period_aliases_to_zero_slope) {
  // sin(2 pi t / T) sampled at h = T or T/2: every central slope is zero.
  const double period = 0.5;
  for (const double h : {period, 0.5 * period}) {
    for (const double t : {0.0, 0.13, 0.4}) {
      const double v = centralDifference(std::sin(2.0 * pi<double> * (t - h) / period),
                                         std::sin(2.0 * pi<double> * (t + h) / period), h);
      EXPECT_NEAR(v, 0.0, 1e-12);
    }
  }
}

TEST(FiniteDifference, vectors_and_bad_steps) {
  const Vec3d v = centralDifference(Vec3d{0.0, 1.0, 2.0}, Vec3d{2.0, 1.0, -2.0}, 0.5);
  EXPECT_EQ(v, (Vec3d{2.0, 0.0, -4.0}));
  expectErrorField([] { (void)backwardDifference(0.0, 1.0, 0.0); }, "h");
  expectErrorField([] { (void)centralDifference(0.0, 1.0, nan); }, "h");
  expectErrorField([] { (void)secondDifferenceUneven(0.0, 1.0, 2.0, 0.1, -0.1); }, "h2");
  expectErrorField([] { (void)forwardDifference(nan, 1.0, 0.1); }, "x");
}

// ---- Savitzky-Golay --------------------------------------------------------------------------------

void expectCoefficients(const SavitzkyGolay& sg, const std::vector<double>& numerators, double norm) {
  const auto c = sg.coefficients();
  ASSERT_EQ(c.size(), numerators.size());
  for (std::size_t k = 0; k < c.size(); ++k) {
    EXPECT_NEAR(c[k], numerators[k] / norm, 1e-13) << k;
  }
}

TEST(SavitzkyGolay, coefficients_match_the_1964_tables) {
  // Savitzky & Golay (1964), Tables I, III and V (quadratic/cubic; the same coefficients).
  expectCoefficients(SavitzkyGolay(2, 2, 0), {-3, 12, 17, 12, -3}, 35);
  expectCoefficients(SavitzkyGolay(3, 3, 0), {-2, 3, 6, 7, 6, 3, -2}, 21);
  expectCoefficients(SavitzkyGolay(2, 2, 1), {-2, -1, 0, 1, 2}, 10);
  expectCoefficients(SavitzkyGolay(3, 2, 1), {-3, -2, -1, 0, 1, 2, 3}, 28);
  expectCoefficients(SavitzkyGolay(2, 3, 1), {1, -8, 0, 8, -1}, 12);
  expectCoefficients(SavitzkyGolay(2, 2, 2), {2, -1, -2, -1, 2}, 7);
  expectCoefficients(SavitzkyGolay(3, 2, 2), {5, 0, -3, -4, -3, 0, 5}, 42);
  expectCoefficients(SavitzkyGolay(3, 4, 0), {5, -30, 75, 131, 75, -30, 5}, 231);
}

TEST(SavitzkyGolay, exact_on_polynomials_up_to_its_order_everywhere) {
  // x = 1 - 2t + 3t^2 - 0.5t^3 on h = 0.05: a cubic fit gives x, x', x'' exactly at every sample,
  // including the ends (evaluated off centre) and at the newest sample.
  const double h = 0.05;
  std::vector<double> x;
  for (int i = 0; i < 30; ++i) {
    const double t = i * h;
    x.push_back(1.0 - 2.0 * t + 3.0 * t * t - 0.5 * t * t * t);
  }
  const std::vector<double> v = SavitzkyGolay(4, 3, 1).filter(x, h);
  const std::vector<double> a = SavitzkyGolay(4, 3, 2).filter(x, h);
  for (int i = 0; i < 30; ++i) {
    const double t = i * h;
    EXPECT_NEAR(v[i], -2.0 + 6.0 * t - 1.5 * t * t, 1e-10) << i;
    EXPECT_NEAR(a[i], 6.0 - 3.0 * t, 1e-8) << i;
  }
  const std::span<const double> lastWindow(x.data() + 21, 9);
  EXPECT_NEAR(SavitzkyGolay(4, 3, 1).applyLatest(lastWindow, h), -2.0 + 6.0 * 29 * h - 1.5 * 29 * h * 29 * h, 1e-10);
}

TEST(SavitzkyGolay, noise_gain_is_the_coefficients_norm_and_beats_the_central_difference) {
  // Positions of a parabola with 2 mm of white noise, 30 Hz: the velocity's noise is
  // sigma sqrt(sum c^2) / h for any linear differentiator.
  const double h = 1.0 / 30.0, sigma = 2e-3;
  std::mt19937 rng(17);
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<double> x;
  const int n = 20'000;
  for (int i = 0; i < n; ++i) {
    const double t = i * h;
    x.push_back(0.2 * t * t + noise(rng));
  }
  const SavitzkyGolay sg(5, 2, 1);
  const std::vector<double> v = sg.filter(x, h);
  double sgErr2 = 0.0, centralErr2 = 0.0;
  int count = 0;
  for (int i = 5; i + 5 < n; ++i) {
    const double exact = 0.4 * i * h;
    sgErr2 += (v[i] - exact) * (v[i] - exact);
    const double c = centralDifference(x[i - 1], x[i + 1], h);
    centralErr2 += (c - exact) * (c - exact);
    ++count;
  }
  double norm2 = 0.0;
  for (const double c : sg.coefficients()) {
    norm2 += c * c;
  }
  const double sgRms = std::sqrt(sgErr2 / count), centralRms = std::sqrt(centralErr2 / count);
  EXPECT_NEAR(sgRms, sigma * std::sqrt(norm2) / h, 0.03 * sgRms);
  EXPECT_NEAR(centralRms, sigma * std::sqrt(0.5) / h, 0.03 * centralRms);
  EXPECT_LT(sgRms, 0.2 * centralRms); // 11 samples: ~7 times quieter
}

TEST(SavitzkyGolay, bad_windows_are_refused) {
  expectErrorField([] { SavitzkyGolay s(0, 0, 0); }, "halfWidth");
  expectErrorField([] { SavitzkyGolay s(1, 3, 0); }, "order");
  expectErrorField([] { SavitzkyGolay s(2, 2, 3); }, "derivative");
  const SavitzkyGolay sg(2, 2, 1);
  const std::vector<double> four(4, 0.0);
  expectErrorField([&] { (void)sg.apply(four, 0.1); }, "window");
  const std::vector<double> five(5, 0.0);
  expectErrorField([&] { (void)sg.apply(five, 0.0); }, "h");
}

// ---- Tracks -------------------------------------------------------------------------------------

/// A ball thrown from the hand: p(t) = p0 + v0 t + g t^2 / 2.
Vec3d ball(double t) { return Vec3d{0.3, 1.2, -2.0} + Vec3d{2.0, 4.0, 1.0} * t + Vec3d{0.0, -4.905, 0.0} * (t * t); }

TEST(OpticalTracking, central_differences_are_exact_on_a_parabolic_track_with_uneven_times) {
  // Frames late by up to 40 % (a camera on a busy machine): the three-point formulas are exact
  // for a parabola, ends included.
  std::vector<TrackSample> samples;
  double t = 0.0;
  for (int i = 0; i < 12; ++i) {
    samples.push_back({t, ball(t)});
    t += (1.0 + 0.4 * ((i * 7) % 5) / 4.0) / 30.0;
  }
  const std::vector<TrackState> states = differentiateTrack(samples);
  for (const TrackState& s : states) {
    const Vec3d v = Vec3d{2.0, 4.0, 1.0} + Vec3d{0.0, -9.81, 0.0} * s.time;
    EXPECT_NEAR(s.velocity.x, v.x, 1e-10);
    EXPECT_NEAR(s.velocity.y, v.y, 1e-10);
    EXPECT_NEAR(s.acceleration.y, -9.81, 1e-8);
    EXPECT_NEAR(s.acceleration.x, 0.0, 1e-9);
  }
}

TEST(OpticalTracking, backward_differences_lag_by_half_a_step) {
  const double h = 1.0 / 30.0;
  std::vector<TrackSample> samples;
  for (int i = 0; i < 6; ++i) {
    samples.push_back({i * h, ball(i * h)});
  }
  TrackOptions o;
  o.method = TrackMethod::backward;
  const std::vector<TrackState> s = differentiateTrack(samples, o);
  // (x_i - x_{i-1}) / h is the velocity half a step back: v(t - h/2).
  EXPECT_NEAR(s[5].velocity.y, 4.0 - 9.81 * (5 * h - 0.5 * h), 1e-10);
  EXPECT_NEAR(s[5].acceleration.y, -9.81, 1e-8);
  EXPECT_EQ(s[0].velocity, Vec3d{});
}

TEST(OpticalTracking, release_hand_off_recovers_the_throw) {
  // Tracked at 30 Hz until release at the 10th frame; Savitzky-Golay (quadratic, 7 samples)
  // evaluated at the newest sample gives the release state exactly for a parabola.
  const double h = 1.0 / 30.0;
  std::vector<TrackSample> samples;
  for (int i = 0; i <= 9; ++i) {
    samples.push_back({i * h, ball(i * h)});
  }
  TrackOptions o;
  o.method = TrackMethod::savitzkyGolay;
  o.halfWidth = 3;
  o.order = 2;
  const TrackState release = releaseState(samples, o);
  const double tr = 9 * h;
  EXPECT_NEAR(release.position.y, ball(tr).y, 1e-12);
  EXPECT_NEAR(release.velocity.x, 2.0, 1e-10);
  EXPECT_NEAR(release.velocity.y, 4.0 - 9.81 * tr, 1e-10);
  EXPECT_NEAR(release.acceleration.y, -9.81, 1e-8);
  // Backward, from the last three: velocity half a step behind, the same acceleration.
  const TrackState quick = releaseState(samples);
  EXPECT_NEAR(quick.velocity.y, 4.0 - 9.81 * (tr - 0.5 * h), 1e-10);
  // Uneven steps are refused by Savitzky-Golay.
  samples.back().time += 0.01;
  expectErrorField([&] { (void)releaseState(samples, o); }, "samples");
}

TEST(OpticalTracking, depth_from_disparity_and_bad_tracks) {
  // f = 525 px (Kinect-class), 7.5 cm baseline, 10 px of disparity: 3.9375 m.
  EXPECT_NEAR(depthFromDisparity(525.0, 0.075, 10.0), 3.9375, 1e-12);
  expectErrorField([] { (void)depthFromDisparity(525.0, 0.075, 0.0); }, "disparity");
  const std::vector<TrackSample> two{{0.0, {}}, {0.1, {}}};
  expectErrorField([&] { (void)differentiateTrack(two); }, "samples");
  const std::vector<TrackSample> back{{0.0, {}}, {0.1, {}}, {0.1, {}}};
  expectErrorField([&] { (void)differentiateTrack(back); }, "samples");
  TrackOptions o;
  o.method = TrackMethod::savitzkyGolay;
  o.order = 1;
  expectErrorField([&] { (void)differentiateTrack(back, o); }, "order");
}

} // namespace
} // namespace impetus::sensors
