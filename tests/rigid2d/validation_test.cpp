// The input validation audit of the 2D world (docs/reliability.md, "Input validation"): every
// creation function, setter, shape maker, joint and effector refuses NaN, infinity, negative and
// degenerate values with an impetus::Error naming the field and showing the value; and accepts
// the boundary values that are valid (zero where zero means something).
#include "support/validation_table.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/effectors.hpp>
#include <impetus/rigid2d/world.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace impetus::rigid2d {
namespace {

using impetus::testing::expectAccepted;
using impetus::testing::expectRejected;
using impetus::testing::inff;
using impetus::testing::nanf;
using impetus::testing::Rejection;

/// A world with a static ground and two dynamic discs, and one destroyed body.
struct Fixture {
  World world;
  BodyId ground;
  BodyId a;
  BodyId b;
  BodyId gone;

  Fixture() {
    ground = world.createBody({});
    world.createShape(ground, {}, makeBox(5.0f, 0.5f));
    a = disc({0.0f, 2.0f});
    b = disc({2.0f, 2.0f});
    gone = disc({4.0f, 2.0f});
    world.destroyBody(gone);
  }

  BodyId disc(const Vec2f& position) {
    BodyDef def;
    def.type = BodyType::dynamicBody;
    def.position = position;
    const BodyId id = world.createBody(def);
    world.createShape(id, {}, Circle{{}, 0.5f});
    return id;
  }
};

/// Runs `f` on a fresh fixture: each row starts from the same valid world.
template <class F> std::function<void()> on(F f) {
  return [f] {
    Fixture x;
    f(x);
  };
}

/// Default settings with one change.
template <class S, class F> S with(F change) {
  S s{};
  change(s);
  return s;
}

template <class Def> Def between(const Fixture& x) {
  Def d;
  d.bodyA = x.a;
  d.bodyB = x.b;
  return d;
}

/// A polygon filled in by hand: the vertices as given, each normal the clockwise perpendicular of
/// its edge (outward when the vertices run counter-clockwise), the centroid the vertices' mean.
Polygon byHand(const std::vector<Vec2f>& vertices) {
  Polygon p;
  p.count = static_cast<int>(vertices.size());
  Vec2f sum;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const Vec2f edge = vertices[(i + 1) % vertices.size()] - vertices[i];
    p.vertices[i] = vertices[i];
    p.normals[i] = normalize(Vec2f{edge.y, -edge.x});
    sum += vertices[i];
  }
  p.centroid = sum / static_cast<float>(vertices.size());
  return p;
}

TEST(Rigid2dValidation, world_def_and_step) {
  const auto def = [](auto change) {
    return [change] {
      WorldDef d;
      change(d);
      World w(d);
    };
  };
  expectRejected({
      {"gravity.x", "nan", def([](WorldDef& d) { d.gravity.x = nanf; })},
      {"gravity.y", "inf", def([](WorldDef& d) { d.gravity.y = inff; })},
      {"substeps", "0", def([](WorldDef& d) { d.substeps = 0; })},
      {"substeps", "65", def([](WorldDef& d) { d.substeps = 65; })},
      {"contactHertz", "-1", def([](WorldDef& d) { d.contactHertz = -1.0f; })},
      {"contactHertz", "nan", def([](WorldDef& d) { d.contactHertz = nanf; })},
      {"contactDampingRatio", "-1", def([](WorldDef& d) { d.contactDampingRatio = -1.0f; })},
      {"maxContactPushSpeed", "0", def([](WorldDef& d) { d.maxContactPushSpeed = 0.0f; })},
      {"maxContactPushSpeed", "inf", def([](WorldDef& d) { d.maxContactPushSpeed = inff; })},
      {"maxJointPushSpeed", "0", def([](WorldDef& d) { d.maxJointPushSpeed = 0.0f; })},
      {"maxJointPushSpeed", "nan", def([](WorldDef& d) { d.maxJointPushSpeed = std::nanf(""); })},
      {"jointHertz", "inf", def([](WorldDef& d) { d.jointHertz = inff; })},
      {"jointDampingRatio", "-1", def([](WorldDef& d) { d.jointDampingRatio = -1.0f; })},
      {"restitutionThreshold", "-1", def([](WorldDef& d) { d.restitutionThreshold = -1.0f; })},
      {"maxLinearSpeed", "0", def([](WorldDef& d) { d.maxLinearSpeed = 0.0f; })},
      {"maxLinearSpeed", "nan", def([](WorldDef& d) { d.maxLinearSpeed = nanf; })},
      {"hitEventThreshold", "nan", def([](WorldDef& d) { d.hitEventThreshold = nanf; })},
      {"contactReuseDistance", "-1", def([](WorldDef& d) { d.contactReuseDistance = -1.0f; })},
      {"contactReuseDistance", "nan", def([](WorldDef& d) { d.contactReuseDistance = nanf; })},
      {"contactReuseAngle", "-1", def([](WorldDef& d) { d.contactReuseAngle = -1.0f; })},
      {"contactReuseAngle", "nan", def([](WorldDef& d) { d.contactReuseAngle = nanf; })},
      {"contactReuseAngle", "2", def([](WorldDef& d) { d.contactReuseAngle = 2.0f; })},
      {"timeToSleep", "-1", def([](WorldDef& d) { d.timeToSleep = -1.0f; })},
      {"sleepLinearTolerance", "inf", def([](WorldDef& d) { d.sleepLinearTolerance = inff; })},
      {"sleepAngularTolerance", "-1", def([](WorldDef& d) { d.sleepAngularTolerance = -1.0f; })},
      {"simd", "7", def([](WorldDef& d) { d.simd = static_cast<SimdLevel>(7); })},
      {"solver", "9", def([](WorldDef& d) { d.solver = static_cast<SolverKind>(9); })},
      {"dt", "0", on([](Fixture& x) { x.world.step(0.0f); })},
      {"dt", "-1", on([](Fixture& x) { x.world.step(-1.0f); })},
      {"dt", "nan", on([](Fixture& x) { x.world.step(nanf); })},
      {"dt", "inf", on([](Fixture& x) { x.world.step(inff); })},
      {"dt", "2", on([](Fixture& x) { x.world.step(2.0f); })},
  });
  expectAccepted({
      {"zero gravity, stiffness and tolerances",
       [] {
         WorldDef d;
         d.gravity = {};
         d.substeps = 1;
         d.contactHertz = d.contactDampingRatio = d.jointHertz = d.jointDampingRatio = 0.0f;
         d.restitutionThreshold = d.hitEventThreshold = d.timeToSleep = 0.0f;
         d.sleepLinearTolerance = d.sleepAngularTolerance = 0.0f;
         World w(d);
         w.step(1.0f);
       }},
      {"64 substeps",
       [] {
         WorldDef d;
         d.substeps = 64;
         World w(d);
       }},
  });
}

