// The scene-file loader (docs/scene-format.md). Every value is checked here, with the JSON path
// of the value in the message, before the world or the rope and cloth builders see it; their own
// checks stay as a backstop, and an error they raise is re-labelled with the element's path.
#include "scene_file.hpp"

#include "json_fields.hpp"

#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/particles/cloth.hpp>
#include <impetus/particles/rope.hpp>

#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <random>

namespace impetus::cli {
namespace {

using json_fields::arrayOf;
using json_fields::at;
using json_fields::fail;
using json_fields::Fields;
using json_fields::forEach;
using json_fields::index;
using nlohmann::json;

/// More particles than this from one file is a mistake (about 1 GB of state), not a scene.

/// A rotation: {"axis": [x, y, z], "angle_deg": a} or {"yaw_deg", "pitch_deg", "roll_deg"}
/// (R = Rz(yaw) Ry(pitch) Rx(roll)).
Quatf rotation(const json& j, const std::string& where) {
  Fields f(j, where);
  Quatf q = Quatf::identity();
  if (f.has("axis")) {
    const Vec3f axis = f.requiredVec3("axis");
    const float angle = degToRad(f.requiredReal("angle_deg"));
    if (!(lengthSquared(axis) > 0.0f)) {
      fail(f.path("axis"), "rotation axis must be non-zero");
    }
    q = Quatf::fromAxisAngle(axis, angle);
  } else {
    q = Quatf::fromEuler(degToRad(f.real("yaw_deg", 0.0)), degToRad(f.real("pitch_deg", 0.0)),
                         degToRad(f.real("roll_deg", 0.0)));
  }
  f.done();
  return q;
}

class Loader {
public:
  explicit Loader(ParticleScene& scene) : scene_(scene) {}

  void load(const json& doc) {
    Fields top(doc, "");
    scene_.description = top.text("description", "");
    if (const json* w = top.find("world")) {
      scene_.world.setSettings(settings(*w));
    }
    // Read in dependency order: particles, ropes and cloths before the springs and constraints
    // that may name them.
    for (const char* key :
         {"obstacles", "particles", "ropes", "cloths", "springs", "constraints", "attractors", "emitters"}) {
      (void)top.has(key);
    }
    top.done();
    forEach(doc, "obstacles", [&](const json& j, const std::string& where) { obstacle(j, where); });
    forEach(doc, "particles", [&](const json& j, const std::string& where) { particles(j, where); });
    forEach(doc, "ropes", [&](const json& j, const std::string& where) { rope(j, where); });
    forEach(doc, "cloths", [&](const json& j, const std::string& where) { cloth(j, where); });
    forEach(doc, "springs", [&](const json& j, const std::string& where) { spring(j, where); });
    forEach(doc, "constraints", [&](const json& j, const std::string& where) { constraint(j, where); });
    forEach(doc, "attractors", [&](const json& j, const std::string& where) { attractor(j, where); });
    forEach(doc, "emitters", [&](const json& j, const std::string& where) { emitter(j, where); });
  }

private:
  /// A travelling gust on top of the steady wind w: w + A sin(2 pi (t / T - (u . x) / L)), with
  /// u the wind's direction (+x in still air): the air at a point varies with period T, and the
  /// pattern moves downwind at L / T. A steady wind brings a flag to a steady pose; a gust
  /// makes it flap.
  static std::function<Vec3f(const Vec3f&, float)> gust(const json& j, const std::string& where, const Vec3f& wind) {
    Fields f(j, where);
    const Vec3f amplitude = f.requiredVec3("amplitude");
    const float period = f.requiredPositive("period");
    const float wavelength = f.requiredPositive("wavelength");
    f.done();
    const Vec3f u = lengthSquared(wind) > 0.0f ? normalize(wind) : Vec3f::unitX();
    return [=](const Vec3f& x, float t) {
      return wind + amplitude * std::sin(2.0f * pi<float> * (t / period - dot(u, x) / wavelength));
    };
  }

