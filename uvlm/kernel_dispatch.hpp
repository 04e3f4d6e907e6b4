#pragma once
/// \file kernel_dispatch.hpp
/// \brief Which compiled variant of the Biot–Savart kernel runs: scalar (baseline
/// x86-64, SSE2), AVX2 or AVX-512, chosen at run time from the CPU (the default build
/// is portable; no -march=native is needed to use the wider units).
///
/// Every variant evaluates the same operations in the same order — the sum over
/// segments is split into a fixed number of lanes (8 in double, 16 in single precision)
/// whatever the vector width, no fused multiply–add is formed (-ffp-contract=off), and
/// sqrt and division are correctly rounded in every instruction set — so all variants
/// return bit-identical velocities and a run's results do not depend on the CPU
/// (tests/uvlm/test_kernel_dispatch.cpp checks this for each variant the CPU supports).

#include <string>
#include <string_view>
#include <vector>

namespace flapsim::uvlm {

enum class KernelIsa { Scalar, Avx2, Avx512 };

/// "scalar", "avx2", "avx512".
std::string_view kernel_isa_name(KernelIsa isa);

/// True if this CPU (and operating system) can run the variant.
bool kernel_isa_supported(KernelIsa isa);

/// The variants this CPU supports, narrowest first.
std::vector<KernelIsa> supported_kernel_isas();

/// The variant in use: the widest supported one unless the environment variable
/// FLAPSIM_KERNEL (scalar, avx2, avx512; read once) or set_kernel_isa chose another.
KernelIsa kernel_isa();

/// A warning when FLAPSIM_KERNEL is set to a variant it cannot choose (not scalar, avx2 or
/// avx512, or one this CPU lacks), which is ignored: a benchmark "with FLAPSIM_KERNEL=AVX2"
/// measured the AVX-512 kernels without a word. Empty when unset or honoured.
std::string kernel_environment_warning();

/// Use `isa` for every later kernel call (tests, benchmarks: identical results by design).
/// \throws std::invalid_argument if this CPU does not support it
void set_kernel_isa(KernelIsa isa);

}  // namespace flapsim::uvlm
