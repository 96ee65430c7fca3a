// 2D buoyancy (effectors.hpp): the submerged area of a shape below a horizontal water line and
// the Buoyancy effector built on it.
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/rigid2d/effectors.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace impetus::rigid2d {

namespace {

/// Room for an outline: a rounded polygon gives at most 8 corners with sum(k_i) <= 64 + 8
/// chords (k_i + 1 points each, so <= 80), and each of the three clips adds at most one point.
constexpr int maxOutline = 96;
/// The largest angle one chord of an arc spans, rad.
constexpr float maxChordAngle = pi<float> / 32.0f;

struct Outline {
  std::array<Vec2f, maxOutline> points{};
  int count = 0;

  void push(const Vec2f& p) noexcept {
    if (count < maxOutline) {
      points[static_cast<std::size_t>(count++)] = p;
    }
  }
};

/// Sutherland-Hodgman against one half-plane: keeps the part of the convex outline `in` where
/// dot(n, p) <= offset.
void clip(const Outline& in, const Vec2f& n, float offset, Outline& out) {
  out.count = 0;
  for (int i = 0; i < in.count; ++i) {
    const Vec2f& a = in.points[static_cast<std::size_t>(i)];
    const Vec2f& b = in.points[static_cast<std::size_t>((i + 1) % in.count)];
    const float da = dot(n, a) - offset;
    const float db = dot(n, b) - offset;
    if (da <= 0.0f) {
      out.push(a);
    }
    if ((da < 0.0f && db > 0.0f) || (da > 0.0f && db < 0.0f)) {
      out.push(a + (b - a) * (da / (da - db)));
    }
  }
}

/// Area and centroid of a convex outline (counter-clockwise), as a fan of triangles from its
/// first point (relative coordinates keep float cancellation small).
SubmergedArea areaOf(const Outline& o) {
  SubmergedArea result;
  if (o.count < 3) {
    return result;
  }
  const Vec2f origin = o.points[0];
  float area = 0.0f;
  Vec2f moment;
  for (int i = 1; i + 1 < o.count; ++i) {
    const Vec2f e1 = o.points[static_cast<std::size_t>(i)] - origin;
    const Vec2f e2 = o.points[static_cast<std::size_t>(i) + 1] - origin;
    const float a = 0.5f * cross(e1, e2);
    area += a;
    moment += (e1 + e2) * (a / 3.0f);
  }
  if (!(area > 0.0f)) {
    return result;
  }
  result.area = area;
  result.centroid = origin + moment / area;
  return result;
}

/// The world outline of a convex core (1 point: a circle, 2: a capsule, 3 to 8: a polygon,
/// counter-clockwise) inflated by `radius`: every corner's arc from the previous edge's normal
/// to the next edge's normal is replaced by chords of at most maxChordAngle.
void roundedOutline(const Vec2f* core, int n, float radius, const Transform2f& xf, Outline& out) {
  out.count = 0;
  if (radius <= 0.0f) {
    for (int i = 0; i < n; ++i) {
      out.push(transformPoint(xf, core[i]));
    }
    return;
  }
  if (n == 1) {
    const int k = static_cast<int>(std::ceil(2.0f * pi<float> / maxChordAngle));
    for (int j = 0; j < k; ++j) {
      const Rot2f q = Rot2f::fromAngle(2.0f * pi<float> * static_cast<float>(j) / static_cast<float>(k));
      out.push(transformPoint(xf, core[0] + Vec2f{q.c, q.s} * radius));
    }
    return;
  }
  // Outward normal of edge i -> i + 1 of a counter-clockwise outline: the edge turned -90 deg.
  const auto normal = [&](int i) {
    const Vec2f e = core[(i + 1) % n] - core[i];
    return normalize(Vec2f{e.y, -e.x});
  };
  for (int i = 0; i < n; ++i) {
    const Vec2f from = normal((i + n - 1) % n);
    const Vec2f to = normal(i);
    // The corner's turn, in (0, pi] for a convex core (pi for a capsule's ends).
    float turn = std::atan2(cross(from, to), dot(from, to));
    if (turn < 0.0f) {
      turn += 2.0f * pi<float>;
    }
    const int k = std::max(1, static_cast<int>(std::ceil(turn / maxChordAngle)));
    for (int j = 0; j <= k; ++j) {
      const Rot2f q = Rot2f::fromAngle(turn * static_cast<float>(j) / static_cast<float>(k));
      out.push(transformPoint(xf, core[i] + rotate(q, from) * radius));
    }
  }
}

/// Clips a world outline to the water (y <= surfaceY, xMin <= x <= xMax) and measures it.
SubmergedArea clipToWater(Outline& a, float surfaceY, float xMin, float xMax) {
  Outline b;
  clip(a, {0.0f, 1.0f}, surfaceY, b);
  if (std::isfinite(xMin)) {
    clip(b, {-1.0f, 0.0f}, -xMin, a);
  } else {
    a = b;
  }
  if (std::isfinite(xMax)) {
    clip(a, {1.0f, 0.0f}, xMax, b);
    return areaOf(b);
  }
  return areaOf(a);
}

/// A circle below y = surfaceY, exactly: with d the height of the centre above the surface
/// (|d| < r), the circular segment below the chord has area r^2 acos(d / r) - d sqrt(r^2 - d^2)
/// and its centroid lies 2 (r^2 - d^2)^(3/2) / (3 A) below the centre.
SubmergedArea circleBelow(const Vec2f& center, float r, float surfaceY) {
  SubmergedArea result;
  const float d = center.y - surfaceY;
  if (d >= r) {
    return result;
  }
  if (d <= -r) {
    result.area = pi<float> * r * r;
    result.centroid = center;
    return result;
  }
  const float h2 = r * r - d * d; // half-chord squared
  const float h = std::sqrt(h2);
  const float area = r * r * std::acos(d / r) - d * h;
  if (!(area > 0.0f)) {
    return result;
  }
  result.area = area;
  result.centroid = {center.x, center.y - 2.0f * h2 * h / (3.0f * area)};
  return result;
}

} // namespace

SubmergedArea submergedArea(const ShapeGeometry& shape, const Transform2f& xf, float surfaceY, float xMin, float xMax) {
  Outline outline;
  if (const auto* circle = std::get_if<Circle>(&shape)) {
    const Vec2f c = transformPoint(xf, circle->center);
    const float r = circle->radius;
    if (c.x - r >= xMin && c.x + r <= xMax) {
      return circleBelow(c, r, surfaceY);
    }
    roundedOutline(&circle->center, 1, r, xf, outline);
  } else if (const auto* capsule = std::get_if<Capsule>(&shape)) {
    const std::array<Vec2f, 2> core{capsule->center1, capsule->center2};
    roundedOutline(core.data(), 2, capsule->radius, xf, outline);
  } else if (const auto* polygon = std::get_if<Polygon>(&shape)) {
    roundedOutline(polygon->vertices.data(), polygon->count, polygon->radius, xf, outline);
  } else {
    return {}; // segments and chain segments enclose no area
  }
  return clipToWater(outline, surfaceY, xMin, xMax);
}

// ---------------------------------------------------------------------------------------------

Buoyancy::Buoyancy(const BuoyancySettings& settings) : settings_(settings) {
  requireFinite(static_cast<double>(settings_.surfaceHeight), "surfaceHeight");
  if (std::isnan(settings_.xMin)) {
    throwInvalid("xMin", static_cast<double>(settings_.xMin), "must not be NaN");
  }
  if (std::isnan(settings_.xMax)) {
    throwInvalid("xMax", static_cast<double>(settings_.xMax), "must not be NaN");
  }
  if (settings_.xMax < settings_.xMin) {
    throwInvalid("xMax", static_cast<double>(settings_.xMax), "must be >= xMin");
  }
  requirePositive(static_cast<double>(settings_.fluidDensity), "fluidDensity");
  requireFinite(settings_.gravity, "gravity");
  requireFinite(settings_.fluidVelocity, "fluidVelocity");
  requireNonNegative(static_cast<double>(settings_.linearDrag), "linearDrag");
  requireNonNegative(static_cast<double>(settings_.angularDrag), "angularDrag");
}

void Buoyancy::setSurfaceHeight(float surfaceHeight) {
  settings_.surfaceHeight = static_cast<float>(requireFinite(static_cast<double>(surfaceHeight), "surfaceHeight"));
}

void Buoyancy::setFluidVelocity(const Vec2f& velocity) {
  settings_.fluidVelocity = requireFinite(velocity, "fluidVelocity");
}

void Buoyancy::apply(World& world, float dt) {
  if (!(dt > 0.0f && dt <= 1.0f)) {
    throwInvalid("dt", static_cast<double>(dt), "time step must be in (0, 1] s");
  }
  const float tau = predictionFraction(world) * dt;
  world.bodyIds(bodies_);
  for (const BodyId body : bodies_) {
    if (world.bodyType(body) != BodyType::dynamicBody || !world.isAwake(body)) {
      continue;
    }
    const Transform2f xf = world.transform(body);
    const Vec2f center = world.worldCenterOfMass(body);
    const Vec2f v = world.linearVelocity(body);
    const float w = world.angularVelocity(body);
    // The body placed tau = beta dt ahead (predictionFraction): the buoyant force is a spring
    // in the depth, evaluated there. Points found there act through the same offsets now.
    Transform2f predicted;
    predicted.q = mul(Rot2f::fromAngle(w * tau), xf.q);
    const Vec2f predictedCenter = center + v * tau;
    predicted.p = predictedCenter - rotate(predicted.q, inverseRotate(xf.q, center - xf.p));

    Vec2f buoyantForce;
    float buoyantTorque = 0.0f;
    Vec2f dragForce;
    float dragTorque = 0.0f;
    float submerged = 0.0f;
    float angularDragInertia = 0.0f; // sum of rho A_sub^2, kg m^2
    world.bodyShapes(body, shapes_);
    for (const ShapeId shape : shapes_) {
      if (world.isSensor(shape)) {
        continue;
      }
      const SubmergedArea part =
          submergedArea(world.shapeGeometry(shape), predicted, settings_.surfaceHeight, settings_.xMin, settings_.xMax);
      if (!(part.area > 0.0f)) {
        continue;
      }
      submerged += part.area;
      angularDragInertia += settings_.fluidDensity * part.area * part.area;
      const Vec2f r = part.centroid - predictedCenter;
      // Archimedes: the weight of the displaced fluid, rho A_sub |g|, against gravity (N).
      const Vec2f fb = settings_.gravity * (-settings_.fluidDensity * part.area);
      buoyantForce += fb;
      buoyantTorque += cross(r, fb);
      // Linear drag at the submerged centroid on its velocity relative to the fluid,
      // -c_lin rho A_sub v_rel (N).
      const Vec2f vRel = v + cross(w, r) - settings_.fluidVelocity;
      const Vec2f fd = vRel * (-settings_.linearDrag * settings_.fluidDensity * part.area);
      dragForce += fd;
      dragTorque += cross(r, fd);
    }
    if (!(submerged > 0.0f)) {
      continue;
    }
    // Explicit drag overshoots when c A dt exceeds the mass (or c_ang A dt the inertia): limit
    // the step's drag to what at most stops the body relative to the water.
    const float m = world.mass(body);
    const float inertia = world.rotationalInertia(body);
    const float linearRate = settings_.linearDrag * settings_.fluidDensity * submerged * dt; // kg
    const float linearScale = linearRate > m ? m / linearRate : 1.0f;
    const float angularRate = settings_.angularDrag * angularDragInertia * dt; // kg m^2
    const float angularScale = inertia > 0.0f && angularRate > inertia ? inertia / angularRate : 1.0f;
    // -c_ang rho A_sub^2 w (N m).
    const float angularDragTorque = -settings_.angularDrag * angularDragInertia * w * angularScale;
    world.applyForce(body, buoyantForce + dragForce * linearScale, center);
    world.applyTorque(body, buoyantTorque + dragTorque * linearScale + angularDragTorque);
  }
}

} // namespace impetus::rigid2d
