// The wide contact kernels for the baseline instruction set: SSE2 on x86-64 (four lanes),
// plain floats elsewhere.
#include "rigid2d/contact_wide_kernels.hpp"

namespace impetus::rigid2d::detail {

const WideKernels& baselineWideKernels() { return wideKernels; }

} // namespace impetus::rigid2d::detail
