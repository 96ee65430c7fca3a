// The bridge from the engines to audio (impetus/bridges/audio_motion.hpp): a falling body's and
// a thrown particle's motion as a sound source, against free fall's closed form.
#include <impetus/bridges/audio_motion.hpp>

#include <gtest/gtest.h>

namespace impetus::audio {
namespace {

TEST(AudioMotion, a_falling_body_sounds_where_it_is_with_its_velocity) {
  rigid2d::World world; // gravity -10 m/s^2
  rigid2d::BodyDef def;
  def.type = rigid2d::BodyType::dynamicBody;
  def.position = {3.0f, 100.0f};
  const rigid2d::BodyId body = world.createBody(def);
  world.createShape(body, {}, rigid2d::Circle{{}, 0.5f});
  for (int i = 0; i < 60; ++i) {
    world.step(1.0f / 60.0f);
  }
  const Motion m = motionOf(world, body, -2.0);
  EXPECT_NEAR(m.velocity.y, -10.0, 1e-3); // v = -g t after 1 s
  EXPECT_DOUBLE_EQ(m.velocity.x, 0.0);
  EXPECT_DOUBLE_EQ(m.velocity.z, 0.0); // the 2D world's plane
  EXPECT_DOUBLE_EQ(m.position.x, 3.0);
  EXPECT_NEAR(m.position.y, 95.0, 0.1); // 100 - g t^2 / 2, less semi-implicit Euler's g h t / 2
  EXPECT_DOUBLE_EQ(m.position.z, -2.0);
}

TEST(AudioMotion, a_particle_sounds_where_it_is_with_its_velocity) {
  ParticleWorld world;
  ParticleDef def;
  def.position = {1.0f, 2.0f, 3.0f};
  def.velocity = {4.0f, 5.0f, 6.0f};
  const ParticleId particle = world.createParticle(def);
  for (int i = 0; i < 30; ++i) {
    world.step(1.0f / 60.0f);
  }
  const Motion m = motionOf(world, particle);
  // Thrown without drag: v = v0 + g t after 0.5 s (g = -9.81 m/s^2 in y).
  EXPECT_NEAR(m.velocity.x, 4.0, 1e-5);
  EXPECT_NEAR(m.velocity.y, 5.0 - 9.81 * 0.5, 1e-4);
  EXPECT_NEAR(m.velocity.z, 6.0, 1e-5);
  EXPECT_NEAR(m.position.x, 1.0 + 4.0 * 0.5, 1e-4);
  EXPECT_NEAR(m.position.z, 3.0 + 6.0 * 0.5, 1e-4);
}

} // namespace
} // namespace impetus::audio