TEST(Rigid2dValidation, body_def) {
  const auto body = [](auto change) {
    return on([change](Fixture& x) {
      BodyDef d;
      d.type = BodyType::dynamicBody;
      change(d);
      x.world.createBody(d);
    });
  };
  expectRejected({
      {"position.x", "nan", body([](BodyDef& d) { d.position.x = nanf; })},
      {"position.y", "inf", body([](BodyDef& d) { d.position.y = inff; })},
      {"angle", "nan", body([](BodyDef& d) { d.angle = nanf; })},
      {"angle", "-inf", body([](BodyDef& d) { d.angle = -inff; })},
      {"linearVelocity.x", "nan", body([](BodyDef& d) { d.linearVelocity.x = nanf; })},
      {"angularVelocity", "inf", body([](BodyDef& d) { d.angularVelocity = inff; })},
      {"linearDamping", "-1", body([](BodyDef& d) { d.linearDamping = -1.0f; })},
      {"linearDamping", "nan", body([](BodyDef& d) { d.linearDamping = nanf; })},
      {"angularDamping", "inf", body([](BodyDef& d) { d.angularDamping = inff; })},
      {"gravityScale", "nan", body([](BodyDef& d) { d.gravityScale = nanf; })},
      {"type", "5", body([](BodyDef& d) { d.type = static_cast<BodyType>(5); })},
  });
  expectAccepted({
      {"zero damping, negative gravity scale", on([](Fixture& x) {
         BodyDef d;
         d.type = BodyType::kinematicBody;
         d.gravityScale = -2.0f;
         x.world.createBody(d);
       })},
  });
}

TEST(Rigid2dValidation, shape_def_and_body_id) {
  const auto shape = [](auto change) {
    return on([change](Fixture& x) {
      ShapeDef d;
      change(d);
      x.world.createShape(x.a, d, Circle{{}, 0.5f});
    });
  };
  expectRejected({
      {"density", "-1", shape([](ShapeDef& d) { d.density = -1.0f; })},
      {"density", "nan", shape([](ShapeDef& d) { d.density = nanf; })},
      {"density", "inf", shape([](ShapeDef& d) { d.density = inff; })},
      {"density", "0", shape([](ShapeDef& d) { d.density = 0.0f; })}, // on a dynamic body
      {"friction", "-1", shape([](ShapeDef& d) { d.friction = -1.0f; })},
      {"friction", "nan", shape([](ShapeDef& d) { d.friction = nanf; })},
      {"restitution", "-0.5", shape([](ShapeDef& d) { d.restitution = -0.5f; })},
      {"restitution", "1.5", shape([](ShapeDef& d) { d.restitution = 1.5f; })},
      {"restitution", "nan", shape([](ShapeDef& d) { d.restitution = nanf; })},
      {"rollingResistance", "-1", shape([](ShapeDef& d) { d.rollingResistance = -1.0f; })},
      {"rollingResistance", "inf", shape([](ShapeDef& d) { d.rollingResistance = inff; })},
      // A density whose mass data overflow float (a 1e6 m square at 1e30 kg/m^2: 1e42 kg), or
      // underflow it (no finite inverse mass), or make the body's sums overflow: a 1 m disc
      // 1e6 m from the body origin at 1e27 kg/m^2 has a finite 3e27 kg and 1.6e27 kg m^2 of
      // its own, but 3e39 kg m^2 about the origin.
      {"density", formatValue(1e30f), on([](Fixture& x) {
         ShapeDef d;
         d.density = 1e30f;
         x.world.createShape(x.a, d, makeBox(5e5f, 5e5f));
       })},
      {"density", formatValue(1e-40f), shape([](ShapeDef& d) { d.density = 1e-40f; })},
      {"density", formatValue(1e27f), on([](Fixture& x) {
         ShapeDef d;
         d.density = 1e27f;
         x.world.createShape(x.a, d, Circle{{1e6f, 0.0f}, 1.0f});
       })},
      {"density", formatValue(1e30f), on([](Fixture& x) { // on a static body too: it may become dynamic
         ShapeDef d;
         d.density = 1e30f;
         x.world.createShape(x.ground, d, Capsule{{-5e5f, 0.0f}, {5e5f, 0.0f}, 5e5f});
       })},
      {"body id", "3", on([](Fixture& x) { x.world.createShape(x.gone, {}, Circle{}); })},
      {"body id", "3", on([](Fixture& x) { x.world.destroyBody(x.gone); })},
      {"body id", "3", on([](Fixture& x) { (void)x.world.position(x.gone); })},
  });
  expectAccepted({
      {"zero density on a static body, zero friction, restitution 0 and 1", on([](Fixture& x) {
         ShapeDef d;
         d.density = 0.0f;
         d.friction = 0.0f;
         d.restitution = 1.0f;
         x.world.createShape(x.ground, d, Circle{{}, 0.5f});
         d.restitution = 0.0f;
         x.world.createShape(x.ground, d, Circle{{1.0f, 0.0f}, 0.5f});
       })},
      {"a zero-density sensor on a dynamic body", on([](Fixture& x) {
         ShapeDef d;
         d.density = 0.0f;
         d.isSensor = true;
         x.world.createShape(x.a, d, Circle{{}, 0.5f});
       })},
  });
}

