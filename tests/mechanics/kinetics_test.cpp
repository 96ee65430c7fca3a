// Kinetics (ch. 4) against references the library did not produce: the ship against the spec's
// Ex 4.1 table (to its printed digits) and RK4 integration of m dv/dt = T - C v; the box's
// reactions against an independent balance of forces and moments about another point; the
// book's six-step procedure, as written in docs/mechanics/kinetics.md.
#include <impetus/error.hpp>
#include <impetus/integrate/rk4.hpp>
#include <impetus/mechanics/forces.hpp>
#include <impetus/mechanics/kinetics.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace impetus {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// ---- Ship ---------------------------------------------------------------------------------------

struct ShipRow {
  double t, v, s, a;
};

// Spec Ex 4.1 [C]: T = 20,000, m = 10,000, C = 1,000, from rest.
constexpr ShipRow ex41[] = {{0, 0, 0, 2.0},
                            {1, 1.9033, 0.9675, 1.80967},
                            {5, 7.8694, 21.3061, 1.21306},
                            {10, 12.6424, 73.5759, 0.73576},
                            {20, 17.2933, 227.0671, 0.27067},
                            {30, 19.0043, 409.9574, 0.09957},
                            {50, 19.8652, 801.3476, 0.01348},
                            {60, 19.9504, 1000.4958, 0.00496}};

TEST(ShipKinetics, matches_the_ex_4_1_table_to_its_printed_digits) {
  for (const ShipRow& row : ex41) {
    const ShipState s = shipMotion(20000.0, 10000.0, 1000.0, row.t);
    // Half a unit of the last printed digit: 4 decimals for v and s, 5 for a.
    EXPECT_NEAR(s.speed, row.v, 5e-5) << "t=" << row.t;
    EXPECT_NEAR(s.distance, row.s, 5e-5) << "t=" << row.t;
    EXPECT_NEAR(s.acceleration, row.a, 5e-6) << "t=" << row.t;
  }
  EXPECT_DOUBLE_EQ(shipTerminalSpeed(20000.0, 1000.0), 20.0); // the book's "steady 20"
  EXPECT_DOUBLE_EQ(shipTimeConstant(10000.0, 1000.0), 10.0);
}

struct Line {
  double s, v;
};
Line operator+(Line a, Line b) { return {a.s + b.s, a.v + b.v}; }
Line operator*(Line a, double k) { return {a.s * k, a.v * k}; }

TEST(ShipKinetics, matches_rk4_from_any_initial_speed_and_thrust_sign) {
  // RK4 with h = 0.01 s on a linear ODE of rate k = 0.1 1/s: global error ~(k h)^4 s ~ 1e-14
  // relative; 1e-9 absolute on values up to ~1000 m is still 1e5 times tighter than a wrong term.
  for (const double v0 : {0.0, 30.0, -4.0}) {
    for (const double thrust : {20000.0, -5000.0}) {
      const double m = 10000.0;
      const double c = 1000.0;
      const auto f = [&](double, const Line& x) { return Line{x.v, (thrust - c * x.v) / m}; };
      Line x{0.0, v0};
      const double h = 0.01;
      for (int i = 0; i < 6000; ++i) {
        x = rk4Step(f, i * h, x, h);
      }
      const ShipState s = shipMotion(thrust, m, c, 60.0, v0);
      EXPECT_NEAR(s.speed, x.v, 1e-9) << "v0=" << v0 << " T=" << thrust;
      EXPECT_NEAR(s.distance, x.s, 1e-9) << "v0=" << v0 << " T=" << thrust;
      EXPECT_NEAR(s.acceleration, (thrust - c * x.v) / m, 1e-12);
    }
  }
}

