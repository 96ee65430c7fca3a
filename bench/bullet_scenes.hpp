// The 3D benchmark scenes (rigid3d_scenes.hpp) built in Bullet 3.24 (Debian's libbullet-dev), the
// peer impetus-bench3d compares against: a btDiscreteDynamicsWorld with a btDbvtBroadphase, the
// default collision configuration (box against box: btBoxBoxDetector) and a
// btSequentialImpulseConstraintSolver at its default 10 iterations (split impulse on, Bullet's
// default); each step is stepSimulation(1/60, 1, 1/60): one fixed step of 1/60 s, no substeps, no
// interpolation. Boxes are btBoxShapes of the scene's half extents (Bullet keeps its 4 cm
// collision margin inside them, so the geometry is the same), spheres btSphereShapes; each
// dynamic body's mass and inertia come from the scene's density; friction as the scene says,
// restitution 0, no damping, no sleeping (deactivation disabled, as Impetus has no sleeping yet).
// A contact's friction is the geometric mean of its two bodies' (Impetus', Box3D's and Jolt's
// rule) rather than Bullet's default product, set through gCalculateCombinedFrictionCallback.
// Only the impetus-bench3d app compiles this; Bullet's headers stay in bullet_scenes.cpp.
#pragma once

#include "rigid3d_scenes.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace impetus::bench {

inline constexpr int bulletSolverIterations = 10; ///< btContactSolverInfo's default, kept

class BulletScene {
public:
  explicit BulletScene(const Rigid3dScene& scene);
  ~BulletScene();
  BulletScene(const BulletScene&) = delete;
  BulletScene& operator=(const BulletScene&) = delete;

  /// One fixed step of scene3dTimeStep.
  void step();
  /// The height of the scene's body `body`, m.
  [[nodiscard]] float height(std::uint32_t body) const;
  /// Every body's pose (its origin's transform), in scene order.
  [[nodiscard]] std::vector<Transform3f> poses() const;
  /// Contact manifolds with at least one point.
  [[nodiscard]] std::size_t touchingContacts() const;
  /// Bullet's version, e.g. "bullet 3.24".
  [[nodiscard]] static std::string version();

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace impetus::bench
