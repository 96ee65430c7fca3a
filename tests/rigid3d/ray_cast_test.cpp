// Ray casts against the 3D shapes: a sphere against the quadratic, a capsule across its side,
// into its caps and along its axis, a turned box against the slab method in its own frame, a
// hull of random points against GJK distances; maxFraction, misses, grazing rays, rays starting
// inside (no hit) and bad input.
#include <impetus/error.hpp>
#include <impetus/rigid3d/distance.hpp>
#include <impetus/rigid3d/ray_cast.hpp>

#include "support/error_field.hpp"
#include "test_random.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

namespace impetus::rigid3d {
namespace {

/// A hit's fraction, point and normal against a closed form or a double-precision reference:
/// float rounding of rays a few metres long, turned by a body's rotation, is a few 1e-7 m.
constexpr float analyticTolerance = 1e-5f; // m, or dimensionless for fractions and unit normals
/// Rays passing this close to an edge of a reference's decision (tangent, starting on the
/// surface, ending at the surface) are left out of the hit/miss agreement: float and double may
/// fairly disagree there. m.
constexpr double ambiguousBand = 1e-4;

const Transform3f identity{};
const Transform3f turned{{1.0f, -2.0f, 0.5f}, Quatf::fromAxisAngle({1.0f, 2.0f, 3.0f}, 0.9f)};

Vec3d toDouble(const Vec3f& v) { return {v.x, v.y, v.z}; }

Vec3f randomVec(Lcg& random, float scale) { return Vec3f{random.next(), random.next(), random.next()} * scale; }

/// A random ray in the frame `xf`: from within `spread` of `center` on each axis toward a point
/// within `aim` of it, its translation 1.5 times that distance and its maxFraction 0.1 to 0.9, so
/// that some rays hit, some stop short, some pass by and some start inside.
RayCastInput aimedRay(Lcg& random, const Transform3f& xf, const Vec3f& center, float spread, float aim) {
  const Vec3f origin = center + randomVec(random, spread);
  const Vec3f target = center + randomVec(random, aim);
  return {transformPoint(xf, origin), rotate(xf.q, (target - origin) * 1.5f), 0.5f + 0.4f * random.next()};
}

void expectNear(const Vec3f& a, const Vec3f& b, float tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

/// A ray given in the body's frame, in world coordinates for a body at `xf`.
RayCastInput worldRay(const Transform3f& xf, const Vec3f& origin, const Vec3f& translation, float maxFraction = 1.0f) {
  return {transformPoint(xf, origin), rotate(xf.q, translation), maxFraction};
}

/// Expects a hit at `fraction` with the body-frame normal `normal`, the point on the ray.
void expectHit(const CastOutput& out, const RayCastInput& ray, const Transform3f& xf, float fraction,
               const Vec3f& normal) {
  ASSERT_TRUE(out.hit);
  EXPECT_NEAR(out.fraction, fraction, analyticTolerance);
  expectNear(out.normal, rotate(xf.q, normal), analyticTolerance);
  expectNear(out.point, ray.origin + ray.translation * fraction, analyticTolerance);
}

/// The distance from a point to a convex point set's hull (GJK), 0 when inside.
float distanceToHull(std::span<const Vec3f> hull, const Vec3f& point) {
  const DistanceOutput d = coreDistance({hull, 0.0f}, {std::span<const Vec3f>(&point, 1), 0.0f});
  return d.overlap ? 0.0f : d.distance;
}

/// The distance from a segment to a convex point set's hull (GJK), 0 when they meet.
float distanceToHull(std::span<const Vec3f> hull, const Vec3f& p, const Vec3f& q) {
  const std::array<Vec3f, 2> segment{p, q};
  const DistanceOutput d = coreDistance({hull, 0.0f}, {segment, 0.0f});
  return d.overlap ? 0.0f : d.distance;
}

/// The height of a point over the hull's surface by its planes, m: the depth inside as a
/// negative; outside, at most the distance (equal off a face, less off an edge or corner).
float planeHeight(const Hull& hull, const Vec3f& point) {
  float height = -std::numeric_limits<float>::infinity();
  for (const HullPlane& plane : hull.planes) {
    height = std::max(height, dot(plane.normal, point) - plane.offset);
  }
  return height;
}

std::vector<Vec3f> worldPoints(std::span<const Vec3f> points, const Transform3f& xf) {
  std::vector<Vec3f> out;
  out.reserve(points.size());
  for (const Vec3f& p : points) {
    out.push_back(transformPoint(xf, p));
  }
  return out;
}

TEST(Rigid3dRayCast, a_sphere_is_hit_where_the_quadratic_says_with_a_radial_normal) {
  // Unit sphere 1 m in front of the origin's x: entry at x = -1, and 0.6 m off the axis at
  // x = -sqrt(1 - 0.36) = -0.8 with the normal (-0.8, 0.6, 0).
  const Sphere sphere{{0.5f, 0.25f, -0.5f}, 1.0f};
  for (const Transform3f& xf : {identity, turned}) {
    const RayCastInput head = worldRay(xf, sphere.center + Vec3f{-3.0f, 0.0f, 0.0f}, {4.0f, 0.0f, 0.0f});
    expectHit(rayCast(sphere, xf, head), head, xf, 0.5f, {-1.0f, 0.0f, 0.0f});
    const RayCastInput off = worldRay(xf, sphere.center + Vec3f{-3.0f, 0.6f, 0.0f}, {4.0f, 0.0f, 0.0f});
    expectHit(rayCast(sphere, xf, off), off, xf, (3.0f - 0.8f) / 4.0f, {-0.8f, 0.6f, 0.0f});
  }

  // Random rays against the roots of |s + t d|^2 = r^2 in double (the code uses the closest
  // approach and Pythagoras in float).
  Lcg random{0x2545f4914f6cdd1dULL};
  const Vec3d center = toDouble(transformPoint(turned, sphere.center));
  int hits = 0;
  int misses = 0;
  for (int i = 0; i < 500; ++i) {
    const RayCastInput ray = aimedRay(random, turned, sphere.center, 2.5f, 1.3f);
    const Vec3d s = toDouble(ray.origin) - center;
    const Vec3d d = toDouble(ray.translation);
    const double dd = dot(d, d);
    const double ss = dot(s, s) - 1.0;
    const double sd = dot(s, d);
    const double disc = sd * sd - dd * ss;
    const double rayLength = std::sqrt(dd);
    if (std::abs(length(s) - 1.0) < ambiguousBand || std::abs(disc) < dd * ambiguousBand * ambiguousBand) {
      continue; // starts on the surface, or tangent
    }
    const double t = disc > 0.0 ? (-sd - std::sqrt(disc)) / dd : -1.0;
    if (std::abs(t) * rayLength < ambiguousBand || std::abs(t - ray.maxFraction) * rayLength < ambiguousBand) {
      continue;
    }
    const bool expected = ss > 0.0 && disc > 0.0 && t >= 0.0 && t <= ray.maxFraction;
    const CastOutput out = rayCast(ShapeGeometry{sphere}, turned, ray);
    ASSERT_EQ(out.hit, expected) << "ray " << i;
    if (!expected) {
      ++misses;
      continue;
    }
    ++hits;
    EXPECT_NEAR(out.fraction, t, analyticTolerance);
    const Vec3d point = toDouble(ray.origin) + d * t;
    expectNear(out.point, {static_cast<float>(point.x), static_cast<float>(point.y), static_cast<float>(point.z)},
               analyticTolerance);
    const Vec3d radial = point - center; // unit: the radius is 1 m
    expectNear(out.normal, {static_cast<float>(radial.x), static_cast<float>(radial.y), static_cast<float>(radial.z)},
               analyticTolerance);
  }
  EXPECT_GT(hits, 100);
  EXPECT_GT(misses, 50);
}

TEST(Rigid3dRayCast, a_capsule_is_hit_across_its_side_into_each_cap_and_along_its_axis) {
  // Axis from (-1, 0, 0) to (1, 0, 0), radius 0.5, in the body of a turned, offset body.
  const Capsule capsule{{-1.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.5f};
  for (const Transform3f& xf : {identity, turned}) {
    // Down across the side 0.1 m off the axis's plane: entry at y = sqrt(0.25 - 0.01).
    const float y = std::sqrt(0.24f);
    const RayCastInput side = worldRay(xf, {0.3f, 2.0f, 0.1f}, {0.0f, -4.0f, 0.0f});
    expectHit(rayCast(capsule, xf, side), side, xf, (2.0f - y) / 4.0f, Vec3f{0.0f, y, 0.1f} * 2.0f);
    // Into the +x cap 0.3 m off the axis: x = 1 + sqrt(0.25 - 0.09) = 1.4, normal (0.8, 0.6, 0).
    const RayCastInput cap2 = worldRay(xf, {3.0f, 0.3f, 0.0f}, {-4.0f, 0.0f, 0.0f});
    expectHit(rayCast(capsule, xf, cap2), cap2, xf, 0.4f, {0.8f, 0.6f, 0.0f});
    // Into the -x cap 0.4 m off: x = -1.3, normal (-0.6, 0, -0.8).
    const RayCastInput cap1 = worldRay(xf, {-3.0f, 0.0f, -0.4f}, {4.0f, 0.0f, 0.0f});
    expectHit(rayCast(capsule, xf, cap1), cap1, xf, 0.425f, {-0.6f, 0.0f, -0.8f});
    // Along the axis from either end: the caps' poles at x = +-1.5.
    const RayCastInput fromPlus = worldRay(xf, {5.0f, 0.0f, 0.0f}, {-10.0f, 0.0f, 0.0f});
    expectHit(rayCast(capsule, xf, fromPlus), fromPlus, xf, 0.35f, {1.0f, 0.0f, 0.0f});
    const RayCastInput fromMinus = worldRay(xf, {-5.0f, 0.0f, 0.0f}, {10.0f, 0.0f, 0.0f});
    expectHit(rayCast(capsule, xf, fromMinus), fromMinus, xf, 0.35f, {-1.0f, 0.0f, 0.0f});
    // Obliquely onto the side near the +x rim: from (0.8, 2.5, 0) down-right by (0.1, -2.5): the
    // side's top line y = 0.5 is reached at fraction 0.8, x = 0.88, before the rim at x = 1.
    const RayCastInput oblique = worldRay(xf, {0.8f, 2.5f, 0.0f}, {0.1f, -2.5f, 0.0f});
    expectHit(rayCast(capsule, xf, oblique), oblique, xf, 0.8f, {0.0f, 1.0f, 0.0f});
    // Parallel to the axis 0.6 m from it: past the caps and the side.
    EXPECT_FALSE(rayCast(capsule, xf, worldRay(xf, {5.0f, 0.6f, 0.0f}, {-10.0f, 0.0f, 0.0f})).hit);
    // Across, beyond the caps: x = 1.6.
    EXPECT_FALSE(rayCast(capsule, xf, worldRay(xf, {1.6f, 2.0f, 0.0f}, {0.0f, -4.0f, 0.0f})).hit);
  }
}

TEST(Rigid3dRayCast, random_rays_meet_a_capsule_where_they_come_within_its_radius_of_its_axis) {
  // GJK between the ray's segment and the capsule's axis: the ray hits where that distance is at
  // most the radius, at a point exactly the radius from the axis, first (a point 1 mm before it
  // along the ray is at least its height over the tangent plane farther), the normal radial.
  const Capsule capsule{{-0.6f, 0.2f, 0.1f}, {0.7f, -0.3f, 0.4f}, 0.4f};
  const std::array<Vec3f, 2> axis{transformPoint(turned, capsule.center1), transformPoint(turned, capsule.center2)};
  constexpr float before = 1e-3f; // m back along the ray from the hit
  Lcg random{0x9e3779b97f4a7c15ULL};
  int hits = 0;
  int misses = 0;
  for (int i = 0; i < 500; ++i) {
    const RayCastInput ray = aimedRay(random, turned, {}, 2.0f, 1.0f);
    const Vec3f end = ray.origin + ray.translation * ray.maxFraction;
    const float originDistance = distanceToHull(axis, ray.origin);
    const float segmentDistance = distanceToHull(axis, ray.origin, end);
    if (std::abs(originDistance - capsule.radius) < ambiguousBand ||
        std::abs(segmentDistance - capsule.radius) < ambiguousBand ||
        std::abs(distanceToHull(axis, end) - capsule.radius) < ambiguousBand) {
      continue;
    }
    const bool expected = originDistance > capsule.radius && segmentDistance < capsule.radius;
    const CastOutput out = rayCast(ShapeGeometry{capsule}, turned, ray);
    ASSERT_EQ(out.hit, expected) << "ray " << i;
    if (!expected) {
      ++misses;
      continue;
    }
    ++hits;
    const float rayLength = length(ray.translation);
    const Vec3f direction = ray.translation * (1.0f / rayLength);
    EXPECT_NEAR(distanceToHull(axis, out.point), capsule.radius, analyticTolerance) << "ray " << i;
    const Vec3f earlier = out.point - direction * before;
    const float height = before * -dot(out.normal, direction); // over the tangent plane, m
    EXPECT_GT(height, 0.0f);
    EXPECT_GE(distanceToHull(axis, earlier) - capsule.radius, height - analyticTolerance) << "ray " << i;
    EXPECT_GT(distanceToHull(axis, ray.origin, earlier), capsule.radius) << "ray " << i;
    // Radial: the normal points from the axis' closest point to the hit point.
    const DistanceOutput d = coreDistance({axis, 0.0f}, {std::span<const Vec3f>(&out.point, 1), 0.0f});
    expectNear(out.normal, (d.pointB - d.pointA) * (1.0f / d.distance), analyticTolerance);
  }
  EXPECT_GT(hits, 100);
  EXPECT_GT(misses, 50);
}

TEST(Rigid3dRayCast, a_turned_offset_box_agrees_with_the_slab_method_in_its_frame) {
  // The box is turned and offset in its body, the body turned and offset in the world. In the
  // box's own frame it is |x| <= h on each axis: the ray is inside each slab between two
  // fractions; it enters the box at the latest entry if that is before the earliest exit.
  const Vec3f h{0.5f, 1.0f, 0.25f};
  const Transform3f inBody{{0.2f, -0.1f, 0.3f}, Quatf::fromAxisAngle({-1.0f, 0.5f, 2.0f}, 0.6f)};
  const Hull box = makeBoxHull(h, inBody.p, inBody.q);
  const Transform3f boxFrame = mul(turned, inBody);
  Lcg random{0xda3e39cb94b95bdbULL};
  int hits = 0;
  int misses = 0;
  int inside = 0;
  for (int i = 0; i < 500; ++i) {
    const RayCastInput ray = aimedRay(random, boxFrame, {}, 2.0f, 1.2f);
    const Vec3d o = toDouble(inverseTransformPoint(boxFrame, ray.origin));
    const Vec3d d = toDouble(inverseRotate(boxFrame.q, ray.translation));
    double enter = -std::numeric_limits<double>::infinity();
    double exit = std::numeric_limits<double>::infinity();
    Vec3f normal;
    bool parallelOutside = false;
    double margin = std::numeric_limits<double>::infinity(); // of the origin to the faces' planes, m
    for (int k = 0; k < 3; ++k) {
      margin = std::min(margin, std::abs(std::abs(o[k]) - h[k]));
      if (d[k] == 0.0) {
        parallelOutside = parallelOutside || std::abs(o[k]) > h[k];
        continue;
      }
      const double t1 = (-h[k] - o[k]) / d[k];
      const double t2 = (h[k] - o[k]) / d[k];
      if (std::min(t1, t2) > enter) {
        enter = std::min(t1, t2);
        normal = Vec3f{};
        normal[k] = d[k] > 0.0 ? -1.0f : 1.0f; // the face the ray meets first
      }
      exit = std::min(exit, std::max(t1, t2));
    }
    const double rayLength = length(d);
    const bool startsInside = std::abs(o.x) <= h.x && std::abs(o.y) <= h.y && std::abs(o.z) <= h.z;
    if (margin < ambiguousBand || std::abs(exit - enter) * rayLength < ambiguousBand ||
        std::abs(enter) * rayLength < ambiguousBand || std::abs(enter - ray.maxFraction) * rayLength < ambiguousBand) {
      continue;
    }
    const bool expected =
        !startsInside && !parallelOutside && enter <= exit && enter >= 0.0 && enter <= ray.maxFraction;
    const CastOutput out = rayCast(box, turned, ray);
    ASSERT_EQ(out.hit, expected) << "ray " << i;
    if (!expected) {
      inside += startsInside ? 1 : 0;
      misses += startsInside ? 0 : 1;
      continue;
    }
    ++hits;
    EXPECT_NEAR(out.fraction, enter, analyticTolerance) << "ray " << i;
    expectNear(out.normal, rotate(boxFrame.q, normal), analyticTolerance);
    expectNear(out.point, ray.origin + ray.translation * static_cast<float>(enter), analyticTolerance);
  }
  EXPECT_GT(hits, 100);
  EXPECT_GT(misses, 50);
  EXPECT_GT(inside, 5);
}

TEST(Rigid3dRayCast, a_hull_of_random_points_is_entered_where_gjk_puts_its_surface) {
  // For each ray: GJK between the ray's segment and the hull says whether it hits; the hit point
  // is on the hull (GJK distance ~ 0) and on the hit face's plane; a point 1 mm before it along
  // the ray is outside, no nearer than its height over that plane nor farther than 1 mm, and the
  // ray up to it misses the hull (so the hit is the entry, not the exit).
  Lcg random{0x6a09e667f3bcc909ULL};
  std::vector<Vec3f> cloud;
  cloud.reserve(24);
  for (int i = 0; i < 24; ++i) {
    const Vec3f p = randomVec(random, 1.0f); // in a 2 x 1.6 x 1.2 m box
    cloud.emplace_back(p.x, 0.8f * p.y, 0.6f * p.z);
  }
  const Hull hull = computeHull(cloud);
  const std::vector<Vec3f> points = worldPoints(hull.points, turned);
  constexpr float before = 1e-3f;             // m back along the ray from the hit
  constexpr float onSurfaceTolerance = 1e-4f; // m: GJK's and the planes' float rounding
  int hits = 0;
  int misses = 0;
  int inside = 0;
  for (int i = 0; i < 500; ++i) {
    const RayCastInput ray = aimedRay(random, turned, {}, 2.0f, 1.2f);
    const Vec3f end = ray.origin + ray.translation * ray.maxFraction;
    const float originDistance = distanceToHull(points, ray.origin);
    const float segmentDistance = distanceToHull(points, ray.origin, end);
    if (std::abs(planeHeight(hull, inverseTransformPoint(turned, ray.origin))) < ambiguousBand ||
        std::abs(planeHeight(hull, inverseTransformPoint(turned, end))) < ambiguousBand ||
        (segmentDistance > 0.0f && segmentDistance < ambiguousBand)) {
      continue;
    }
    if (originDistance == 0.0f) {
      ++inside;
      EXPECT_FALSE(rayCast(hull, turned, ray).hit) << "ray " << i;
      continue;
    }
    const CastOutput out = rayCast(ShapeGeometry{hull}, turned, ray);
    ASSERT_EQ(out.hit, segmentDistance == 0.0f) << "ray " << i;
    if (!out.hit) {
      ++misses;
      continue;
    }
    ++hits;
    EXPECT_LE(distanceToHull(points, out.point), onSurfaceTolerance) << "ray " << i;
    const auto face = std::find_if(hull.planes.begin(), hull.planes.end(), [&](const HullPlane& p) {
      return length(rotate(turned.q, p.normal) - out.normal) < analyticTolerance;
    });
    ASSERT_NE(face, hull.planes.end()) << "the normal is a face's, ray " << i;
    EXPECT_NEAR(dot(face->normal, inverseTransformPoint(turned, out.point)), face->offset, onSurfaceTolerance);
    const Vec3f direction = normalize(ray.translation);
    const Vec3f earlier = out.point - direction * before;
    const float height = before * -dot(out.normal, direction);
    EXPECT_GT(height, 0.0f);
    const float earlierDistance = distanceToHull(points, earlier);
    EXPECT_GE(earlierDistance, height - onSurfaceTolerance * 0.1f) << "ray " << i;
    EXPECT_LE(earlierDistance, before + onSurfaceTolerance * 0.1f) << "ray " << i;
    EXPECT_GT(distanceToHull(points, ray.origin, earlier), 0.0f) << "ray " << i;
  }
  EXPECT_GT(hits, 100);
  EXPECT_GT(misses, 50);
  EXPECT_GT(inside, 5);
}

TEST(Rigid3dRayCast, max_fraction_clips_the_ray_and_may_reach_past_the_translation) {
  // Each shape's surface 2 m along a ray of translation 4 m: fraction 0.5.
  const std::array<ShapeGeometry, 3> shapes{Sphere{{}, 1.0f}, Capsule{{0.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 1.0f},
                                            makeBoxHull({1.0f, 1.0f, 1.0f})};
  for (const ShapeGeometry& shape : shapes) {
    const RayCastInput ray = worldRay(turned, {-3.0f, 0.0f, 0.0f}, {4.0f, 0.0f, 0.0f});
    expectHit(rayCast(shape, turned, {ray.origin, ray.translation, 0.51f}), ray, turned, 0.5f, {-1.0f, 0.0f, 0.0f});
    EXPECT_FALSE(rayCast(shape, turned, {ray.origin, ray.translation, 0.49f}).hit);
    EXPECT_FALSE(rayCast(shape, turned, {ray.origin, ray.translation, 0.0f}).hit);
    // A translation of 1 m reaches the surface at fraction 2 when allowed to.
    const RayCastInput shortRay = worldRay(turned, {-3.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 2.5f);
    expectHit(rayCast(shape, turned, shortRay), shortRay, turned, 2.0f, {-1.0f, 0.0f, 0.0f});
    EXPECT_FALSE(rayCast(shape, turned, {shortRay.origin, shortRay.translation, 1.0f}).hit);
  }
  // Exactly at maxFraction counts (the axis-aligned sphere's 0.5 is exact).
  const RayCastInput exact{{-3.0f, 0.0f, 0.0f}, {4.0f, 0.0f, 0.0f}, 0.5f};
  EXPECT_TRUE(rayCast(Sphere{{}, 1.0f}, identity, exact).hit);
  EXPECT_TRUE(rayCast(makeBoxHull({1.0f, 1.0f, 1.0f}), identity, exact).hit);
}

TEST(Rigid3dRayCast, rays_that_pass_by_point_away_or_stop_short_miss) {
  const std::array<ShapeGeometry, 3> shapes{Sphere{{}, 1.0f}, Capsule{{0.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 1.0f},
                                            makeBoxHull({1.0f, 1.0f, 1.0f})};
  for (const ShapeGeometry& shape : shapes) {
    // Passing 1.5 m off the centre along z (each shape reaches 1 m there).
    EXPECT_FALSE(rayCast(shape, turned, worldRay(turned, {-3.0f, 0.0f, 1.5f}, {6.0f, 0.0f, 0.0f})).hit);
    // The shape behind the origin.
    EXPECT_FALSE(rayCast(shape, turned, worldRay(turned, {-3.0f, 0.0f, 0.0f}, {-6.0f, 0.0f, 0.0f})).hit);
    // Stopping short: the ray ends 0.5 m before the surface.
    EXPECT_FALSE(rayCast(shape, turned, worldRay(turned, {-3.0f, 0.0f, 0.0f}, {1.5f, 0.0f, 0.0f})).hit);
    // Going nowhere: a zero translation, even aimed from the surface's doorstep.
    EXPECT_FALSE(rayCast(shape, turned, worldRay(turned, {-1.001f, 0.0f, 0.0f}, {}, 10.0f)).hit);
    // The same ray aimed at it hits: the misses above are the ray's, not the shape's.
    EXPECT_TRUE(rayCast(shape, turned, worldRay(turned, {-3.0f, 0.0f, 0.0f}, {6.0f, 0.0f, 0.0f})).hit);
  }
}

TEST(Rigid3dRayCast, a_ray_touching_the_surface_hits_and_one_just_beside_it_misses) {
  // A box's top face y = 1: a ray along its plane touches the box from the -x face's top edge
  // (the shapes are closed), 0.1 mm above it misses, 0.1 mm below it enters through the -x face.
  const Hull box = makeBoxHull({1.0f, 1.0f, 1.0f});
  const RayCastInput along{{-3.0f, 1.0f, 0.2f}, {6.0f, 0.0f, 0.0f}};
  expectHit(rayCast(box, identity, along), along, identity, 2.0f / 6.0f, {-1.0f, 0.0f, 0.0f});
  EXPECT_FALSE(rayCast(box, identity, {{-3.0f, 1.0001f, 0.2f}, {6.0f, 0.0f, 0.0f}}).hit);
  const RayCastInput below{{-3.0f, 0.9999f, 0.2f}, {6.0f, 0.0f, 0.0f}};
  expectHit(rayCast(box, identity, below), below, identity, 2.0f / 6.0f, {-1.0f, 0.0f, 0.0f});
  // Down onto the top face at a shallow angle (1 in 100): the face's normal.
  const RayCastInput shallow{{-1.5f, 1.01f, 0.2f}, {2.0f, -0.02f, 0.0f}};
  expectHit(rayCast(box, identity, shallow), shallow, identity, 0.5f, {0.0f, 1.0f, 0.0f});

  // Tangent to a sphere at its top: hits there; 0.1 mm higher misses.
  const Sphere sphere{{}, 1.0f};
  const RayCastInput tangent{{-2.0f, 1.0f, 0.0f}, {4.0f, 0.0f, 0.0f}};
  expectHit(rayCast(sphere, identity, tangent), tangent, identity, 0.5f, {0.0f, 1.0f, 0.0f});
  EXPECT_FALSE(rayCast(sphere, identity, {{-2.0f, 1.0001f, 0.0f}, {4.0f, 0.0f, 0.0f}}).hit);

  // Along a capsule's side line (radius 0.5 from the x axis): touches at its closest point.
  const Capsule capsule{{-1.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.5f};
  const RayCastInput sideLine{{0.0f, 0.5f, 2.0f}, {0.0f, 0.0f, -4.0f}};
  expectHit(rayCast(capsule, identity, sideLine), sideLine, identity, 0.5f, {0.0f, 1.0f, 0.0f});
  EXPECT_FALSE(rayCast(capsule, identity, {{0.0f, 0.5001f, 2.0f}, {0.0f, 0.0f, -4.0f}}).hit);
}

TEST(Rigid3dRayCast, a_ray_starting_inside_or_on_the_surface_does_not_hit) {
  // The documented rule: a cast sees out of a shape that holds its origin. Each shape holds the
  // body-frame origin; its surface is 1 m along -x.
  const std::array<ShapeGeometry, 3> shapes{Sphere{{}, 1.0f}, Capsule{{0.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 1.0f},
                                            makeBoxHull({1.0f, 1.0f, 1.0f})};
  for (const ShapeGeometry& shape : shapes) {
    // From the centre, out through the surface.
    EXPECT_FALSE(rayCast(shape, turned, worldRay(turned, {}, {-4.0f, 0.0f, 0.0f})).hit);
    // From inside near the surface, crossing the whole shape and out the far side.
    EXPECT_FALSE(rayCast(shape, turned, worldRay(turned, {-0.9f, 0.0f, 0.0f}, {4.0f, 0.0f, 0.0f})).hit);
    // From exactly on the surface (identity: exact), heading in or out.
    EXPECT_FALSE(rayCast(shape, identity, {{-1.0f, 0.0f, 0.0f}, {4.0f, 0.0f, 0.0f}}).hit);
    EXPECT_FALSE(rayCast(shape, identity, {{-1.0f, 0.0f, 0.0f}, {-4.0f, 0.0f, 0.0f}}).hit);
    // 1 mm outside, heading in: a hit 1 mm along.
    const RayCastInput outside = worldRay(turned, {-1.001f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f});
    const CastOutput out = rayCast(shape, turned, outside);
    ASSERT_TRUE(out.hit);
    EXPECT_NEAR(out.fraction, 0.001f, analyticTolerance);
  }
}

TEST(Rigid3dRayCast, bad_rays_are_refused_naming_the_field) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const std::array<ShapeGeometry, 3> shapes{Sphere{{}, 1.0f}, Capsule{{0.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 1.0f},
                                            makeBoxHull({1.0f, 1.0f, 1.0f})};
  for (const ShapeGeometry& shape : shapes) {
    const auto cast = [&](const RayCastInput& ray) { (void)rayCast(shape, turned, ray); };
    expectErrorField([&] { cast({{0.0f, nan, 0.0f}, {1.0f, 0.0f, 0.0f}}); }, "origin.y");
    expectErrorField([&] { cast({{-inf, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}); }, "origin.x");
    expectErrorField([&] { cast({{-3.0f, 0.0f, 0.0f}, {1.0f, 0.0f, inf}}); }, "translation.z");
    expectErrorField([&] { cast({{-3.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, -0.5f}); }, "maxFraction");
    expectErrorField([&] { cast({{-3.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, nan}); }, "maxFraction");
    expectErrorField([&] { cast({{-3.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, inf}); }, "maxFraction");
    // Checked before anything else: a bad ray with a zero translation is still refused.
    expectErrorField([&] { cast({{nan, 0.0f, 0.0f}, {}}); }, "origin.x");
  }
  // Each overload checks on its own, not only the dispatcher.
  expectErrorField([] { (void)rayCast(Sphere{{}, 1.0f}, identity, {{}, {1.0f, 0.0f, 0.0f}, -1.0f}); }, "maxFraction");
}

} // namespace
} // namespace impetus::rigid3d
