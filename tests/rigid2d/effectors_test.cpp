// Force effectors against physics references: Archimedes, the circular segment, hand-clipped
// polygons, F = m a and tau = I alpha, a spring's period, quadratic-drag terminal velocity,
// weathervaning, Kepler's third law and an explosion's impulses.
#include "support/error_field.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/effectors.hpp>
#include <impetus/rigid2d/world.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace impetus::rigid2d {
namespace {

constexpr float dt = 1.0f / 60.0f;

WorldDef zeroGravity() {
  WorldDef def;
  def.gravity = {0.0f, 0.0f};
  return def;
}

BodyId addDynamic(World& world, const Vec2f& position, float angle = 0.0f) {
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = position;
  def.angle = angle;
  return world.createBody(def);
}

BodyId addDisc(World& world, const Vec2f& position, float radius, float density = 1.0f) {
  const BodyId body = addDynamic(world, position);
  ShapeDef shape;
  shape.density = density;
  world.createShape(body, shape, Circle{{}, radius});
  return body;
}

Transform2f placed(const Vec2f& p, float angle) { return {p, Rot2f::fromAngle(angle)}; }

// Area and centroid of the part of a shape below y = surface, by a midpoint grid of n x n cells
// over [lo, hi]^2 (world): an independent reference with error ~ perimeter * cell / 2.
SubmergedArea gridReference(const Polygon& polygon, const Transform2f& xf, float surface, float lo, float hi, int n) {
  const double cell = static_cast<double>(hi - lo) / n;
  double area = 0.0;
  double mx = 0.0;
  double my = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Vec2f p{static_cast<float>(lo + (i + 0.5) * cell), static_cast<float>(lo + (j + 0.5) * cell)};
      if (p.y <= surface && containsPoint(polygon, inverseTransformPoint(xf, p))) {
        area += cell * cell;
        mx += cell * cell * p.x;
        my += cell * cell * p.y;
      }
    }
  }
  return {static_cast<float>(area), {static_cast<float>(mx / area), static_cast<float>(my / area)}};
}

// ---------------------------------------------------------------------------------------------
// Submerged area.

// The circular segment below a chord, against Simpson quadrature of the chord widths
// 2 sqrt(r^2 - y^2) (20000 intervals: error < 1e-6 relative despite the endpoint singularity).
TEST(SubmergedArea, circle_matches_circular_segment_by_quadrature) {
  const float r = 0.8f;
  const Vec2f c{1.5f, -0.3f};
  for (const float d : {-0.95f, -0.5f, 0.0f, 0.3f, 0.9f}) { // centre height above the surface / r
    const float surface = c.y - d * r;
    const SubmergedArea s = submergedArea(Circle{{0.5f, 0.0f}, r}, placed({1.0f, -0.3f}, 0.0f), surface);
    const int n = 20000;
    const double top = static_cast<double>(surface - c.y); // chord height relative to the centre
    const double h = (top + r) / n;
    double area = 0.0;
    double moment = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double y = -r + i * h;
      const double width = 2.0 * std::sqrt(std::max(0.0, static_cast<double>(r) * r - y * y));
      const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
      area += weight * width;
      moment += weight * width * y;
    }
    area *= h / 3.0;
    moment *= h / 3.0;
    EXPECT_NEAR(s.area, area, 1e-5 * pi<double> * r * r) << "d = " << d;
    EXPECT_NEAR(s.centroid.x, c.x, 1e-5f);
    EXPECT_NEAR(s.centroid.y, c.y + moment / area, 1e-4) << "d = " << d;
  }
  // Above and below the water.
  EXPECT_EQ(submergedArea(Circle{{}, r}, placed({0.0f, 1.0f}, 0.0f), 0.0f).area, 0.0f);
  EXPECT_NEAR(submergedArea(Circle{{}, r}, placed({0.0f, -1.0f}, 0.0f), 0.0f).area, pi<float> * r * r, 1e-5f);
  // An x bound through the centre keeps exactly half of the half-submerged disc (by symmetry),
  // here through the chord outline: within the chords' 0.17% of pi r^2.
  const SubmergedArea half = submergedArea(Circle{{}, r}, {}, 0.0f, 0.0f);
  EXPECT_NEAR(half.area, 0.25f * pi<float> * r * r, 0.0017f * pi<float> * r * r);
  EXPECT_NEAR(half.centroid.x, 4.0f * r / (3.0f * pi<float>), 2e-3f);
  EXPECT_NEAR(half.centroid.y, -4.0f * r / (3.0f * pi<float>), 2e-3f);
}

