// The hourglass (ch. 8's sand with ch. 21's accelerometer): conservation of grains, the glass
// holds them, gravity from the reading decides where the sand goes, a granular discharge that
// does not slow with the head, a neck that sets the rate, and a glass on its side that stops.
#include <impetus/error.hpp>
#include <impetus/sensors/hourglass.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace {

using impetus::Error;
using impetus::Vec2d;
using impetus::Vec3d;
using namespace impetus::sensors;

constexpr double frame = 1.0 / 60.0;

/// Whether a point lies inside a simple polygon (even-odd ray crossing): the test's own geometry.
bool inside(const std::vector<Vec2d>& polygon, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2d& a = polygon[i];
    const Vec2d& b = polygon[j];
    if ((a.y > y) != (b.y > y) && x < (b.x - a.x) * (y - a.y) / (b.y - a.y) + a.x) {
      in = !in;
    }
  }
  return in;
}

/// Grains whose centre lies outside the glass. The outline is rebuilt here from the settings,
/// not taken from the model.
int escaped(const Hourglass& hg) {
  const HourglassSettings& s = hg.settings();
  const double w = 0.5 * s.bulbWidth;
  const double h = s.bulbHeight;
  const double n = 0.5 * s.neckWidth;
  const double f = (w - n) * std::tan(s.funnelAngle);
  const std::vector<Vec2d> glass{{w, -h}, {w, -f}, {n, 0.0},  {w, f},   {w, h},
                                 {-w, h}, {-w, f}, {-n, 0.0}, {-w, -f}, {-w, -h}};
  int out = 0;
  for (const auto& p : hg.positions()) {
    out += inside(glass, p.x, p.y) ? 0 : 1;
  }
  return out;
}

/// Times (s) at which the top bulb has lost 10 %, 20 %, ... 100 % of the sand, upright, stepped
/// at 1/60 s for at most `limit` s (-1: not reached).
std::vector<double> drainTimes(Hourglass& hg, double limit) {
  const int n = hg.grainCount();
  std::vector<double> times(10, -1.0);
  for (int i = 0; i < static_cast<int>(limit / frame) && times.back() < 0.0; ++i) {
    hg.stepAtTilt(0.0, frame);
    const int moved = n - hg.grainsIn(Bulb::top);
    for (int q = 0; q < 10; ++q) {
      if (times[q] < 0.0 && 10 * moved >= (q + 1) * n) {
        times[q] = hg.time();
      }
    }
  }
  return times;
}

TEST(Hourglass, settings_are_validated_naming_the_field) {
  const auto refused = [](HourglassSettings s, const std::string& field) {
    try {
      Hourglass hg(s);
      ADD_FAILURE() << field << " accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.field(), field) << e.what();
    }
  };
  HourglassSettings s;
  s.bulbWidth = std::numeric_limits<double>::quiet_NaN();
  refused(s, "bulbWidth");
  s = {};
  s.bulbHeight = -0.06;
  refused(s, "bulbHeight");
  s = {};
  s.bulbHeight = 0.02; // below the 60-degree funnel's 36 mm
  refused(s, "bulbHeight");
  s = {};
  s.neckWidth = 0.0021; // the largest grain is 2.2 mm
  refused(s, "neckWidth");
  s = {};
  s.grainDiameter = 0.0;
  refused(s, "grainDiameter");
  s = {};
  s.grainCount = 100000;
  refused(s, "grainCount");
  s = {};
  s.grainCount = 0;
  refused(s, "grainCount");
  s = {};
  s.funnelAngle = 0.5; // flatter than 45 degrees
  refused(s, "funnelAngle");
  s = {};
  s.sizeSpread = 0.5;
  refused(s, "sizeSpread");
  s = {};
  s.wallRestitution = 1.5;
  refused(s, "wallRestitution");
  s = {};
  s.substeps = 0;
  refused(s, "substeps");
  try {
    Hourglass(HourglassSettings{}).stepAtTilt(0.0, 0.0);
    ADD_FAILURE() << "dt = 0 accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "dt");
  }
  try {
    Hourglass(HourglassSettings{}).step({std::nan(""), -1.0, 0.0}, frame);
    ADD_FAILURE() << "a NaN reading accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "reading.x");
  }
}

TEST(Hourglass, upright_the_sand_runs_down_and_turned_over_it_runs_back_none_lost_none_escaping) {
  HourglassSettings s;
  s.grainCount = 200;
  Hourglass hg(s, Bulb::top);
  EXPECT_EQ(hg.grainsIn(Bulb::top), 200);
  EXPECT_EQ(escaped(hg), 0);
  // Upright: an iOS-style reading of gravity along the device's -y.
  for (int i = 0; i < 90; ++i) {
    hg.step({0.0, -1.0, 0.0}, frame);
    ASSERT_EQ(escaped(hg), 0) << "at " << hg.time() << " s";
  }
  EXPECT_EQ(hg.grainCount(), 200);
  EXPECT_EQ(hg.grainsIn(Bulb::top), 0);
  EXPECT_EQ(hg.grainsIn(Bulb::bottom), 200);
  // Turned over (tilt pi: gravity along +y in the device's frame): back into the top bulb.
  for (int i = 0; i < 150; ++i) {
    hg.stepAtTilt(std::numbers::pi, frame);
    ASSERT_EQ(escaped(hg), 0) << "at " << hg.time() << " s";
  }
  EXPECT_EQ(hg.grainCount(), 200);
  EXPECT_EQ(hg.grainsIn(Bulb::top), 200);
}

