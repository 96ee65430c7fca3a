// Time of impact of two moving, turning shapes: conservative advancement on separating axes
// (Box2D's b2TimeOfImpact, after Erin Catto's "Continuous Collision", GDC 2013). Each outer step
// takes the closest features from GJK at the current time t1, builds the axis they define (a
// point pair, or a face of one shape against a point of the other), and finds on it the time at
// which the deepest point reaches the target separation: the shapes cannot be closer than that
// axis says before then, so t1 may advance there. A new axis is built from the new closest
// features, until GJK reports the target distance.
#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/rigid2d/distance.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace impetus::rigid2d {
namespace {

void requireSweep(const Sweep& s, const char* name) {
  const bool finite = isFinite(s.localCenter) && isFinite(s.c1) && isFinite(s.c2) && std::isfinite(s.q1.c) &&
                      std::isfinite(s.q1.s) && std::isfinite(s.q2.c) && std::isfinite(s.q2.s);
  if (finite) {
    return;
  }
  const std::string field(name);
  requireFinite(s.localCenter, field + ".localCenter");
  requireFinite(s.c1, field + ".c1");
  requireFinite(s.c2, field + ".c2");
  requireFinite(static_cast<double>(s.q1.c), field + ".q1.c");
  requireFinite(static_cast<double>(s.q1.s), field + ".q1.s");
  requireFinite(static_cast<double>(s.q2.c), field + ".q2.c");
  requireFinite(static_cast<double>(s.q2.s), field + ".q2.s");
}

/// The index of the point farthest along d.
int findSupport(const ShapeProxy& p, const Vec2f& d) {
  int best = 0;
  float bestValue = dot(p.points[0], d);
  for (int i = 1; i < p.count; ++i) {
    const float value = dot(p.points[static_cast<std::size_t>(i)], d);
    if (value > bestValue) {
      best = i;
      bestValue = value;
    }
  }
  return best;
}

Vec2f point(const ShapeProxy& p, int index) { return p.points[static_cast<std::size_t>(index)]; }

/// The separation of the two cores along one axis, as a function of time. The axis is fixed in
/// the frame that defines it: world for a point pair (the axis between the two closest points at
/// t1), or the body frame of the shape whose face it is, so it turns with that shape.
class SeparationFunction {
public:
  enum class Type { points, faceA, faceB };

  SeparationFunction(const SimplexCache& cache, const ShapeProxy& a, const Sweep& sweepA, const ShapeProxy& b,
                     const Sweep& sweepB, float t1)
      : a_(a), b_(b), sweepA_(sweepA), sweepB_(sweepB) {
    const Transform2f xfA = sweepTransform(sweepA, t1);
    const Transform2f xfB = sweepTransform(sweepB, t1);
    // Two simplex points on one shape and one on the other make a face; a face whose two points
    // coincide (a degenerate user proxy) cannot give a normal and falls back to the point pair.
    if (cache.count == 2 && cache.indexA[0] == cache.indexA[1]) {
      const Vec2f b1 = point(b, cache.indexB[0]);
      const Vec2f b2 = point(b, cache.indexB[1]);
      axis_ = normalize(perp(b2 - b1));
      if (lengthSquared(axis_) > 0.0f) {
        type_ = Type::faceB;
        localPoint_ = (b1 + b2) * 0.5f;
        const Vec2f normal = rotate(xfB.q, axis_);
        const Vec2f pointA = transformPoint(xfA, point(a, cache.indexA[0]));
        if (dot(pointA - transformPoint(xfB, localPoint_), normal) < 0.0f) {
          axis_ = -axis_; // face B's normal must point toward A
        }
        return;
      }
    } else if (cache.count == 2) {
      const Vec2f a1 = point(a, cache.indexA[0]);
      const Vec2f a2 = point(a, cache.indexA[1]);
      axis_ = normalize(perp(a2 - a1));
      if (lengthSquared(axis_) > 0.0f) {
        type_ = Type::faceA;
        localPoint_ = (a1 + a2) * 0.5f;
        const Vec2f normal = rotate(xfA.q, axis_);
        const Vec2f pointB = transformPoint(xfB, point(b, cache.indexB[0]));
        if (dot(pointB - transformPoint(xfA, localPoint_), normal) < 0.0f) {
          axis_ = -axis_; // face A's normal must point toward B
        }
        return;
      }
    }
    type_ = Type::points;
    const Vec2f pointA = transformPoint(xfA, point(a, cache.indexA[0]));
    const Vec2f pointB = transformPoint(xfB, point(b, cache.indexB[0]));
    axis_ = normalize(pointB - pointA);
  }

  /// The deepest points along the axis at time t (their indices; -1 for the face's own shape)
  /// and their separation.
  float findMinSeparation(int& indexA, int& indexB, float t) const {
    const Transform2f xfA = sweepTransform(sweepA_, t);
    const Transform2f xfB = sweepTransform(sweepB_, t);
    switch (type_) {
    case Type::points: {
      indexA = findSupport(a_, inverseRotate(xfA.q, axis_));
      indexB = findSupport(b_, inverseRotate(xfB.q, -axis_));
      return dot(transformPoint(xfB, point(b_, indexB)) - transformPoint(xfA, point(a_, indexA)), axis_);
    }
    case Type::faceA: {
      const Vec2f normal = rotate(xfA.q, axis_);
      indexA = -1;
      indexB = findSupport(b_, inverseRotate(xfB.q, -normal));
      return dot(transformPoint(xfB, point(b_, indexB)) - transformPoint(xfA, localPoint_), normal);
    }
    case Type::faceB:
    default: {
      const Vec2f normal = rotate(xfB.q, axis_);
      indexB = -1;
      indexA = findSupport(a_, inverseRotate(xfA.q, -normal));
      return dot(transformPoint(xfA, point(a_, indexA)) - transformPoint(xfB, localPoint_), normal);
    }
    }
  }

