// Several floats at once for the wide constraint solvers of every world (the solver layer: no
// dimension in it): eight with AVX2 (IMPETUS_SIMD_AVX2 in a translation unit compiled with
// -mavx2), four with SSE2 (always present on x86-64), four plain floats elsewhere. Each flavour
// lives in its own inline namespace, so translation units built for different instruction sets
// never share a function of the same name. Only what the solvers need; every operation is lane
// by lane, with no fused multiply-add, so a lane computes exactly what the scalar solver would.
//
// Bodies are loaded and stored as rows of eight floats (2D: v.x, v.y, w, unused, dp.x, dp.y,
// dq.c, dq.s) and transposed into one FloatW per field.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#if defined(IMPETUS_SIMD_AVX2) && defined(__AVX2__)
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#define IMPETUS_SIMD_SSE2 1
#undef IMPETUS_SIMD_AVX2
#else
#undef IMPETUS_SIMD_AVX2
#endif

#if defined(IMPETUS_SIMD_AVX2)
#define IMPETUS_SIMD_NAMESPACE simd_avx2
#elif defined(IMPETUS_SIMD_SSE2)
#define IMPETUS_SIMD_NAMESPACE simd_sse2
#else
#define IMPETUS_SIMD_NAMESPACE simd_scalar
#endif

namespace impetus::solver {
inline namespace IMPETUS_SIMD_NAMESPACE {

#if defined(IMPETUS_SIMD_AVX2)

inline constexpr int simdWidth = 8;
inline constexpr const char* simdName = "avx2";

struct FloatW {
  __m256 v;
};

inline FloatW splatW(float s) { return {_mm256_set1_ps(s)}; }
inline FloatW zeroW() { return {_mm256_setzero_ps()}; }
inline FloatW operator+(FloatW a, FloatW b) { return {_mm256_add_ps(a.v, b.v)}; }
inline FloatW operator-(FloatW a, FloatW b) { return {_mm256_sub_ps(a.v, b.v)}; }
inline FloatW operator*(FloatW a, FloatW b) { return {_mm256_mul_ps(a.v, b.v)}; }
inline FloatW operator/(FloatW a, FloatW b) { return {_mm256_div_ps(a.v, b.v)}; }
inline FloatW sqrtW(FloatW a) { return {_mm256_sqrt_ps(a.v)}; }
inline FloatW operator-(FloatW a) { return {_mm256_sub_ps(_mm256_setzero_ps(), a.v)}; }
/// -a exactly as the scalar -x: the sign flipped (0 - a would turn -0 into +0).
inline FloatW negateW(FloatW a) { return {_mm256_xor_ps(a.v, _mm256_set1_ps(-0.0f))}; }
inline FloatW minW(FloatW a, FloatW b) { return {_mm256_min_ps(a.v, b.v)}; }
inline FloatW maxW(FloatW a, FloatW b) { return {_mm256_max_ps(a.v, b.v)}; }
inline FloatW greaterW(FloatW a, FloatW b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GT_OQ)}; }
inline FloatW equalW(FloatW a, FloatW b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_EQ_OQ)}; }
inline FloatW orW(FloatW a, FloatW b) { return {_mm256_or_ps(a.v, b.v)}; }
inline FloatW andW(FloatW a, FloatW b) { return {_mm256_and_ps(a.v, b.v)}; }
inline FloatW selectW(FloatW mask, FloatW ifTrue, FloatW ifFalse) {
  return {_mm256_blendv_ps(ifFalse.v, ifTrue.v, mask.v)};
}
/// Whether any lane of a is non-zero (a mask or a value: -0.0 counts as zero). Unordered, as
/// SSE2's cmpneq: a mask's set lanes are NaN bit patterns.
inline bool anyNonZeroW(FloatW a) {
  return _mm256_movemask_ps(_mm256_cmp_ps(a.v, _mm256_setzero_ps(), _CMP_NEQ_UQ)) != 0;
}