  static ParticleWorldSettings settings(const json& j) {
    Fields f(j, "world");
    ParticleWorldSettings s;
    s.gravity = f.vec3("gravity", s.gravity);
    const std::string integrator = f.text("integrator", "semi-implicit-euler");
    if (integrator == "semi-implicit-euler") {
      s.integrator = ParticleIntegrator::semiImplicitEuler;
    } else if (integrator == "explicit-euler") {
      s.integrator = ParticleIntegrator::explicitEuler;
    } else if (integrator == "velocity-verlet") {
      s.integrator = ParticleIntegrator::velocityVerlet;
    } else if (integrator == "rk4") {
      s.integrator = ParticleIntegrator::rk4;
    } else {
      fail(f.path("integrator"),
           "unknown integrator '" + integrator + "' (semi-implicit-euler, explicit-euler, velocity-verlet, rk4)");
    }
    s.substeps = static_cast<int>(f.integer("substeps", s.substeps, 1, 1000));
    s.wind = f.vec3("wind", s.wind);
    if (const json* g = f.find("gust")) {
      s.windField = gust(*g, f.path("gust"), s.wind);
    }
    s.linearDrag = f.nonNegative("linear_drag", s.linearDrag);
    s.dragCoefficient = f.nonNegative("drag_coefficient", s.dragCoefficient);
    s.airDensity = f.nonNegative("air_density", s.airDensity);
    s.restThreshold = f.nonNegative("rest_threshold", s.restThreshold);
    s.particleCollisions = f.boolean("particle_collisions", s.particleCollisions);
    s.particleRestitution = f.fraction("particle_restitution", s.particleRestitution);
    f.done();
    return s;
  }

  // Particles ------------------------------------------------------------------------------

  void addName(const std::string& name, ParticleId id, const std::string& field) {
    if (name.empty()) {
      return;
    }
    if (!names_.emplace(name, id).second) {
      fail(field, "duplicate particle name '" + name + "'");
    }
  }

  ParticleId create(const ParticleDef& def, const std::string& name, const std::string& where) {
    if (static_cast<std::int64_t>(created_.size()) >= maxSceneParticles) {
      fail(where, "more than " + std::to_string(maxSceneParticles) + " particles in the scene");
    }
    const ParticleId id = at(where, [&] { return scene_.world.createParticle(def); });
    created_.push_back(id);
    scene_.particleNames.push_back(name);
    return id;
  }

