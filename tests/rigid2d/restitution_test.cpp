// Restitution of the soft-step solver against Newton's law of restitution: a box landing flat
// rebounds to e^2 h without turning, two boxes meeting face to face leave with the 1D
// collision's velocities, whatever their rotational inertia, and a row of touching boxes struck
// at one end passes the impulse to the other (Newton's cradle). A two-point manifold's normal
// rows bounce as a block; one point after the other, the first point's impulse turned the body
// and the second's left it spinning.
#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/world.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace impetus::rigid2d {
namespace {

/// A frictionless dynamic box (half extents, m) that never sleeps.
BodyId addFrictionlessBox(World& world, const Vec2f& position, float halfWidth, float halfHeight, float restitution,
                          float density = 1.0f) {
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = position;
  def.enableSleep = false;
  const BodyId body = world.createBody(def);
  ShapeDef shape;
  shape.friction = 0.0f;
  shape.restitution = restitution;
  shape.density = density;
  world.createShape(body, shape, makeBox(halfWidth, halfHeight));
  return body;
}

struct Rebound {
  float speed = 0.0f;   ///< speed it left the floor at (from the step that bounced: v^2 + 2 g y), m/s
  float apex = 0.0f;    ///< highest the box's bottom rose after the bounce, m
  float maxSpin = 0.0f; ///< largest |angular velocity| seen, rad/s
};

/// Drops a 1 m x 0.4 m box flat onto a frictionless floor from `height` (its bottom, m) and
/// follows it to the apex of its first rebound.
Rebound dropFlatBox(float restitution, float height, float stepRate) {
  World world;
  const BodyId ground = world.createBody({});
  ShapeDef floor;
  floor.friction = 0.0f;
  world.createShape(ground, floor, makeOffsetBox(20.0f, 0.5f, {0.0f, -0.5f}, 0.0f)); // top at y = 0
  const float halfHeight = 0.2f;
  const BodyId box = addFrictionlessBox(world, {0.0f, height + halfHeight}, 0.5f, halfHeight, restitution);
  Rebound r;
  const float dt = 1.0f / stepRate;
  for (int i = 0; i < static_cast<int>(5.0f * stepRate); ++i) {
    world.step(dt);
    const float vy = world.linearVelocity(box).y;
    r.maxSpin = std::max(r.maxSpin, std::abs(world.angularVelocity(box)));
    if (vy > 0.0f && r.speed == 0.0f) {
      // The bounce happens within the step and gravity slows the box for the rest of it: its
      // energy gives the speed it left the floor at.
      r.speed = std::sqrt(vy * vy + 2.0f * 10.0f * (world.position(box).y - halfHeight));
    }
    if (r.speed > 0.0f) {
      r.apex = std::max(r.apex, world.position(box).y - halfHeight);
      if (vy < 0.0f) {
        break;
      }
    }
  }
  return r;
}

TEST(Restitution2D, a_box_dropped_flat_rebounds_to_e_squared_h_without_spin) {
  const float h = 2.0f;
  const float impactSpeed = std::sqrt(2.0f * 10.0f * h);
  for (const float rate : {60.0f, 240.0f}) {
    for (const float e : {0.5f, 0.8f, 1.0f}) {
      const Rebound r = dropFlatBox(e, h, rate);
      const auto label = [&] { return testing::Message() << rate << " Hz, e = " << e; };
      // Newton's law: the box leaves at e times the impact speed sqrt(2 g h). 1%: the approach is
      // measured at the start of the impact's substep, up to a substep's gravity (g dt / 4)
      // before contact.
      EXPECT_NEAR(r.speed, e * impactSpeed, 0.01f * e * impactSpeed) << label();
      // A flat landing gives both corners the same impulse: no turn. (One point after the other,
      // it turned at 3 rad/s.)
      EXPECT_LT(r.maxSpin, 1e-3f) << label();
      if (e >= 0.8f) {
        // And it rises to e^2 h, within 2%: the apex is sampled once a step, the rebound starts
        // from the soft contact's depth, and semi-implicit Euler's apex lies u dt / 2 below the
        // parabola's (at e = 0.5 and 60 Hz, 2.6 cm of 0.5 m: the integrator's, not the bounce's).
        EXPECT_NEAR(r.apex, e * e * h, 0.02f * e * e * h) << label();
      }
    }
  }
}

struct HeadOn {
  float vA = 0.0f, vB = 0.0f; ///< velocities along the line of centres after, m/s
  float spin = 0.0f;          ///< largest |angular velocity| of either box after, rad/s
  float energyBefore = 0.0f, energyAfter = 0.0f;
};

/// Two frictionless boxes without gravity, A at `speed` towards B at rest, face to face (their
/// contact faces 2 halfHeight tall, so the manifold has two points). halfHeight sets the
/// rotational inertia; densityB / densityA the mass ratio.
HeadOn collideHeadOn(float restitution, float halfHeight, float densityA, float densityB, float speed) {
  WorldDef def;
  def.gravity = {0.0f, 0.0f};
  World world(def);
  const float halfWidth = 0.5f;
  const BodyId a = addFrictionlessBox(world, {-2.0f, 0.0f}, halfWidth, halfHeight, restitution, densityA);
  const BodyId b = addFrictionlessBox(world, {0.0f, 0.0f}, halfWidth, halfHeight, restitution, densityB);
  world.setLinearVelocity(a, {speed, 0.0f});
  HeadOn r;
  const auto energy = [&] {
    float e = 0.0f;
    for (const BodyId id : {a, b}) {
      const Vec2f v = world.linearVelocity(id);
      const float w = world.angularVelocity(id);
      e += 0.5f * world.mass(id) * dot(v, v) + 0.5f * world.rotationalInertia(id) * w * w;
    }
    return e;
  };
  r.energyBefore = energy();
  for (int i = 0; i < 60; ++i) { // 1 s: contact after about 0.2 s, apart again soon after
    world.step(1.0f / 60.0f);
  }
  r.vA = world.linearVelocity(a).x;
  r.vB = world.linearVelocity(b).x;
  r.spin = std::max(std::abs(world.angularVelocity(a)), std::abs(world.angularVelocity(b)));
  r.energyAfter = energy();
  return r;
}

TEST(Restitution2D, boxes_meeting_face_to_face_leave_with_the_1d_collision_velocities_for_any_inertia) {
  const float speed = 5.0f;
  // Rotational inertia from a flat plank to a tall block: the faces meet over 0.2 m to 4 m.
  for (const float halfHeight : {0.1f, 0.5f, 2.0f}) {
    for (const float massRatio : {1.0f, 3.0f}) { // mB / mA
      for (const float e : {1.0f, 0.6f}) {
        const HeadOn r = collideHeadOn(e, halfHeight, 1.0f, massRatio, speed);
        // The 1D formula: vA' = (mA - e mB) v / (mA + mB), vB' = (1 + e) mA v / (mA + mB).
        const float vA = (1.0f - e * massRatio) * speed / (1.0f + massRatio);
        const float vB = (1.0f + e) * speed / (1.0f + massRatio);
        const auto label = [&] {
          return testing::Message() << "half height " << halfHeight << ", mB/mA " << massRatio << ", e " << e;
        };
        EXPECT_NEAR(r.vA, vA, 0.01f * speed) << label();
        EXPECT_NEAR(r.vB, vB, 0.01f * speed) << label();
        EXPECT_LT(r.spin, 1e-3f) << label();
        if (e == 1.0f) {
          EXPECT_NEAR(r.energyAfter, r.energyBefore, 0.01f * r.energyBefore) << label();
        }
      }
    }
  }
}

/// A row of `count` frictionless 1 m boxes along x without gravity, `gap` (m) apart; the first
/// `strikers` of them, touching one another, move at `speed` towards the rest, which lie still.
/// `reversed` makes the bodies in the opposite order (so the contacts are met in the opposite
/// order by the solver). Returns each box's velocity along x after 2 s.
std::vector<float> strikeRow(int count, int strikers, float gap, bool reversed, float stepRate, float speed) {
  WorldDef def;
  def.gravity = {0.0f, 0.0f};
  World world(def);
  std::vector<BodyId> boxes(static_cast<std::size_t>(count));
  for (int j = 0; j < count; ++j) {
    const int i = reversed ? count - 1 - j : j;
    const float x = (1.0f + gap) * static_cast<float>(i) - (i < strikers ? 1.0f : 0.0f);
    boxes[static_cast<std::size_t>(i)] = addFrictionlessBox(world, {x, 0.0f}, 0.5f, 0.5f, 1.0f);
    if (i < strikers) {
      world.setLinearVelocity(boxes[static_cast<std::size_t>(i)], {speed, 0.0f});
    }
  }
  for (int k = 0; k < static_cast<int>(2.0f * stepRate); ++k) {
    world.step(1.0f / stepRate);
  }
  std::vector<float> v;
  for (const BodyId b : boxes) {
    v.push_back(world.linearVelocity(b).x);
  }
  return v;
}

TEST(Restitution2D, a_row_of_touching_boxes_passes_the_impulse_to_the_last_as_newtons_cradle) {
  // Each contact bounces when its approach is met, not once for the whole row: an elastic impact
  // between equal masses swaps their velocities, so k strikers set the last k boxes moving at
  // their speed and leave the rest at rest. Solved as one simultaneous problem instead, the row
  // took the momentum together (the first box bounced back at half the speed, and 12% of the
  // energy went). Within 2% of the speed at 240 Hz and 4% at 60 Hz: the strikers overlap the row
  // by up to a substep's travel (8 mm at 60 Hz) before the bounce, and the soft contact pushing
  // that overlap out trades a little momentum between neighbours.
  const float speed = 2.0f;
  const int count = 6;
  for (const float rate : {60.0f, 240.0f}) {
    for (const float gap : {0.0f, 0.001f, 0.02f}) {
      for (const int strikers : {1, 2, 3}) {
        for (const bool reversed : {false, true}) {
          const std::vector<float> v = strikeRow(count, strikers, gap, reversed, rate, speed);
          const float tolerance = (rate < 100.0f ? 0.04f : 0.02f) * speed;
          for (int i = 0; i < count; ++i) {
            const float expected = i >= count - strikers ? speed : 0.0f;
            EXPECT_NEAR(v[static_cast<std::size_t>(i)], expected, tolerance)
                << "box " << i << ", " << strikers << " strikers, gap " << gap << " m, " << rate << " Hz"
                << (reversed ? ", made in reverse" : "");
          }
        }
      }
    }
  }
}

TEST(Restitution2D, a_box_landing_on_one_corner_still_turns) {
  // The block only couples the two rows: a tilted box that lands on one corner is pushed at that
  // corner alone and must turn (its angular momentum about the corner is conserved through the
  // impact, so it cannot stay at zero).
  World world;
  const BodyId ground = world.createBody({});
  world.createShape(ground, {}, makeOffsetBox(20.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = {0.0f, 2.0f};
  def.angle = 0.3f;
  def.enableSleep = false;
  const BodyId box = world.createBody(def);
  ShapeDef shape;
  shape.restitution = 0.8f;
  shape.friction = 0.0f;
  world.createShape(box, shape, makeBox(0.5f, 0.2f));
  float maxSpin = 0.0f;
  for (int i = 0; i < 60; ++i) {
    world.step(1.0f / 60.0f);
    maxSpin = std::max(maxSpin, std::abs(world.angularVelocity(box)));
  }
  EXPECT_GT(maxSpin, 1.0f);
}

} // namespace
} // namespace impetus::rigid2d
