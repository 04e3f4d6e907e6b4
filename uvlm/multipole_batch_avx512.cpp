/// \file multipole_batch_avx512.cpp
/// \brief The tree code's batched expansions (multipole_batch.hpp), the AVX-512 variant (compiled with -mavx512f, called only where the CPU has it).
/// Same arithmetic as the other variants; flags in uvlm/CMakeLists.txt.
#include "uvlm/multipole_batch.hpp"

namespace flapsim::uvlm::detail {

void multipole_batch_avx512(MultipoleBatch& b) { multipole_batch_any_order(b); }

}  // namespace flapsim::uvlm::detail
