// Building and stepping a 3D benchmark scene in Bullet 3.24 (see bullet_scenes.hpp).
#include "bullet_scenes.hpp"

#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <tuple>

namespace impetus::bench {
namespace {

/// A contact's friction: the geometric mean of its two bodies' (Bullet's default is their product).
btScalar geometricMeanFriction(const btCollisionObject* a, const btCollisionObject* b) {
  return std::sqrt(a->getFriction() * b->getFriction());
}

btVector3 toBullet(const Vec3f& v) { return {v.x, v.y, v.z}; }

} // namespace

struct BulletScene::Impl {
  // Declared in the order they are built; destroyed in reverse (the world before its parts).
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  std::map<std::tuple<float, float, float>, std::unique_ptr<btBoxShape>> boxes;
  std::map<float, std::unique_ptr<btSphereShape>> spheres;
  std::vector<std::unique_ptr<btRigidBody>> bodies;

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl() {
    for (const std::unique_ptr<btRigidBody>& b : bodies) {
      world.removeRigidBody(b.get());
    }
  }

  btCollisionShape* shapeOf(const Scene3dBody& b) {
    if (b.shape == Scene3dBody::Shape::sphere) {
      std::unique_ptr<btSphereShape>& s = spheres[b.radius];
      if (!s) {
        s = std::make_unique<btSphereShape>(b.radius);
      }
      return s.get();
    }
    std::unique_ptr<btBoxShape>& s = boxes[std::make_tuple(b.halfExtents.x, b.halfExtents.y, b.halfExtents.z)];
    if (!s) {
      s = std::make_unique<btBoxShape>(toBullet(b.halfExtents));
    }
    return s.get();
  }
};

BulletScene::BulletScene(const Rigid3dScene& scene) : impl_(std::make_unique<Impl>()) {
  gCalculateCombinedFrictionCallback = &geometricMeanFriction;
  btDiscreteDynamicsWorld& world = impl_->world;
  world.setGravity(toBullet(scene.gravity));
  world.getSolverInfo().m_numIterations = bulletSolverIterations;
  impl_->bodies.reserve(scene.bodies.size());
  for (const Scene3dBody& b : scene.bodies) {
    btCollisionShape* shape = impl_->shapeOf(b);
    btScalar mass = 0.0f;
    btVector3 inertia(0.0f, 0.0f, 0.0f);
    if (b.type == Scene3dBody::Type::dynamicBody) {
      const float volume = b.shape == Scene3dBody::Shape::sphere
                               ? 4.0f / 3.0f * std::numbers::pi_v<float> * b.radius * b.radius * b.radius
                               : 8.0f * b.halfExtents.x * b.halfExtents.y * b.halfExtents.z;
      mass = b.density * volume;
      shape->calculateLocalInertia(mass, inertia); // a solid box's or ball's, margin included
    }
    btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shape, inertia);
    info.m_startWorldTransform =
        btTransform(btQuaternion(b.rotation.x, b.rotation.y, b.rotation.z, b.rotation.w), toBullet(b.position));
    info.m_friction = b.friction;
    info.m_restitution = 0.0f;
    auto body = std::make_unique<btRigidBody>(info);
    if (b.type == Scene3dBody::Type::dynamicBody) {
      body->setActivationState(DISABLE_DEACTIVATION);
    }
    world.addRigidBody(body.get());
    impl_->bodies.push_back(std::move(body));
  }
}

BulletScene::~BulletScene() = default;

void BulletScene::step() { impl_->world.stepSimulation(scene3dTimeStep, 1, scene3dTimeStep); }

float BulletScene::height(std::uint32_t body) const { return impl_->bodies[body]->getWorldTransform().getOrigin().y(); }

std::vector<Transform3f> BulletScene::poses() const {
  std::vector<Transform3f> out;
  out.reserve(impl_->bodies.size());
  for (const std::unique_ptr<btRigidBody>& b : impl_->bodies) {
    const btTransform& xf = b->getWorldTransform();
    const btVector3& p = xf.getOrigin();
    const btQuaternion q = xf.getRotation();
    out.push_back({{p.x(), p.y(), p.z()}, Quatf(q.w(), q.x(), q.y(), q.z())});
  }
  return out;
}

std::size_t BulletScene::touchingContacts() const {
  std::size_t n = 0;
  const int manifolds = impl_->dispatcher.getNumManifolds();
  for (int i = 0; i < manifolds; ++i) {
    n += impl_->dispatcher.getManifoldByIndexInternal(i)->getNumContacts() > 0 ? 1 : 0;
  }
  return n;
}

std::string BulletScene::version() {
  const int v = btGetVersion();
  return "bullet " + std::to_string(v / 100) + "." + std::to_string(v % 100);
}

} // namespace impetus::bench