TEST(Rigid2dValidation, shapes) {
  Polygon box = makeBox(0.5f, 0.5f);
  const auto polygon = [box](auto change) {
    return on([box, change](Fixture& x) {
      Polygon p = box;
      change(p);
      x.world.createShape(x.a, {}, p);
    });
  };
  expectRejected({
      {"center.x", "nan", on([](Fixture& x) {
         x.world.createShape(x.a, {}, Circle{{nanf, 0.0f}, 1.0f});
       })},
      {"radius", "0", on([](Fixture& x) {
         x.world.createShape(x.a, {}, Circle{{}, 0.0f});
       })},
      {"radius", "-1", on([](Fixture& x) {
         x.world.createShape(x.a, {}, Circle{{}, -1.0f});
       })},
      {"radius", "nan", on([](Fixture& x) {
         x.world.createShape(x.a, {}, Circle{{}, nanf});
       })},
      {"radius", "inf", on([](Fixture& x) {
         x.world.createShape(x.a, {}, Circle{{}, inff});
       })},
      {"center1.x", "nan", on([](Fixture& x) {
         x.world.createShape(x.a, {}, Capsule{{nanf, 0}, {1, 0}, 0.5f});
       })},
      {"center2.y", "inf", on([](Fixture& x) {
         x.world.createShape(x.a, {}, Capsule{{0, 0}, {1, inff}, 0.5f});
       })},
      {"radius", "0", on([](Fixture& x) {
         x.world.createShape(x.a, {}, Capsule{{0, 0}, {1, 0}, 0.0f});
       })},
      {"center2", "0", on([](Fixture& x) {
         x.world.createShape(x.a, {}, Capsule{{1, 1}, {1, 1}, 0.5f});
       })},
      {"center2", "0.00390625", on([](Fixture& x) {
         x.world.createShape(x.a, {}, Capsule{{0, 0}, {0.00390625f, 0}, 0.5f});
       })},
      {"point1.x", "nan", on([](Fixture& x) {
         x.world.createShape(x.ground, {}, Segment{{nanf, 0}, {1, 0}});
       })},
      {"point2.y", "-inf", on([](Fixture& x) {
         x.world.createShape(x.ground, {}, Segment{{0, 0}, {1, -inff}});
       })},
      {"point2", "0", on([](Fixture& x) {
         x.world.createShape(x.ground, {}, Segment{{2, 3}, {2, 3}});
       })},
      {"polygon.count", "2", polygon([](Polygon& p) { p.count = 2; })},
      {"polygon.count", "9", polygon([](Polygon& p) { p.count = 9; })},
      {"polygon.vertices[1].x", "nan", polygon([](Polygon& p) { p.vertices[1].x = nanf; })},
      {"polygon.normals[2].y", "inf", polygon([](Polygon& p) { p.normals[2].y = inff; })},
      {"polygon.normals[0]", "0", polygon([](Polygon& p) { p.normals[0] = {}; })},
      {"polygon.centroid.x", "nan", polygon([](Polygon& p) { p.centroid.x = nanf; })},
      {"polygon.radius", "-1", polygon([](Polygon& p) { p.radius = -1.0f; })},
      {"polygon.radius", "inf", polygon([](Polygon& p) { p.radius = inff; })},
      // Hand-built shapes are bounded by maxPolygonCoordinate (1e6 m), as the makers bound theirs.
      {"center.x", formatValue(2e6), on([](Fixture& x) {
         x.world.createShape(x.a, {}, Circle{{2e6f, 0.0f}, 1.0f});
       })},
      {"radius", formatValue(2e6), on([](Fixture& x) {
         x.world.createShape(x.a, {}, Circle{{}, 2e6f});
       })},
      {"center1.y", formatValue(-3e7), on([](Fixture& x) {
         x.world.createShape(x.a, {}, Capsule{{0, -3e7f}, {1, 0}, 0.5f});
       })},
      {"radius", formatValue(1.5e6), on([](Fixture& x) {
         x.world.createShape(x.a, {}, Capsule{{0, 0}, {1, 0}, 1.5e6f});
       })},
      {"point2.x", formatValue(1e7), on([](Fixture& x) {
         x.world.createShape(x.ground, {}, Segment{{0, 0}, {1e7f, 0}});
       })},
      {"polygon.vertices[2].x", formatValue(3e7), polygon([](Polygon& p) { p.vertices[2].x = 3e7f; })},
      {"polygon.radius", formatValue(2e6), polygon([](Polygon& p) { p.radius = 2e6f; })},
      // A hand-built polygon must be one makePolygon could return.
      {"polygon.normals[1]", formatValue(std::sqrt(2.0)), polygon([](Polygon& p) { p.normals[1] = p.normals[0]; })},
      {"polygon.normals[3]", formatValue(2.0), polygon([](Polygon& p) { p.normals[3] = -p.normals[3]; })},
      {"polygon.vertices[0]", formatValue(-1.0 / std::sqrt(2.0)), on([](Fixture& x) { // clockwise
         x.world.createShape(x.a, {}, byHand({{-0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, -0.5f}, {-0.5f, -0.5f}}));
       })},
      {"polygon.vertices[2]", formatValue(-2.0 / std::sqrt(8.0)), on([](Fixture& x) { // a dart: reflex at 2
         x.world.createShape(x.a, {}, byHand({{0, 0}, {2, 0}, {0.5f, 0.5f}, {0, 2}}));
       })},
      {"polygon.vertices[1]", "0", on([](Fixture& x) { // a vertex on its neighbours' line
         x.world.createShape(x.a, {}, byHand({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {0, 1}}));
       })},
      {"polygon.vertices[2]", formatValue(static_cast<double>(0.001f)), on([](Fixture& x) { // welded vertices
         x.world.createShape(x.a, {}, byHand({{0, 0}, {1, 0}, {1, 0.001f}, {0, 1}}));
       })},
      {"polygon.vertices", "2", on([](Fixture& x) { // a pentagram: every turn left, twice round
         std::vector<Vec2f> star;
         star.reserve(5);
         for (int k = 0; k < 5; ++k) {
           const float a = 2.0f * 0.6283185f * static_cast<float>(2 * k); // every second point of a pentagon
           star.emplace_back(std::cos(a), std::sin(a));
         }
         x.world.createShape(x.a, {}, byHand(star));
       })},
      {"polygon.centroid", formatValue(4.5), polygon([](Polygon& p) {
         p.centroid = {5.0f, 0.0f};
       })},
  });
  expectAccepted({
      {"shapes at the bound, and a polygon filled in by hand", on([](Fixture& x) {
         const float b = maxPolygonCoordinate;
         x.world.createShape(x.a, {}, Circle{{b, -b}, b});
         x.world.createShape(x.a, {}, Capsule{{-b, b}, {b, b}, b});
         x.world.createShape(x.ground, {}, Segment{{-b, -b}, {b, b}});
         x.world.createShape(x.a, {}, makePolygon(std::vector<Vec2f>{{-b, -b}, {b, -b}, {b, b}, {-b, b}}, b));
         x.world.createShape(x.a, {}, byHand({{0, 0}, {1, 0}, {0.5f, 1}}));
       })},
  });
}

TEST(Rigid2dValidation, chains) {
  const auto chain = [](std::vector<Vec2f> points, bool loop) {
    return on([points, loop](Fixture& x) { x.world.createChain(x.ground, {}, ChainDef{points, loop}); });
  };
  expectRejected({
      {"points.size", "1", chain({{0, 0}}, false)},
      {"points.size", "2", chain({{0, 0}, {1, 0}}, true)},
      {"points[1].x", "nan", chain({{0, 0}, {nanf, 0}, {2, 0}}, false)},
      {"points[2].y", "inf", chain({{0, 0}, {1, 0}, {2, inff}}, false)},
      {"points[1]", "0", chain({{0, 0}, {0, 0}, {2, 0}}, false)},
      {"points[0]", "0", chain({{0, 0}, {1, 0}, {1, 1}, {0, 0}}, true)}, // the loop's closing pair
      {"body id", "3", on([](Fixture& x) {
         x.world.createChain(x.gone, {}, ChainDef{{{0, 0}, {1, 0}}, false});
       })},
  });
}

