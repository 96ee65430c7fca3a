// The wide contact kernels for AVX2 (eight lanes). This translation unit alone is compiled
// with -mavx2 (src/CMakeLists.txt); its code has internal linkage (contact_wide_kernels.hpp), so
// nothing built for AVX2 can stand in for a baseline function elsewhere, and it runs only after
// contact_solver.cpp has asked the CPU whether it supports AVX2. The test rigid2d_avx2_object_is_sealed checks that
// this object defines no shared (weak) symbol.
#if defined(__x86_64__) && defined(__AVX2__)
#define IMPETUS_SIMD_AVX2 1
#include "rigid2d/contact_wide_kernels.hpp"
#else
#include "rigid2d/contact_constraint.hpp"
#endif

namespace impetus::rigid2d::detail {

const WideKernels* avx2WideKernelsBuilt() {
#if defined(__x86_64__) && defined(__AVX2__)
  return &wideKernels;
#else
  return nullptr;
#endif
}

} // namespace impetus::rigid2d::detail
