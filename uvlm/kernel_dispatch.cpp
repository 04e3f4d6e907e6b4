#include "uvlm/kernel_dispatch.hpp"

#include <atomic>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace flapsim::uvlm {

namespace {

KernelIsa widest_supported() {
  if (kernel_isa_supported(KernelIsa::Avx512)) return KernelIsa::Avx512;
  if (kernel_isa_supported(KernelIsa::Avx2)) return KernelIsa::Avx2;
  return KernelIsa::Scalar;
}

// FLAPSIM_KERNEL=scalar|avx2|avx512 chooses a narrower variant (to measure what a CPU
// without the wider units gets; the results are the same bits); unknown or unsupported
// values are ignored (kernel_environment_warning says so).
KernelIsa initial() {
  const char* env = std::getenv("FLAPSIM_KERNEL");
  if (env != nullptr)
    for (KernelIsa isa : {KernelIsa::Scalar, KernelIsa::Avx2, KernelIsa::Avx512})
      if (kernel_isa_name(isa) == env && kernel_isa_supported(isa)) return isa;
  return widest_supported();
}

std::atomic<KernelIsa>& current() {
  static std::atomic<KernelIsa> isa{initial()};
  return isa;
}

}  // namespace

std::string kernel_environment_warning() {
  const char* env = std::getenv("FLAPSIM_KERNEL");
  if (env == nullptr) return "";
  const std::string value(env);
  const std::string used = "the kernels run " + std::string(kernel_isa_name(widest_supported())) +
                           ", the widest this CPU has (docs/performance.md)";
  for (KernelIsa isa : {KernelIsa::Scalar, KernelIsa::Avx2, KernelIsa::Avx512})
    if (kernel_isa_name(isa) == value)
      return kernel_isa_supported(isa) ? ""
                                       : "FLAPSIM_KERNEL='" + value + "': this CPU cannot run it; " + used;
  return "FLAPSIM_KERNEL='" + value +
         "' is not one of scalar, avx2, avx512 (lower case) and is ignored: " + used;
}

std::string_view kernel_isa_name(KernelIsa isa) {
  switch (isa) {
    case KernelIsa::Scalar: return "scalar";
    case KernelIsa::Avx2: return "avx2";
    case KernelIsa::Avx512: return "avx512";
  }
  return "?";
}

bool kernel_isa_supported(KernelIsa isa) {
  __builtin_cpu_init();
  switch (isa) {
    case KernelIsa::Scalar: return true;
    case KernelIsa::Avx2: return __builtin_cpu_supports("avx2");
    case KernelIsa::Avx512: return __builtin_cpu_supports("avx512f");
  }
  return false;
}

std::vector<KernelIsa> supported_kernel_isas() {
  std::vector<KernelIsa> out;
  for (KernelIsa isa : {KernelIsa::Scalar, KernelIsa::Avx2, KernelIsa::Avx512})
    if (kernel_isa_supported(isa)) out.push_back(isa);
  return out;
}

KernelIsa kernel_isa() { return current().load(std::memory_order_relaxed); }

void set_kernel_isa(KernelIsa isa) {
  if (!kernel_isa_supported(isa))
    throw std::invalid_argument("Biot-Savart kernel: this CPU does not support " +
                                std::string(kernel_isa_name(isa)));
  current().store(isa, std::memory_order_relaxed);
}

}  // namespace flapsim::uvlm
