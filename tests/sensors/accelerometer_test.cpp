// Accelerometers (ch. 21) against references the library did not produce: readings made here by
// rotating gravity with the math layer's quaternions, the spec's tilt oracles (and the book's
// wrong values), the book's Table 21-2, the RC filters' closed-form step and frequency
// responses, and the tilt sprite's constant-acceleration and friction closed forms (the spec's
// a = 0.5 g, dt = 1/60 s oracle).
#include <impetus/math/quat.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/sensors/accelerometer.hpp>
#include <impetus/sensors/sensor_filters.hpp>
#include <impetus/sensors/tilt.hpp>
#include <impetus/sensors/tilt_sprite.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace impetus::sensors {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double twoPi = 2.0 * pi<double>;

// ---- Tilt ----------------------------------------------------------------------------------------

TEST(Tilt, single_axis_angle_is_zero_upright_and_grows_turning_left) {
  EXPECT_DOUBLE_EQ(tiltAngle(0.0, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(tiltAngle(1.0, 0.0), 90.0);
  EXPECT_DOUBLE_EQ(tiltAngle(0.0, -1.0), 180.0);
  EXPECT_DOUBLE_EQ(tiltAngle(-1.0, 0.0), 270.0);
  // Turned 10 degrees to the right (clockwise): "up" leans to the device's -x.
  EXPECT_NEAR(tiltAngle(-std::sin(degToRad(10.0)), std::cos(degToRad(10.0))), 350.0, 1e-12);
  expectErrorField([] { (void)tiltAngle(0.0, 0.0); }, "ay");
  expectErrorField([] { (void)tiltAngle(nan, 1.0); }, "ax");
}

TEST(Tilt, the_books_negative_angles_are_mirrored_and_the_corrected_mapping_is_not) {
  // Spec ch. 21 oracles, in the book's atan2(a_y, a_x) order: book value, corrected value.
  struct Case {
    double ax, ay, book, correct;
  };
  const double c10 = std::cos(degToRad(-10.0)), s10 = std::sin(degToRad(-10.0));
  for (const Case& k : {Case{c10, s10, 190.0, 350.0}, Case{1.0, -1.0, 225.0, 315.0}, Case{-1.0, -1.0, 315.0, 225.0},
                        Case{0.0, 1.0, 90.0, 90.0}, Case{1.0, 0.0, 0.0, 0.0}}) {
    EXPECT_NEAR(bookFind2dAngle(k.ax, k.ay), k.book, 2e-4) << k.ax << "," << k.ay; // the book's PI = 3.14159
    EXPECT_NEAR(angle360(k.ax, k.ay), k.correct, 1e-12) << k.ax << "," << k.ay;
  }
  // Only -90 degrees comes out right in the book.
  EXPECT_NEAR(bookFind2dAngle(0.0, -1.0), 270.0, 2e-4);
}

TEST(Tilt, pitch_and_roll_recovered_in_every_quadrant) {
  // The device's attitude: roll about its x axis, then pitch about y (R = R_y(pitch) R_x(roll),
  // body to world). A still device reads the specific force: world +z (up) in body axes.
  for (double pitchDeg = -85.0; pitchDeg <= 85.0; pitchDeg += 17.0) {
    for (double rollDeg = -175.0; rollDeg <= 180.0; rollDeg += 25.0) {
      const double pitch = degToRad(pitchDeg), roll = degToRad(rollDeg);
      const Quatd q = Quatd::fromAxisAngle({0.0, 1.0, 0.0}, pitch) * Quatd::fromAxisAngle({1.0, 0.0, 0.0}, roll);
      const Vec3d reading = inverseRotate(q, Vec3d{0.0, 0.0, 1.0}) * 0.98; // any scale
      const Tilt t = tiltFromGravity(reading);
      EXPECT_NEAR(t.pitch, pitch, 1e-12) << pitchDeg << " " << rollDeg;
      EXPECT_NEAR(t.roll, roll, 1e-12) << pitchDeg << " " << rollDeg;
      // The iOS convention reads the opposite vector and gives the same attitude.
      const Tilt ios = tiltFromGravity(-reading, AccelConvention::gravityDirection);
      EXPECT_NEAR(ios.roll, roll, 1e-12);
      // And gravityReading is the inverse.
      const Vec3d back = gravityReading(t);
      EXPECT_NEAR(back.x, reading.x / 0.98, 1e-12);
      EXPECT_NEAR(back.z, reading.z / 0.98, 1e-12);
    }
  }
  // Lying face up in iOS terms (z = -1) is level, not upside down.
  const Tilt flat = tiltFromGravity({0.0, 0.0, -1.0}, AccelConvention::gravityDirection);
  EXPECT_DOUBLE_EQ(flat.roll, 0.0);
  EXPECT_DOUBLE_EQ(flat.pitch, 0.0);
  expectErrorField([] { (void)tiltFromGravity({0.0, 0.0, 0.0}); }, "reading");
}

TEST(Tilt, gross_orientations_are_the_books_table_21_2) {
  using enum GrossOrientation;
  const auto g = AccelConvention::gravityDirection;
  EXPECT_EQ(grossOrientation({0, 0, 1}, g), faceDown);
  EXPECT_EQ(grossOrientation({0, 0, -1}, g), faceUp);
  EXPECT_EQ(grossOrientation({1, 0, 0}, g), rightSideDown);
  EXPECT_EQ(grossOrientation({-1, 0, 0}, g), leftSideDown);
  EXPECT_EQ(grossOrientation({0, -1, 0}, g), bottomDown);
  EXPECT_EQ(grossOrientation({0, 1, 0}, g), topDown);
  // Android's sign: face up reads +1.
  EXPECT_EQ(grossOrientation({0, 0, 1}, AccelConvention::specificForce), faceUp);
  // Halfway between two (45 degrees) and a small reading (moving, or in free fall): no call.
  EXPECT_EQ(grossOrientation({0.7, 0.0, -0.7}, g), unknown);
  EXPECT_EQ(grossOrientation({0.1, 0.0, 0.2}, g), unknown);
  EXPECT_EQ(grossOrientation({0.3, 0.1, -0.9}, g), faceUp);
  expectErrorField([] { (void)grossOrientation({0, 0, 1}, AccelConvention::specificForce, -0.1); }, "deadBand");
}

// ---- Range, clipping, calibration ---------------------------------------------------------------

TEST(Accelerometer, proof_mass_reading_is_hookes_law_over_m_g) {
  // 1 ug proof mass on a 0.5 N/m spring deflected 19.6 nm: F = 9.8e-9 N, a = 9.8 m/s^2 = 1 g (g = 9.8).
  EXPECT_NEAR(proofMassReading(19.6e-9, 0.5, 1e-9, 9.8), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(gToMetresPerSecond2(2.0), 2.0 * 9.80665);
  expectErrorField([] { (void)proofMassReading(1e-9, 0.5, 0.0); }, "proofMass");
}

TEST(Accelerometer, readings_saturate_at_the_range_and_zero_range_is_refused) {
  EXPECT_DOUBLE_EQ(clipReading(1.5, 2.3), 1.5);
  EXPECT_DOUBLE_EQ(clipReading(3.1, 2.3), 2.3);
  EXPECT_DOUBLE_EQ(clipReading(-4.0, 2.3), -2.3);
  EXPECT_TRUE(isClipped(2.3, 2.3));
  EXPECT_FALSE(isClipped(2.29, 2.3));
  expectErrorField([] { (void)clipReading(1.0, 0.0); }, "range");
  expectErrorField([] { (void)isClipped(1.0, -2.0); }, "range");
  expectErrorField([] { (void)clipReading(nan, 2.0); }, "trueG");
}

TEST(Accelerometer, clipped_peaks_are_bridged_closer_to_the_truth) {
  // A 3 g, 2 Hz shake sampled at 100 Hz by a phone that clips at 2.3 g.
  const double range = 2.3;
  std::vector<double> truth, clipped;
  for (int i = 0; i < 200; ++i) {
    truth.push_back(3.0 * std::sin(twoPi * 2.0 * i / 100.0));
    clipped.push_back(clipReading(truth.back(), range));
  }
  const std::vector<double> filled = fillClippedGaps(clipped, range);
  double errClipped = 0.0, errFilled = 0.0, peak = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    errClipped = std::max(errClipped, std::abs(clipped[i] - truth[i]));
    errFilled = std::max(errFilled, std::abs(filled[i] - truth[i]));
    peak = std::max(peak, filled[i]);
  }
  EXPECT_NEAR(errClipped, 0.7, 0.01);
  EXPECT_LT(errFilled, 0.03); // the flat tops (0.7 g short) become peaks: 0.012 g off at worst
  EXPECT_GT(peak, 2.8);
  // Unclipped samples are untouched.
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (!isClipped(clipped[i], range)) {
      EXPECT_EQ(filled[i], clipped[i]);
    }
  }
}

TEST(Accelerometer, six_position_calibration_removes_offset_and_scale) {
  // An axis with a 0.05 g offset and a 3 % scale error: r = 0.05 + 1.03 a.
  const auto raw = [](double a) { return 0.05 + 1.03 * a; };
  const AxisCalibration c = AxisCalibration::fromFlip(raw(1.0), raw(-1.0));
  EXPECT_NEAR(c.offset, 0.05, 1e-15);
  EXPECT_NEAR(c.scale, 1.03, 1e-15);
  for (const double a : {-2.0, -0.3, 0.0, 0.7, 1.9}) {
    EXPECT_NEAR(c.apply(raw(a)), a, 1e-14);
  }
  AccelCalibration all{c, AxisCalibration::fromFlip(0.98, -1.02), AxisCalibration::fromFlip(1.0, -1.0)};
  EXPECT_NEAR(all.apply({raw(0.5), -0.02, 1.0}).y, 0.0, 1e-15);
  expectErrorField([] { (void)AxisCalibration::fromFlip(-1.0, 1.0); }, "readingUp");
}

// ---- Filters -------------------------------------------------------------------------------------

TEST(SensorFilters, low_pass_step_response_is_the_discrete_rc_closed_form) {
  // y_n = 1 - (1 - alpha)^n for a unit step after a primed zero; alpha = dt / (RC + dt).
  LowPassFilter f(5.0, 100.0);
  const double rc = 1.0 / (twoPi * 5.0), dt = 0.01, alpha = dt / (rc + dt);
  f.update(0.0);
  for (int n = 1; n <= 50; ++n) {
    EXPECT_NEAR(f.update(1.0), 1.0 - std::pow(1.0 - alpha, n), 1e-14);
  }
}

/// The steady-state amplitude of a filter's output for a unit sine of frequency f.
template <class Filter> double measuredGain(Filter filter, double f, double rate) {
  const int settle = static_cast<int>(10.0 * rate / std::min(f, filter.cutoffHz())) + 1;
  const int periods = static_cast<int>(3.0 * rate / f);
  double peak = 0.0;
  for (int i = 0; i < settle + periods; ++i) {
    const double y = filter.update(std::sin(twoPi * f * i / rate));
    if (i >= settle) {
      peak = std::max(peak, std::abs(y));
    }
  }
  return peak;
}

TEST(SensorFilters, gain_at_and_around_the_cut_off_matches_the_rc_circuit) {
  // Continuous RC: low-pass 1/sqrt(1 + (f/fc)^2), high-pass (f/fc)/sqrt(1 + (f/fc)^2): -3 dB at fc.
  // Sampled at 500 x fc the discrete filters agree to within 1 %.
  const double fc = 2.0, rate = 1000.0;
  for (const double f : {0.5, 2.0, 8.0}) {
    const double r = f / fc;
    EXPECT_NEAR(measuredGain(LowPassFilter(fc, rate), f, rate), 1.0 / std::sqrt(1.0 + r * r), 0.01) << f;
    EXPECT_NEAR(measuredGain(HighPassFilter(fc, rate), f, rate), r / std::sqrt(1.0 + r * r), 0.01) << f;
  }
}

TEST(SensorFilters, real_timestamps_keep_the_response_under_jitter) {
  // Events due every 10 ms arrive 0-8 ms late. With each sample's real interval the step response
  // follows 1 - exp(-t / RC); taking the nominal 10 ms every time would lag.
  const double fc = 1.0, rc = 1.0 / (twoPi * fc);
  LowPassFilter real(fc, 100.0), nominal(fc, 100.0);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> late(0.0, 0.008);
  double t = 0.0;
  real.update(0.0);
  nominal.update(0.0);
  double yReal = 0.0, yNominal = 0.0;
  while (t < 0.3) {
    const double dt = 0.01 + late(rng);
    t += dt;
    yReal = real.update(1.0, dt);
    yNominal = nominal.update(1.0);
  }
  const double exact = 1.0 - std::exp(-t / rc);
  EXPECT_NEAR(yReal, exact, 0.02); // the discrete RC itself is first order in dt / RC
  EXPECT_GT(std::abs(yNominal - exact), 0.05);
}

TEST(SensorFilters, cut_off_at_or_above_nyquist_is_refused) {
  expectErrorField([] { LowPassFilter f(50.0, 100.0); }, "cutoffHz");
  expectErrorField([] { HighPassFilter f(60.0, 100.0); }, "cutoffHz");
  expectErrorField([] { LowPassFilter f(0.0, 100.0); }, "cutoffHz");
  expectErrorField([] { LowPassFilter f(1.0, 0.0); }, "sampleRateHz");
  LowPassFilter ok(49.0, 100.0);
  ok.update(1.0);
  expectErrorField([&] { (void)ok.update(1.0, 0.0); }, "dt");
  expectErrorField([&] { (void)ok.update(nan); }, "x");
}

// ---- The tilt sprite --------------------------------------------------------------------------

TEST(TiltSprite, one_step_matches_the_books_constant_acceleration_kinematics) {
  // Spec oracle: a_x = 0.5 g with g = 9.8, dt = 1/60 s from rest: dx = 6.806e-4 m, v = 0.08167 m/s.
  TiltSprite sprite({});
  const Vec2d start = sprite.position();
  EXPECT_DOUBLE_EQ(sprite.update({0.5, 0.0, -0.866}, 10.0), 0.0); // first call: only the time
  EXPECT_EQ(sprite.position(), start);
  EXPECT_NEAR(sprite.update({0.5, 0.0, -0.866}, 10.0 + 1.0 / 60.0), 1.0 / 60.0, 1e-12);
  EXPECT_NEAR(sprite.position().x - start.x, 0.5 * 4.9 / 3600.0, 1e-12);
  EXPECT_NEAR(sprite.position().x - start.x, 6.806e-4, 1e-7);
  EXPECT_NEAR(sprite.velocity().x, 0.08167, 1e-5);
  EXPECT_DOUBLE_EQ(sprite.position().y, start.y);
}

TEST(TiltSprite, constant_tilt_without_friction_is_exact_kinematics_over_many_steps) {
  TiltSpriteSettings s;
  s.worldSize = {20.0, 20.0};
  TiltSprite sprite(s);
  sprite.setState({1.0, 10.0}, {0.0, 0.0});
  // Right side down by 30 degrees (iOS reading: x = +sin 30, z = -cos 30): a = g sin 30 along +x.
  const Vec3d reading{0.5, 0.0, -std::sqrt(0.75)};
  for (int i = 0; i < 90; ++i) {
    sprite.step(reading, 1.0 / 60.0);
  }
  const double t = 1.5, a = 9.8 * 0.5;
  EXPECT_NEAR(sprite.position().x, 1.0 + 0.5 * a * t * t, 1e-12);
  EXPECT_NEAR(sprite.velocity().x, a * t, 1e-12);
}

TEST(TiltSprite, coulomb_friction_holds_below_the_angle_of_repose_and_slows_above_it) {
  TiltSpriteSettings s;
  s.worldSize = {50.0, 50.0};
  s.staticFriction = 0.3;
  s.kineticFriction = 0.2;
  // 10 degrees: tan 10 = 0.176 < 0.3, it stays.
  TiltSprite held(s);
  const Vec2d start = held.position();
  for (int i = 0; i < 60; ++i) {
    held.step({std::sin(degToRad(10.0)), 0.0, -std::cos(degToRad(10.0))}, 1.0 / 60.0);
  }
  EXPECT_EQ(held.position(), start);
  // 20 degrees: tan 20 = 0.364 > 0.3, it slides at g (sin - mu_k cos).
  TiltSprite slides(s);
  slides.setState({1.0, 25.0}, {});
  for (int i = 0; i < 60; ++i) {
    slides.step({std::sin(degToRad(20.0)), 0.0, -std::cos(degToRad(20.0))}, 1.0 / 60.0);
  }
  const double a = 9.8 * (std::sin(degToRad(20.0)) - 0.2 * std::cos(degToRad(20.0)));
  EXPECT_NEAR(slides.velocity().x, a, 1e-12);
  EXPECT_NEAR(slides.position().x, 1.0 + 0.5 * a, 1e-12);
  // Level, pushed at 1 m/s: stops after v / (mu_k g) = 0.5102 s, v^2 / (2 mu_k g) = 0.2551 m away,
  // and stays stopped (friction never pushes it back).
  TiltSprite coasting(s);
  coasting.setState({10.0, 10.0}, {0.6, 0.8});
  for (int i = 0; i < 60; ++i) {
    coasting.step({0.0, 0.0, -1.0}, 1.0 / 60.0);
  }
  EXPECT_EQ(coasting.velocity(), (Vec2d{0.0, 0.0}));
  const double d = 1.0 / (2.0 * 0.2 * 9.8);
  EXPECT_NEAR(coasting.position().x, 10.0 + 0.6 * d, 1e-12);
  EXPECT_NEAR(coasting.position().y, 10.0 + 0.8 * d, 1e-12);
}

TEST(TiltSprite, screen_edges_stop_or_bounce_the_sprite) {
  TiltSpriteSettings s; // the book's: 0.5 x 0.75 m, stop at the edges
  TiltSprite stop(s);
  for (int i = 0; i < 300; ++i) {
    stop.step({-0.7, 0.0, -0.7}, 1.0 / 60.0); // left side down
  }
  EXPECT_DOUBLE_EQ(stop.position().x, 0.0);
  EXPECT_DOUBLE_EQ(stop.velocity().x, 0.0);
  EXPECT_EQ(stop.edgeHits(), 1); // resting against the edge is one arrival, not one a step
  // With restitution 0.5 a hit reverses and halves the velocity into the wall.
  s.restitution = 0.5;
  TiltSprite bounce(s);
  bounce.setState({0.44, 0.3}, {1.2, 0.0});
  bounce.step({0.0, 0.0, -1.0}, 0.1); // reaches x = 0.45 (0.5 - 0.05) and would pass it
  EXPECT_DOUBLE_EQ(bounce.position().x, 0.45);
  EXPECT_DOUBLE_EQ(bounce.velocity().x, -0.6);
  // Pixels: a 320 x 480 view, the book's convertX = 320 / 0.5 px/m; y flips (screen y down).
  TiltSprite centred({});
  EXPECT_NEAR(centred.screenPosition({320.0, 480.0}).x, 0.225 * 640.0, 1e-9);
  EXPECT_NEAR(centred.screenPosition({320.0, 480.0}).y, (0.75 - 0.35 - 0.05) * 640.0, 1e-9);
}

TEST(TiltSprite, bad_settings_and_input_are_refused) {
  TiltSpriteSettings s;
  s.spriteSize = {1.0, 0.05};
  expectErrorField([&] { TiltSprite t(s); }, "spriteSize.x");
  s = {};
  s.kineticFriction = 0.5;
  s.staticFriction = 0.2;
  expectErrorField([&] { TiltSprite t(s); }, "kineticFriction");
  s = {};
  s.restitution = 1.5;
  expectErrorField([&] { TiltSprite t(s); }, "restitution");
  TiltSprite t({});
  expectErrorField([&] { t.step({nan, 0.0, 1.0}, 0.01); }, "reading.x");
  t.update({0, 0, 1}, 1.0);
  expectErrorField([&] { (void)t.update({0, 0, 1}, 0.5); }, "timestamp");
}

} // namespace
} // namespace impetus::sensors
