// Ray casts against spheres, capsules and hulls. The ray is brought into the body's frame (a
// rigid motion keeps its fractions), cast against the shape there, and its hit's normal turned
// back; the hit point is taken on the world ray, origin + fraction translation.
#include <impetus/math/validate.hpp>
#include <impetus/rigid3d/ray_cast.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <variant>

namespace impetus::rigid3d {

namespace {

/// A ray in the shape's frame, with a translation of non-zero length.
struct LocalRay {
  Vec3f origin;
  Vec3f translation;
  float maxFraction = 1.0f;
};

/// A hit in the shape's frame.
struct LocalHit {
  Vec3f normal;
  float fraction = 0.0f;
  bool hit = false;
};

/// The earlier of two hits.
LocalHit first(const LocalHit& a, const LocalHit& b) {
  if (!a.hit) {
    return b;
  }
  if (!b.hit) {
    return a;
  }
  return b.fraction < a.fraction ? b : a;
}

/// The first hit on a ball from outside it (an origin inside or on it: none). In the ray's unit
/// direction d, with s the origin from the centre: the ray comes closest to the centre at
/// distance t = -s.d along it, at c = s + t d, and enters sqrt(r^2 - |c|^2) before that
/// (Pythagoras). This, rather than the quadratic |s + t d|^2 = r^2 in t, keeps the digits of a
/// small ball far down a long ray (Box2D v3's circle cast).
LocalHit castBall(const Vec3f& center, float radius, const LocalRay& ray) {
  const Vec3f s = ray.origin - center;
  const float rr = radius * radius;
  if (dot(s, s) <= rr) {
    return {};
  }
  const float rayLength = length(ray.translation);
  const Vec3f d = ray.translation * (1.0f / rayLength);
  const float t = -dot(s, d); // m
  if (t < 0.0f) {
    return {}; // outside and heading away
  }
  const Vec3f c = s + d * t;
  const float cc = dot(c, c);
  if (cc > rr) {
    return {}; // passes by
  }
  // Outside, the entry is not behind the origin; a negative value is rounding.
  const float distance = std::max(t - std::sqrt(rr - cc), 0.0f); // m along the ray
  const float fraction = distance / rayLength;
  if (fraction > ray.maxFraction) {
    return {};
  }
  return {normalize(s + d * distance), fraction, true};
}

/// The first hit on the side of the cylinder of radius r about the segment [c1, c1 + L a] (a a
/// unit axis), from outside the infinite cylinder: the ball cast's construction in the plane
/// across the axis, its hit kept where it lies between the end planes.
LocalHit castCylinderSide(const Vec3f& c1, const Vec3f& a, float axisLength, float radius, const LocalRay& ray) {
  const Vec3f s = ray.origin - c1;
  const float along = dot(s, a);
  const Vec3f sAcross = s - a * along;
  const float rr = radius * radius;
  if (dot(sAcross, sAcross) <= rr) {
    return {}; // inside the infinite cylinder: the ray can only enter through an end ball
  }
  const Vec3f dAcross = ray.translation - a * dot(ray.translation, a);
  const float acrossLength = length(dAcross);
  if (acrossLength == 0.0f) {
    return {}; // along the axis, outside the cylinder: it never meets the side
  }
  const Vec3f u = dAcross * (1.0f / acrossLength);
  const float t = -dot(sAcross, u); // m, across the axis
  if (t < 0.0f) {
    return {};
  }
  const Vec3f c = sAcross + u * t;
  const float cc = dot(c, c);
  if (cc > rr) {
    return {};
  }
  const float fraction = std::max(t - std::sqrt(rr - cc), 0.0f) / acrossLength;
  if (fraction > ray.maxFraction) {
    return {};
  }
  const float height = along + fraction * dot(ray.translation, a); // m along the axis
  if (height < 0.0f || height > axisLength) {
    return {};
  }
  return {normalize(sAcross + dAcross * fraction), fraction, true};
}

LocalHit castLocal(const Sphere& shape, const LocalRay& ray) { return castBall(shape.center, shape.radius, ray); }

LocalHit castLocal(const Capsule& shape, const LocalRay& ray) {
  const Vec3f axis = shape.center2 - shape.center1;
  const float axisLength = length(axis);
  if (axisLength == 0.0f) {
    return castBall(shape.center1, shape.radius, ray);
  }
  const Vec3f a = axis * (1.0f / axisLength);
  const float along = std::clamp(dot(ray.origin - shape.center1, a), 0.0f, axisLength);
  if (lengthSquared(ray.origin - (shape.center1 + a * along)) <= shape.radius * shape.radius) {
    return {}; // inside or on the surface
  }
  // The capsule is the union of its cylinder and its end balls, and the origin is outside each:
  // the first entry into the union is the first entry into any of them.
  const LocalHit ends = first(castBall(shape.center1, shape.radius, ray), castBall(shape.center2, shape.radius, ray));
  return first(ends, castCylinderSide(shape.center1, a, axisLength, shape.radius, ray));
}

LocalHit castLocal(const Hull& shape, const LocalRay& ray) {
  // Cyrus-Beck: the ray is inside the hull where it is behind every face's plane. Each plane it
  // crosses toward the inside raises the entry fraction, each it crosses toward the outside
  // lowers the exit; the hit is on the last plane entered, if that comes before the exit.
  float lower = 0.0f;
  float upper = ray.maxFraction;
  std::size_t entered = shape.planes.size();
  for (std::size_t f = 0; f < shape.planes.size(); ++f) {
    const HullPlane& plane = shape.planes[f];
    const float numerator = plane.offset - dot(plane.normal, ray.origin); // m, < 0 in front
    const float denominator = dot(plane.normal, ray.translation);
    if (denominator == 0.0f) {
      if (numerator < 0.0f) {
        return {}; // parallel to the plane and in front of it
      }
    } else if (denominator < 0.0f && numerator < lower * denominator) {
      lower = numerator / denominator; // enters behind the plane later
      entered = f;
    } else if (denominator > 0.0f && numerator < upper * denominator) {
      upper = numerator / denominator; // leaves earlier
    }
    if (upper < lower) {
      return {};
    }
  }
  if (entered == shape.planes.size()) {
    return {}; // behind or on every plane it crosses inward at the start: inside or on the surface
  }
  return {shape.planes[entered].normal, lower, true};
}

void requireRay(const RayCastInput& ray) {
  requireFinite(ray.origin, "origin");
  requireFinite(ray.translation, "translation");
  if (!(ray.maxFraction >= 0.0f) || !std::isfinite(ray.maxFraction)) {
    throwInvalid("maxFraction", ray.maxFraction, "must be finite and non-negative");
  }
}

template <class Shape> CastOutput cast(const Shape& shape, const Transform3f& xf, const RayCastInput& ray) {
  requireRay(ray);
  const LocalRay local{inverseTransformPoint(xf, ray.origin), inverseRotate(xf.q, ray.translation), ray.maxFraction};
  if (lengthSquared(local.translation) == 0.0f) {
    return {}; // a zero translation goes nowhere
  }
  const LocalHit hit = castLocal(shape, local);
  if (!hit.hit) {
    return {};
  }
  return {rotate(xf.q, hit.normal), ray.origin + ray.translation * hit.fraction, hit.fraction, true};
}

} // namespace

CastOutput rayCast(const Sphere& shape, const Transform3f& xf, const RayCastInput& ray) { return cast(shape, xf, ray); }

CastOutput rayCast(const Capsule& shape, const Transform3f& xf, const RayCastInput& ray) {
  return cast(shape, xf, ray);
}

CastOutput rayCast(const Hull& shape, const Transform3f& xf, const RayCastInput& ray) { return cast(shape, xf, ray); }

CastOutput rayCast(const ShapeGeometry& shape, const Transform3f& xf, const RayCastInput& ray) {
  return std::visit([&](const auto& s) { return rayCast(s, xf, ray); }, shape);
}

} // namespace impetus::rigid3d
