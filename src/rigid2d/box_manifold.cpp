// The polygon narrowphase's shortcut for two plain boxes (makeBox; A may be offset, as
// makeOffsetBox at angle 0, B centred): the general path's manifold bit for bit on fewer floats
// (polygon_manifold.cpp holds the general path, polygon_narrowphase.hpp the shared steps).
#include "rigid2d/polygon_narrowphase.hpp"

namespace impetus::rigid2d::narrowphase {
namespace {

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
template <int Face> void clipOnFaceOfA(const Polygon& a, const BoxInA& boxB, const Apart* apart, const Transform2f& xfA,
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
  const float tolerance = sideTolerance(v1, v2, w1, w2);
  const Vec2f r1 = f::to(v1);
  const Vec2f r2 = f::to(v2);
  std::array<Vec2f, 2> clip{f::to(w1), f::to(w2)};
  std::array<int, 2> clipId{incident, incidentNext};
  // clipContact's clip, where the tangent's dot product is the u coordinate.
  const auto clipTo = [&](float offsetAlong, float sign, int planeId) {
    const float d0 = sign * (clip[0].x - offsetAlong);
    const float d1 = sign * (clip[1].x - offsetAlong);
    return clipToPlane(clip, clipId, d0, d1, tolerance, planeId);
  };
  if (!clipTo(r1.x, -1.0f, 8) || !clipTo(r2.x, 1.0f, 9)) {
    if (apart != nullptr) {
      closestPointsContact(*apart, xfA, xfB, m);
      return;
    }
    clip = {f::to(w1), f::to(w2)};
    clipId = {incident, incidentNext};
  }
  m.normal = f::rotatedNormal(xfA.q);
  // Unrounded: the separation is the core distance, the incident point is p and the reference
  // point p pulled back onto the face; the contact point is midway (as lerp).
  const auto clipPoint = [&](std::size_t k) {
    const Vec2f p = clip[k];
    const float separation = p.y - r1.y;
    const Vec2f local{p.x, p.y + ((p.y - separation) - p.y) * 0.5f};
    return ClipPoint{transformPoint(xfA, f::from(local)), separation,
                     clipPointId(k == 0 ? edgeNext : edge, k == 0 ? incident : incidentNext, false), clipId[k]};
  };
  storePoints(clipPoint(1), clipPoint(0), xfA, xfB, m); // storePoints' order, for A's face
}

/// collideBoxes with B's face `sb.edge` as the reference: clipContact, with the products with
/// A's normals (the axes) and with the radii (zero) folded.
void clipOnFaceOfB(const Polygon& a, const BoxInA& boxB, const EdgeSeparation& sb, const Apart* apart,
                   const Transform2f& xfA, const Transform2f& xfB, Manifold& m) {
  const int edge = sb.edge;
  const int edgeNext = (edge + 1) & 3;
  const Vec2f v1 = boxB.corner(edge);
  const Vec2f v2 = boxB.corner(edgeNext);
  const Vec2f n = boxB.normal(edge);
  // dot(n, A's normals (0, -1), (1, 0), (0, 1), (-1, 0)).
  const int incident = firstSmallest({-n.y, n.x, n.y, -n.x});
  const int incidentNext = (incident + 1) & 3;
  const Vec2f w1 = a.vertices[static_cast<std::size_t>(incident)];
  const Vec2f w2 = a.vertices[static_cast<std::size_t>(incidentNext)];
  const float tolerance = sideTolerance(v1, v2, w1, w2);
  std::array<Vec2f, 2> clip{w1, w2};
  std::array<int, 2> clipId{incident, incidentNext};
  const Vec2f tangent{-n.y, n.x};
  const auto clipTo = [&](float offsetAlong, float sign, int planeId) {
    const float d0 = sign * (dot(tangent, clip[0]) - offsetAlong);
    const float d1 = sign * (dot(tangent, clip[1]) - offsetAlong);
    return clipToPlane(clip, clipId, d0, d1, tolerance, planeId);
  };
  if (!clipTo(dot(tangent, v1), -1.0f, 8) || !clipTo(dot(tangent, v2), 1.0f, 9)) {
    if (apart != nullptr) {
      closestPointsContact(*apart, xfA, xfB, m);
      return;
    }
    clip = {w1, w2};
    clipId = {incident, incidentNext};
  }
  m.normal = rotate(xfA.q, -n);
  const auto clipPoint = [&](std::size_t k) {
    const Vec2f p = clip[k];
    const float separation = dot(n, p - v1);
    return ClipPoint{transformPoint(xfA, lerp(p, p - n * separation, 0.5f)), separation,
                     clipPointId(k == 0 ? edgeNext : edge, k == 0 ? incident : incidentNext, true), clipId[k]};
  };
  storePoints(clipPoint(0), clipPoint(1), xfA, xfB, m);
}

} // namespace

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

/// collidePolygons for two plain boxes, B centred (the pyramid's, the tumbler's: most box
/// stacks). The same floats as the general path, fewer of them and on shorter chains:
/// - B's corners (+-hx, +-hy) rotated share four products up to sign, and its normals rotated
///   are (c, s) up to order and sign;
/// - the separating-axis searches are collideRectangle's, with A's normals the axes;
/// - the clip is clipContact's, with A's face as the reference (the common case) in that
///   face's frame, where the face normal's dot products are coordinates.
void collideBoxes(const Polygon& a, const Transform2f& xfA, const Polygon& b, const Transform2f& xfB, Manifold& m) {
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
    m.separationBound = sa.separation;
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
    m.separationBound = sb.separation;
    return;
  }
  // clipContact's vertex contact for cores apart (boxes have area: their separating-axis test is
  // complete), on the same floats: B's corners and normals are the general path's.
  Apart apart{};
  const bool coresApart = std::max(sa.separation, sb.separation) > 0.0f;
  if (coresApart) {
    apart = apartFaces(view(a), 4, 0.0f, {boxB.corners.data(), boxB.normals.data(), 4}, 4, 0.0f, sa, sb);
    if (vertexContact(apart, xfA, xfB, m)) {
      return;
    }
  }
  const Apart* apartIf = coresApart ? &apart : nullptr;
  // clipContact's choice of reference face.
  if (referenceIsB(a.normals[static_cast<std::size_t>(sa.edge)], boxB.normal(sb.edge), sa, sb, apartIf)) {
    clipOnFaceOfB(a, boxB, sb, apartIf, xfA, xfB, m);
  } else {
    switch (sa.edge) {
    case 0:
      clipOnFaceOfA<0>(a, boxB, apartIf, xfA, xfB, m);
      break;
    case 1:
      clipOnFaceOfA<1>(a, boxB, apartIf, xfA, xfB, m);
      break;
    case 2:
      clipOnFaceOfA<2>(a, boxB, apartIf, xfA, xfB, m);
      break;
    default:
      clipOnFaceOfA<3>(a, boxB, apartIf, xfA, xfB, m);
      break;
    }
  }
}

} // namespace impetus::rigid2d::narrowphase