TEST(Hourglass, readings_in_either_convention_and_the_tilt_give_the_same_sand) {
  HourglassSettings s;
  s.grainCount = 60;
  Hourglass iosStyle(s);
  s.convention = AccelConvention::specificForce;
  Hourglass androidStyle(s);
  Hourglass tilted(s);
  for (int i = 0; i < 30; ++i) {
    iosStyle.step({0.0, -1.0, -0.2}, frame);   // gravity's direction; z presses on the screen
    androidStyle.step({0.0, 1.0, 0.2}, frame); // the reaction, +1 g up
    tilted.stepAtTilt(0.0, frame);
  }
  EXPECT_EQ(iosStyle.stateHash(), androidStyle.stateHash());
  EXPECT_EQ(iosStyle.stateHash(), tilted.stateHash());
}

TEST(Hourglass, the_discharge_does_not_slow_as_the_top_bulb_drains) {
  // A liquid through an orifice slows as its head h falls (Torricelli, Q ~ sqrt(h)): here the
  // head falls from about 25 to 10 mm between 20 % and 60 % drained, which would slow a liquid
  // by sqrt(10/25), 37 %. Grains flow at a rate set by the neck (Beverloo): each 10 % of the
  // sand between 20 % and 60 % takes within 35 % of the mean time (timed every 1/960 s instead
  // of every frame, the deciles from 10 % to 70 % lie within 13 % of their mean).
  HourglassSettings s;
  Hourglass hg(s, Bulb::top);
  const std::vector<double> t = drainTimes(hg, 3.0);
  ASSERT_GT(t[5], 0.0);
  const double mean = (t[5] - t[1]) / 4.0;
  for (int q = 2; q <= 5; ++q) {
    EXPECT_NEAR(t[q] - t[q - 1], mean, 0.35 * mean) << "decile " << q + 1;
  }
}

TEST(Hourglass, a_wider_neck_passes_more_sand) {
  // Beverloo in 2D: Q ~ (D - k d)^(3/2). The model's contacts are soft (the particle world's
  // single pass per substep), so the measured exponent is lower, about 1 in D: the rate must
  // grow with D, by more than D^0.5 (sqrt 2 = 1.41 from 6 to 12 mm) and less than the
  // Beverloo bound with k = 1.5, ((12 - 3)/(6 - 3))^1.5 = 5.2. Measured: 2700 / 1350 = 2.0.
  const auto rate = [](double neck) {
    HourglassSettings s;
    s.neckWidth = neck;
    Hourglass hg(s, Bulb::top);
    const std::vector<double> t = drainTimes(hg, 4.0);
    return 0.6 * hg.grainCount() / (t[7] - t[1]); // grains/s from 20 % to 80 % drained
  };
  const double narrow = rate(0.006);
  const double middle = rate(0.008);
  const double wide = rate(0.012);
  EXPECT_LT(narrow, middle);
  EXPECT_LT(middle, wide);
  EXPECT_GT(wide / narrow, std::sqrt(2.0));
  EXPECT_LT(wide / narrow, std::pow(3.0, 1.5));
}

TEST(Hourglass, on_its_side_the_flow_stops) {
  // Tilted 90 degrees the neck lies level with the sand beside it: gravity runs along the neck's
  // line and the grains that have not crossed in the first settling stay. After 1 s none cross.
  HourglassSettings s;
  Hourglass hg(s, Bulb::top);
  for (int i = 0; i < 60; ++i) {
    hg.stepAtTilt(0.5 * std::numbers::pi, frame);
  }
  const int settled = hg.grainsIn(Bulb::top);
  EXPECT_GT(settled, s.grainCount / 2);
  for (int i = 0; i < 60; ++i) {
    hg.stepAtTilt(0.5 * std::numbers::pi, frame);
  }
  EXPECT_EQ(hg.grainsIn(Bulb::top), settled);
  EXPECT_EQ(escaped(hg), 0);
}

TEST(Hourglass, the_same_inputs_give_the_same_sand) {
  HourglassSettings s;
  s.grainCount = 120;
  Hourglass a(s);
  Hourglass b(s);
  for (int i = 0; i < 20; ++i) {
    a.stepAtTilt(0.3, frame);
    b.stepAtTilt(0.3, frame);
  }
  EXPECT_EQ(a.stateHash(), b.stateHash());
  s.seed = 2;
  Hourglass c(s);
  for (int i = 0; i < 20; ++i) {
    c.stepAtTilt(0.3, frame);
  }
  EXPECT_NE(a.stateHash(), c.stateHash());
}

TEST(Hourglass, beverloo_2d_formula) {
  // Q = C (phi / (pi d^2 / 4)) sqrt(g) (D - k d)^(3/2): D = 8 mm, d = 2 mm, k = 1.5, C = 1,
  // phi = 0.82: 0.82 / 3.1416e-6 x 3.1316 x (0.005)^1.5 = 289.0 grains/s.
  const double q = beverlooRate2d(0.008, 0.002, 9.80665, 1.0, 1.5, 0.82);
  EXPECT_NEAR(q, 0.82 / (0.25 * std::numbers::pi * 4e-6) * std::sqrt(9.80665) * std::pow(0.005, 1.5), 1e-9);
  EXPECT_NEAR(q, 289.0, 0.1);
  EXPECT_EQ(beverlooRate2d(0.003, 0.002, 9.81, 1.0, 1.5), 0.0); // jammed: D <= k d
  EXPECT_THROW((void)beverlooRate2d(-1.0, 0.002, 9.81, 1.0, 1.5), Error);
}

} // namespace