TEST(Rigid2dValidation, shape_makers_and_mass) {
  const std::array<Vec2f, 3> triangle{{{0, 0}, {1, 0}, {0, 1}}};
  expectRejected({
      {"points.size", "2",
       [] {
         (void)makePolygon(std::vector<Vec2f>{{0, 0}, {1, 0}});
       }},
      {"points.size", "9", [] { (void)makePolygon(std::vector<Vec2f>(9, Vec2f{})); }},
      {"points[1].x", "nan",
       [] {
         (void)makePolygon(std::vector<Vec2f>{{0, 0}, {nanf, 0}, {0, 1}});
       }},
      {"points[2].y", "inf",
       [] {
         std::array<Vec2f, 8> storage{};
         (void)computeHull(std::vector<Vec2f>{{0, 0}, {1, 0}, {0, inff}}, storage);
       }},
      {"points", "0",
       [] {
         (void)makePolygon(std::vector<Vec2f>{{0, 0}, {1, 1}, {2, 2}});
       }}, // collinear
      {"points", "0",
       [] {
         (void)makePolygon(std::vector<Vec2f>{{0, 0}, {0, 0}, {0, 0.001f}});
       }}, // welded
      {"radius", "-1", [triangle] { (void)makePolygon(triangle, -1.0f); }},
      {"radius", "nan", [triangle] { (void)makePolygon(triangle, nanf); }},
      {"halfWidth", "0", [] { (void)makeBox(0.0f, 1.0f); }},
      {"halfWidth", "-1", [] { (void)makeBox(-1.0f, 1.0f); }},
      {"halfHeight", "nan", [] { (void)makeBox(1.0f, nanf); }},
      {"halfHeight", "inf", [] { (void)makeOffsetBox(1.0f, inff, {}, 0.0f); }},
      {"center.x", "nan",
       [] {
         (void)makeOffsetBox(1.0f, 1.0f, {nanf, 0.0f}, 0.0f);
       }},
      {"angle", "inf", [] { (void)makeOffsetBox(1.0f, 1.0f, {}, inff); }},
      {"density", "0",
       [] {
         (void)computeMass(Circle{{}, 1.0f}, 0.0f);
       }},
      {"radius", "0",
       [] {
         (void)computeMass(Circle{{}, 0.0f}, 1.0f);
       }},
      {"density", "nan",
       [] {
         (void)computeMass(Capsule{{0, 0}, {1, 0}, 0.5f}, nanf);
       }},
      {"radius", "-1",
       [] {
         (void)computeMass(Capsule{{0, 0}, {1, 0}, -1.0f}, 1.0f);
       }},
      {"density", "-1", [] { (void)computeMass(makeBox(1.0f, 1.0f), -1.0f); }},
      {"density", formatValue(1e30f), [] { (void)computeMass(makeBox(5e5f, 5e5f), 1e30f); }},
      {"density", formatValue(1e37f),
       [] {
         (void)computeMass(Circle{{}, 10.0f}, 1e37f);
       }},
      {"density", formatValue(1e36f),
       [] {
         (void)computeMass(Capsule{{0, 0}, {100, 0}, 1.0f}, 1e36f);
       }},
      {"density", formatValue(1e-40f),
       [] {
         (void)computeMass(Circle{{}, 0.5f}, 1e-40f);
       }},
  });
  expectAccepted({
      {"a rounded polygon of radius 0 and a triangle", [triangle] { (void)makePolygon(triangle, 0.0f); }},
      {"8 points",
       [] {
         std::vector<Vec2f> pts;
         for (int i = 0; i < 8; ++i) {
           pts.push_back(Vec2f{std::cos(0.785f * static_cast<float>(i)), std::sin(0.785f * static_cast<float>(i))});
         }
         (void)makePolygon(pts);
       }},
  });
}

// computeMass refuses a density at which the mass data are not finite, normal floats; below that
// they are the closed form. A 1e6 m square (the largest makeBox) at 1e14 kg/m^2: m = rho s^2 =
// 1e26 kg, I = m s^2 / 6 = 1.7e37 kg m^2, a tenth of float's limit (computeMass integrates in
// double and rounds once: relative error below 1e-7, checked to 1e-6).
TEST(Rigid2dValidation, a_density_refused_for_its_mass_leaves_the_world_as_it_was) {
  const auto rho = static_cast<double>(1e14f);
  const double side = 1e6;
  const MassData largest = computeMass(makeBox(5e5f, 5e5f), 1e14f);
  EXPECT_NEAR(largest.mass, rho * side * side, 1e-6 * rho * side * side);
  EXPECT_NEAR(largest.rotationalInertia, rho * side * side * side * side / 6.0,
              1e-6 * rho * side * side * side * side / 6.0);

  // Refused before the shape is added: the body keeps its shapes and mass, and steps.
  Fixture x;
  const std::size_t shapes = x.world.shapeCount();
  const float mass = x.world.mass(x.a);
  const float inertia = x.world.rotationalInertia(x.a);
  ShapeDef d;
  d.density = 1e27f;
  EXPECT_THROW(x.world.createShape(x.a, d, Circle{{1e6f, 0.0f}, 1.0f}), Error);
  EXPECT_EQ(x.world.shapeCount(), shapes);
  EXPECT_EQ(x.world.mass(x.a), mass);
  EXPECT_EQ(x.world.rotationalInertia(x.a), inertia);
  for (int i = 0; i < 10; ++i) {
    x.world.step(1.0f / 60.0f);
  }
  EXPECT_TRUE(isFinite(x.world.position(x.a)) && isFinite(x.world.linearVelocity(x.a)));
}

TEST(Rigid2dValidation, joint_base_and_bodies) {
  expectRejected({
      {"bodyA", "3", on([](Fixture& x) {
         RevoluteJointDef d = between<RevoluteJointDef>(x);
         d.bodyA = x.gone;
         x.world.createJoint(d);
       })},
      {"bodyB", "3", on([](Fixture& x) {
         WeldJointDef d = between<WeldJointDef>(x);
         d.bodyB = x.gone;
         x.world.createJoint(d);
       })},
      {"bodyB", "0", on([](Fixture& x) { x.world.createJoint(DistanceJointDef{}); })}, // null ids
      {"bodyB", "1", on([](Fixture& x) {
         RevoluteJointDef d = between<RevoluteJointDef>(x);
         d.bodyB = x.a;
         x.world.createJoint(d);
       })},
      {"localAnchorA.x", "nan", on([](Fixture& x) {
         RevoluteJointDef d = between<RevoluteJointDef>(x);
         d.localAnchorA.x = nanf;
         x.world.createJoint(d);
       })},
      {"localAnchorB.y", "inf", on([](Fixture& x) {
         PrismaticJointDef d = between<PrismaticJointDef>(x);
         d.localAnchorB.y = inff;
         x.world.createJoint(d);
       })},
      {"breakForce", "-1", on([](Fixture& x) {
         WeldJointDef d = between<WeldJointDef>(x);
         d.breakForce = -1.0f;
         x.world.createJoint(d);
       })},
      {"breakForce", "nan", on([](Fixture& x) {
         WeldJointDef d = between<WeldJointDef>(x);
         d.breakForce = nanf;
         x.world.createJoint(d);
       })},
      {"breakTorque", "-1", on([](Fixture& x) {
         MotorJointDef d = between<MotorJointDef>(x);
         d.breakTorque = -1.0f;
         x.world.createJoint(d);
       })},
      {"bodyB", "3", on([](Fixture& x) {
         MouseJointDef d;
         d.bodyB = x.gone;
         x.world.createJoint(d);
       })},
  });
  expectAccepted({
      {"break limits 0 and infinity, coincident anchors", on([](Fixture& x) {
         RevoluteJointDef d = between<RevoluteJointDef>(x);
         d.breakForce = 0.0f;
         d.breakTorque = inff;
         x.world.createJoint(d);
       })},
  });
}