  void particles(const json& j, const std::string& where) {
    Fields f(j, where);
    ParticleDef def;
    def.velocity = f.vec3("velocity", {});
    def.mass = f.positive("mass", def.mass);
    def.radius = f.positive("radius", def.radius);
    if (f.has("lifetime")) {
      def.lifetime = f.positive("lifetime", 0.0);
    }
    def.pinned = f.boolean("pinned", false);
    const std::string name = f.text("name", "");

    // Where the particles go: one position, or a generator.
    std::vector<Vec3f> positions;
    int given = 0;
    for (const char* key : {"position", "grid", "line", "random_box"}) {
      given += f.has(key) ? 1 : 0;
    }
    if (given != 1) {
      fail(where, "give exactly one of position, grid, line or random_box");
    }
    if (f.has("position")) {
      positions.push_back(f.requiredVec3("position"));
    } else if (f.has("grid")) {
      Fields g(f.require("grid"), f.path("grid"));
      const Vec3f origin = g.requiredVec3("origin");
      const Vec3f spacing = g.requiredVec3("spacing");
      const json& countsJson = g.require("counts");
      if (!countsJson.is_array() || countsJson.size() != 3) {
        fail(g.path("counts"), "expected an array of 3 whole numbers, got " + countsJson.dump());
      }
      std::int64_t counts[3];
      for (std::size_t a = 0; a < 3; ++a) {
        counts[a] = Fields::integerAt(countsJson[a], index(g.path("counts"), a), 1, maxSceneParticles);
      }
      g.done();
      if (counts[0] * counts[1] * counts[2] > maxSceneParticles) {
        fail(g.path("counts"), "more than " + std::to_string(maxSceneParticles) + " particles");
      }
      for (std::int64_t k = 0; k < counts[2]; ++k) {
        for (std::int64_t jy = 0; jy < counts[1]; ++jy) {
          for (std::int64_t ix = 0; ix < counts[0]; ++ix) {
            positions.push_back(origin + Vec3f{static_cast<float>(ix) * spacing.x, static_cast<float>(jy) * spacing.y,
                                               static_cast<float>(k) * spacing.z});
          }
        }
      }
    } else if (f.has("line")) {
      Fields l(f.require("line"), f.path("line"));
      const Vec3f from = l.requiredVec3("from");
      const Vec3f to = l.requiredVec3("to");
      const std::int64_t count = Fields::integerAt(l.require("count"), l.path("count"), 1, maxSceneParticles);
      l.done();
      for (std::int64_t k = 0; k < count; ++k) {
        const float t = count == 1 ? 0.0f : static_cast<float>(k) / static_cast<float>(count - 1);
        positions.push_back(lerp(from, to, t));
      }
    } else {
      // Uniform in an axis-aligned box, from mt19937's raw output (the same on every platform).
      Fields r(f.require("random_box"), f.path("random_box"));
      const Vec3f lo = r.requiredVec3("min");
      const Vec3f hi = r.requiredVec3("max");
      if (!(hi.x >= lo.x && hi.y >= lo.y && hi.z >= lo.z)) {
        fail(r.path("max"), "must be >= min in every component");
      }
      const std::int64_t count = Fields::integerAt(r.require("count"), r.path("count"), 1, maxSceneParticles);
      std::mt19937 rng(static_cast<std::uint32_t>(r.integer("seed", 1, 0, 4294967295)));
      r.done();
      const auto uniform = [&](float a, float b) {
        return a + (b - a) * static_cast<float>(static_cast<double>(rng()) / 4294967296.0);
      };
      for (std::int64_t k = 0; k < count; ++k) {
        const float x = uniform(lo.x, hi.x);
        const float y = uniform(lo.y, hi.y);
        const float z = uniform(lo.z, hi.z);
        positions.push_back({x, y, z});
      }
    }
    f.done();

    const bool single = positions.size() == 1 && f.has("position");
    for (std::size_t k = 0; k < positions.size(); ++k) {
      def.position = positions[k];
      const std::string particleName = name.empty() ? "" : (single ? name : index(name, k));
      addName(particleName, create(def, particleName, where), f.path("name"));
    }
  }

  /// A particle named in a spring or constraint: a whole number (its place in creation order,
  /// as in the output) or a name.
  ParticleId particle(const json& j, const std::string& field) const {
    if (j.is_number_integer()) {
      const std::int64_t k = j.get<std::int64_t>();
      if (k < 0 || k >= static_cast<std::int64_t>(created_.size())) {
        throwInvalid(field, static_cast<double>(k),
                     "no such particle (the scene has " + std::to_string(created_.size()) + ")");
      }
      return created_[static_cast<std::size_t>(k)];
    }
    if (j.is_string()) {
      const auto it = names_.find(j.get<std::string>());
      if (it == names_.end()) {
        fail(field, "no particle named '" + j.get<std::string>() + "'");
      }
      return it->second;
    }
    fail(field, "expected a particle name or number, got " + j.dump());
  }

  /// The second end of a spring or constraint: particle `b` or the fixed point `anchor`.
  void secondEnd(Fields& f, ParticleId& b, Vec3f& anchor) const {
    const bool hasB = f.has("b");
    const bool hasAnchor = f.has("anchor");
    if (hasB == hasAnchor) {
      fail(f.where(), "give exactly one of b (a particle) or anchor (a fixed point)");
    }
    if (hasB) {
      b = particle(f.require("b"), f.path("b"));
    } else {
      anchor = f.requiredVec3("anchor");
    }
  }

