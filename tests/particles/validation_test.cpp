// The input validation audit of the particle world (docs/reliability.md, "Input validation"):
// settings, particles, obstacles, springs, constraints, attractors, emitters, ropes and cloths
// refuse NaN, infinity, negative and degenerate values with an impetus::Error naming the field
// and showing the value; the boundary values that are valid are accepted.
#include "support/validation_table.hpp"

#include <impetus/particles/cloth.hpp>
#include <impetus/particles/particle_world.hpp>
#include <impetus/particles/rope.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace impetus {
namespace {

using impetus::testing::expectAccepted;
using impetus::testing::expectRejected;
using impetus::testing::inff;
using impetus::testing::nanf;

/// A world with two particles and one destroyed particle.
struct Fixture {
  ParticleWorld world;
  ParticleId a;
  ParticleId b;
  ParticleId gone;

  Fixture() {
    a = world.createParticle({});
    ParticleDef def;
    def.position = {1.0f, 0.0f, 0.0f};
    b = world.createParticle(def);
    gone = world.createParticle(def);
    world.destroyParticle(gone);
  }
};

/// Runs `f` on a fresh fixture.
template <class F> std::function<void()> on(F f) {
  return [f] {
    Fixture x;
    f(x);
  };
}

/// The smallest float, as the messages show it: shared among particles it rounds to 0 kg.
const std::string tiny = formatValue(static_cast<double>(std::numeric_limits<float>::denorm_min()));

/// A default value with one change.
template <class S, class F> S with(F change) {
  S s{};
  change(s);
  return s;
}

TEST(ParticleValidation, world_settings_and_step) {
  const auto settings = [](auto change) { return [change] { ParticleWorld w(with<ParticleWorldSettings>(change)); }; };
  const auto setSettings = [](auto change) {
    return on([change](Fixture& x) { x.world.setSettings(with<ParticleWorldSettings>(change)); });
  };
  expectRejected({
      {"gravity.x", "nan", settings([](ParticleWorldSettings& s) { s.gravity.x = nanf; })},
      {"wind.z", "inf", settings([](ParticleWorldSettings& s) { s.wind.z = inff; })},
      {"substeps", "0", settings([](ParticleWorldSettings& s) { s.substeps = 0; })},
      {"substeps", "1001", setSettings([](ParticleWorldSettings& s) { s.substeps = 1001; })},
      {"constraintIterations", "0", settings([](ParticleWorldSettings& s) { s.constraintIterations = 0; })},
      {"linearDrag", "-1", settings([](ParticleWorldSettings& s) { s.linearDrag = -1.0f; })},
      {"dragCoefficient", "nan", settings([](ParticleWorldSettings& s) { s.dragCoefficient = nanf; })},
      {"airDensity", "-1", setSettings([](ParticleWorldSettings& s) { s.airDensity = -1.0f; })},
      {"restThreshold", "inf", settings([](ParticleWorldSettings& s) { s.restThreshold = inff; })},
      {"particleRestitution", "1.5", settings([](ParticleWorldSettings& s) { s.particleRestitution = 1.5f; })},
      {"particleRestitution", "nan", settings([](ParticleWorldSettings& s) { s.particleRestitution = nanf; })},
      {"integrator", "9",
       settings([](ParticleWorldSettings& s) { s.integrator = static_cast<ParticleIntegrator>(9); })},
      {"dt", "0", on([](Fixture& x) { x.world.step(0.0f); })},
      {"dt", "-1", on([](Fixture& x) { x.world.step(-1.0f); })},
      {"dt", "nan", on([](Fixture& x) { x.world.step(nanf); })},
      {"dt", "2", on([](Fixture& x) { x.world.step(2.0f); })},
  });
  expectAccepted({
      {"zero drag, restitution 0 and 1, one substep, dt 1",
       [] {
         ParticleWorldSettings s;
         s.substeps = s.constraintIterations = 1;
         s.linearDrag = s.dragCoefficient = s.airDensity = s.restThreshold = 0.0f;
         s.particleRestitution = 0.0f;
         ParticleWorld w(s);
         s.particleRestitution = 1.0f;
         w.setSettings(s);
         w.step(1.0f);
       }},
  });
}

TEST(ParticleValidation, particles_and_setters) {
  const auto particle = [](auto change) {
    return on([change](Fixture& x) { x.world.createParticle(with<ParticleDef>(change)); });
  };
  expectRejected({
      {"position.x", "nan", particle([](ParticleDef& d) { d.position.x = nanf; })},
      {"velocity.y", "inf", particle([](ParticleDef& d) { d.velocity.y = inff; })},
      {"mass", "0", particle([](ParticleDef& d) { d.mass = 0.0f; })},
      {"mass", "-1", particle([](ParticleDef& d) { d.mass = -1.0f; })},
      {"mass", "nan", particle([](ParticleDef& d) { d.mass = nanf; })},
      {"radius", "0", particle([](ParticleDef& d) { d.radius = 0.0f; })},
      {"radius", "inf", particle([](ParticleDef& d) { d.radius = inff; })},
      {"lifetime", "0", particle([](ParticleDef& d) { d.lifetime = 0.0f; })},
      {"lifetime", "-1", particle([](ParticleDef& d) { d.lifetime = -1.0f; })},
      {"lifetime", "nan", particle([](ParticleDef& d) { d.lifetime = nanf; })},
      {"position.z", "nan", on([](Fixture& x) {
         x.world.setPosition(x.a, {0.0f, 0.0f, nanf});
       })},
      {"velocity.x", "inf", on([](Fixture& x) {
         x.world.setVelocity(x.a, {inff, 0.0f, 0.0f});
       })},
      {"force.y", "nan", on([](Fixture& x) {
         x.world.applyForce(x.a, {0.0f, nanf, 0.0f});
       })},
      {"impulse.x", "-inf", on([](Fixture& x) {
         x.world.applyImpulse(x.a, {-inff, 0.0f, 0.0f});
       })},
      {"particle id", "2", on([](Fixture& x) { x.world.setPosition(x.gone, {}); })},
      {"particle id", "2", on([](Fixture& x) { x.world.setPinned(x.gone, true); })},
      {"particle id", "2", on([](Fixture& x) { x.world.destroyParticle(x.gone); })},
      {"particle id", "0", on([](Fixture& x) { (void)x.world.position(ParticleId{}); })},
  });
  expectAccepted({
      {"an infinite lifetime, a pinned particle, zero velocity and force", on([](Fixture& x) {
         ParticleDef d;
         d.pinned = true;
         d.lifetime = infiniteLifetime;
         const ParticleId p = x.world.createParticle(d);
         x.world.applyForce(p, {});
         x.world.applyImpulse(p, {1.0f, 0.0f, 0.0f});
         x.world.step(0.1f);
       })},
  });
}

TEST(ParticleValidation, obstacles) {
  const auto add = [](auto shape, SurfaceMaterial material = {}) {
    return on([shape, material](Fixture& x) { x.world.addObstacle(shape, material); });
  };
  expectRejected({
      {"normal.x", "nan", add(PlaneObstacle{{nanf, 1.0f, 0.0f}, 0.0f})},
      {"normal", "0", add(PlaneObstacle{{0.0f, 0.0f, 0.0f}, 0.0f})},
      {"offset", "inf", add(PlaneObstacle{{0.0f, 1.0f, 0.0f}, inff})},
      {"center.y", "nan", add(SphereObstacle{{0.0f, nanf, 0.0f}, 1.0f})},
      {"radius", "0", add(SphereObstacle{{}, 0.0f})},
      {"radius", "-1", add(SphereObstacle{{}, -1.0f})},
      {"center.z", "inf", add(BoxObstacle{{0.0f, 0.0f, inff}})},
      {"halfExtents.x", "0", add(BoxObstacle{{}, {0.0f, 1.0f, 1.0f}})},
      {"halfExtents.y", "-1", add(BoxObstacle{{}, {1.0f, -1.0f, 1.0f}})},
      {"halfExtents.z", "nan", add(BoxObstacle{{}, {1.0f, 1.0f, nanf}})},
      {"rotation", "0", add(BoxObstacle{{}, {1.0f, 1.0f, 1.0f}, Quatf{0.0f, 0.0f, 0.0f, 0.0f}})},
      {"rotation", "nan", add(BoxObstacle{{}, {1.0f, 1.0f, 1.0f}, Quatf{nanf, 0.0f, 0.0f, 1.0f}})},
      {"pointA.x", "nan", add(CapsuleObstacle{{nanf, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.5f})},
      {"pointB.y", "inf", add(CapsuleObstacle{{}, {1.0f, inff, 0.0f}, 0.5f})},
      {"radius", "0", add(CapsuleObstacle{{}, {1.0f, 0.0f, 0.0f}, 0.0f})},
      {"restitution", "1.5", add(SphereObstacle{}, SurfaceMaterial{1.5f, 0.0f})},
      {"restitution", "nan", add(SphereObstacle{}, SurfaceMaterial{nanf, 0.0f})},
      {"friction", "-1", add(SphereObstacle{}, SurfaceMaterial{0.5f, -1.0f})},
      {"friction", "inf", add(SphereObstacle{}, SurfaceMaterial{0.5f, inff})},
      {"obstacle id", "0", on([](Fixture& x) {
         const ObstacleId id = x.world.addObstacle(SphereObstacle{});
         x.world.removeObstacle(id);
         x.world.removeObstacle(id);
       })},
  });
  expectAccepted({
      {"a capsule with coincident ends (a sphere), restitution 0 and 1, no friction", on([](Fixture& x) {
         x.world.addObstacle(CapsuleObstacle{{}, {}, 0.5f}, {1.0f, 0.0f});
         x.world.addObstacle(PlaneObstacle{{0.0f, 3.0f, 0.0f}, -2.0f}, {0.0f, 0.0f});
         x.world.step(0.1f);
       })},
  });
}

TEST(ParticleValidation, springs_and_constraints) {
  const auto spring = [](auto change) {
    return on([change](Fixture& x) {
      SpringDef d;
      d.a = x.a;
      d.b = x.b;
      change(x, d);
      x.world.addSpring(d);
    });
  };
  const auto constraint = [](auto change) {
    return on([change](Fixture& x) {
      DistanceConstraintDef d;
      d.a = x.a;
      d.b = x.b;
      change(x, d);
      x.world.addDistanceConstraint(d);
    });
  };
  expectRejected({
      {"particle id", "2", spring([](Fixture& x, SpringDef& d) { d.a = x.gone; })},
      {"particle id", "2", spring([](Fixture& x, SpringDef& d) { d.b = x.gone; })},
      {"b", "0", spring([](Fixture& x, SpringDef& d) { d.b = x.a; })},
      {"anchor.x", "nan", spring([](Fixture&, SpringDef& d) {
         d.b = {};
         d.anchor.x = nanf;
       })},
      {"stiffness", "-1", spring([](Fixture&, SpringDef& d) { d.stiffness = -1.0f; })},
      {"stiffness", "inf", spring([](Fixture&, SpringDef& d) { d.stiffness = inff; })},
      {"damping", "nan", spring([](Fixture&, SpringDef& d) { d.damping = nanf; })},
      {"restLength", "nan", spring([](Fixture&, SpringDef& d) { d.restLength = nanf; })},
      {"restLength", "inf", spring([](Fixture&, SpringDef& d) { d.restLength = inff; })},
      {"particle id", "2", constraint([](Fixture& x, DistanceConstraintDef& d) { d.b = x.gone; })},
      {"b", "0", constraint([](Fixture& x, DistanceConstraintDef& d) { d.b = x.a; })},
      {"anchor.z", "inf", constraint([](Fixture&, DistanceConstraintDef& d) {
         d.b = {};
         d.anchor.z = inff;
       })},
      {"compliance", "-1", constraint([](Fixture&, DistanceConstraintDef& d) { d.compliance = -1.0f; })},
      {"compliance", "nan", constraint([](Fixture&, DistanceConstraintDef& d) { d.compliance = nanf; })},
      {"length", "nan", constraint([](Fixture&, DistanceConstraintDef& d) { d.length = nanf; })},
      {"length", "inf", constraint([](Fixture&, DistanceConstraintDef& d) { d.length = inff; })},
      {"spring id", "0", on([](Fixture& x) {
         const SpringId id = x.world.addSpring({x.a, x.b, {}});
         x.world.removeSpring(id);
         x.world.removeSpring(id);
       })},
      {"constraint id", "0", on([](Fixture& x) {
         const ConstraintId id = x.world.addDistanceConstraint({x.a, x.b, {}});
         x.world.removeDistanceConstraint(id);
         x.world.removeDistanceConstraint(id);
       })},
  });
  expectAccepted({
      {"zero stiffness, damping, rest length and compliance; an anchored end", on([](Fixture& x) {
         SpringDef s;
         s.a = x.a;
         s.b = x.b;
         s.stiffness = s.damping = s.restLength = 0.0f;
         x.world.addSpring(s);
         DistanceConstraintDef c;
         c.a = x.a;
         c.anchor = {0.0f, 1.0f, 0.0f};
         c.length = 0.0f;
         x.world.addDistanceConstraint(c);
         x.world.step(0.1f);
       })},
  });
}

// A constraint so compliant that compliance / h^2 overflows a float exerts no force: it used to
// turn both particles into NaN (infinity times a zero multiplier) on the first step.
TEST(ParticleValidation, an_overflowing_compliance_does_not_produce_nan) {
  Fixture x;
  DistanceConstraintDef c;
  c.a = x.a;
  c.b = x.b;
  c.length = 0.5f;
  c.compliance = 3.0e38f;
  x.world.addDistanceConstraint(c);
  x.world.step(1.0f / 60.0f);
  EXPECT_TRUE(isFinite(x.world.position(x.a)));
  EXPECT_TRUE(isFinite(x.world.position(x.b)));
}

TEST(ParticleValidation, attractors_and_emitters) {
  const auto emitter = [](auto change) {
    return on([change](Fixture& x) { x.world.addEmitter(with<EmitterDef>(change)); });
  };
  expectRejected({
      {"position.x", "nan", on([](Fixture& x) {
         x.world.addAttractor({{nanf, 0.0f, 0.0f}});
       })},
      {"strength", "inf", on([](Fixture& x) {
         x.world.addAttractor({{}, inff});
       })},
      {"softening", "0", on([](Fixture& x) {
         x.world.addAttractor({{}, 1.0f, 0.0f});
       })},
      {"softening", "-1", on([](Fixture& x) {
         x.world.addAttractor({{}, 1.0f, -1.0f});
       })},
      {"position.y", "inf", emitter([](EmitterDef& d) { d.position.y = inff; })},
      {"direction", "0", emitter([](EmitterDef& d) { d.direction = {}; })},
      {"direction.z", "nan", emitter([](EmitterDef& d) { d.direction.z = nanf; })},
      {"coneAngle", "-1", emitter([](EmitterDef& d) { d.coneAngle = -1.0f; })},
      {"coneAngle", "inf", emitter([](EmitterDef& d) { d.coneAngle = inff; })},
      {"minSpeed", "-1", emitter([](EmitterDef& d) { d.minSpeed = -1.0f; })},
      {"maxSpeed", "0.5", emitter([](EmitterDef& d) { d.maxSpeed = 0.5f; })},
      {"maxSpeed", "inf", emitter([](EmitterDef& d) { d.maxSpeed = inff; })},
      {"rate", "-1", emitter([](EmitterDef& d) { d.rate = -1.0f; })},
      {"rate", "nan", emitter([](EmitterDef& d) { d.rate = nanf; })},
      {"rate", "2e+09", emitter([](EmitterDef& d) { d.rate = 2e9f; })},
      {"burst", "-1", emitter([](EmitterDef& d) { d.burst = -1; })},
      {"burst", "1000001", emitter([](EmitterDef& d) { d.burst = 1'000'001; })},
      {"duration", "-1", emitter([](EmitterDef& d) { d.duration = -1.0f; })},
      {"duration", "nan", emitter([](EmitterDef& d) { d.duration = nanf; })},
      {"minLifetime", "0", emitter([](EmitterDef& d) { d.minLifetime = 0.0f; })},
      {"maxLifetime", "0.5", emitter([](EmitterDef& d) { d.maxLifetime = 0.5f; })},
      {"maxLifetime", "inf", emitter([](EmitterDef& d) { d.maxLifetime = inff; })},
      {"mass", "0", emitter([](EmitterDef& d) { d.mass = 0.0f; })},
      {"radius", "nan", emitter([](EmitterDef& d) { d.radius = nanf; })},
      {"emitter id", "0", on([](Fixture& x) {
         const EmitterId id = x.world.addEmitter({});
         x.world.removeEmitter(id);
         x.world.removeEmitter(id);
       })},
  });
  expectAccepted({
      {"a repelling attractor; a still, single-direction emitter forever", on([](Fixture& x) {
         x.world.addAttractor({{}, -5.0f, 0.1f});
         EmitterDef d;
         d.coneAngle = 0.0f;
         d.minSpeed = d.maxSpeed = 0.0f;
         d.rate = 0.0f;
         d.burst = 1'000;
         d.duration = infiniteLifetime;
         x.world.addEmitter(d);
         x.world.step(0.1f);
       })},
  });
}

TEST(ParticleValidation, ropes) {
  const auto rope = [](auto change) {
    return on([change](Fixture& x) { (void)createRope(x.world, with<RopeDef>(change)); });
  };
  expectRejected({
      {"start.x", "nan", rope([](RopeDef& d) { d.start.x = nanf; })},
      {"end.y", "inf", rope([](RopeDef& d) { d.end.y = inff; })},
      {"end", "0", rope([](RopeDef& d) { d.end = d.start; })},
      {"end", "inf", rope([](RopeDef& d) { // finite ends whose distance overflows
         d.start = {-3e38f, 0.0f, 0.0f};
         d.end = {3e38f, 0.0f, 0.0f};
       })},
      {"segments", "0", rope([](RopeDef& d) { d.segments = 0; })},
      {"segments", "1000001", rope([](RopeDef& d) { d.segments = 1'000'001; })},
      {"totalMass", "0", rope([](RopeDef& d) { d.totalMass = 0.0f; })},
      {"totalMass", "nan", rope([](RopeDef& d) { d.totalMass = nanf; })},
      {"totalMass", tiny,
       rope([](RopeDef& d) { d.totalMass = std::numeric_limits<float>::denorm_min(); })}, // 0 kg each
      {"particleRadius", "-1", rope([](RopeDef& d) { d.particleRadius = -1.0f; })},
      {"compliance", "-1", rope([](RopeDef& d) { d.compliance = -1.0f; })},
      {"stiffness", "0", rope([](RopeDef& d) { d.stiffness = 0.0f; })},
      {"damping", "-1", rope([](RopeDef& d) { d.damping = -1.0f; })},
      {"direction", "0", [] { (void)RopeDef::along({}, {}, 1.0f); }},
      {"direction.x", "nan",
       [] {
         (void)RopeDef::along({}, {nanf, 0.0f, 0.0f}, 1.0f);
       }},
      {"length", "0",
       [] {
         (void)RopeDef::along({}, {1.0f, 0.0f, 0.0f}, 0.0f);
       }},
      {"length", "-1",
       [] {
         (void)RopeDef::along({}, {1.0f, 0.0f, 0.0f}, -1.0f);
       }},
  });
  // A refused rope leaves the world as it was.
  Fixture x;
  RopeDef bad;
  bad.start = {-3e38f, 0.0f, 0.0f};
  bad.end = {3e38f, 0.0f, 0.0f};
  EXPECT_THROW((void)createRope(x.world, bad), Error);
  EXPECT_EQ(x.world.particleCount(), 2U);
  expectAccepted({
      {"one segment, zero compliance and damping", on([](Fixture& f) {
         RopeDef d;
         d.segments = 1;
         d.compliance = d.damping = 0.0f;
         (void)createRope(f.world, d);
       })},
  });
}

TEST(ParticleValidation, cloths) {
  const auto cloth = [](auto change) {
    return on([change](Fixture& x) { (void)createCloth(x.world, with<ClothDef>(change)); });
  };
  expectRejected({
      {"origin.x", "nan", cloth([](ClothDef& d) { d.origin.x = nanf; })},
      {"across.y", "inf", cloth([](ClothDef& d) { d.across.y = inff; })},
      {"down.z", "nan", cloth([](ClothDef& d) { d.down.z = nanf; })},
      {"down", "0", cloth([](ClothDef& d) { d.down = d.across * 2.0f; })}, // parallel
      {"down", "0", cloth([](ClothDef& d) { d.down = {}; })},
      {"across", "inf", cloth([](ClothDef& d) { // finite edges whose corners overflow
         d.origin = {3e38f, 0.0f, 0.0f};
         d.across = {3e38f, 0.0f, 0.0f};
       })},
      {"down", "inf", cloth([](ClothDef& d) {
         d.origin = {0.0f, -3e38f, 0.0f};
         d.down = {0.0f, -3e38f, 0.0f};
       })},
      {"rows", "1", cloth([](ClothDef& d) { d.rows = 1; })},
      {"columns", "10001", cloth([](ClothDef& d) { d.columns = 10'001; })},
      {"totalMass", "0", cloth([](ClothDef& d) { d.totalMass = 0.0f; })},
      {"totalMass", tiny,
       cloth([](ClothDef& d) { d.totalMass = std::numeric_limits<float>::denorm_min(); })}, // 0 kg each
      {"particleRadius", "nan", cloth([](ClothDef& d) { d.particleRadius = nanf; })},
      {"structuralCompliance", "-1", cloth([](ClothDef& d) { d.structuralCompliance = -1.0f; })},
      {"shearCompliance", "inf", cloth([](ClothDef& d) { d.shearCompliance = inff; })},
      {"bendCompliance", "nan", cloth([](ClothDef& d) { d.bendCompliance = nanf; })},
      {"structuralStiffness", "0", cloth([](ClothDef& d) { d.structuralStiffness = 0.0f; })},
      {"shearStiffness", "-1", cloth([](ClothDef& d) { d.shearStiffness = -1.0f; })},
      {"bendStiffness", "inf", cloth([](ClothDef& d) { d.bendStiffness = inff; })},
      {"damping", "-1", cloth([](ClothDef& d) { d.damping = -1.0f; })},
      {"pinned[0].row", "10", cloth([](ClothDef& d) {
         d.pinned = {{10, 0}};
       })},
      {"pinned[1].column", "-1", cloth([](ClothDef& d) {
         d.pinned = {{0, 0}, {0, -1}};
       })},
      {"row", "-1", on([](Fixture& x) { (void)createCloth(x.world, {}).at(-1, 0); })},
      {"column", "10", on([](Fixture& x) { (void)createCloth(x.world, {}).at(0, 10); })},
  });
  expectAccepted({
      {"a 2 x 2 rigid cloth with no damping", on([](Fixture& x) {
         ClothDef d;
         d.rows = d.columns = 2;
         d.structuralCompliance = d.shearCompliance = d.bendCompliance = d.damping = 0.0f;
         (void)createCloth(x.world, d);
       })},
  });
}

} // namespace
} // namespace impetus