TEST(SubmergedArea, polygon_hand_computed_cases) {
  const Polygon square = makeBox(0.5f, 0.5f); // 1 m x 1 m
  // Half submerged: area 1/2, centroid a quarter below the surface.
  SubmergedArea s = submergedArea(square, {}, 0.0f);
  EXPECT_NEAR(s.area, 0.5f, 1e-6f);
  EXPECT_NEAR(s.centroid.x, 0.0f, 1e-6f);
  EXPECT_NEAR(s.centroid.y, -0.25f, 1e-6f);
  // Three quarters: centroid midway between the bottom (-0.5) and the surface (0.25).
  s = submergedArea(square, {}, 0.25f);
  EXPECT_NEAR(s.area, 0.75f, 1e-6f);
  EXPECT_NEAR(s.centroid.y, -0.125f, 1e-6f);
  // Wholly below and above.
  s = submergedArea(square, placed({3.0f, -2.0f}, 0.3f), 0.0f);
  EXPECT_NEAR(s.area, 1.0f, 1e-5f);
  EXPECT_NEAR(s.centroid.x, 3.0f, 1e-5f);
  EXPECT_NEAR(s.centroid.y, -2.0f, 1e-5f);
  EXPECT_EQ(submergedArea(square, placed({0.0f, 2.0f}, 0.3f), 0.0f).area, 0.0f);
  // A diamond (the square turned 45 deg, half-diagonal a): cut through its centre, the lower
  // triangle (area 1/2) has its centroid a/3 below the cut; cut at -a/2, the tip triangle has
  // half the base and height: area 1/8, centroid 2a/3 below the centre.
  const float a = std::sqrt(0.5f);
  s = submergedArea(square, placed({}, 0.25f * pi<float>), 0.0f);
  EXPECT_NEAR(s.area, 0.5f, 1e-6f);
  EXPECT_NEAR(s.centroid.y, -a / 3.0f, 1e-6f);
  s = submergedArea(square, placed({}, 0.25f * pi<float>), -0.5f * a);
  EXPECT_NEAR(s.area, 0.125f, 1e-6f);
  EXPECT_NEAR(s.centroid.x, 0.0f, 1e-6f);
  EXPECT_NEAR(s.centroid.y, -2.0f * a / 3.0f, 1e-6f);
  // Tilted 30 deg and cut through the centre: half the area (central symmetry); the centroid
  // against a 1000 x 1000 grid (cell 2 mm: error < 1e-3 m).
  const Transform2f tilted = placed({}, pi<float> / 6.0f);
  s = submergedArea(square, tilted, 0.0f);
  EXPECT_NEAR(s.area, 0.5f, 1e-6f);
  SubmergedArea ref = gridReference(square, tilted, 0.0f, -1.0f, 1.0f, 1000);
  EXPECT_NEAR(s.centroid.x, ref.centroid.x, 1e-3f);
  EXPECT_NEAR(s.centroid.y, ref.centroid.y, 1e-3f);
  // Tilted and cut off-centre: area and centroid against the grid.
  s = submergedArea(square, tilted, 0.3f);
  ref = gridReference(square, tilted, 0.3f, -1.0f, 1.0f, 1000);
  EXPECT_NEAR(s.area, ref.area, 5e-3f);
  EXPECT_NEAR(s.centroid.x, ref.centroid.x, 1e-3f);
  EXPECT_NEAR(s.centroid.y, ref.centroid.y, 1e-3f);
  // Bounded in x: the lower-left quarter.
  s = submergedArea(square, {}, 0.0f, -10.0f, 0.0f);
  EXPECT_NEAR(s.area, 0.25f, 1e-6f);
  EXPECT_NEAR(s.centroid.x, -0.25f, 1e-6f);
  EXPECT_NEAR(s.centroid.y, -0.25f, 1e-6f);
  // Segments enclose nothing.
  EXPECT_EQ(submergedArea(Segment{{-1.0f, 0.0f}, {1.0f, 0.0f}}, placed({0.0f, -5.0f}, 0.0f), 0.0f).area, 0.0f);
}

