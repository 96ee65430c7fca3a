// Four floats at once for the wide contact solver: SSE2 on x86-64 (always present there), plain
// arrays elsewhere. Only what the solver needs; every operation is lane by lane, with no fused
// multiply-add, so a lane computes exactly what the scalar solver would.
#pragma once

#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#define IMPETUS_SIMD_SSE2 1
#endif

namespace impetus::rigid2d::detail {

inline constexpr int simdWidth = 4;

#if defined(IMPETUS_SIMD_SSE2)

struct FloatW {
  __m128 v;
};

inline FloatW splatW(float s) { return {_mm_set1_ps(s)}; }
inline FloatW zeroW() { return {_mm_setzero_ps()}; }
inline FloatW loadW(const float* p) { return {_mm_loadu_ps(p)}; }
inline void storeW(float* p, FloatW a) { _mm_storeu_ps(p, a.v); }
inline FloatW operator+(FloatW a, FloatW b) { return {_mm_add_ps(a.v, b.v)}; }
inline FloatW operator-(FloatW a, FloatW b) { return {_mm_sub_ps(a.v, b.v)}; }
inline FloatW operator*(FloatW a, FloatW b) { return {_mm_mul_ps(a.v, b.v)}; }
inline FloatW operator-(FloatW a) { return {_mm_sub_ps(_mm_setzero_ps(), a.v)}; }
inline FloatW minW(FloatW a, FloatW b) { return {_mm_min_ps(a.v, b.v)}; }
inline FloatW maxW(FloatW a, FloatW b) { return {_mm_max_ps(a.v, b.v)}; }
/// All bits set in the lanes where a > b.
inline FloatW greaterW(FloatW a, FloatW b) { return {_mm_cmpgt_ps(a.v, b.v)}; }
inline FloatW equalW(FloatW a, FloatW b) { return {_mm_cmpeq_ps(a.v, b.v)}; }
inline FloatW orW(FloatW a, FloatW b) { return {_mm_or_ps(a.v, b.v)}; }
/// Lanes of `ifTrue` where `mask` is set, of `ifFalse` elsewhere.
inline FloatW selectW(FloatW mask, FloatW ifTrue, FloatW ifFalse) {
  return {_mm_or_ps(_mm_and_ps(mask.v, ifTrue.v), _mm_andnot_ps(mask.v, ifFalse.v))};
}
/// Transposes four rows of four floats in place.
inline void transposeW(FloatW& a, FloatW& b, FloatW& c, FloatW& d) { _MM_TRANSPOSE4_PS(a.v, b.v, c.v, d.v); }

#else

struct FloatW {
  float v[4];
};

template <class Op> inline FloatW mapW(FloatW a, FloatW b, Op op) {
  FloatW r;
  for (int i = 0; i < 4; ++i) {
    r.v[i] = op(a.v[i], b.v[i]);
  }
  return r;
}
inline FloatW splatW(float s) { return {{s, s, s, s}}; }
inline FloatW zeroW() { return splatW(0.0f); }
inline FloatW loadW(const float* p) { return {{p[0], p[1], p[2], p[3]}}; }
inline void storeW(float* p, FloatW a) {
  for (int i = 0; i < 4; ++i) {
    p[i] = a.v[i];
  }
}
inline FloatW operator+(FloatW a, FloatW b) {
  return mapW(a, b, [](float x, float y) { return x + y; });
}
inline FloatW operator-(FloatW a, FloatW b) {
  return mapW(a, b, [](float x, float y) { return x - y; });
}
inline FloatW operator*(FloatW a, FloatW b) {
  return mapW(a, b, [](float x, float y) { return x * y; });
}
inline FloatW operator-(FloatW a) { return zeroW() - a; }
inline FloatW minW(FloatW a, FloatW b) {
  return mapW(a, b, [](float x, float y) { return y < x ? y : x; });
}
inline FloatW maxW(FloatW a, FloatW b) {
  return mapW(a, b, [](float x, float y) { return x < y ? y : x; });
}
// Masks are 1.0f (true) or 0.0f (false) in the fallback.
inline FloatW greaterW(FloatW a, FloatW b) {
  return mapW(a, b, [](float x, float y) { return x > y ? 1.0f : 0.0f; });
}
inline FloatW equalW(FloatW a, FloatW b) {
  return mapW(a, b, [](float x, float y) { return x == y ? 1.0f : 0.0f; });
}
inline FloatW orW(FloatW a, FloatW b) {
  return mapW(a, b, [](float x, float y) { return (x != 0.0f || y != 0.0f) ? 1.0f : 0.0f; });
}
inline FloatW selectW(FloatW mask, FloatW ifTrue, FloatW ifFalse) {
  FloatW r;
  for (int i = 0; i < 4; ++i) {
    r.v[i] = mask.v[i] != 0.0f ? ifTrue.v[i] : ifFalse.v[i];
  }
  return r;
}
inline void transposeW(FloatW& a, FloatW& b, FloatW& c, FloatW& d) {
  FloatW* rows[4] = {&a, &b, &c, &d};
  FloatW t[4];
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      t[i].v[j] = rows[j]->v[i];
    }
  }
  a = t[0];
  b = t[1];
  c = t[2];
  d = t[3];
}

#endif

} // namespace impetus::rigid2d::detail
