#include <impetus/rigid2d/manifold.hpp>

#include <algorithm>
#include <limits>

namespace impetus::rigid2d {
namespace {

void finishPoint(ManifoldPoint& mp, const Transform2f& xfA, const Transform2f& xfB) {
  mp.anchorA = mp.point - xfA.p;
  mp.anchorB = mp.point - xfB.p;
}

/// B's vertices in A's frame.
Polygon inFrame(const Polygon& b, const Transform2f& xfA, const Transform2f& xfB) {
  const Transform2f relative = invMul(xfA, xfB);
  Polygon out = b;
  for (int i = 0; i < b.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    out.vertices[k] = transformPoint(relative, b.vertices[k]);
    out.normals[k] = rotate(relative.q, b.normals[k]);
  }
  return out;
}

/// The edge of `p1` along whose normal `p2` is farthest away, and that separation.
struct EdgeSeparation {
  int edge = 0;
  float separation = -std::numeric_limits<float>::max();
};

EdgeSeparation maxSeparation(const Polygon& p1, const Polygon& p2) {
  EdgeSeparation best;
  for (int i = 0; i < p1.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    float deepest = std::numeric_limits<float>::max();
    for (int j = 0; j < p2.count; ++j) {
      deepest = std::min(deepest, dot(p1.normals[k], p2.vertices[static_cast<std::size_t>(j)] - p1.vertices[k]));
    }
    if (deepest > best.separation) {
      best = {i, deepest};
    }
  }
  return best;
}

/// Closest points between segments p1-q1 and p2-q2 (Ericson, Real-Time Collision Detection
/// 5.1.9): parameters s on the first, t on the second, both in [0, 1].
struct SegmentClosest {
  float s;
  float t;
};

SegmentClosest segmentDistance(const Vec2f& p1, const Vec2f& q1, const Vec2f& p2, const Vec2f& q2) {
  const Vec2f d1 = q1 - p1;
  const Vec2f d2 = q2 - p2;
  const Vec2f r = p1 - p2;
  const float a = dot(d1, d1);
  const float e = dot(d2, d2);
  const float f = dot(d2, r);
  constexpr float tiny = 1e-12f;
  if (a <= tiny && e <= tiny) {
    return {0.0f, 0.0f};
  }
  if (a <= tiny) {
    return {0.0f, std::clamp(f / e, 0.0f, 1.0f)};
  }
  const float c = dot(d1, r);
  if (e <= tiny) {
    return {std::clamp(-c / a, 0.0f, 1.0f), 0.0f};
  }
  const float b = dot(d1, d2);
  const float denom = a * e - b * b;
  float s = denom > tiny ? std::clamp((b * f - c * e) / denom, 0.0f, 1.0f) : 0.0f;
  float t = (b * s + f) / e;
  if (t < 0.0f) {
    t = 0.0f;
    s = std::clamp(-c / a, 0.0f, 1.0f);
  } else if (t > 1.0f) {
    t = 1.0f;
    s = std::clamp((b - c) / a, 0.0f, 1.0f);
  }
  return {s, t};
}

std::uint16_t featureId(int referenceEdge, int incidentVertex, bool flipped) {
  return static_cast<std::uint16_t>((flipped ? 0x8000 : 0) | (referenceEdge << 4) | incidentVertex);
}

} // namespace

Polygon asPolygon(const Circle& circle) {
  Polygon p;
  p.count = 1;
  p.vertices[0] = circle.center;
  p.centroid = circle.center;
  p.radius = circle.radius;
  return p;
}

Polygon asPolygon(const Capsule& capsule) {
  Polygon p;
  p.count = 2;
  p.vertices[0] = capsule.center1;
  p.vertices[1] = capsule.center2;
  const Vec2f axis = normalize(capsule.center2 - capsule.center1);
  p.normals[0] = {axis.y, -axis.x};
  p.normals[1] = -p.normals[0];
  p.centroid = (capsule.center1 + capsule.center2) * 0.5f;
  p.radius = capsule.radius;
  return p;
}

Polygon asPolygon(const Segment& segment) { return asPolygon(Capsule{segment.point1, segment.point2, 0.0f}); }

Manifold collideCircles(const Circle& a, const Transform2f& xfA, const Circle& b, const Transform2f& xfB) {
  Manifold m;
  const Vec2f pa = transformPoint(xfA, a.center);
  const Vec2f pb = transformPoint(xfB, b.center);
  const float dist = distance(pa, pb);
  const float separation = dist - a.radius - b.radius;
  if (separation > speculativeDistance) {
    return m;
  }
  m.normal = dist > 0.0f ? (pb - pa) / dist : Vec2f{0.0f, 1.0f};
  ManifoldPoint& mp = m.points[0];
  // Midway between the two surfaces along the normal.
  mp.point = lerp(pa + m.normal * a.radius, pb - m.normal * b.radius, 0.5f);
  mp.separation = separation;
  finishPoint(mp, xfA, xfB);
  m.pointCount = 1;
  return m;
}

Manifold collidePolygonAndCircle(const Polygon& a, const Transform2f& xfA, const Circle& b, const Transform2f& xfB) {
  Manifold m;
  const Vec2f c = inverseTransformPoint(xfA, transformPoint(xfB, b.center)); // in A's frame
  const float radius = a.radius + b.radius;
  Vec2f normal;
  float separation = 0.0f;
  if (a.count == 1) {
    const Vec2f d = c - a.vertices[0];
    const float len = length(d);
    normal = len > 0.0f ? d / len : Vec2f{0.0f, 1.0f};
    separation = len - radius;
  } else {
    // The face of greatest separation; then, if the centre is beyond that face's ends, the
    // nearest vertex decides (its Voronoi region).
    int face = 0;
    float faceSeparation = -std::numeric_limits<float>::max();
    for (int i = 0; i < a.count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const float s = dot(a.normals[k], c - a.vertices[k]);
      if (s > faceSeparation) {
        faceSeparation = s;
        face = i;
      }
    }
    const Vec2f v1 = a.vertices[static_cast<std::size_t>(face)];
    const Vec2f v2 = a.vertices[static_cast<std::size_t>((face + 1) % a.count)];
    const Vec2f edge = v2 - v1;
    const float u = dot(c - v1, edge);
    if (faceSeparation > 0.0f && (u < 0.0f || u > dot(edge, edge))) {
      const Vec2f vertex = u < 0.0f ? v1 : v2;
      const Vec2f d = c - vertex;
      const float len = length(d);
      normal = len > 0.0f ? d / len : a.normals[static_cast<std::size_t>(face)];
      separation = len - radius;
    } else {
      normal = a.normals[static_cast<std::size_t>(face)];
      separation = faceSeparation - radius;
    }
  }
  if (separation > speculativeDistance) {
    return m;
  }
  m.normal = rotate(xfA.q, normal);
  const Vec2f cWorld = transformPoint(xfB, b.center);
  ManifoldPoint& mp = m.points[0];
  // Circle surface point and A's surface point, midway.
  const Vec2f onB = cWorld - m.normal * b.radius;
  const Vec2f onA = onB - m.normal * separation;
  mp.point = lerp(onA, onB, 0.5f);
  mp.separation = separation;
  finishPoint(mp, xfA, xfB);
  m.pointCount = 1;
  return m;
}

Manifold collidePolygons(const Polygon& a, const Transform2f& xfA, const Polygon& b, const Transform2f& xfB) {
  Manifold m;
  // Work in A's frame.
  const Polygon pb = inFrame(b, xfA, xfB);
  const EdgeSeparation sa = maxSeparation(a, pb);
  const EdgeSeparation sb = maxSeparation(pb, a);
  const float radius = a.radius + b.radius;
  if (sa.separation - radius > speculativeDistance || sb.separation - radius > speculativeDistance) {
    return m;
  }
  // Prefer A's face unless B's is clearly better (hysteresis keeps the choice stable).
  const bool flip = sb.separation > sa.separation + 0.1f * linearSlop;
  const Polygon& reference = flip ? pb : a;
  const Polygon& incident = flip ? a : pb;
  const int edge = flip ? sb.edge : sa.edge;
  const float rRef = flip ? b.radius : a.radius;
  const float rInc = flip ? a.radius : b.radius;
  const auto e = static_cast<std::size_t>(edge);
  const Vec2f v1 = reference.vertices[e];
  const Vec2f v2 = reference.vertices[static_cast<std::size_t>((edge + 1) % reference.count)];
  const Vec2f n = reference.normals[e];
  // Incident edge: the one most anti-parallel to the reference normal.
  int incidentEdge = 0;
  float minDot = std::numeric_limits<float>::max();
  for (int i = 0; i < incident.count; ++i) {
    const float d = dot(n, incident.normals[static_cast<std::size_t>(i)]);
    if (d < minDot) {
      minDot = d;
      incidentEdge = i;
    }
  }
  const int i1 = incidentEdge;
  const int i2 = (incidentEdge + 1) % incident.count;
  std::array<Vec2f, 2> clip{incident.vertices[static_cast<std::size_t>(i1)],
                            incident.vertices[static_cast<std::size_t>(i2)]};
  std::array<int, 2> clipId{i1, i2};
  // Clip the incident edge to the reference face's side planes.
  // The edge's direction: the outward normal of a counter-clockwise edge is (t.y, -t.x).
  const Vec2f tangent{-n.y, n.x};
  const auto clipTo = [&](float offsetAlong, float sign) {
    // Keep the part where sign * (dot(tangent, p) - offsetAlong) <= 0.
    const float d0 = sign * (dot(tangent, clip[0]) - offsetAlong);
    const float d1 = sign * (dot(tangent, clip[1]) - offsetAlong);
    if (d0 > 0.0f && d1 > 0.0f) {
      return false;
    }
    // A clipped point is a new feature: the reference face's side plane (ids 8 and 9).
    const int planeId = sign < 0.0f ? 8 : 9;
    if (d0 > 0.0f) {
      clip[0] = clip[0] + (clip[1] - clip[0]) * (d0 / (d0 - d1));
      clipId[0] = planeId;
    } else if (d1 > 0.0f) {
      clip[1] = clip[1] + (clip[0] - clip[1]) * (d1 / (d1 - d0));
      clipId[1] = planeId;
    }
    return true;
  };
  // Cores apart: if the closest features of the two edges are two vertices, the contact normal
  // is along the line between them (a rounded corner against a rounded corner), not a face
  // normal, and the separation is their true distance.
  const float coreSeparation = flip ? sb.separation : sa.separation;
  if (coreSeparation > 0.1f * linearSlop) {
    const Vec2f w1 = clip[0];
    const Vec2f w2 = clip[1];
    const SegmentClosest sc = segmentDistance(v1, v2, w1, w2);
    const bool refVertex = sc.s == 0.0f || sc.s == 1.0f;
    const bool incVertex = sc.t == 0.0f || sc.t == 1.0f;
    if (refVertex && incVertex) {
      const Vec2f pRef = lerp(v1, v2, sc.s);
      const Vec2f pInc = lerp(w1, w2, sc.t);
      const float dist = distance(pRef, pInc);
      const float separation = dist - rRef - rInc;
      if (separation > speculativeDistance || dist == 0.0f) {
        return m;
      }
      const Vec2f dir = (pInc - pRef) / dist; // reference to incident
      m.normal = rotate(xfA.q, flip ? -dir : dir);
      ManifoldPoint& mp = m.points[0];
      mp.point = transformPoint(xfA, lerp(pRef + dir * rRef, pInc - dir * rInc, 0.5f));
      mp.separation = separation;
      mp.id = featureId(sc.s == 0.0f ? edge : (edge + 1) % reference.count, 10 + (sc.t == 0.0f ? 0 : 1), flip);
      finishPoint(mp, xfA, xfB);
      m.pointCount = 1;
      return m;
    }
  }
  if (!clipTo(dot(tangent, v1), -1.0f) || !clipTo(dot(tangent, v2), 1.0f)) {
    return m;
  }
  const Vec2f normalWorld = rotate(xfA.q, flip ? -n : n);
  m.normal = normalWorld;
  for (int k = 0; k < 2; ++k) {
    const Vec2f p = clip[static_cast<std::size_t>(k)];
    const float core = dot(n, p - v1);
    const float separation = core - rRef - rInc;
    if (separation > speculativeDistance) {
      continue;
    }
    // Surface points: on the incident shape (p pulled back by its radius) and on the reference
    // face (pushed out by its radius); the contact point is midway.
    const Vec2f onIncident = p - n * rInc;
    const Vec2f onReference = p - n * (core - rRef);
    ManifoldPoint& mp = m.points[static_cast<std::size_t>(m.pointCount)];
    mp.point = transformPoint(xfA, lerp(onIncident, onReference, 0.5f));
    mp.separation = separation;
    mp.id = featureId(edge, clipId[static_cast<std::size_t>(k)], flip);
    finishPoint(mp, xfA, xfB);
    ++m.pointCount;
  }
  if (m.pointCount == 2 && m.points[0].id == m.points[1].id) {
    m.pointCount = 1; // both clipped to the same vertex
  }
  return m;
}

} // namespace impetus::rigid2d