TEST(ShipKinetics, no_resistance_is_uniform_acceleration_and_small_resistance_is_smooth) {
  const ShipState free = shipMotion(20000.0, 10000.0, 0.0, 7.0, 3.0);
  EXPECT_DOUBLE_EQ(free.speed, 3.0 + 2.0 * 7.0);
  EXPECT_DOUBLE_EQ(free.distance, 3.0 * 7.0 + 0.5 * 2.0 * 49.0);
  EXPECT_DOUBLE_EQ(free.acceleration, 2.0);
  // Across the switch from the Taylor series to expm1 (k t = 0.5) and down to tiny k t, the
  // distance matches a long double reference of the same closed form s = f t^2 phi2(k t), with
  // phi2(x) = (x - 1 + e^{-x}) / x^2 summed as its series (-x)^n / (n + 2)! to n = 40 for x < 1
  // (terms below 1e-50) and directly above (cancellation 2 eps_ld / x <= 2e-19 there). 1e-14
  // relative is ~50 eps of double.
  for (const double kt : {1e-12, 1e-6, 0.0101, 0.3, 0.4999, 0.5001, 0.9, 8.0}) {
    const double t = 10.0;
    const double c = kt / t * 10000.0;
    const long double x = static_cast<long double>(kt);
    long double phi2 = 0.0L;
    if (x < 1.0L) {
      long double term = 0.5L; // n = 0: 1 / 2!
      for (int n = 0; n <= 40; ++n) {
        phi2 += term;
        term *= -x / static_cast<long double>(n + 3);
      }
    } else {
      phi2 = (x + std::expm1(-x)) / (x * x);
    }
    const double ref = static_cast<double>(2.0L * static_cast<long double>(t * t) * phi2); // f = T/m = 2
    const double got = shipMotion(20000.0, 10000.0, c, t).distance;
    EXPECT_NEAR(got, ref, 1e-14 * ref) << "kt=" << kt;
  }
}

TEST(ShipKinetics, rejects_bad_input) {
  EXPECT_EQ(thrownField([] { static_cast<void>(shipMotion(1.0, 0.0, 1.0, 1.0)); }), "mass");
  EXPECT_EQ(thrownField([] { static_cast<void>(shipMotion(1.0, 1.0, -1.0, 1.0)); }), "resistanceCoefficient");
  EXPECT_EQ(thrownField([] { static_cast<void>(shipMotion(1.0, 1.0, 1.0, -1.0)); }), "time");
  EXPECT_EQ(thrownField([] { static_cast<void>(shipMotion(nan, 1.0, 1.0, 1.0)); }), "thrust");
  EXPECT_EQ(thrownField([] { static_cast<void>(shipTerminalSpeed(1.0, 0.0)); }), "resistanceCoefficient");
}

// ---- Box tipping ---------------------------------------------------------------------------------

/// Checks Newton's laws for the box with the given reactions independently of the derivation in
/// kinetics.cpp: sum of forces = m a (x), 0 (y), and moments about the *leading bottom corner*
/// (not the centre of gravity used there) = r_cg x m a_cg, for a box that does not rotate.
void expectBalanced(const PushedBox& box, double push, const BoxSupportReactions& r) {
  const double w = box.width;
  const double h = box.height;
  const double mg = box.mass * box.gravity;
  const std::array<AppliedForce2, 5> forces{
      AppliedForce2{{push, 0.0}, {-w / 2.0, box.pushHeight}},    // push on the trailing face
      AppliedForce2{{0.0, -mg}, {0.0, h / 2.0}},                 // weight at the centre
      AppliedForce2{{0.0, r.leadingReaction}, {w / 2.0, 0.0}},   // R1
      AppliedForce2{{0.0, r.trailingReaction}, {-w / 2.0, 0.0}}, // R2
      AppliedForce2{{-r.frictionForce, 0.0}, {0.1 * w, 0.0}}};   // friction, anywhere on the floor
  const Vec2d corner{w / 2.0, 0.0};
  const ForceResultant2 sum = resultant(forces, corner);
  const Vec2d inertial{box.mass * r.acceleration, 0.0};
  const double scale = 1e-12 * mg * (w + h); // rounding of sums of products ~ mg * size
  EXPECT_NEAR(sum.force.x, inertial.x, 1e-12 * mg);
  EXPECT_NEAR(sum.force.y, 0.0, 1e-12 * mg);
  EXPECT_NEAR(sum.torque, cross(Vec2d{0.0, h / 2.0} - corner, inertial), scale);
}

