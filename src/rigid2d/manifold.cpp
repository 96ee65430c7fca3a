#include <impetus/rigid2d/manifold.hpp>

#include "rigid2d/manifold_internal.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace impetus::rigid2d {
namespace {

void finishPoint(ManifoldPoint& mp, const Transform2f& xfA, const Transform2f& xfB) {
  mp.anchorA = mp.point - xfA.p;
  mp.anchorB = mp.point - xfB.p;
}

/// A polygon contact point: finishPoint's anchors from the point in registers (reading the
/// point back from the manifold would wait on its two stores).
void setPoint(ManifoldPoint& mp, Vec2f point, float separation, std::uint16_t id, const Transform2f& xfA,
              const Transform2f& xfB) {
  mp.point = point;
  mp.anchorA = point - xfA.p;
  mp.anchorB = point - xfB.p;
  mp.separation = separation;
  mp.id = id;
}

/// A polygon's vertices and normals without the rest of the struct: B in A's frame lives in
/// local arrays, so the narrowphase never copies (or transforms) the unused slots.
struct PolygonView {
  const Vec2f* vertices;
  const Vec2f* normals;
  int count;
};

PolygonView view(const Polygon& p) { return {p.vertices.data(), p.normals.data(), p.count}; }

/// The edge of `p1` along whose normal `p2` is farthest away, and that separation.
struct EdgeSeparation {
  int edge = 0;
  float separation = -std::numeric_limits<float>::max();
};

EdgeSeparation maxSeparation(const PolygonView& p1, const PolygonView& p2) {
  EdgeSeparation best;
  for (int i = 0; i < p1.count; ++i) {
    float deepest = std::numeric_limits<float>::max();
    for (int j = 0; j < p2.count; ++j) {
      deepest = std::min(deepest, dot(p1.normals[i], p2.vertices[j] - p1.vertices[i]));
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

/// Cores apart: if the closest features of the reference edge v1-v2 and the incident edge
/// w1-w2 (A's frame) are two vertices, the contact normal is along the line between them (a
/// rounded corner against a rounded corner), not a face normal, and the separation is their
/// true distance. Then `m` is that contact (or none, beyond reach) and the result is true.
bool cornerContact(const Vec2f& v1, const Vec2f& v2, const Vec2f& w1, const Vec2f& w2, float rRef, float rInc, int edge,
                   int edgeNext, bool flip, const Transform2f& xfA, const Transform2f& xfB, Manifold& m) {
  const SegmentClosest sc = segmentDistance(v1, v2, w1, w2);
  const bool refVertex = sc.s == 0.0f || sc.s == 1.0f;
  const bool incVertex = sc.t == 0.0f || sc.t == 1.0f;
  if (!refVertex || !incVertex) {
    return false;
  }
  const Vec2f pRef = lerp(v1, v2, sc.s);
  const Vec2f pInc = lerp(w1, w2, sc.t);
  const float dist = distance(pRef, pInc);
  const float separation = dist - rRef - rInc;
  if (separation > speculativeDistance || dist == 0.0f) {
    return true;
  }
  const Vec2f dir = (pInc - pRef) / dist; // reference to incident
  m.normal = rotate(xfA.q, flip ? -dir : dir);
  setPoint(m.points[0], transformPoint(xfA, lerp(pRef + dir * rRef, pInc - dir * rInc, 0.5f)), separation,
           featureId(sc.s == 0.0f ? edge : edgeNext, 10 + (sc.t == 0.0f ? 0 : 1), flip), xfA, xfB);
  m.pointCount = 1;
  return true;
}

/// A contact point of the clip, before its anchors.
struct ClipPoint {
  Vec2f point; // world
  float separation;
  std::uint16_t id;
};

/// clipContact's output for two clip points: each kept unless beyond reach, in order, and the
/// second dropped when both were clipped to the same feature (after being written, as there).
/// The slots are fixed, so both points can be computed side by side.
[[gnu::always_inline]] inline void storePoints(const ClipPoint& p0, const ClipPoint& p1, const Transform2f& xfA,
                                               const Transform2f& xfB, Manifold& m) {
  const bool keep0 = !(p0.separation > speculativeDistance);
  const bool keep1 = !(p1.separation > speculativeDistance);
  if (keep0) {
    setPoint(m.points[0], p0.point, p0.separation, p0.id, xfA, xfB);
    if (keep1) {
      setPoint(m.points[1], p1.point, p1.separation, p1.id, xfA, xfB);
      m.pointCount = p0.id == p1.id ? 1 : 2; // both clipped to the same vertex: one
    } else {
      m.pointCount = 1;
    }
  } else if (keep1) {
    setPoint(m.points[0], p1.point, p1.separation, p1.id, xfA, xfB);
    m.pointCount = 1;
  }
}

/// The polygon narrowphase after both separating-axis searches, in A's frame (`pb` is B there):
/// the reference face, the incident edge, the clip and the points. CountA and CountB > 0 fix
/// the vertex counts at compile time (so that the loops unroll); 0 reads them.
template <int CountA, int CountB> void clipContact(const PolygonView& a, float radiusA, const PolygonView& pb,
                                                   float radiusB, const EdgeSeparation& sa, const EdgeSeparation& sb,
                                                   const Transform2f& xfA, const Transform2f& xfB, Manifold& m) {
  const int countA = CountA > 0 ? CountA : a.count;
  const int countB = CountB > 0 ? CountB : pb.count;
  // Prefer A's face unless B's is clearly better (hysteresis keeps the choice stable).
  const bool flip = sb.separation > sa.separation + 0.1f * linearSlop;
  const PolygonView& reference = flip ? pb : a;
  const PolygonView& incident = flip ? a : pb;
  const int referenceCount = flip ? countB : countA;
  const int incidentCount = flip ? countA : countB;
  const int edge = flip ? sb.edge : sa.edge;
  const int edgeNext = edge + 1 < referenceCount ? edge + 1 : 0;
  const float rRef = flip ? radiusB : radiusA;
  const float rInc = flip ? radiusA : radiusB;
  const Vec2f v1 = reference.vertices[edge];
  const Vec2f v2 = reference.vertices[edgeNext];
  const Vec2f n = reference.normals[edge];
  // Incident edge: the one most anti-parallel to the reference normal.
  int incidentEdge = 0;
  float minDot = std::numeric_limits<float>::max();
  for (int i = 0; i < incidentCount; ++i) {
    const float d = dot(n, incident.normals[i]);
    if (d < minDot) {
      minDot = d;
      incidentEdge = i;
    }
  }
  const int i1 = incidentEdge;
  const int i2 = incidentEdge + 1 < incidentCount ? incidentEdge + 1 : 0;
  std::array<Vec2f, 2> clip{incident.vertices[i1], incident.vertices[i2]};
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
  // Cores apart (see cornerContact).
  const float coreSeparation = flip ? sb.separation : sa.separation;
  if (coreSeparation > 0.1f * linearSlop &&
      cornerContact(v1, v2, clip[0], clip[1], rRef, rInc, edge, edgeNext, flip, xfA, xfB, m)) {
    return;
  }
  if (!clipTo(dot(tangent, v1), -1.0f) || !clipTo(dot(tangent, v2), 1.0f)) {
    return;
  }
  m.normal = rotate(xfA.q, flip ? -n : n);
  const auto clipPoint = [&](std::size_t k) {
    const Vec2f p = clip[k];
    const float core = dot(n, p - v1);
    // Surface points: on the incident shape (p pulled back by its radius) and on the reference
    // face (pushed out by its radius); the contact point is midway.
    const Vec2f onIncident = p - n * rInc;
    const Vec2f onReference = p - n * (core - rRef);
    return ClipPoint{transformPoint(xfA, lerp(onIncident, onReference, 0.5f)), core - rRef - rInc,
                     featureId(edge, clipId[k], flip)};
  };
  storePoints(clipPoint(0), clipPoint(1), xfA, xfB, m);
}

/// The empty manifold, to copy from. Not const on purpose: a Manifold's zero initialisation
/// compiles to a string store (rep stos), a few ns per call here, where copying this one is six
/// vector moves; as a constant the compiler would fold it back into that zero initialisation.
constinit Manifold emptyManifold{};

/// The general path: B in A's frame, both separating-axis searches in full, then the clip.
void collideGeneral(const Polygon& a, const Transform2f& xfA, const Polygon& b, const Transform2f& xfB, Manifold& m) {
  const Transform2f relative = invMul(xfA, xfB);
  std::array<Vec2f, maxPolygonVertices> vertices;
  std::array<Vec2f, maxPolygonVertices> normals;
  for (int i = 0; i < b.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    vertices[k] = transformPoint(relative, b.vertices[k]);
    normals[k] = rotate(relative.q, b.normals[k]);
  }
  const PolygonView pa = view(a);
  const PolygonView pb{vertices.data(), normals.data(), b.count};
  const float radius = a.radius + b.radius;
  const EdgeSeparation sa = maxSeparation(pa, pb);
  if (sa.separation - radius > speculativeDistance) {
    return;
  }
  const EdgeSeparation sb = maxSeparation(pb, pa);
  if (sb.separation - radius > speculativeDistance) {
    return;
  }
  clipContact<0, 0>(pa, a.radius, pb, b.radius, sa, sb, xfA, xfB, m);
}

/// Whether `p` is a rectangle along its own frame's axes (makeBox; makeOffsetBox at angle 0):
/// its corners are {x0, x2} x {y0, y2} and each normal has an exactly zero component.
bool isAxisAlignedRectangle(const Polygon& p) {
  if (p.count != 4) {
    return false;
  }
  const auto& v = p.vertices;
  const bool grid = (v[1].x == v[0].x && v[1].y == v[2].y && v[3].x == v[2].x && v[3].y == v[0].y) ||
                    (v[1].y == v[0].y && v[1].x == v[2].x && v[3].y == v[2].y && v[3].x == v[0].x);
  const auto axial = [](const Vec2f& n) { return n.x == 0.0f || n.y == 0.0f; };
  return grid && axial(p.normals[0]) && axial(p.normals[1]) && axial(p.normals[2]) && axial(p.normals[3]);
}

/// collidePolygons when A is an axis-aligned rectangle (CountB > 0: B has that many vertices).
/// The two separating-axis searches shrink from count x count dot products each to one per
/// edge, with exactly the general search's float results, so the manifold is the same:
/// - A's normal has one zero component, so its dot product with (vertex of B - vertex of A)
///   depends on one coordinate of B's vertex, and monotonically (float rounding is monotone):
///   B's least or greatest x (or y) in A's frame gives the minimum.
/// - For B's normal, the dot product with (corner of A - vertex of B) is monotone in the
///   corner's x and in its y separately, and A's corners are all four combinations of its two
///   x and two y values: the corner with the x and the y against the normal gives the minimum.
template <int CountB>
void collideRectangle(const Polygon& a, const Transform2f& xfA, const Polygon& b, const Transform2f& xfB, Manifold& m) {
  const int countB = CountB > 0 ? CountB : b.count;
  const Transform2f relative = invMul(xfA, xfB);
  std::array<Vec2f, maxPolygonVertices> vertices;
  std::array<Vec2f, maxPolygonVertices> normals;
  vertices[0] = transformPoint(relative, b.vertices[0]);
  normals[0] = rotate(relative.q, b.normals[0]);
  Vec2f lower = vertices[0];
  Vec2f upper = vertices[0];
  for (int i = 1; i < countB; ++i) {
    const auto k = static_cast<std::size_t>(i);
    vertices[k] = transformPoint(relative, b.vertices[k]);
    normals[k] = rotate(relative.q, b.normals[k]);
    lower = {std::min(lower.x, vertices[k].x), std::min(lower.y, vertices[k].y)};
    upper = {std::max(upper.x, vertices[k].x), std::max(upper.y, vertices[k].y)};
  }
  const float radius = a.radius + b.radius;
  EdgeSeparation sa;
  for (int i = 0; i < 4; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Vec2f n = a.normals[k];
    const Vec2f deepest{n.x > 0.0f ? lower.x : upper.x, n.y > 0.0f ? lower.y : upper.y};
    const float separation = dot(n, deepest - a.vertices[k]);
    if (separation > sa.separation) {
      sa = {i, separation};
    }
  }
  if (sa.separation - radius > speculativeDistance) {
    return;
  }
  const Vec2f aLower{std::min(a.vertices[0].x, a.vertices[2].x), std::min(a.vertices[0].y, a.vertices[2].y)};
  const Vec2f aUpper{std::max(a.vertices[0].x, a.vertices[2].x), std::max(a.vertices[0].y, a.vertices[2].y)};
  EdgeSeparation sb;
  for (int i = 0; i < countB; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Vec2f n = normals[k];
    const Vec2f deepest{n.x > 0.0f ? aLower.x : aUpper.x, n.y > 0.0f ? aLower.y : aUpper.y};
    const float separation = dot(n, deepest - vertices[k]);
    if (separation > sb.separation) {
      sb = {i, separation};
    }
  }
  if (sb.separation - radius > speculativeDistance) {
    return;
  }
  clipContact<4, CountB>(view(a), a.radius, {vertices.data(), normals.data(), countB}, b.radius, sa, sb, xfA, xfB, m);
}

/// Whether `p` is exactly what makeBox builds (and makeOffsetBox at angle 0): unrounded,
/// corners counter-clockwise from the lower left, and the normals makePolygon gives every such
/// box, bit for bit: (0, -1), (1, -0), (0, 1), (-1, -0) (-0 where it negates an edge's zero).
/// With `centred`, also v2 = -v0 (makeBox). Coordinates are compared as bits, which only a box
/// whose equal coordinates differ in the sign of a zero would fail (it takes a slower path).
/// This runs twice per polygon pair, so it is a few vector compares on x86-64.
bool isPlainBox(const Polygon& p, bool centred) {
  if (p.count != 4 || p.radius != 0.0f) {
    return false;
  }
#if defined(__SSE2__)
  const __m128 v01 = _mm_loadu_ps(&p.vertices[0].x); // x0 y0 x1 y1
  const __m128 v23 = _mm_loadu_ps(&p.vertices[2].x); // x2 y2 x3 y3
  const __m128 xy = _mm_unpacklo_ps(v01, v23);       // x0 x2 y0 y2
  // On a grid: (y1, x1, y3, x3) = (y0, x2, y2, x0).
  const __m128i grid = _mm_cmpeq_epi32(_mm_castps_si128(_mm_shuffle_ps(v01, v23, _MM_SHUFFLE(2, 3, 2, 3))),
                                       _mm_castps_si128(_mm_shuffle_ps(xy, xy, _MM_SHUFFLE(0, 3, 1, 2))));
  // Counter-clockwise from the lower left: (x0, y0) < (x2, y2).
  const __m128 ordered =
      _mm_cmplt_ps(_mm_shuffle_ps(xy, xy, _MM_SHUFFLE(2, 0, 2, 0)), _mm_shuffle_ps(xy, xy, _MM_SHUFFLE(3, 1, 3, 1)));
  const __m128i normals01 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(&p.normals[0].x));
  const __m128i normals23 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(&p.normals[2].x));
  const __m128i axes01 =
      _mm_setr_epi32(0x00000000, static_cast<int>(0xbf800000), 0x3f800000, static_cast<int>(0x80000000));
  const __m128i axes23 =
      _mm_setr_epi32(0x00000000, 0x3f800000, static_cast<int>(0xbf800000), static_cast<int>(0x80000000));
  __m128i all = _mm_and_si128(_mm_and_si128(grid, _mm_castps_si128(ordered)),
                              _mm_and_si128(_mm_cmpeq_epi32(normals01, axes01), _mm_cmpeq_epi32(normals23, axes23)));
  if (centred) {
    // (x2, y2) = -(x0, y0), in lanes 0 and 1 (and again in 2 and 3).
    const __m128i negated =
        _mm_cmpeq_epi32(_mm_castps_si128(v23), _mm_castps_si128(_mm_xor_ps(v01, _mm_set1_ps(-0.0f))));
    all = _mm_and_si128(all, _mm_shuffle_epi32(negated, _MM_SHUFFLE(1, 0, 1, 0)));
  }
  return _mm_movemask_epi8(all) == 0xffff;
#else
  constexpr std::array<std::uint32_t, 8> axes{0x00000000, 0xbf800000, 0x3f800000, 0x80000000,
                                              0x00000000, 0x3f800000, 0xbf800000, 0x80000000};
  std::array<std::uint32_t, 8> v{};
  std::array<std::uint32_t, 8> n{};
  std::memcpy(v.data(), p.vertices.data(), sizeof(v));
  std::memcpy(n.data(), p.normals.data(), sizeof(n));
  std::uint32_t differ = 0;
  for (std::size_t i = 0; i < 8; ++i) {
    differ |= n[i] ^ axes[i];
  }
  // y1 = y0, x1 = x2, y3 = y2, x3 = x0.
  differ |= (v[3] ^ v[1]) | (v[2] ^ v[4]) | (v[7] ^ v[5]) | (v[6] ^ v[0]);
  if (centred) {
    constexpr std::uint32_t sign = 0x80000000;
    differ |= (v[4] ^ v[0] ^ sign) | (v[5] ^ v[1] ^ sign);
  }
  return differ == 0 && p.vertices[0].x < p.vertices[2].x && p.vertices[0].y < p.vertices[2].y;
#endif
}

/// collidePolygons' choice of path (detail::polygonPath).
detail::PolygonPath pathFor(const Polygon& a, const Polygon& b) {
  if (isPlainBox(a, false) && isPlainBox(b, true)) {
    return detail::PolygonPath::boxes;
  }
  return isAxisAlignedRectangle(a) ? detail::PolygonPath::rectangle : detail::PolygonPath::general;
}

/// The first of the largest of four separations, as maxSeparation's scan finds it (a later
/// equal one does not replace it), by a two-level comparison instead of a chain of four.
EdgeSeparation firstLargest(const std::array<float, 4>& s) {
  const bool second01 = s[1] > s[0];
  const bool second23 = s[3] > s[2];
  const float best01 = second01 ? s[1] : s[0];
  const float best23 = second23 ? s[3] : s[2];
  if (best23 > best01) {
    return {second23 ? 3 : 2, best23};
  }
  return {second01 ? 1 : 0, best01};
}

/// Coordinates in the frame of A's face `Face` (0 bottom, normal -y; 1 right, +x; 2 top, +y;
/// 3 left, -x): u along the face (counter-clockwise), w along its outward normal. A plain box's
/// faces lie along its axes, so this change of frame only swaps and negates coordinates, exactly:
/// every float of the general path in A's frame has its exact counterpart here, and the face
/// normal's and tangent's dot products become copies. A template, so that the swaps and signs
/// cost nothing.
template <int Face> struct FaceFrame {
  static constexpr bool swap = (Face & 1) != 0; // u is y and w is x
  static constexpr bool negateU = Face >= 2;
  static constexpr bool negateW = Face == 0 || Face == 3;

  [[nodiscard]] static float sign(bool negate, float v) { return negate ? -v : v; }
  [[nodiscard]] static Vec2f to(const Vec2f& v) {
    return {sign(negateU, swap ? v.y : v.x), sign(negateW, swap ? v.x : v.y)};
  }
  [[nodiscard]] static Vec2f from(const Vec2f& f) {
    return {swap ? sign(negateW, f.y) : sign(negateU, f.x), swap ? sign(negateU, f.x) : sign(negateW, f.y)};
  }
  /// rotate(q, the face's normal): the products with the normal's 0 and +-1 folded.
  [[nodiscard]] static Vec2f rotatedNormal(const Rot2f& q) {
    constexpr std::array<bool, 4> negateC{true, false, false, true}; // -c, c, c, -c
    constexpr std::array<bool, 4> negateS{false, false, true, true}; // s, s, -s, -s
    const float c = sign(negateC[Face], q.c);
    const float s = sign(negateS[Face], q.s);
    return swap ? Vec2f{c, s} : Vec2f{s, c};
  }
};

/// The first of the smallest of four values, as the incident-edge scan finds it (a later equal
/// one does not replace it).
int firstSmallest(const std::array<float, 4>& d) {
  const bool second01 = d[1] < d[0];
  const bool second23 = d[3] < d[2];
  const float best01 = second01 ? d[1] : d[0];
  const float best23 = second23 ? d[3] : d[2];
  if (best23 < best01) {
    return second23 ? 3 : 2;
  }
  return second01 ? 1 : 0;
}

/// B, a centred plain box, in A's frame: its corners and normals, the floats transformPoint
/// and rotate give.
struct BoxInA {
  std::array<Vec2f, 4> corners;
  std::array<Vec2f, 4> normals;

  [[nodiscard]] Vec2f corner(int i) const { return corners[static_cast<std::size_t>(i)]; }
  [[nodiscard]] Vec2f normal(int i) const { return normals[static_cast<std::size_t>(i)]; }
};

/// collideBoxes with A's face `sa.edge` as the reference: clipContact in that face's frame.
template <int Face> void clipOnFaceOfA(const Polygon& a, const BoxInA& boxB, float separationA, const Transform2f& xfA,
                                       const Transform2f& xfB, Manifold& m) {
  constexpr int edge = Face;
  constexpr int edgeNext = (Face + 1) & 3;
  using f = FaceFrame<Face>;
  // Incident edge: the one most anti-parallel to the face normal (its dot product with B's
  // normal is the normal's w).
  const int incident = firstSmallest(
      {f::to(boxB.normal(0)).y, f::to(boxB.normal(1)).y, f::to(boxB.normal(2)).y, f::to(boxB.normal(3)).y});
  const int incidentNext = (incident + 1) & 3;
  const Vec2f v1 = a.vertices[static_cast<std::size_t>(edge)];
  const Vec2f v2 = a.vertices[static_cast<std::size_t>(edgeNext)];
  const Vec2f w1 = boxB.corner(incident);
  const Vec2f w2 = boxB.corner(incidentNext);
  if (separationA > 0.1f * linearSlop &&
      cornerContact(v1, v2, w1, w2, 0.0f, 0.0f, edge, edgeNext, false, xfA, xfB, m)) {
    return;
  }
  const Vec2f r1 = f::to(v1);
  const Vec2f r2 = f::to(v2);
  std::array<Vec2f, 2> clip{f::to(w1), f::to(w2)};
  std::array<int, 2> clipId{incident, incidentNext};
  // clipContact's clip, where the tangent's dot product is the u coordinate.
  const auto clipTo = [&](float offsetAlong, float sign, int planeId) {
    const float d0 = sign * (clip[0].x - offsetAlong);
    const float d1 = sign * (clip[1].x - offsetAlong);
    if (d0 > 0.0f && d1 > 0.0f) {
      return false;
    }
    if (d0 > 0.0f) {
      clip[0] = clip[0] + (clip[1] - clip[0]) * (d0 / (d0 - d1));
      clipId[0] = planeId;
    } else if (d1 > 0.0f) {
      clip[1] = clip[1] + (clip[0] - clip[1]) * (d1 / (d1 - d0));
      clipId[1] = planeId;
    }
    return true;
  };
  if (!clipTo(r1.x, -1.0f, 8) || !clipTo(r2.x, 1.0f, 9)) {
    return;
  }
  m.normal = f::rotatedNormal(xfA.q);
  // Unrounded: the separation is the core distance, the incident point is p and the reference
  // point p pulled back onto the face; the contact point is midway (as lerp).
  const auto clipPoint = [&](std::size_t k) {
    const Vec2f p = clip[k];
    const float separation = p.y - r1.y;
    const Vec2f local{p.x, p.y + ((p.y - separation) - p.y) * 0.5f};
    return ClipPoint{transformPoint(xfA, f::from(local)), separation, featureId(edge, clipId[k], false)};
  };
  storePoints(clipPoint(0), clipPoint(1), xfA, xfB, m);
}

/// collideBoxes with B's face `sb.edge` as the reference: clipContact, with the products with
/// A's normals (the axes) and with the radii (zero) folded.
void clipOnFaceOfB(const Polygon& a, const BoxInA& boxB, const EdgeSeparation& sb, const Transform2f& xfA,
                   const Transform2f& xfB, Manifold& m) {
  const int edge = sb.edge;
  const int edgeNext = (edge + 1) & 3;
  const Vec2f v1 = boxB.corner(edge);
  const Vec2f v2 = boxB.corner(edgeNext);
  const Vec2f n = boxB.normal(edge);
  // dot(n, A's normals (0, -1), (1, 0), (0, 1), (-1, 0)).
  const int incident = firstSmallest({-n.y, n.x, n.y, -n.x});
  const int incidentNext = (incident + 1) & 3;
  std::array<Vec2f, 2> clip{a.vertices[static_cast<std::size_t>(incident)],
                            a.vertices[static_cast<std::size_t>(incidentNext)]};
  std::array<int, 2> clipId{incident, incidentNext};
  if (sb.separation > 0.1f * linearSlop &&
      cornerContact(v1, v2, clip[0], clip[1], 0.0f, 0.0f, edge, edgeNext, true, xfA, xfB, m)) {
    return;
  }
  const Vec2f tangent{-n.y, n.x};
  const auto clipTo = [&](float offsetAlong, float sign, int planeId) {
    const float d0 = sign * (dot(tangent, clip[0]) - offsetAlong);
    const float d1 = sign * (dot(tangent, clip[1]) - offsetAlong);
    if (d0 > 0.0f && d1 > 0.0f) {
      return false;
    }
    if (d0 > 0.0f) {
      clip[0] = clip[0] + (clip[1] - clip[0]) * (d0 / (d0 - d1));
      clipId[0] = planeId;
    } else if (d1 > 0.0f) {
      clip[1] = clip[1] + (clip[0] - clip[1]) * (d1 / (d1 - d0));
      clipId[1] = planeId;
    }
    return true;
  };
  if (!clipTo(dot(tangent, v1), -1.0f, 8) || !clipTo(dot(tangent, v2), 1.0f, 9)) {
    return;
  }
  m.normal = rotate(xfA.q, -n);
  const auto clipPoint = [&](std::size_t k) {
    const Vec2f p = clip[k];
    const float separation = dot(n, p - v1);
    return ClipPoint{transformPoint(xfA, lerp(p, p - n * separation, 0.5f)), separation,
                     featureId(edge, clipId[k], true)};
  };
  storePoints(clipPoint(0), clipPoint(1), xfA, xfB, m);
}

/// collidePolygons for two plain boxes, B centred (the pyramid's, the tumbler's: most box
/// stacks). The same floats as the general path, fewer of them and on shorter chains:
/// - B's corners (+-hx, +-hy) rotated share four products up to sign, and its normals rotated
///   are (c, s) up to order and sign;
/// - the separating-axis searches are collideRectangle's, with A's normals the axes;
/// - the clip is clipContact's, with A's face as the reference (the common case) in that
///   face's frame, where the face normal's dot products are coordinates.
[[gnu::noinline]] void collideBoxes(const Polygon& a, const Transform2f& xfA, const Polygon& b, const Transform2f& xfB,
                                    Manifold& m) {
  const Transform2f relative = invMul(xfA, xfB);
  const float c = relative.q.c;
  const float s = relative.q.s;
  const Vec2f half = b.vertices[2];
  const float cx = c * half.x;
  const float sy = s * half.y;
  const float sx = s * half.x;
  const float cy = c * half.y;
  const float x1 = cx - sy;
  const float x2 = cx + sy;
  const float y1 = sx + cy;
  const float y2 = sx - cy;
  // rotate(q, (hx, hy)) = (x1, y1) and rotate(q, (hx, -hy)) = (x2, y2); the opposite corners
  // negate them. The normals (0, -1), (1, 0), ... rotated are (s, -c), (c, s), ...
  const BoxInA boxB{{Vec2f{-x1, -y1} + relative.p, Vec2f{x2, y2} + relative.p, Vec2f{x1, y1} + relative.p,
                     Vec2f{-x2, -y2} + relative.p},
                    {Vec2f{s, -c}, Vec2f{c, s}, Vec2f{-s, c}, Vec2f{-c, -s}}};
  // B's extent in A's frame: the corners' coordinates are p + (+-x1 or +-x2, ...), and adding
  // p is monotone, so the least is p - max(|x1|, |x2|) exactly as the least of the four sums.
  const Vec2f reach{std::max(std::abs(x1), std::abs(x2)), std::max(std::abs(y1), std::abs(y2))};
  const Vec2f lower = relative.p - reach;
  const Vec2f upper = relative.p + reach;
  // A's faces: B's extent along each axis (collideRectangle) with the normals' products folded.
  const Vec2f a0 = a.vertices[0]; // lower left
  const Vec2f a2 = a.vertices[2]; // upper right
  const EdgeSeparation sa = firstLargest({a0.y - upper.y, lower.x - a2.x, lower.y - a2.y, a0.x - upper.x});
  if (sa.separation > speculativeDistance) {
    return;
  }
  // B's faces: the deepest of A's corners along each normal (collideRectangle). Each of the
  // dot product's two terms is monotone in its corner coordinate, so the least term over A's
  // two x (and two y) values, summed, is the least of the four corners' dot products.
  std::array<float, 4> sbs{};
  for (std::size_t i = 0; i < 4; ++i) {
    const Vec2f n = boxB.normals[i];
    const Vec2f to0 = a0 - boxB.corners[i];
    const Vec2f to2 = a2 - boxB.corners[i];
    sbs[i] = std::min(n.x * to0.x, n.x * to2.x) + std::min(n.y * to0.y, n.y * to2.y);
  }
  const EdgeSeparation sb = firstLargest(sbs);
  if (sb.separation > speculativeDistance) {
    return;
  }
  // clipContact's choice of reference face.
  if (sb.separation > sa.separation + 0.1f * linearSlop) {
    clipOnFaceOfB(a, boxB, sb, xfA, xfB, m);
  } else {
    switch (sa.edge) {
    case 0:
      clipOnFaceOfA<0>(a, boxB, sa.separation, xfA, xfB, m);
      break;
    case 1:
      clipOnFaceOfA<1>(a, boxB, sa.separation, xfA, xfB, m);
      break;
    case 2:
      clipOnFaceOfA<2>(a, boxB, sa.separation, xfA, xfB, m);
      break;
    default:
      clipOnFaceOfA<3>(a, boxB, sa.separation, xfA, xfB, m);
      break;
    }
  }
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
    // On or outside the face's plane and beyond one of its ends: the end vertex is the closest
    // feature. (">= 0", not "> 0": a centre on a segment's or capsule core's line, beyond its
    // end, has a face separation of exactly 0 and got a phantom contact at any distance.)
    if (faceSeparation >= 0.0f && (u < 0.0f || u > dot(edge, edge))) {
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

namespace detail {

Manifold collidePolygonsGeneral(const Polygon& a, const Transform2f& xfA, const Polygon& b, const Transform2f& xfB) {
  Manifold m = emptyManifold;
  collideGeneral(a, xfA, b, xfB, m);
  return m;
}

PolygonPath polygonPath(const Polygon& a, const Polygon& b) { return pathFor(a, b); }

} // namespace detail

Manifold collidePolygons(const Polygon& a, const Transform2f& xfA, const Polygon& b, const Transform2f& xfB) {
  // One named result for every path: built in place, not copied out.
  Manifold m = emptyManifold;
  switch (pathFor(a, b)) {
  case detail::PolygonPath::boxes:
    collideBoxes(a, xfA, b, xfB, m);
    break;
  case detail::PolygonPath::rectangle:
    if (b.count == 4) {
      collideRectangle<4>(a, xfA, b, xfB, m);
    } else {
      collideRectangle<0>(a, xfA, b, xfB, m);
    }
    break;
  case detail::PolygonPath::general:
    collideGeneral(a, xfA, b, xfB, m);
    break;
  }
  return m;
}

} // namespace impetus::rigid2d
