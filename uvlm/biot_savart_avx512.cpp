/// \file biot_savart_avx512.cpp
/// \brief The Biot–Savart kernel for AVX-512F (compiled with -mavx512f, called only where the CPU has it).
/// Same arithmetic as the other variants (biot_savart_lanes.hpp, lattice_lanes.hpp, influence_lanes.hpp); flags in uvlm/CMakeLists.txt.
#define FLAPSIM_KERNEL_VECTOR_BYTES 64
#include "uvlm/biot_savart_lanes.hpp"
#include "uvlm/influence_lanes.hpp"
#include "uvlm/lattice_lanes.hpp"

namespace flapsim::uvlm::detail {

void sum_avx512(const KernelCall<double>& c) { sum_any_model(c); }
void sum_avx512(const KernelCall<float>& c) { sum_any_model(c); }
void point_range_avx512(const PointRangeCall& c) { point_range_any_model(c); }
void lattice_sum_avx512(const LatticeCall<double>& c) { lattice_sum_any_model(c); }
void lattice_sum_avx512(const LatticeCall<float>& c) { lattice_sum_any_model(c); }
void influence_row_avx512(const InfluenceRowCall& c) { influence_row_any_model(c); }

}  // namespace flapsim::uvlm::detail