  /// The separation along the axis at time t of the given points (from findMinSeparation).
  float evaluate(int indexA, int indexB, float t) const {
    const Transform2f xfA = sweepTransform(sweepA_, t);
    const Transform2f xfB = sweepTransform(sweepB_, t);
    switch (type_) {
    case Type::points:
      return dot(transformPoint(xfB, point(b_, indexB)) - transformPoint(xfA, point(a_, indexA)), axis_);
    case Type::faceA:
      return dot(transformPoint(xfB, point(b_, indexB)) - transformPoint(xfA, localPoint_), rotate(xfA.q, axis_));
    case Type::faceB:
    default:
      return dot(transformPoint(xfA, point(a_, indexA)) - transformPoint(xfB, localPoint_), rotate(xfB.q, axis_));
    }
  }

private:
  const ShapeProxy& a_;
  const ShapeProxy& b_;
  const Sweep& sweepA_;
  const Sweep& sweepB_;
  Type type_ = Type::points;
  Vec2f localPoint_; ///< the face's midpoint, in its body frame
  Vec2f axis_;       ///< unit: world for points, the face's body frame otherwise
};

} // namespace

Transform2f sweepTransform(const Sweep& sweep, float t) {
  // (1 - t) a + t b rather than a + t (b - a): exact at both ends.
  const Vec2f center = sweep.c1 * (1.0f - t) + sweep.c2 * t;
  const Rot2f q = normalize(Rot2f{(1.0f - t) * sweep.q1.c + t * sweep.q2.c, (1.0f - t) * sweep.q1.s + t * sweep.q2.s});
  // The sweep follows the centre of mass; the transform places the body origin.
  return {center - rotate(q, sweep.localCenter), q};
}

TOIOutput timeOfImpact(const ShapeProxy& a, const Sweep& sweepA, const ShapeProxy& b, const Sweep& sweepB,
                       float maxFraction) {
  requireSweep(sweepA, "sweepA");
  requireSweep(sweepB, "sweepB");
  if (!(maxFraction >= 0.0f && maxFraction <= 1.0f)) {
    throwInvalid("maxFraction", static_cast<double>(maxFraction), "must be in [0, 1]");
  }
  // shapeDistance checks the proxies on the first call.

  // Stop with the cores this far apart: rounded shapes just into the contact slop, sharp ones
  // linearSlop apart (touching cores have no separating axis to advance on).
  const float totalRadius = a.radius + b.radius;
  const float target = std::max(linearSlop, totalRadius - linearSlop);
  const float tolerance = 0.25f * linearSlop;

  SimplexCache cache;
  float t1 = 0.0f;
  // t1 only moves forward, and each outer step usually settles a new pair of closest features, so
  // a few steps suffice; the bounds (Box2D's) only stop a grazing approach that creeps.
  constexpr int maxIterations = 20;
  constexpr int maxRootIterations = 50;

  for (int iteration = 0;; ++iteration) {
    const Transform2f xfA = sweepTransform(sweepA, t1);
    const Transform2f xfB = sweepTransform(sweepB, t1);
    const DistanceOutput d = shapeDistance(a, xfA, b, xfB, false, &cache);

    if (d.distance <= 0.0f) {
      return {TOIOutput::State::overlapped, t1}; // only possible at t1 = 0: every advance keeps a gap
    }
    if (d.distance < target + tolerance) {
      return {TOIOutput::State::hit, t1};
    }

    const SeparationFunction fcn(cache, a, sweepA, b, sweepB, t1);
    // Push t2 back from the end of the sweep until the deepest point on this axis is at the
    // target; each push-back resolves a different deepest point, so it ends within the vertex count.
    float t2 = maxFraction;
    for (int pushBack = 0; pushBack < maxPolygonVertices; ++pushBack) {
      int indexA = 0;
      int indexB = 0;
      float s2 = fcn.findMinSeparation(indexA, indexB, t2);

      if (s2 > target + tolerance) {
        return {TOIOutput::State::separated, maxFraction}; // apart along this axis all the way
      }
      if (s2 > target - tolerance) {
        t1 = t2; // at the target at t2: advance there and take a new axis
        break;
      }

      float s1 = fcn.evaluate(indexA, indexB, t1);
      if (s1 < target - tolerance) {
        // Already past the target at t1: the root finder ran out of iterations earlier.
        return {TOIOutput::State::failed, t1};
      }
      if (s1 <= target + tolerance) {
        return {TOIOutput::State::hit, t1}; // touching at t1
      }

      // The root of s(t) = target in [t1, t2], where s(t1) > target > s(t2): alternate bisection
      // (guaranteed progress) with the secant rule (fast once close), keeping the root bracketed.
      float lo = t1;
      float hi = t2;
      for (int root = 0; root < maxRootIterations; ++root) {
        const float t = (root & 1) != 0 ? lo + (target - s1) * (hi - lo) / (s2 - s1) : 0.5f * (lo + hi);
        const float s = fcn.evaluate(indexA, indexB, t);
        if (std::abs(s - target) < tolerance) {
          t2 = t;
          break;
        }
        if (s > target) {
          lo = t;
          s1 = s;
        } else {
          hi = t;
          s2 = s;
        }
      }
    }

    if (iteration + 1 == maxIterations) {
      return {TOIOutput::State::failed, t1}; // stuck on a grazing approach; t1 is still safe
    }
  }
}

} // namespace impetus::rigid2d