// Capsules and rounded polygons go through a chord outline: within 0.17% of pi r^2.
TEST(SubmergedArea, capsule_and_rounded_polygon_within_chord_error) {
  const float r = 0.5f;
  const float tolerance = 0.0017f * pi<float> * r * r;
  const Capsule capsule{{-1.0f, 0.0f}, {1.0f, 0.0f}, r};
  const float full = pi<float> * r * r + 2.0f * 2.0f * r;
  EXPECT_NEAR(submergedArea(capsule, placed({0.0f, -3.0f}, 0.4f), 0.0f).area, full, tolerance);
  // Horizontal, cut along its axis: half, by symmetry.
  SubmergedArea s = submergedArea(capsule, {}, 0.0f);
  EXPECT_NEAR(s.area, 0.5f * full, tolerance);
  EXPECT_NEAR(s.centroid.x, 0.0f, 1e-5f);
  // Upright (core from y = -1 to 1), water up to y = 0.5: the lower half-disc (pi r^2 / 2,
  // centroid 4r/(3 pi) below y = -1) and a 1 m x 1.5 m rectangle (centroid y = -0.25).
  s = submergedArea(capsule, placed({}, 0.5f * pi<float>), 0.5f);
  const float halfDisc = 0.5f * pi<float> * r * r;
  const float expected = halfDisc + 1.5f;
  EXPECT_NEAR(s.area, expected, tolerance);
  const float yc = (halfDisc * (-1.0f - 4.0f * r / (3.0f * pi<float>)) + 1.5f * -0.25f) / expected;
  EXPECT_NEAR(s.centroid.y, yc, 2e-3f);
  // A rounded 1 m square (radius 0.1 m): 1 + 4 (1)(0.1) + pi 0.01.
  const std::vector<Vec2f> corners{{-0.5f, -0.5f}, {0.5f, -0.5f}, {0.5f, 0.5f}, {-0.5f, 0.5f}};
  const Polygon rounded = makePolygon(corners, 0.1f);
  EXPECT_NEAR(submergedArea(rounded, placed({0.0f, -2.0f}, 1.0f), 0.0f).area, 1.4f + pi<float> * 0.01f,
              0.0017f * pi<float> * 0.01f);
  // Cut through the centre: half.
  EXPECT_NEAR(submergedArea(rounded, placed({}, 0.2f), 0.0f).area, 0.5f * (1.4f + pi<float> * 0.01f), 1e-4f);
}

// ---------------------------------------------------------------------------------------------
// Buoyancy.

// A 2 m x 0.5 m box (stable flat: metacentric height d/2 + b^2/(12 d) - h/2 = 1.21 m > 0) of
// half the water's density, dropped from above the surface: Archimedes puts its draft at
// (rho_box / rho_water) h = 0.25 m. The default drag decays the heave oscillation as e^(-t)
// (c_lin / 2 with the displaced mass ~ m), so 10 s leaves < 1e-4 of the 0.5 m drop.
TEST(Buoyancy, floating_box_settles_at_archimedes_depth) {
  World world; // gravity (0, -10)
  const BodyId box = addDynamic(world, {0.0f, 0.5f});
  ShapeDef shape;
  shape.density = 1.0f; // kg/m^2
  world.createShape(box, shape, makeBox(1.0f, 0.25f));
  BuoyancySettings water;
  water.fluidDensity = 2.0f;
  ForceEffectorSet effectors;
  effectors.add(Buoyancy(water));
  for (int i = 0; i < 600; ++i) {
    effectors.apply(world, dt);
    world.step(dt);
  }
  const float draft = water.surfaceHeight - (world.position(box).y - 0.25f);
  const float archimedes = 0.5f * 0.5f;
  std::printf("floating box draft %.6f m (Archimedes %.6f m, error %.3f%%), angle %.2e rad\n", draft, archimedes,
              100.0 * std::abs(draft - archimedes) / archimedes, world.angle(box));
  EXPECT_NEAR(draft, archimedes, 0.02f * archimedes);
  EXPECT_NEAR(world.angle(box), 0.0f, 0.01f);
  EXPECT_NEAR(world.linearVelocity(box).y, 0.0f, 1e-3f);
}