  void spring(const json& j, const std::string& where) {
    Fields f(j, where);
    SpringDef def;
    def.a = particle(f.require("a"), f.path("a"));
    secondEnd(f, def.b, def.anchor);
    if (def.a == def.b) {
      fail(f.path("b"), "a spring needs two different particles");
    }
    def.stiffness = f.nonNegative("stiffness", def.stiffness);
    def.damping = f.nonNegative("damping", def.damping);
    if (f.has("rest_length")) {
      def.restLength = f.nonNegative("rest_length", 0.0);
    }
    f.done();
    (void)at(where, [&] { return scene_.world.addSpring(def); });
  }

  void constraint(const json& j, const std::string& where) {
    Fields f(j, where);
    DistanceConstraintDef def;
    def.a = particle(f.require("a"), f.path("a"));
    secondEnd(f, def.b, def.anchor);
    if (def.a == def.b) {
      fail(f.path("b"), "a constraint needs two different particles");
    }
    if (f.has("length")) {
      def.length = f.nonNegative("length", 0.0);
    }
    def.compliance = f.nonNegative("compliance", def.compliance);
    def.maxOnly = f.boolean("max_only", def.maxOnly);
    f.done();
    (void)at(where, [&] { return scene_.world.addDistanceConstraint(def); });
  }

  // Ropes and cloths ---------------------------------------------------------------------------

  void rope(const json& j, const std::string& where) {
    Fields f(j, where);
    RopeDef def;
    def.start = f.requiredVec3("start");
    def.end = f.requiredVec3("end");
    if (!(distance(def.start, def.end) > 0.0f)) {
      fail(f.path("end"), "must differ from start (the rope needs a length)");
    }
    def.segments = static_cast<int>(f.integer("segments", def.segments, 1, 1'000'000));
    def.totalMass = f.positive("total_mass", def.totalMass);
    def.particleRadius = f.positive("particle_radius", def.particleRadius);
    const std::string model = f.text("model", "xpbd");
    if (model == "xpbd") {
      def.model = RopeModel::xpbd;
    } else if (model == "book-springs") {
      def.model = RopeModel::bookSprings;
    } else {
      fail(f.path("model"), "unknown rope model '" + model + "' (xpbd, book-springs)");
    }
    def.compliance = f.nonNegative("compliance", def.compliance);
    def.stiffness = f.positive("stiffness", def.stiffness);
    def.damping = f.nonNegative("damping", def.damping);
    def.pinStart = f.boolean("pin_start", def.pinStart);
    def.pinEnd = f.boolean("pin_end", def.pinEnd);
    const std::string name = f.text("name", "");
    f.done();
    if (static_cast<std::int64_t>(created_.size()) + def.segments + 1 > maxSceneParticles) {
      fail(f.path("segments"), "more than " + std::to_string(maxSceneParticles) + " particles in the scene");
    }
    const Rope made = at(where, [&] { return createRope(scene_.world, def); });
    adopt(made.particles, name, f.path("name"));
    ++scene_.ropeCount;
  }

