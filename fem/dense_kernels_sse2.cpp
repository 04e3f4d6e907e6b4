/// \file dense_kernels_sse2.cpp
/// \brief The dense kernels for SSE2, which every x86-64 CPU has (dense_kernels_lanes.hpp:
/// the same arithmetic as the AVX2 variant, two doubles at a time).
#define FLAPSIM_DENSE_VECTOR_BYTES 16
#include "fem/dense_kernels_lanes.hpp"

namespace flapsim::fem::dense::detail {

const KernelTable& sse2_kernels() { return kKernels; }

}  // namespace flapsim::fem::dense::detail
