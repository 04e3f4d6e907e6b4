/// \file biot_savart_scalar.cpp
/// \brief The Biot–Savart kernel for baseline x86-64 (SSE2): runs on every x86-64 CPU.
/// Same arithmetic as the other variants (biot_savart_lanes.hpp, lattice_lanes.hpp, influence_lanes.hpp); flags in uvlm/CMakeLists.txt.
#define FLAPSIM_KERNEL_VECTOR_BYTES 16
#include "uvlm/biot_savart_lanes.hpp"
#include "uvlm/influence_lanes.hpp"
#include "uvlm/lattice_lanes.hpp"

namespace flapsim::uvlm::detail {

void sum_scalar(const KernelCall<double>& c) { sum_any_model(c); }
void sum_scalar(const KernelCall<float>& c) { sum_any_model(c); }
void point_range_scalar(const PointRangeCall& c) { point_range_any_model(c); }
void lattice_sum_scalar(const LatticeCall<double>& c) { lattice_sum_any_model(c); }
void lattice_sum_scalar(const LatticeCall<float>& c) { lattice_sum_any_model(c); }
void influence_row_scalar(const InfluenceRowCall& c) { influence_row_any_model(c); }

}  // namespace flapsim::uvlm::detail