/// Eight rows of eight floats (one per body) into eight columns (one per field).
inline void loadRowsW(const float* const (&rows)[8], FloatW (&columns)[8]) {
  __m256 r[8];
  for (int i = 0; i < 8; ++i) {
    r[i] = _mm256_loadu_ps(rows[i]);
  }
  const __m256 t0 = _mm256_unpacklo_ps(r[0], r[1]);
  const __m256 t1 = _mm256_unpackhi_ps(r[0], r[1]);
  const __m256 t2 = _mm256_unpacklo_ps(r[2], r[3]);
  const __m256 t3 = _mm256_unpackhi_ps(r[2], r[3]);
  const __m256 t4 = _mm256_unpacklo_ps(r[4], r[5]);
  const __m256 t5 = _mm256_unpackhi_ps(r[4], r[5]);
  const __m256 t6 = _mm256_unpacklo_ps(r[6], r[7]);
  const __m256 t7 = _mm256_unpackhi_ps(r[6], r[7]);
  const __m256 s0 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0));
  const __m256 s1 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
  const __m256 s2 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0));
  const __m256 s3 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2));
  const __m256 s4 = _mm256_shuffle_ps(t4, t6, _MM_SHUFFLE(1, 0, 1, 0));
  const __m256 s5 = _mm256_shuffle_ps(t4, t6, _MM_SHUFFLE(3, 2, 3, 2));
  const __m256 s6 = _mm256_shuffle_ps(t5, t7, _MM_SHUFFLE(1, 0, 1, 0));
  const __m256 s7 = _mm256_shuffle_ps(t5, t7, _MM_SHUFFLE(3, 2, 3, 2));
  columns[0].v = _mm256_permute2f128_ps(s0, s4, 0x20);
  columns[1].v = _mm256_permute2f128_ps(s1, s5, 0x20);
  columns[2].v = _mm256_permute2f128_ps(s2, s6, 0x20);
  columns[3].v = _mm256_permute2f128_ps(s3, s7, 0x20);
  columns[4].v = _mm256_permute2f128_ps(s0, s4, 0x31);
  columns[5].v = _mm256_permute2f128_ps(s1, s5, 0x31);
  columns[6].v = _mm256_permute2f128_ps(s2, s6, 0x31);
  columns[7].v = _mm256_permute2f128_ps(s3, s7, 0x31);
}

/// Writes columns c0..c3 as the first four floats of each row .
inline void storeRowHeadsW(float* const (&rows)[8], FloatW c0, FloatW c1, FloatW c2, FloatW c3) {
  for (int half = 0; half < 2; ++half) {
    __m128 a = half == 0 ? _mm256_castps256_ps128(c0.v) : _mm256_extractf128_ps(c0.v, 1);
    __m128 b = half == 0 ? _mm256_castps256_ps128(c1.v) : _mm256_extractf128_ps(c1.v, 1);
    __m128 c = half == 0 ? _mm256_castps256_ps128(c2.v) : _mm256_extractf128_ps(c2.v, 1);
    __m128 d = half == 0 ? _mm256_castps256_ps128(c3.v) : _mm256_extractf128_ps(c3.v, 1);
    _MM_TRANSPOSE4_PS(a, b, c, d);
    const __m128 out[4] = {a, b, c, d};
    for (int i = 0; i < 4; ++i) {
      _mm_storeu_ps(rows[4 * half + i], out[i]);
    }
  }
}

/// The first four floats of eight rows into four columns (velocities only: warm start, bounce).
inline void loadRowHeadsW(const float* const (&rows)[8], FloatW& c0, FloatW& c1, FloatW& c2, FloatW& c3) {
  __m128 lo[4];
  __m128 hi[4];
  for (int i = 0; i < 4; ++i) {
    lo[i] = _mm_loadu_ps(rows[i]);
    hi[i] = _mm_loadu_ps(rows[4 + i]);
  }
  _MM_TRANSPOSE4_PS(lo[0], lo[1], lo[2], lo[3]);
  _MM_TRANSPOSE4_PS(hi[0], hi[1], hi[2], hi[3]);
  c0.v = _mm256_insertf128_ps(_mm256_castps128_ps256(lo[0]), hi[0], 1);
  c1.v = _mm256_insertf128_ps(_mm256_castps128_ps256(lo[1]), hi[1], 1);
  c2.v = _mm256_insertf128_ps(_mm256_castps128_ps256(lo[2]), hi[2], 1);
  c3.v = _mm256_insertf128_ps(_mm256_castps128_ps256(lo[3]), hi[3], 1);
}

#elif defined(IMPETUS_SIMD_SSE2)