TEST(BoxTipping, reactions_balance_forces_and_moments_about_another_point) {
  for (const double hp : {0.2, 0.5, 0.8, 1.0}) {
    const PushedBox box{50.0, 0.5, 1.0, hp, 0.6, 0.4, 9.81};
    for (const double push : {0.0, 100.0, 250.0, 400.0}) {
      SCOPED_TRACE(testing::Message() << "hp=" << hp << " F=" << push);
      expectBalanced(box, push, boxSupportReactions(box, push, false));
      expectBalanced(box, push, boxSupportReactions(box, push, true));
    }
  }
}

TEST(BoxTipping, trailing_reaction_vanishes_at_both_tipping_forces) {
  // m = 50 kg, w = 0.5 m, h = 1 m, h_p = 0.8 m, g = 9.81: held, F_tip = m g w / (2 h_p) =
  // 490.5 * 0.5 / 1.6 = 153.28125 N; sliding with mu_k = 0.4, F_tip = 490.5 (0.5 - 0.4) / 0.6 =
  // 81.75 N (hand values).
  const PushedBox box{50.0, 0.5, 1.0, 0.8, 0.6, 0.4, 9.81};
  const BoxTipping t = boxTipping(box);
  EXPECT_NEAR(t.tippingForceAtRest, 153.28125, 1e-12);
  ASSERT_TRUE(t.tippingForceWhileSliding.has_value());
  EXPECT_NEAR(*t.tippingForceWhileSliding, 81.75, 1e-12);
  EXPECT_FALSE(t.backwardTippingForceWhileSliding.has_value());
  EXPECT_NEAR(boxSupportReactions(box, t.tippingForceAtRest, false).trailingReaction, 0.0, 1e-12);
  EXPECT_NEAR(boxSupportReactions(box, *t.tippingForceWhileSliding, true).trailingReaction, 0.0, 1e-12);
  EXPECT_GT(boxSupportReactions(box, 0.99 * t.tippingForceAtRest, false).trailingReaction, 0.0);
  EXPECT_LT(boxSupportReactions(box, 1.01 * t.tippingForceAtRest, false).trailingReaction, 0.0);
  // The critical height w / (2 mu_s) = 0.4167 m is below 0.8 m: it tips before it slides
  // (153 N < mu_s m g = 294.3 N).
  EXPECT_NEAR(t.criticalPushHeight, 0.5 / 1.2, 1e-15);
  EXPECT_NEAR(t.slidingForce, 294.3, 1e-12);
  EXPECT_TRUE(t.tipsFirst);
  EXPECT_EQ(pushBoxAtRest(box, 150.0).motion, BoxMotion::rests);
  EXPECT_EQ(pushBoxAtRest(box, 160.0).motion, BoxMotion::tipsForward);
}

TEST(BoxTipping, both_formulas_agree_at_the_critical_height_when_mu_s_equals_mu_k) {
  // Spec ch. 4 item 7: with one mu, the held and sliding tipping forces meet at F = mu m g,
  // which happens at h_p = w / (2 mu).
  // w = 0.6 m, h = 1.2 m: h_p = w / (2 mu) lies in (h/2, h], where the sliding formula holds,
  // for mu in [0.25, 0.5).
  for (const double mu : {0.26, 0.3, 0.4, 0.45}) {
    const double w = 0.6;
    const PushedBox box{20.0, w, 1.2, w / (2.0 * mu), mu, mu, 9.81};
    ASSERT_GT(2.0 * box.pushHeight, box.height);
    ASSERT_LE(box.pushHeight, box.height);
    const BoxTipping t = boxTipping(box);
    EXPECT_NEAR(t.tippingForceAtRest, mu * 20.0 * 9.81, 1e-11) << mu;
    ASSERT_TRUE(t.tippingForceWhileSliding.has_value());
    EXPECT_NEAR(*t.tippingForceWhileSliding, mu * 20.0 * 9.81, 1e-11) << mu;
  }
}

