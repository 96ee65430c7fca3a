#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/mechanics/explosion.hpp>

#include <gtest/gtest.h>

namespace impetus {
namespace {

TEST(Explosion, same_seed_gives_the_same_explosion) {
  ExplosionSettings s;
  s.seed = 42;
  const KinematicExplosion a(s);
  const KinematicExplosion b(s);
  s.seed = 43;
  const KinematicExplosion c(s);
  ASSERT_EQ(a.particles().size(), 50U);
  bool anyDifferent = false;
  for (std::size_t i = 0; i < a.particles().size(); ++i) {
    EXPECT_EQ(a.particles()[i].velocity, b.particles()[i].velocity);
    EXPECT_EQ(a.particles()[i].life, b.particles()[i].life);
    anyDifferent = anyDifferent || !(a.particles()[i].velocity == c.particles()[i].velocity);
  }
  EXPECT_TRUE(anyDifferent);
}

TEST(Explosion, particles_follow_the_books_distributions) {
  ExplosionSettings s;
  s.speed = 20.0;
  s.life = 3.0;
  s.direction = pi<double> / 2; // up
  s.count = 2000;
  const KinematicExplosion e(s);
  double lowest = 1e9;
  double highest = 0.0;
  for (const ExplosionParticle& p : e.particles()) {
    const double speed = length(p.velocity);
    EXPECT_GE(speed, 10.0 - 1e-12);
    EXPECT_LE(speed, 20.0 + 1e-12);
    EXPECT_GE(p.life, 0.8 * 3.0 - 1e-12);
    EXPECT_LE(p.life, 3.0 + 1e-12);
    const double angle = std::atan2(p.velocity.y, p.velocity.x);
    EXPECT_LE(std::abs(angle - pi<double> / 2), s.spread + 1e-12);
    lowest = std::min(lowest, speed);
    highest = std::max(highest, speed);
  }
  // 2000 uniform draws cover the range: the gaps at the ends are ~1/2000 of it.
  EXPECT_LT(lowest, 10.1);
  EXPECT_GT(highest, 19.9);
}

TEST(Explosion, motion_is_ballistic_and_fades_linearly) {
  ExplosionSettings s;
  s.origin = {3.0, 4.0};
  s.gravity = -9.81;
  const KinematicExplosion e(s);
  const ExplosionParticle& p = e.particles()[7];
  const double t = 0.4 * p.life;
  const double h = 1e-3;
  const Vec2d x0 = e.particleAt(7, t - h).position;
  const Vec2d x1 = e.particleAt(7, t).position;
  const Vec2d x2 = e.particleAt(7, t + h).position;
  // The second difference of a parabola is exact: the acceleration is gravity, straight down.
  const Vec2d accel = (x2 - x1 * 2.0 + x0) / (h * h);
  EXPECT_NEAR(accel.x, 0.0, 1e-6);
  EXPECT_NEAR(accel.y, -9.81, 1e-6);
  EXPECT_EQ(e.particleAt(7, 0.0).position, s.origin);
  EXPECT_NEAR(e.particleAt(7, t).fade, 0.6, 1e-12);
  EXPECT_FALSE(e.particleAt(7, p.life).alive);
  EXPECT_EQ(e.particleAt(7, p.life).fade, 0.0);
}

TEST(Explosion, ends_when_the_last_particle_dies) {
  const KinematicExplosion e(ExplosionSettings{});
  EXPECT_EQ(e.aliveCount(0.0), 50U);
  EXPECT_GT(e.aliveCount(e.endTime() * 0.99), 0U);
  EXPECT_EQ(e.aliveCount(e.endTime()), 0U);
  EXPECT_LE(e.endTime(), 2.0);
}

TEST(Explosion, bad_input_names_the_field) {
  const auto field = [](ExplosionSettings s) {
    try {
      (void)KinematicExplosion(s);
    } catch (const Error& e) {
      return e.field();
    }
    return std::string("no error");
  };
  ExplosionSettings s;
  s.count = 0;
  EXPECT_EQ(field(s), "count");
  s = {};
  s.speed = -1.0;
  EXPECT_EQ(field(s), "speed");
  s = {};
  s.life = 0.0;
  EXPECT_EQ(field(s), "life");
  s = {};
  s.direction = std::nan("");
  EXPECT_EQ(field(s), "direction");
}

} // namespace
} // namespace impetus