  void cloth(const json& j, const std::string& where) {
    Fields f(j, where);
    ClothDef def;
    def.origin = f.requiredVec3("origin");
    def.across = f.vec3("across", def.across);
    def.down = f.vec3("down", def.down);
    def.rows = static_cast<int>(f.integer("rows", def.rows, 2, 10'000));
    def.columns = static_cast<int>(f.integer("columns", def.columns, 2, 10'000));
    if (!(lengthSquared(cross(def.across, def.down)) > 0.0f)) {
      fail(f.path("down"), "must be non-zero and not parallel to across");
    }
    def.totalMass = f.positive("total_mass", def.totalMass);
    def.particleRadius = f.positive("particle_radius", def.particleRadius);
    const std::string model = f.text("model", "xpbd");
    if (model == "xpbd") {
      def.model = ClothModel::xpbd;
    } else if (model == "book-springs") {
      def.model = ClothModel::bookSprings;
    } else {
      fail(f.path("model"), "unknown cloth model '" + model + "' (xpbd, book-springs)");
    }
    def.shear = f.boolean("shear", def.shear);
    def.bend = f.boolean("bend", def.bend);
    def.structuralCompliance = f.nonNegative("structural_compliance", def.structuralCompliance);
    def.shearCompliance = f.nonNegative("shear_compliance", def.shearCompliance);
    def.bendCompliance = f.nonNegative("bend_compliance", def.bendCompliance);
    def.structuralStiffness = f.positive("structural_stiffness", def.structuralStiffness);
    def.shearStiffness = f.positive("shear_stiffness", def.shearStiffness);
    def.bendStiffness = f.positive("bend_stiffness", def.bendStiffness);
    def.damping = f.nonNegative("damping", def.damping);
    // Pins: single particles [row, column], whole rows and whole columns.
    if (const json* pins = f.find("pinned")) {
      if (!pins->is_array()) {
        fail(f.path("pinned"), "expected an array of [row, column] pairs, got " + pins->dump());
      }
      for (std::size_t k = 0; k < pins->size(); ++k) {
        const std::string field = index(f.path("pinned"), k);
        const json& pin = (*pins)[k];
        if (!pin.is_array() || pin.size() != 2) {
          fail(field, "expected [row, column], got " + pin.dump());
        }
        def.pinned.push_back({static_cast<int>(Fields::integerAt(pin[0], field + "[0]", 0, def.rows - 1)),
                              static_cast<int>(Fields::integerAt(pin[1], field + "[1]", 0, def.columns - 1))});
      }
    }
    const auto lines = [&](const std::string& key, int limit, auto&& pinLine) {
      if (const json* list = f.find(key)) {
        if (!list->is_array()) {
          fail(f.path(key), "expected an array of whole numbers, got " + list->dump());
        }
        for (std::size_t k = 0; k < list->size(); ++k) {
          pinLine(static_cast<int>(Fields::integerAt((*list)[k], index(f.path(key), k), 0, limit - 1)));
        }
      }
    };
    lines("pin_rows", def.rows, [&](int r) { def.pinRow(r); });
    lines("pin_columns", def.columns, [&](int c) {
      for (int r = 0; r < def.rows; ++r) {
        def.pinned.push_back({r, c});
      }
    });
    const std::string name = f.text("name", "");
    f.done();
    if (static_cast<std::int64_t>(created_.size()) + std::int64_t{def.rows} * def.columns > maxSceneParticles) {
      fail(f.path("rows"), "more than " + std::to_string(maxSceneParticles) + " particles in the scene");
    }
    const Cloth made = at(where, [&] { return createCloth(scene_.world, def); });
    adopt(made.particles, name, f.path("name"));
    ++scene_.clothCount;
  }

  /// Records particles a builder made; with a name, particle k is "name[k]".
  void adopt(const std::vector<ParticleId>& ids, const std::string& name, const std::string& field) {
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const std::string particleName = name.empty() ? "" : index(name, k);
      created_.push_back(ids[k]);
      scene_.particleNames.push_back(particleName);
      addName(particleName, ids[k], field);
    }
  }

  // Obstacles, attractors, emitters ------------------------------------------------------------

  void obstacle(const json& j, const std::string& where) {
    Fields f(j, where);
    const json& typeJson = f.require("type");
    if (!typeJson.is_string()) {
      fail(f.path("type"), "expected a string, got " + typeJson.dump());
    }
    const std::string type = typeJson.get<std::string>();
    SurfaceMaterial material;
    material.restitution = f.fraction("restitution", material.restitution);
    material.friction = f.nonNegative("friction", material.friction);
    if (type == "plane") {
      PlaneObstacle plane;
      plane.normal = f.vec3("normal", plane.normal);
      if (!(lengthSquared(plane.normal) > 0.0f)) {
        fail(f.path("normal"), "must be non-zero");
      }
      plane.offset = f.real("offset", 0.0);
      f.done();
      (void)at(where, [&] { return scene_.world.addObstacle(plane, material); });
    } else if (type == "sphere") {
      SphereObstacle sphere;
      sphere.center = f.requiredVec3("center");
      sphere.radius = f.requiredPositive("radius");
      f.done();
      (void)at(where, [&] { return scene_.world.addObstacle(sphere, material); });
    } else if (type == "box") {
      BoxObstacle box;
      box.center = f.requiredVec3("center");
      const Vec3f half = f.requiredVec3("half_extents");
      for (int a = 0; a < 3; ++a) {
        requirePositive(half[a], index(f.path("half_extents"), static_cast<std::size_t>(a)));
      }
      box.halfExtents = half;
      if (const json* r = f.find("rotation")) {
        box.rotation = rotation(*r, f.path("rotation"));
      }
      f.done();
      (void)at(where, [&] { return scene_.world.addObstacle(box, material); });
    } else if (type == "capsule") {
      CapsuleObstacle capsule;
      capsule.pointA = f.requiredVec3("a");
      capsule.pointB = f.requiredVec3("b");
      capsule.radius = f.requiredPositive("radius");
      f.done();
      (void)at(where, [&] { return scene_.world.addObstacle(capsule, material); });
    } else {
      fail(f.path("type"), "unknown obstacle type '" + type + "' (plane, sphere, box, capsule)");
    }
  }

  void attractor(const json& j, const std::string& where) {
    Fields f(j, where);
    Attractor a;
    a.position = f.requiredVec3("position");
    a.strength = f.real("strength", a.strength);
    a.softening = f.positive("softening", a.softening);
    f.done();
    at(where, [&] { scene_.world.addAttractor(a); });
    ++scene_.attractorCount;
  }

  void emitter(const json& j, const std::string& where) {
    Fields f(j, where);
    EmitterDef def;
    def.position = f.requiredVec3("position");
    def.direction = f.vec3("direction", def.direction);
    if (!(lengthSquared(def.direction) > 0.0f)) {
      fail(f.path("direction"), "must be non-zero");
    }
    const double cone = f.number("cone_angle_deg", 180.0);
    if (!(cone >= 0.0 && cone <= 180.0)) {
      throwInvalid(f.path("cone_angle_deg"), cone, "must be in [0, 180] degrees");
    }
    def.coneAngle = degToRad(static_cast<float>(cone));
    def.minSpeed = f.nonNegative("min_speed", def.minSpeed);
    def.maxSpeed = f.nonNegative("max_speed", def.maxSpeed);
    if (def.maxSpeed < def.minSpeed) {
      throwInvalid(f.path("max_speed"), def.maxSpeed, "must be >= min_speed");
    }
    def.rate = f.nonNegative("rate", def.rate);
    def.burst = static_cast<int>(f.integer("burst", def.burst, 0, 1'000'000));
    if (f.has("duration")) {
      def.duration = f.nonNegative("duration", 0.0);
    }
    def.minLifetime = f.positive("min_lifetime", def.minLifetime);
    def.maxLifetime = f.positive("max_lifetime", def.maxLifetime);
    if (def.maxLifetime < def.minLifetime) {
      throwInvalid(f.path("max_lifetime"), def.maxLifetime, "must be >= min_lifetime");
    }
    def.mass = f.positive("mass", def.mass);
    def.radius = f.positive("radius", def.radius);
    def.planar = f.boolean("planar", def.planar);
    def.seed = static_cast<std::uint32_t>(f.integer("seed", def.seed, 0, 4294967295));
    f.done();
    (void)at(where, [&] { return scene_.world.addEmitter(def); });
    ++scene_.emitterCount;
  }

  ParticleScene& scene_;
  std::vector<ParticleId> created_;
  std::map<std::string, ParticleId> names_;
};

} // namespace

ParticleScene parseScene(const std::string& jsonText) {
  const json doc = json_fields::parseObject(jsonText, "a JSON object (docs/scene-format.md)");
  ParticleScene scene;
  Loader(scene).load(doc);
  return scene;
}

ParticleScene loadScene(const std::string& path) { return parseScene(json_fields::readFile(path)); }

} // namespace impetus::cli