TEST(Rigid2dValidation, revolute_and_prismatic_joints) {
  const auto revolute = [](auto change) {
    return on([change](Fixture& x) {
      RevoluteJointDef d = between<RevoluteJointDef>(x);
      change(d);
      x.world.createJoint(d);
    });
  };
  const auto prismatic = [](auto change) {
    return on([change](Fixture& x) {
      PrismaticJointDef d = between<PrismaticJointDef>(x);
      change(d);
      x.world.createJoint(d);
    });
  };
  const auto limited = [](float lower, float upper) {
    return [lower, upper](auto& d) {
      d.enableLimit = true;
      if constexpr (requires { d.lowerAngle; }) {
        d.lowerAngle = lower;
        d.upperAngle = upper;
      } else {
        d.lowerTranslation = lower;
        d.upperTranslation = upper;
      }
    };
  };
  expectRejected({
      {"referenceAngle", "nan", revolute([](RevoluteJointDef& d) { d.referenceAngle = nanf; })},
      {"lowerAngle", "nan", revolute(limited(nanf, 0.0f))},
      {"upperAngle", "inf", revolute(limited(0.0f, inff))},
      {"lowerAngle", "1", revolute(limited(1.0f, 0.5f))},
      {"lowerAngle", "-4", revolute(limited(-4.0f, 0.0f))},
      {"upperAngle", "4", revolute(limited(0.0f, 4.0f))},
      {"motorSpeed", "inf", revolute([](RevoluteJointDef& d) { d.motorSpeed = inff; })},
      {"maxMotorTorque", "-1", revolute([](RevoluteJointDef& d) { d.maxMotorTorque = -1.0f; })},
      {"frictionTorque", "-1", revolute([](RevoluteJointDef& d) { d.frictionTorque = -1.0f; })},
      {"hertz", "-1", revolute([](RevoluteJointDef& d) { d.hertz = -1.0f; })},
      {"dampingRatio", "nan", revolute([](RevoluteJointDef& d) { d.dampingRatio = nanf; })},
      {"referenceAngle", "inf", prismatic([](PrismaticJointDef& d) { d.referenceAngle = inff; })},
      {"localAxisA", "0", prismatic([](PrismaticJointDef& d) { d.localAxisA = {}; })},
      {"localAxisA.x", "nan", prismatic([](PrismaticJointDef& d) { d.localAxisA.x = nanf; })},
      {"lowerTranslation", "2", prismatic(limited(2.0f, 1.0f))},
      {"lowerTranslation", "-inf", prismatic(limited(-inff, 1.0f))},
      {"upperTranslation", "nan", prismatic(limited(0.0f, nanf))},
      {"motorSpeed", "nan", prismatic([](PrismaticJointDef& d) { d.motorSpeed = nanf; })},
      {"maxMotorForce", "-1", prismatic([](PrismaticJointDef& d) { d.maxMotorForce = -1.0f; })},
      {"hertz", "inf", prismatic([](PrismaticJointDef& d) { d.hertz = inff; })},
      {"dampingRatio", "-1", prismatic([](PrismaticJointDef& d) { d.dampingRatio = -1.0f; })},
  });
  expectAccepted({
      {"revolute limits at -pi and pi, equal limits, zero spring", revolute([](RevoluteJointDef& d) {
         d.enableLimit = true;
         d.lowerAngle = -pi<float>;
         d.upperAngle = pi<float>;
       })},
      {"a locked prismatic (lower == upper) with a non-unit axis", prismatic([](PrismaticJointDef& d) {
         d.enableLimit = true;
         d.localAxisA = {3.0f, 4.0f};
       })},
  });
}

