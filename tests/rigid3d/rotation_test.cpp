// Torque-free rotation in the 3D world against the closed forms of Euler's equations (ch. 11-12):
// the precession of a symmetric top, the conservation of energy and angular momentum of an
// asymmetric body, and the intermediate axis flip (Dzhanibekov's nut).
#include <impetus/rigid3d/world.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace impetus::rigid3d {
namespace {

constexpr float dt = 1.0f / 60.0f;

World freeSpace() { return World{WorldDef{{0.0f, 0.0f, 0.0f}}}; }

BodyId spinningBody(World& world, const Vec3f& moments, const Vec3f& spin) {
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.angularVelocity = spin;
  def.massData = MassData{1.0f, {}, Mat33f::diagonal(moments)};
  return world.createBody(def);
}

double angleBetween(const Vec3d& a, const Vec3d& b) { return std::atan2(length(cross(a, b)), dot(a, b)); }

Vec3d toDouble(const Vec3f& v) { return {v.x, v.y, v.z}; }

TEST(Rigid3dRotation, a_symmetric_top_precesses_about_its_angular_momentum_at_L_over_I1) {
  // I = diag(I1, I1, I3), spin w0 = (w1, 0, w3): L = (I1 w1, 0, I3 w3) is fixed in the world and
  // the symmetry axis turns about it at |L| / I1, keeping its angle to L; the spin about the
  // symmetry axis, w3, is constant.
  World world = freeSpace();
  const double i1 = 1.0;
  const double i3 = 1.8;
  const double w1 = 0.8;
  const double w3 = 4.0;
  const BodyId top = spinningBody(world, {1.0f, 1.0f, 1.8f}, {0.8f, 0.0f, 4.0f});
  const Vec3d l{i1 * w1, 0.0, i3 * w3};
  const double rate = length(l) / i1;
  const int steps = 300; // 5 s: about 16 turns of the axis about L
  for (int i = 0; i < steps; ++i) {
    world.step(dt);
  }
  const double t = steps * static_cast<double>(dt);
  const Quatd precession = Quatd::fromAxisAngle(l, rate * t);
  const Vec3d expectedAxis = rotate(precession, Vec3d{0.0, 0.0, 1.0});
  const Quatf q = world.rotation(top);
  const Vec3d axis = toDouble(rotate(q, Vec3f{0.0f, 0.0f, 1.0f}));
  // The axis has precessed 82 rad; the body turned 20 rad. The orientation's Cayley rotation
  // turns by 2 atan(h |w| / 2), short of h |w| by (h |w|)^2 / 12 of the angle: at most 5e-4 rad
  // here (8e-5 measured).
  EXPECT_LT(angleBetween(axis, expectedAxis), 1e-3);
  EXPECT_NEAR(dot(toDouble(world.angularVelocity(top)), axis), w3, 1e-3);
}

/// Energy and angular momentum of a body over `steps` steps: the largest relative drift of each.
struct Drift {
  double energy = 0.0;
  double momentum = 0.0; ///< |L - L0| / |L0|: direction and size
};

Drift driftOver(World& world, BodyId body, int steps) {
  const double e0 = world.kineticEnergy(body);
  const Vec3d l0 = world.angularMomentum(body);
  Drift d;
  for (int i = 0; i < steps; ++i) {
    world.step(dt);
    d.energy = std::max(d.energy, std::abs(world.kineticEnergy(body) - e0) / e0);
    d.momentum = std::max(d.momentum, length(world.angularMomentum(body) - l0) / length(l0));
  }
  return d;
}

TEST(Rigid3dRotation, a_free_asymmetric_body_keeps_its_energy_and_angular_momentum) {
  // Torque-free, both are invariants of Euler's equations. The gyroscopic step (the implicit
  // midpoint rule in the body frame) keeps them to the solve's rounding in each substep; what
  // is left is the rotation update's error, second order, bounded rather than drifting.
  World world = freeSpace();
  const BodyId body = spinningBody(world, {2.0f, 3.0f, 4.0f}, {3.0f, 0.5f, -1.0f});
  const Drift d = driftOver(world, body, 10000);
  EXPECT_LT(d.energy, 1e-3);
  EXPECT_LT(d.momentum, 1e-3);
}

TEST(Rigid3dRotation, spun_about_its_intermediate_axis_a_body_flips_over_and_back) {
  // Dzhanibekov's nut: a spin about the axis of the middle moment is unstable; the body turns
  // over (its intermediate axis reverses against L) and back, periodically, with its energy and
  // angular momentum kept. An explicit gyroscopic term would gain energy at every flip.
  World world = freeSpace();
  const BodyId body = spinningBody(world, {1.0f, 2.0f, 2.5f}, {0.02f, 6.0f, 0.02f});
  const Vec3d l = world.angularMomentum(body);
  const double e0 = world.kineticEnergy(body);
  int flips = 0;
  double previous = 1.0;
  double worstEnergy = 0.0;
  for (int i = 0; i < 60 * 30; ++i) {
    world.step(dt);
    const Vec3d axis = toDouble(rotate(world.rotation(body), Vec3f{0.0f, 1.0f, 0.0f}));
    const double along = dot(axis, l) / length(l);
    if ((previous > 0.0) != (along > 0.0)) {
      ++flips;
    }
    previous = along;
    worstEnergy = std::max(worstEnergy, std::abs(world.kineticEnergy(body) - e0) / e0);
  }
  EXPECT_GE(flips, 4);          // over and back, at least twice in 30 s
  EXPECT_LT(worstEnergy, 1e-4); // 8e-6 measured: the substeps' rounding
}

TEST(Rigid3dRotation, a_spin_about_a_principal_axis_of_least_or_most_inertia_is_stable) {
  // The same body spun about its axes of least and most inertia, slightly off: the axis stays
  // within a few times the initial wobble of where it started.
  for (const Vec3f spin : {Vec3f{6.0f, 0.02f, 0.02f}, Vec3f{0.02f, 0.02f, 6.0f}}) {
    World world = freeSpace();
    const BodyId body = spinningBody(world, {1.0f, 2.0f, 2.5f}, spin);
    const Vec3d start = toDouble(normalize(spin));
    const Vec3f principal = spin.x > 1.0f ? Vec3f{1.0f, 0.0f, 0.0f} : Vec3f{0.0f, 0.0f, 1.0f};
    double worst = 0.0;
    for (int i = 0; i < 60 * 30; ++i) {
      world.step(dt);
      worst = std::max(worst, angleBetween(toDouble(rotate(world.rotation(body), principal)), start));
    }
    EXPECT_LT(worst, 0.05);
  }
}

} // namespace
} // namespace impetus::rigid3d