TEST(BoxTipping, pushed_low_it_slides_first_and_a_tall_box_can_tip_backward) {
  // h_p = 0.3 m < w / (2 mu_s) = 0.4167 m: it slides (at 294.3 N) before it could tip (408.75 N).
  const PushedBox low{50.0, 0.5, 1.0, 0.3, 0.6, 0.4, 9.81};
  const BoxTipping t = boxTipping(low);
  EXPECT_FALSE(t.tipsFirst);
  EXPECT_EQ(pushBoxAtRest(low, 290.0).motion, BoxMotion::rests);
  EXPECT_EQ(pushBoxAtRest(low, 300.0).motion, BoxMotion::slides);
  EXPECT_FALSE(t.tippingForceWhileSliding.has_value()); // below the centre: never forward
  // Backward: R1 = 0 at m g (w + mu_k h) / (h - 2 h_p) = 490.5 * 0.9 / 0.4 = 1103.625 N.
  ASSERT_TRUE(t.backwardTippingForceWhileSliding.has_value());
  EXPECT_NEAR(*t.backwardTippingForceWhileSliding, 1103.625, 1e-10);
  EXPECT_NEAR(boxSupportReactions(low, *t.backwardTippingForceWhileSliding, true).leadingReaction, 0.0, 1e-10);
  EXPECT_EQ(pushBoxAtRest(low, 1200.0).motion, BoxMotion::tipsBackward);
  // mu_s = 0: any push slides it; the critical height is infinite.
  const PushedBox ice{50.0, 0.5, 1.0, 1.0, 0.0, 0.0, 9.81};
  EXPECT_TRUE(std::isinf(boxTipping(ice).criticalPushHeight));
  EXPECT_EQ(pushBoxAtRest(ice, 1.0).motion, BoxMotion::slides);
}

TEST(BoxTipping, rejects_bad_input) {
  EXPECT_EQ(thrownField([] { static_cast<void>(boxTipping({50.0, 0.5, 1.0, 1.2, 0.6, 0.4})); }), "pushHeight");
  EXPECT_EQ(thrownField([] { static_cast<void>(boxTipping({50.0, 0.5, 1.0, 0.0, 0.6, 0.4})); }), "pushHeight");
  EXPECT_EQ(thrownField([] { static_cast<void>(boxTipping({-1.0, 0.5, 1.0, 0.5, 0.6, 0.4})); }), "mass");
  EXPECT_EQ(thrownField([] { static_cast<void>(boxTipping({50.0, 0.0, 1.0, 0.5, 0.6, 0.4})); }), "width");
  EXPECT_EQ(thrownField([] { static_cast<void>(boxTipping({50.0, 0.5, 1.0, 0.5, 0.3, 0.4})); }), "kineticCoefficient");
  EXPECT_EQ(thrownField([] { static_cast<void>(pushBoxAtRest({50.0, 0.5, 1.0, 0.5, 0.6, 0.4}, -1.0)); }), "pushForce");
}

// ---- The six-step procedure (docs/mechanics/kinetics.md) ---------------------------------------

TEST(SixStepProcedure, docs_example_matches_the_closed_form) {
  // Step 1: mass properties. The ship of Ex 4.1 is a particle: only its mass matters.
  const double mass = 10000.0; // kg
  // Step 2: every force. Thrust ahead; water resistance -C v; weight and buoyancy cancel.
  const double thrust = 20000.0;    // N
  const double resistance = 1000.0; // C, N s/m
  struct State {
    double distance, speed;
    State operator+(const State& o) const { return {distance + o.distance, speed + o.speed}; }
    State operator*(double k) const { return {distance * k, speed * k}; }
  };
  const auto derivative = [&](double /*t*/, const State& s) {
    // Step 3: sum them. Step 4: a = F / m.
    const double force = thrust + linearDragForce({s.speed, 0.0, 0.0}, resistance).x;
    const double acceleration = force / mass;
    return State{s.speed, acceleration};
  };
  // Steps 5 and 6: integrate twice (RK4 does both at once on the state).
  State s{0.0, 0.0};
  const double dt = 0.1;
  for (int i = 0; i < 100; ++i) {
    s = rk4Step(derivative, i * dt, s, dt);
  }
  const ShipState exact = shipMotion(thrust, mass, resistance, 10.0);
  // RK4 at k dt = 0.01: error ~ (k dt)^4 ~ 1e-8 relative; 1e-6 absolute is ample.
  EXPECT_NEAR(s.speed, exact.speed, 1e-6);       // 12.6424 m/s
  EXPECT_NEAR(s.distance, exact.distance, 1e-6); // 73.5759 m
}

} // namespace
} // namespace impetus