TEST(Rigid2dValidation, distance_weld_wheel_motor_mouse_joints) {
  const auto distanceJoint = [](auto change) {
    return on([change](Fixture& x) {
      DistanceJointDef d = between<DistanceJointDef>(x);
      change(d);
      x.world.createJoint(d);
    });
  };
  const auto weld = [](auto change) {
    return on([change](Fixture& x) {
      WeldJointDef d = between<WeldJointDef>(x);
      change(d);
      x.world.createJoint(d);
    });
  };
  const auto wheel = [](auto change) {
    return on([change](Fixture& x) {
      WheelJointDef d = between<WheelJointDef>(x);
      change(d);
      x.world.createJoint(d);
    });
  };
  const auto motor = [](auto change) {
    return on([change](Fixture& x) {
      MotorJointDef d = between<MotorJointDef>(x);
      change(d);
      x.world.createJoint(d);
    });
  };
  const auto mouse = [](auto change) {
    return on([change](Fixture& x) {
      MouseJointDef d;
      d.bodyB = x.a;
      change(d);
      x.world.createJoint(d);
    });
  };
  expectRejected({
      {"length", "0", distanceJoint([](DistanceJointDef& d) { d.length = 0.0f; })},
      {"length", "-1", distanceJoint([](DistanceJointDef& d) { d.length = -1.0f; })},
      {"length", "nan", distanceJoint([](DistanceJointDef& d) { d.length = nanf; })},
      {"length", "inf", distanceJoint([](DistanceJointDef& d) { d.length = inff; })},
      {"minLength", "-1", distanceJoint([](DistanceJointDef& d) {
         d.enableLimit = true;
         d.minLength = -1.0f;
       })},
      {"maxLength", "1", distanceJoint([](DistanceJointDef& d) {
         d.enableLimit = true;
         d.minLength = 2.0f;
         d.maxLength = 1.0f;
       })},
      {"maxLength", "nan", distanceJoint([](DistanceJointDef& d) {
         d.enableLimit = true;
         d.maxLength = nanf;
       })},
      {"motorSpeed", "nan", distanceJoint([](DistanceJointDef& d) { d.motorSpeed = nanf; })},
      {"maxMotorForce", "-1", distanceJoint([](DistanceJointDef& d) { d.maxMotorForce = -1.0f; })},
      {"hertz", "-1", distanceJoint([](DistanceJointDef& d) { d.hertz = -1.0f; })},
      {"dampingRatio", "inf", distanceJoint([](DistanceJointDef& d) { d.dampingRatio = inff; })},
      {"referenceAngle", "nan", weld([](WeldJointDef& d) { d.referenceAngle = nanf; })},
      {"linearHertz", "-1", weld([](WeldJointDef& d) { d.linearHertz = -1.0f; })},
      {"linearDampingRatio", "nan", weld([](WeldJointDef& d) { d.linearDampingRatio = nanf; })},
      {"angularHertz", "inf", weld([](WeldJointDef& d) { d.angularHertz = inff; })},
      {"angularDampingRatio", "-1", weld([](WeldJointDef& d) { d.angularDampingRatio = -1.0f; })},
      {"localAxisA", "0", wheel([](WheelJointDef& d) { d.localAxisA = {}; })},
      {"localAxisA.y", "inf", wheel([](WheelJointDef& d) { d.localAxisA.y = inff; })},
      {"lowerTranslation", "1", wheel([](WheelJointDef& d) {
         d.enableLimit = true;
         d.lowerTranslation = 1.0f;
         d.upperTranslation = -1.0f;
       })},
      {"upperTranslation", "inf", wheel([](WheelJointDef& d) {
         d.enableLimit = true;
         d.upperTranslation = inff;
       })},
      {"motorSpeed", "inf", wheel([](WheelJointDef& d) { d.motorSpeed = inff; })},
      {"maxMotorTorque", "-1", wheel([](WheelJointDef& d) { d.maxMotorTorque = -1.0f; })},
      {"hertz", "-1", wheel([](WheelJointDef& d) { d.hertz = -1.0f; })},
      {"dampingRatio", "nan", wheel([](WheelJointDef& d) { d.dampingRatio = nanf; })},
      {"linearOffset.x", "nan", motor([](MotorJointDef& d) { d.linearOffset.x = nanf; })},
      {"angularOffset", "inf", motor([](MotorJointDef& d) { d.angularOffset = inff; })},
      {"maxForce", "-1", motor([](MotorJointDef& d) { d.maxForce = -1.0f; })},
      {"maxTorque", "nan", motor([](MotorJointDef& d) { d.maxTorque = nanf; })},
      {"correctionFactor", "1.5", motor([](MotorJointDef& d) { d.correctionFactor = 1.5f; })},
      {"correctionFactor", "-0.5", motor([](MotorJointDef& d) { d.correctionFactor = -0.5f; })},
      {"correctionFactor", "nan", motor([](MotorJointDef& d) { d.correctionFactor = nanf; })},
      {"target.x", "nan", mouse([](MouseJointDef& d) { d.target.x = nanf; })},
      {"hertz", "-1", mouse([](MouseJointDef& d) { d.hertz = -1.0f; })},
      {"dampingRatio", "-1", mouse([](MouseJointDef& d) { d.dampingRatio = -1.0f; })},
      {"maxForce", "-1", mouse([](MouseJointDef& d) { d.maxForce = -1.0f; })},
      {"maxForce", "nan", mouse([](MouseJointDef& d) { d.maxForce = nanf; })},
  });
  expectAccepted({
      {"a rope: min length 0, max length infinity", distanceJoint([](DistanceJointDef& d) {
         d.enableLimit = true;
         d.minLength = 0.0f;
       })},
      {"a rigid weld (zero hertz)", weld([](WeldJointDef&) {})},
      {"a motor with correction 0 and 1 and no force", motor([](MotorJointDef& d) {
         d.correctionFactor = 0.0f;
         d.maxForce = d.maxTorque = 0.0f;
       })},
      {"a rigid mouse (zero hertz)", mouse([](MouseJointDef& d) { d.hertz = 0.0f; })},
  });
}

TEST(Rigid2dValidation, joint_setters) {
  const auto with = [](auto make, auto set) { return on([make, set](Fixture& x) { set(x.world, make(x)); }); };
  const auto revolute = [](Fixture& x) { return x.world.createJoint(between<RevoluteJointDef>(x)); };
  const auto prismatic = [](Fixture& x) { return x.world.createJoint(between<PrismaticJointDef>(x)); };
  const auto distanceJoint = [](Fixture& x) { return x.world.createJoint(between<DistanceJointDef>(x)); };
  const auto wheel = [](Fixture& x) { return x.world.createJoint(between<WheelJointDef>(x)); };
  const auto motor = [](Fixture& x) { return x.world.createJoint(between<MotorJointDef>(x)); };
  const auto mouse = [](Fixture& x) {
    MouseJointDef d;
    d.bodyB = x.a;
    return x.world.createJoint(d);
  };
  const auto destroyed = [](Fixture& x) {
    const JointId id = x.world.createJoint(between<WeldJointDef>(x));
    x.world.destroyJoint(id);
    return id;
  };
  expectRejected({
      {"motorSpeed", "nan",
       with(revolute, [](World& w, JointId j) { setRevoluteMotor(w, RevoluteJointId{j}, true, nanf, 1.0f); })},
      {"maxMotorTorque", "-1",
       with(revolute, [](World& w, JointId j) { setRevoluteMotor(w, RevoluteJointId{j}, true, 1.0f, -1.0f); })},
      {"lowerAngle", "1",
       with(revolute, [](World& w, JointId j) { setRevoluteLimit(w, RevoluteJointId{j}, true, 1.0f, 0.0f); })},
      {"upperAngle", "nan",
       with(revolute, [](World& w, JointId j) { setRevoluteLimit(w, RevoluteJointId{j}, true, 0.0f, nanf); })},
      {"motorSpeed", "inf",
       with(prismatic, [](World& w, JointId j) { setPrismaticMotor(w, PrismaticJointId{j}, true, inff, 1.0f); })},
      {"maxMotorForce", "nan",
       with(prismatic, [](World& w, JointId j) { setPrismaticMotor(w, PrismaticJointId{j}, true, 0.0f, nanf); })},
      {"lowerTranslation", "3",
       with(prismatic, [](World& w, JointId j) { setPrismaticLimit(w, PrismaticJointId{j}, true, 3.0f, 2.0f); })},
      {"upperTranslation", "-inf",
       with(prismatic, [](World& w, JointId j) { setPrismaticLimit(w, PrismaticJointId{j}, true, 0.0f, -inff); })},
      {"length", "0",
       with(distanceJoint, [](World& w, JointId j) { setDistanceJointLength(w, DistanceJointId{j}, 0.0f); })},
      {"length", "nan",
       with(distanceJoint, [](World& w, JointId j) { setDistanceJointLength(w, DistanceJointId{j}, nanf); })},
      {"motorSpeed", "nan",
       with(wheel, [](World& w, JointId j) { setWheelMotor(w, WheelJointId{j}, true, nanf, 1.0f); })},
      {"maxMotorTorque", "-1",
       with(wheel, [](World& w, JointId j) { setWheelMotor(w, WheelJointId{j}, true, 0.0f, -1.0f); })},
      {"linearOffset.y", "inf",
       with(motor,
            [](World& w, JointId j) {
              setMotorJointTarget(w, MotorJointId{j}, {0.0f, inff}, 0.0f);
            })},
      {"angularOffset", "nan",
       with(motor, [](World& w, JointId j) { setMotorJointTarget(w, MotorJointId{j}, {}, nanf); })},
      {"target.x", "nan",
       with(mouse,
            [](World& w, JointId j) {
              setMouseTarget(w, MouseJointId{j}, {nanf, 0.0f});
            })},
      {"joint id", "0",
       with(prismatic, [](World& w, JointId j) { setRevoluteMotor(w, RevoluteJointId{j}, true, 0.0f, 0.0f); })},
      {"joint id", "0",
       with(destroyed, [](World& w, JointId j) { setDistanceJointLength(w, DistanceJointId{j}, 1.0f); })},
      {"joint id", "0", with(destroyed, [](World& w, JointId j) { w.destroyJoint(j); })},
  });
}

