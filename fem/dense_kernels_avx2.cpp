/// \file dense_kernels_avx2.cpp
/// \brief The dense kernels for AVX2, compiled with -mavx2 and without FMA, called only
/// where the CPU has AVX2 (dense_kernels_lanes.hpp: the same arithmetic as the SSE2
/// variant, four doubles at a time).
#define FLAPSIM_DENSE_VECTOR_BYTES 32
#include "fem/dense_kernels_lanes.hpp"

namespace flapsim::fem::dense::detail {

const KernelTable& avx2_kernels() { return kKernels; }

}  // namespace flapsim::fem::dense::detail