inline constexpr int simdWidth = 4;
inline constexpr const char* simdName = "sse2";

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
inline FloatW operator/(FloatW a, FloatW b) { return {_mm_div_ps(a.v, b.v)}; }
/// The correctly rounded square root in each lane, as std::sqrt.
inline FloatW sqrtW(FloatW a) { return {_mm_sqrt_ps(a.v)}; }
inline FloatW operator-(FloatW a) { return {_mm_sub_ps(_mm_setzero_ps(), a.v)}; }
/// -a exactly as the scalar -x: the sign flipped (0 - a would turn -0 into +0).
inline FloatW negateW(FloatW a) { return {_mm_xor_ps(a.v, _mm_set1_ps(-0.0f))}; }
inline FloatW minW(FloatW a, FloatW b) { return {_mm_min_ps(a.v, b.v)}; }
inline FloatW maxW(FloatW a, FloatW b) { return {_mm_max_ps(a.v, b.v)}; }
/// All bits set in the lanes where a > b.
inline FloatW greaterW(FloatW a, FloatW b) { return {_mm_cmpgt_ps(a.v, b.v)}; }
inline FloatW equalW(FloatW a, FloatW b) { return {_mm_cmpeq_ps(a.v, b.v)}; }
inline FloatW orW(FloatW a, FloatW b) { return {_mm_or_ps(a.v, b.v)}; }
inline FloatW andW(FloatW a, FloatW b) { return {_mm_and_ps(a.v, b.v)}; }
/// Lanes of `ifTrue` where `mask` is set, of `ifFalse` elsewhere.
inline FloatW selectW(FloatW mask, FloatW ifTrue, FloatW ifFalse) {
  return {_mm_or_ps(_mm_and_ps(mask.v, ifTrue.v), _mm_andnot_ps(mask.v, ifFalse.v))};
}
/// Transposes four rows of four floats in place.
inline void transposeW(FloatW& a, FloatW& b, FloatW& c, FloatW& d) { _MM_TRANSPOSE4_PS(a.v, b.v, c.v, d.v); }
/// Whether any lane of a is non-zero (a mask or a value: -0.0 counts as zero).
inline bool anyNonZeroW(FloatW a) { return _mm_movemask_ps(_mm_cmpneq_ps(a.v, _mm_setzero_ps())) != 0; }

#else

inline constexpr int simdWidth = 4;
inline constexpr const char* simdName = "scalar";

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
inline FloatW operator/(FloatW a, FloatW b) {
  return mapW(a, b, [](float x, float y) { return x / y; });
}
inline FloatW operator-(FloatW a) { return zeroW() - a; }
inline FloatW negateW(FloatW a) { return {{-a.v[0], -a.v[1], -a.v[2], -a.v[3]}}; }
inline FloatW sqrtW(FloatW a) { return {{std::sqrt(a.v[0]), std::sqrt(a.v[1]), std::sqrt(a.v[2]), std::sqrt(a.v[3])}}; }
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
inline FloatW andW(FloatW a, FloatW b) {
  return mapW(a, b, [](float x, float y) { return (x != 0.0f && y != 0.0f) ? 1.0f : 0.0f; });
}
inline FloatW selectW(FloatW mask, FloatW ifTrue, FloatW ifFalse) {
  FloatW r;
  for (int i = 0; i < 4; ++i) {
    r.v[i] = mask.v[i] != 0.0f ? ifTrue.v[i] : ifFalse.v[i];
  }
  return r;
}
inline bool anyNonZeroW(FloatW a) { return a.v[0] != 0.0f || a.v[1] != 0.0f || a.v[2] != 0.0f || a.v[3] != 0.0f; }
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

#if !defined(IMPETUS_SIMD_AVX2)
/// Four rows of eight floats (one per body) into eight columns (one per field).
inline void loadRowsW(const float* const (&rows)[4], FloatW (&columns)[8]) {
  for (int half = 0; half < 2; ++half) {
    FloatW r[4];
    for (int i = 0; i < 4; ++i) {
      r[i] = loadW(rows[i] + static_cast<std::ptrdiff_t>(4 * half));
    }
    transposeW(r[0], r[1], r[2], r[3]);
    for (int i = 0; i < 4; ++i) {
      columns[4 * half + i] = r[i];
    }
  }
}

/// The first four floats of four rows into four columns (velocities only: warm start, bounce).
inline void loadRowHeadsW(const float* const (&rows)[4], FloatW& c0, FloatW& c1, FloatW& c2, FloatW& c3) {
  c0 = loadW(rows[0]);
  c1 = loadW(rows[1]);
  c2 = loadW(rows[2]);
  c3 = loadW(rows[3]);
  transposeW(c0, c1, c2, c3);
}

/// Writes columns c0..c3 as the first four floats of each row .
inline void storeRowHeadsW(float* const (&rows)[4], FloatW c0, FloatW c1, FloatW c2, FloatW c3) {
  transposeW(c0, c1, c2, c3);
  const FloatW out[4] = {c0, c1, c2, c3};
  for (int i = 0; i < 4; ++i) {
    storeW(rows[i], out[i]);
  }
}
#endif

} // namespace IMPETUS_SIMD_NAMESPACE
} // namespace impetus::solver