TEST(Rigid2dValidation, body_setters) {
  expectRejected({
      {"position.x", "nan", on([](Fixture& x) {
         x.world.setTransform(x.a, {nanf, 0.0f}, 0.0f);
       })},
      {"angle", "inf", on([](Fixture& x) { x.world.setTransform(x.a, {}, inff); })},
      {"linearVelocity.y", "nan", on([](Fixture& x) {
         x.world.setLinearVelocity(x.a, {0.0f, nanf});
       })},
      {"linearVelocity.x", "inf", on([](Fixture& x) {
         x.world.setLinearVelocity(x.ground, {inff, 0.0f});
       })},
      {"angularVelocity", "inf", on([](Fixture& x) { x.world.setAngularVelocity(x.a, inff); })},
      {"angularVelocity", "nan", on([](Fixture& x) { x.world.setAngularVelocity(x.ground, nanf); })},
      {"force.x", "nan", on([](Fixture& x) {
         x.world.applyForce(x.a, {nanf, 0.0f}, {});
       })},
      {"point.y", "inf", on([](Fixture& x) {
         x.world.applyForce(x.a, {}, {0.0f, inff});
       })},
      {"torque", "nan", on([](Fixture& x) { x.world.applyTorque(x.a, nanf); })},
      {"impulse.x", "-inf", on([](Fixture& x) {
         x.world.applyLinearImpulse(x.a, {-inff, 0.0f}, {});
       })},
      {"point.x", "nan", on([](Fixture& x) {
         x.world.applyLinearImpulse(x.a, {}, {nanf, 0.0f});
       })},
      {"mass", "0", on([](Fixture& x) {
         x.world.setMassData(x.a, {0.0f, {}, 1.0f});
       })},
      {"mass", "-1", on([](Fixture& x) {
         x.world.setMassData(x.a, {-1.0f, {}, 1.0f});
       })},
      {"mass", "nan", on([](Fixture& x) {
         x.world.setMassData(x.a, {nanf, {}, 1.0f});
       })},
      {"center.x", "inf", on([](Fixture& x) {
         x.world.setMassData(x.a, {1.0f, {inff, 0.0f}, 1.0f});
       })},
      {"rotationalInertia", "0", on([](Fixture& x) {
         x.world.setMassData(x.a, {1.0f, {}, 0.0f});
       })},
      {"rotationalInertia", "nan", on([](Fixture& x) {
         x.world.setMassData(x.a, {1.0f, {}, nanf});
       })},
      {"body id", "0", on([](Fixture& x) {
         x.world.setMassData(x.ground, {1.0f, {}, 1.0f});
       })}, // static
      {"body id", "3", on([](Fixture& x) { x.world.setTransform(x.gone, {}, 0.0f); })},
      {"body id", "3", on([](Fixture& x) { x.world.setLinearVelocity(x.gone, {}); })},
      {"body id", "3", on([](Fixture& x) { x.world.applyForce(x.gone, {}, {}); })},
      {"body id", "3", on([](Fixture& x) { x.world.setAwake(x.gone, true); })},
  });
  expectAccepted({
      {"zero velocities, forces and impulses", on([](Fixture& x) {
         x.world.setLinearVelocity(x.a, {});
         x.world.setAngularVelocity(x.a, 0.0f);
         x.world.applyForce(x.a, {}, {});
         x.world.applyTorque(x.a, 0.0f);
         x.world.applyLinearImpulse(x.a, {}, {});
         x.world.setLinearVelocity(x.ground, {1.0f, 0.0f}); // a static body ignores it
       })},
  });
}

TEST(Rigid2dValidation, queries) {
  ShapeProxy proxy = makeProxy(Circle{{}, 0.5f});
  const auto cast = [proxy](auto change) {
    return on([proxy, change](Fixture& x) {
      ShapeProxy p = proxy;
      Transform2f xf{{0.0f, 5.0f}, Rot2f::identity()};
      change(p, xf);
      (void)x.world.castShape(p, xf, {0.0f, -5.0f});
    });
  };
  expectRejected({
      {"origin.x", "nan", on([](Fixture& x) {
         (void)x.world.castRayClosest({nanf, 0.0f}, {1.0f, 0.0f});
       })},
      {"translation.y", "inf", on([](Fixture& x) {
         (void)x.world.castRayAll({}, {0.0f, inff});
       })},
      {"box.upper.x", "0", on([](Fixture& x) {
         (void)x.world.queryAABB({{1.0f, 1.0f}, {0.0f, 0.0f}});
       })},
      {"point.x", "nan", on([](Fixture& x) {
         (void)x.world.queryPoint({nanf, 0.0f});
       })},
      {"proxy.count", "0", cast([](ShapeProxy& p, Transform2f&) { p.count = 0; })},
      {"proxy.radius", "-1", cast([](ShapeProxy& p, Transform2f&) { p.radius = -1.0f; })},
      {"proxy.points[0].x", "nan", cast([](ShapeProxy& p, Transform2f&) { p.points[0].x = nanf; })},
      {"transform.p.x", "nan", cast([](ShapeProxy&, Transform2f& xf) { xf.p.x = nanf; })},
      {"transform.q.c", "nan", cast([](ShapeProxy&, Transform2f& xf) { xf.q.c = nanf; })},
      {"origin.x", "inf",
       [] {
         (void)rayCast(Circle{{}, 1.0f}, RayCastInput{{inff, 0.0f}, {1.0f, 0.0f}, 1.0f});
       }},
      {"maxFraction", "-1",
       [] {
         (void)rayCast(makeBox(1, 1), RayCastInput{{-3.0f, 0.0f}, {1.0f, 0.0f}, -1.0f});
       }},
      {"points.size", "0", [] { (void)makeProxy(std::vector<Vec2f>{}, 0.0f); }},
      {"radius", "-1",
       [] {
         (void)makeProxy(std::vector<Vec2f>{{0.0f, 0.0f}}, -1.0f);
       }},
  });
}