// The same hull tilted 0.4 rad: the submerged centroid moves to the low side, the buoyant force
// there rights it (positive metacentric height), and the angular drag damps the roll.
TEST(Buoyancy, tilted_hull_rights_itself) {
  World world;
  const BodyId box = addDynamic(world, {0.0f, 0.0f}, 0.4f);
  world.createShape(box, {}, makeBox(1.0f, 0.25f));
  BuoyancySettings settings;
  settings.fluidDensity = 2.0f;
  Buoyancy water(settings);
  float maxAngle = 0.0f;
  for (int i = 0; i < 600; ++i) {
    water.apply(world, dt);
    world.step(dt);
    if (i > 30) {
      maxAngle = std::max(maxAngle, std::abs(world.angle(box)));
    }
  }
  EXPECT_LT(maxAngle, 0.4f); // it never rolls further than it started
  EXPECT_NEAR(world.angle(box), 0.0f, 0.01f);
}

// A box 1.5 times as dense as the water, fully submerged: without drag it accelerates down at
// g (1 - rho_w / rho_b) = 10/3 m/s^2; with drag it sinks at the terminal speed where
// (rho_b - rho_w) A g = c_lin rho_w A v, v = g (rho_b - rho_w) / (c_lin rho_w) = 2.5 m/s.
TEST(Buoyancy, heavy_box_sinks) {
  for (const float drag : {0.0f, 2.0f}) {
    World world;
    const BodyId box = addDynamic(world, {0.0f, -2.0f});
    ShapeDef shape;
    shape.density = 3.0f;
    world.createShape(box, shape, makeBox(0.5f, 0.5f));
    BuoyancySettings settings;
    settings.fluidDensity = 2.0f;
    settings.linearDrag = drag;
    Buoyancy water(settings);
    const int steps = drag == 0.0f ? 30 : 600;
    for (int i = 0; i < steps; ++i) {
      water.apply(world, dt);
      world.step(dt);
    }
    if (drag == 0.0f) {
      EXPECT_NEAR(world.linearVelocity(box).y, -10.0f / 3.0f * 0.5f, 1e-3f);
    } else {
      std::printf("sinking box %.5f m/s (terminal %.5f m/s)\n", world.linearVelocity(box).y, -2.5);
      EXPECT_NEAR(world.linearVelocity(box).y, -2.5f, 0.01f * 2.5f);
      EXPECT_LT(world.position(box).y, -10.0f);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Thruster, gravity field, attractor.

// A 1 m x 0.5 m box of 2 kg/m^2: m = 1 kg, I = m (1 + 0.25) / 12. Through the centre, 3 N gives
// 3 m/s^2 and no spin; 0.25 m above it, the same thrust also spins it at -F d / I.
TEST(EffectorThruster, accelerates_at_f_over_m_and_spins_at_f_d_over_i) {
  World world(zeroGravity());
  ShapeDef shape;
  shape.density = 2.0f;
  const BodyId centred = addDynamic(world, {0.0f, 0.0f});
  world.createShape(centred, shape, makeBox(0.5f, 0.25f));
  const BodyId offset = addDynamic(world, {0.0f, 5.0f});
  world.createShape(offset, shape, makeBox(0.5f, 0.25f));
  const float force = 3.0f;
  Thruster main({centred, {}, {2.0f, 0.0f}, force}); // the direction is normalized
  Thruster side({offset, {0.0f, 0.25f}, {1.0f, 0.0f}, 0.0f});
  side.setThrust(force);
  const float m = world.mass(centred);
  const float inertia = world.rotationalInertia(offset);
  EXPECT_NEAR(m, 1.0f, 1e-6f);
  main.apply(world, dt);
  side.apply(world, dt);
  world.step(dt);
  EXPECT_NEAR(world.linearVelocity(offset).x, force / m * dt, 1e-6f);
  EXPECT_NEAR(world.angularVelocity(offset), -force * 0.25f / inertia * dt, 1e-6f);
  for (int i = 1; i < 60; ++i) {
    main.apply(world, dt);
    world.step(dt);
  }
  EXPECT_NEAR(world.linearVelocity(centred).x, force / m, 1e-4f); // a t, t = 1 s
  EXPECT_NEAR(world.linearVelocity(centred).y, 0.0f, 1e-6f);
  EXPECT_EQ(world.angularVelocity(centred), 0.0f);
}

TEST(EffectorGravityField, accelerates_only_inside_its_region) {
  World world(zeroGravity());
  const BodyId inside = addDisc(world, {0.0f, 0.0f}, 0.25f, 3.0f);
  const BodyId outside = addDisc(world, {10.0f, 0.0f}, 0.25f);
  GravityField field({{0.0f, 5.0f}, AABB{{-5.0f, -5.0f}, {5.0f, 50.0f}}});
  for (int i = 0; i < 60; ++i) {
    field.apply(world, dt);
    world.step(dt);
  }
  EXPECT_NEAR(world.linearVelocity(inside).y, 5.0f, 1e-4f); // a t, whatever the mass
  EXPECT_EQ(world.linearVelocity(outside).y, 0.0f);
}

// A small disc on a circular orbit of radius r at speed sqrt(mu / r): Kepler's period
// 2 pi sqrt(r^3 / mu). The period is read where the unwrapped angle crosses 2 pi (linear
// interpolation between steps), and the radius must hold within 1% for two orbits.
TEST(EffectorPointAttractor, circular_orbit_keeps_keplers_period) {
  World world(zeroGravity());
  const float r = 10.0f;
  const float mu = 1000.0f;
  const BodyId disc = addDisc(world, {r, 0.0f}, 0.05f);
  world.setLinearVelocity(disc, {0.0f, std::sqrt(mu / r)});
  PointAttractor attractor({{}, mu, 0.0f, 100.0f});
  const double period = 2.0 * pi<double> * std::sqrt(static_cast<double>(r) * r * r / mu);
  double previous = 0.0;
  double unwrapped = 0.0;
  double measured = 0.0;
  float minRadius = r;
  float maxRadius = r;
  for (int i = 1; i <= 800; ++i) {
    attractor.apply(world, dt);
    world.step(dt);
    const Vec2f p = world.position(disc);
    const double angle = std::atan2(static_cast<double>(p.y), static_cast<double>(p.x));
    double delta = angle - previous;
    delta -= 2.0 * pi<double> * std::round(delta / (2.0 * pi<double>));
    const double before = unwrapped;
    unwrapped += delta;
    previous = angle;
    if (measured == 0.0 && unwrapped >= 2.0 * pi<double>) {
      const double fraction = (2.0 * pi<double> - before) / (unwrapped - before);
      measured = (i - 1 + fraction) * static_cast<double>(dt);
    }
    minRadius = std::min(minRadius, length(p));
    maxRadius = std::max(maxRadius, length(p));
  }
  std::printf("orbit period %.5f s (Kepler %.5f s, error %.3f%%), radius %.4f..%.4f m\n", measured, period,
              100.0 * std::abs(measured - period) / period, minRadius, maxRadius);
  EXPECT_NEAR(measured, period, 0.01 * period);
  EXPECT_NEAR(minRadius, r, 0.01f * r);
  EXPECT_NEAR(maxRadius, r, 0.01f * r);
}

// ---------------------------------------------------------------------------------------------
// Spring-damper.

/// Times of the upward zero crossings of x(t) - x0, linearly interpolated.
struct CrossingClock {
  float rest = 0.0f;
  float last = 0.0f;
  std::vector<double> times;
  void sample(float x, int step) {
    const float now = x - rest;
    if (step > 0 && last < 0.0f && now >= 0.0f) {
      times.push_back((static_cast<double>(step - 1) + static_cast<double>(last / (last - now))) *
                      static_cast<double>(dt));
    }
    last = now;
  }
  [[nodiscard]] double period() const { return (times.back() - times.front()) / static_cast<double>(times.size() - 1); }
};

// A 1 kg disc on a spring to a fixed point, k = 4 pi^2 N/m: period 2 pi sqrt(m / k) = 1 s. The
// step (with the spring evaluated beta dt ahead) is area-preserving: the amplitude holds, and
// the discrete period is longer by (w dt)^2 / 24 ~ 0.05%.
TEST(EffectorSpringDamper, anchored_oscillator_period_and_amplitude) {
  for (const SolverKind solver : {SolverKind::softStep, SolverKind::bookImpulse}) {
    WorldDef def = zeroGravity();
    def.solver = solver;
    World world(def);
    const BodyId disc = addDisc(world, {1.3f, 0.0f}, 0.1f, 1.0f / (pi<float> * 0.01f)); // m = 1 kg
    ASSERT_NEAR(world.mass(disc), 1.0f, 1e-5f);
    const float k = 4.0f * pi<float> * pi<float>;
    SpringDamper spring({disc, {}, {}, {0.0f, 0.0f}, k, 0.0f, 1.0f});
    CrossingClock clock;
    clock.rest = 1.0f;
    float maxX = 0.0f;
    for (int i = 0; i <= 600; ++i) {
      clock.sample(world.position(disc).x, i);
      if (i >= 540) {
        maxX = std::max(maxX, world.position(disc).x);
      }
      spring.apply(world, dt);
      world.step(dt);
    }
    ASSERT_GE(clock.times.size(), 5u);
    std::printf("anchored spring (%s) period %.5f s (reference 1 s), amplitude after 10 s %.4f m (0.3 m)\n",
                solver == SolverKind::softStep ? "soft step" : "book", clock.period(), maxX - 1.0f);
    EXPECT_NEAR(clock.period(), 1.0, 0.01);
    EXPECT_NEAR(maxX - 1.0f, 0.3f, 0.01f * 0.3f);
    // The tension is taken beta dt ahead: within k |v| beta dt (< 2 N) of k (L - L0) now.
    EXPECT_NEAR(spring.lastTension(), k * (length(world.position(disc)) - 1.0f), 0.05f * k);
  }
}

// Two free discs (1 kg and 3 kg) on a damped spring in zero gravity: equal and opposite forces
// keep the pair's momentum (to float rounding), and the undamped pair oscillates at
// 2 pi sqrt(mu / k), mu the reduced mass.
TEST(EffectorSpringDamper, pair_conserves_momentum_and_uses_reduced_mass) {
  for (const float damping : {0.0f, 0.5f}) {
    World world(zeroGravity());
    const float density = 1.0f / (pi<float> * 0.01f);
    const BodyId a = addDisc(world, {0.0f, 0.0f}, 0.1f, density);
    // Undamped: along the x axis, moving along it (no spin, so the pair's radial frequency is
    // sqrt(k / mu)); damped: off-centre anchors and oblique velocities (the pair tumbles).
    const bool plain = damping == 0.0f;
    const BodyId b = addDisc(world, {1.3f, plain ? 0.0f : 0.2f}, 0.1f, 3.0f * density);
    world.setLinearVelocity(a, {0.2f, plain ? 0.1f : 0.5f});
    world.setLinearVelocity(b, {-0.1f, 0.1f});
    const float k = 10.0f;
    const Vec2f anchor = plain ? Vec2f{} : Vec2f{0.05f, 0.0f};
    SpringDamper spring({a, anchor, b, -anchor, k, damping, 1.0f});
    const Vec2f p0 = world.linearVelocity(a) * world.mass(a) + world.linearVelocity(b) * world.mass(b);
    CrossingClock clock;
    const auto separation = [&] { return length(world.position(b) - world.position(a)); };
    clock.rest = 0.0f;
    std::vector<float> lengths;
    for (int i = 0; i <= 600; ++i) {
      lengths.push_back(separation());
      spring.apply(world, dt);
      world.step(dt);
    }
    const Vec2f p1 = world.linearVelocity(a) * world.mass(a) + world.linearVelocity(b) * world.mass(b);
    // Float rounding of 2400 substep velocity updates per body: ~1e-5 N s of ~1 N s.
    EXPECT_NEAR(p1.x, p0.x, 1e-4f);
    EXPECT_NEAR(p1.y, p0.y, 1e-4f);
    if (damping == 0.0f) {
      // The separation oscillates about its mean (the spin stretches it a little).
      double mean = 0.0;
      for (const float l : lengths) {
        mean += l;
      }
      clock.rest = static_cast<float>(mean / static_cast<double>(lengths.size()));
      for (std::size_t i = 0; i < lengths.size(); ++i) {
        clock.sample(lengths[i], static_cast<int>(i));
      }
      const double reduced = 1.0 * 3.0 / (1.0 + 3.0);
      const double period = 2.0 * pi<double> * std::sqrt(reduced / k);
      ASSERT_GE(clock.times.size(), 5u);
      std::printf("spring pair period %.5f s (2 pi sqrt(mu/k) = %.5f s)\n", clock.period(), period);
      EXPECT_NEAR(clock.period(), period, 0.01 * period);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Wind drag.

// A disc falling through still air and through a 5 m/s side wind: the vertical speed tends to
// the terminal sqrt(2 m g / (rho CdA)) and, since drag acts on the velocity relative to the air,
// the horizontal speed to the wind's (the book's separate wind force drifts too slowly).
TEST(EffectorWindDrag, terminal_velocity_relative_to_the_air) {
  for (const float wind : {0.0f, 5.0f}) {
    World world;
    const BodyId disc = addDisc(world, {0.0f, 0.0f}, 0.5f);
    WindDrag drag({disc, {wind, 0.0f}, 1.225f, 0.1f, 0.0f, {}});
    for (int i = 0; i < 1200; ++i) {
      drag.apply(world, dt);
      world.step(dt);
    }
    const float terminal = std::sqrt(2.0f * world.mass(disc) * 10.0f / (1.225f * 0.1f));
    const Vec2f v = world.linearVelocity(disc);
    std::printf("wind %.0f m/s: velocity (%.4f, %.4f) m/s, terminal %.4f m/s\n", wind, v.x, v.y, terminal);
    EXPECT_NEAR(-v.y, terminal, 0.02f * terminal);
    EXPECT_NEAR(v.x, wind, 0.02f * terminal);
    EXPECT_EQ(world.angularVelocity(disc), 0.0f); // the centre of pressure is the centre of mass
  }
}

// A 2 m plank pinned at its centre, broadside to a 10 m/s wind: with the centre of pressure
// 0.5 m aft it turns to trail the wind (nose into it, angle pi); with the centre of pressure at
// the pin it feels no torque and stays put.
TEST(EffectorWindDrag, offset_centre_of_pressure_weathervanes) {
  for (const float aft : {0.5f, 0.0f}) {
    World world(zeroGravity());
    const BodyId ground = world.createBody({});
    const BodyId plank = addDynamic(world, {}, 0.5f * pi<float>);
    world.createShape(plank, {}, makeBox(1.0f, 0.1f));
    RevoluteJointDef pin;
    pin.bodyA = ground;
    pin.bodyB = plank;
    world.createJoint(pin);
    WindDrag drag({plank, {10.0f, 0.0f}, 1.225f, 0.5f, 0.0f, {-aft, 0.0f}});
    for (int i = 0; i < 600; ++i) {
      drag.apply(world, dt);
      world.step(dt);
    }
    const float angle = world.angle(plank);
    std::printf("weathervane (centre of pressure %.1f m aft): angle %.4f rad\n", aft, angle);
    if (aft > 0.0f) {
      EXPECT_NEAR(std::abs(angle), pi<float>, 0.02f); // ~1 degree
      EXPECT_NEAR(world.angularVelocity(plank), 0.0f, 0.01f);
    } else {
      EXPECT_NEAR(angle, 0.5f * pi<float>, 1e-4f);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Explosion.

// Discs at 0, 1, 2.5 and 4 m from a blast of J0 = 10 N s, R = 3 m: each body's momentum change
// is J0 (1 - r / R) outward; the one at the centre (no direction) and the one beyond R get
// nothing; a second apply() does nothing.
TEST(EffectorExplosion, impulses_fall_linearly_with_distance) {
  World world(zeroGravity());
  const Vec2f center{1.0f, 2.0f};
  const std::vector<Vec2f> offsets{{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, -2.5f}, {4.0f, 0.0f}, {1.5f, 1.5f}};
  std::vector<BodyId> discs;
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    discs.push_back(addDisc(world, center + offsets[i], 0.2f, 1.0f + static_cast<float>(i)));
  }
  Explosion blast({center, 3.0f, 10.0f});
  EXPECT_FALSE(blast.fired());
  blast.apply(world, dt);
  EXPECT_TRUE(blast.fired());
  blast.apply(world, dt); // nothing more
  for (std::size_t i = 0; i < discs.size(); ++i) {
    const float r = length(offsets[i]);
    const Vec2f expected = r > 0.0f && r < 3.0f ? offsets[i] * (10.0f * (1.0f - r / 3.0f) / r) : Vec2f{};
    const Vec2f momentum = world.linearVelocity(discs[i]) * world.mass(discs[i]);
    EXPECT_NEAR(momentum.x, expected.x, 1e-5f) << i;
    EXPECT_NEAR(momentum.y, expected.y, 1e-5f) << i;
    EXPECT_EQ(world.angularVelocity(discs[i]), 0.0f);
  }
  blast.rearm();
  blast.apply(world, dt);
  EXPECT_NEAR(world.linearVelocity(discs[1]).x * world.mass(discs[1]), 2.0f * 10.0f * (2.0f / 3.0f), 1e-5f);
}

// ---------------------------------------------------------------------------------------------
// Bad input.

TEST(EffectorSettings, bad_input_names_the_field) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  expectErrorField([&] { GravityField({{nan, 0.0f}, {}}); }, "acceleration.x");
  expectErrorField([&] { GravityField({{}, AABB{{1.0f, 0.0f}, {0.0f, 1.0f}}}); }, "region.upper.x");
  expectErrorField([&] { PointAttractor({{}, nan, 0.0f, {}}); }, "mu");
  expectErrorField([&] { PointAttractor({{}, 1.0f, -1.0f, {}}); }, "softening");
  expectErrorField([&] { PointAttractor({{}, 1.0f, 0.0f, 0.0f}); }, "maxRadius");
  expectErrorField([&] { WindDrag({{}, {}, -1.0f, 1.0f, 0.0f, {}}); }, "airDensity");
  expectErrorField([&] { WindDrag({{}, {}, 1.2f, nan, 0.0f, {}}); }, "dragArea");
  expectErrorField([&] { WindDrag({{}, {}, 1.2f, 1.0f, -0.1f, {}}); }, "linearDrag");
  expectErrorField([&] { WindDrag({{}, {0.0f, nan}, 1.2f, 1.0f, 0.0f, {}}); }, "airVelocity.y");
  expectErrorField([&] { Thruster({{}, {}, {0.0f, 0.0f}, 1.0f}); }, "localDirection");
  expectErrorField([&] { Thruster({{}, {}, {1.0f, 0.0f}, nan}); }, "thrust");
  expectErrorField([&] { Thruster({{}, {}, {1.0f, 0.0f}, 1.0f}).setThrust(nan); }, "thrust");
  expectErrorField([&] { SpringDamper({{}, {}, {}, {}, -1.0f, 0.0f, 1.0f}); }, "stiffness");
  expectErrorField([&] { SpringDamper({{}, {}, {}, {}, 1.0f, -1.0f, 1.0f}); }, "damping");
  expectErrorField([&] { SpringDamper({{}, {}, {}, {}, 1.0f, 0.0f, nan}); }, "restLength");
  expectErrorField([&] { Explosion({{}, 0.0f, 1.0f}); }, "radius");
  expectErrorField([&] { Explosion({{}, 1.0f, -1.0f}); }, "impulse");
  BuoyancySettings water;
  water.fluidDensity = -1.0f;
  expectErrorField([&] { Buoyancy{water}; }, "fluidDensity");
  water = {};
  water.surfaceHeight = nan;
  expectErrorField([&] { Buoyancy{water}; }, "surfaceHeight");
  water = {};
  water.xMin = 1.0f;
  water.xMax = 0.0f;
  expectErrorField([&] { Buoyancy{water}; }, "xMax");
  water = {};
  water.angularDrag = -1.0f;
  expectErrorField([&] { Buoyancy{water}; }, "angularDrag");

  // Ids and steps are checked when applied.
  World world;
  Thruster orphan({{}, {}, {1.0f, 0.0f}, 1.0f});
  expectErrorField([&] { orphan.apply(world, dt); }, "body");
  const BodyId disc = addDisc(world, {}, 0.5f);
  SpringDamper spring({disc, {}, BodyId{7, 1}, {}, 1.0f, 0.0f, 1.0f});
  expectErrorField([&] { spring.apply(world, dt); }, "bodyB");
  expectErrorField([&] { Buoyancy(BuoyancySettings{}).apply(world, 0.0f); }, "dt");
}

} // namespace
} // namespace impetus::rigid2d

namespace impetus::rigid2d {
namespace {

// An unsoftened attractor does not blow up on a body at (almost) its centre: the pull there is
// skipped instead of reaching the world as an infinite force.
TEST(EffectorAttractor, unsoftened_pull_at_the_centre_stays_finite) {
  WorldDef def;
  def.gravity = {};
  World world(def);
  BodyDef body;
  body.type = BodyType::dynamicBody;
  body.position = {1e-20f, 0.0f};
  const BodyId b = world.createBody(body);
  world.createShape(b, {}, Circle{{}, 0.1f});
  PointAttractorSettings settings;
  settings.center = {};
  settings.mu = 1000.0f;
  settings.softening = 0.0f;
  PointAttractor attractor(settings);
  for (int i = 0; i < 10; ++i) {
    EXPECT_NO_THROW(attractor.apply(world, 1.0f / 60.0f));
    world.step(1.0f / 60.0f);
  }
  EXPECT_TRUE(std::isfinite(world.position(b).x));
  EXPECT_TRUE(std::isfinite(world.linearVelocity(b).x));
}

} // namespace
} // namespace impetus::rigid2d