TEST(Rigid2dValidation, effectors) {
  const auto build = [](auto make) { return [make] { (void)make(); }; };
  expectRejected({
      {"acceleration.x", "nan", build([] {
         return GravityField({{nanf, 0.0f}, {}});
       })},
      {"region.lower.y", "inf", build([] {
         return GravityField({{}, AABB{{0.0f, inff}, {1.0f, 1.0f}}});
       })},
      {"region.upper.x", "-1", build([] {
         return GravityField({{}, AABB{{0.0f, 0.0f}, {-1.0f, 1.0f}}});
       })},
      {"acceleration.y", "inf",
       [] {
         GravityField({{}, {}}).setAcceleration({0.0f, inff});
       }},
      {"dt", "0", on([](Fixture& x) {
         GravityField({{}, {}}).apply(x.world, 0.0f);
       })},
      {"dt", "nan", on([](Fixture& x) { PointAttractor({}).apply(x.world, nanf); })},
      {"center.x", "nan", build([] {
         return PointAttractor({{nanf, 0.0f}, 1.0f, 0.0f, {}});
       })},
      {"mu", "inf", build([] {
         return PointAttractor({{}, inff, 0.0f, {}});
       })},
      {"softening", "-1", build([] {
         return PointAttractor({{}, 1.0f, -1.0f, {}});
       })},
      {"maxRadius", "0", build([] {
         return PointAttractor({{}, 1.0f, 0.0f, 0.0f});
       })},
      {"airVelocity.x", "nan",
       build([] { return WindDrag(with<WindDragSettings>([](auto& s) { s.airVelocity.x = nanf; })); })},
      {"airDensity", "-1",
       build([] { return WindDrag(with<WindDragSettings>([](auto& s) { s.airDensity = -1.0f; })); })},
      {"dragArea", "nan", build([] { return WindDrag(with<WindDragSettings>([](auto& s) { s.dragArea = nanf; })); })},
      {"linearDrag", "-1",
       build([] { return WindDrag(with<WindDragSettings>([](auto& s) { s.linearDrag = -1.0f; })); })},
      {"localCenterOfPressure.y", "inf",
       build([] { return WindDrag(with<WindDragSettings>([](auto& s) { s.localCenterOfPressure.y = inff; })); })},
      {"body", "3", on([](Fixture& x) {
         WindDrag(with<WindDragSettings>([&x](auto& s) { s.body = x.gone; })).apply(x.world, 0.1f);
       })},
      {"localPoint.x", "nan", build([] {
         return Thruster({{}, {nanf, 0.0f}});
       })},
      {"localDirection", "0", build([] {
         return Thruster({{}, {}, {0.0f, 0.0f}});
       })},
      {"localDirection.y", "inf", build([] {
         return Thruster({{}, {}, {1.0f, inff}});
       })},
      {"thrust", "nan", build([] {
         return Thruster({{}, {}, {1.0f, 0.0f}, nanf});
       })},
      {"thrust", "inf", [] { Thruster({}).setThrust(inff); }},
      {"body", "0", on([](Fixture& x) { Thruster({}).apply(x.world, 0.1f); })},
      {"localAnchorA.x", "nan",
       build([] { return SpringDamper(with<SpringDamperSettings>([](auto& s) { s.localAnchorA.x = nanf; })); })},
      {"localAnchorB.y", "inf",
       build([] { return SpringDamper(with<SpringDamperSettings>([](auto& s) { s.localAnchorB.y = inff; })); })},
      {"stiffness", "-1",
       build([] { return SpringDamper(with<SpringDamperSettings>([](auto& s) { s.stiffness = -1.0f; })); })},
      {"damping", "nan",
       build([] { return SpringDamper(with<SpringDamperSettings>([](auto& s) { s.damping = nanf; })); })},
      {"restLength", "-1",
       build([] { return SpringDamper(with<SpringDamperSettings>([](auto& s) { s.restLength = -1.0f; })); })},
      {"bodyA", "3", on([](Fixture& x) {
         SpringDamper(with<SpringDamperSettings>([&x](auto& s) { s.bodyA = x.gone; })).apply(x.world, 0.1f);
       })},
      {"bodyB", "3", on([](Fixture& x) {
         SpringDamper(with<SpringDamperSettings>([&x](auto& s) {
           s.bodyA = x.a;
           s.bodyB = x.gone;
         })).apply(x.world, 0.1f);
       })},
      {"center.y", "nan", build([] {
         return Explosion({{0.0f, nanf}});
       })},
      {"radius", "0", build([] {
         return Explosion({{}, 0.0f});
       })},
      {"impulse", "-1", build([] {
         return Explosion({{}, 1.0f, -1.0f});
       })},
      {"dt", "2", on([](Fixture& x) { Explosion({}).apply(x.world, 2.0f); })},
      {"surfaceHeight", "nan",
       [] {
         BuoyancySettings s;
         s.surfaceHeight = nanf;
         Buoyancy b(s);
       }},
      {"xMin", "nan",
       [] {
         BuoyancySettings s;
         s.xMin = nanf;
         Buoyancy b(s);
       }},
      {"xMax", "-1",
       [] {
         BuoyancySettings s;
         s.xMin = 0.0f;
         s.xMax = -1.0f;
         Buoyancy b(s);
       }},
      {"fluidDensity", "0",
       [] {
         BuoyancySettings s;
         s.fluidDensity = 0.0f;
         Buoyancy b(s);
       }},
      {"gravity.x", "inf",
       [] {
         BuoyancySettings s;
         s.gravity.x = inff;
         Buoyancy b(s);
       }},
      {"fluidVelocity.y", "nan",
       [] {
         BuoyancySettings s;
         s.fluidVelocity.y = nanf;
         Buoyancy b(s);
       }},
      {"linearDrag", "-1",
       [] {
         BuoyancySettings s;
         s.linearDrag = -1.0f;
         Buoyancy b(s);
       }},
      {"angularDrag", "inf",
       [] {
         BuoyancySettings s;
         s.angularDrag = inff;
         Buoyancy b(s);
       }},
      {"surfaceHeight", "inf", [] { Buoyancy({}).setSurfaceHeight(inff); }},
      {"fluidVelocity.x", "nan",
       [] {
         Buoyancy({}).setFluidVelocity({nanf, 0.0f});
       }},
      {"dt", "-1", on([](Fixture& x) { Buoyancy({}).apply(x.world, -1.0f); })},
  });
  expectAccepted({
      {"zero coefficients and an infinite water", on([](Fixture& x) {
         WindDrag(with<WindDragSettings>([&x](auto& s) {
           s.body = x.a;
           s.airDensity = s.dragArea = s.linearDrag = 0.0f;
         })).apply(x.world, 1.0f);
         SpringDamper(with<SpringDamperSettings>([&x](auto& s) {
           s.bodyA = x.a;
           s.bodyB = x.b;
         })).apply(x.world, 1.0f);
         Explosion({{}, 1.0f, 0.0f}).apply(x.world, 1.0f);
         BuoyancySettings s;
         s.linearDrag = s.angularDrag = 0.0f;
         Buoyancy(s).apply(x.world, 1.0f);
         Thruster({x.a, {}, {0.0f, 2.0f}, -5.0f}).apply(x.world, 1.0f);
         PointAttractor({{}, -1.0f, 0.0f, {}}).apply(x.world, 1.0f);
       })},
  });
}

} // namespace
} // namespace impetus::rigid2d
