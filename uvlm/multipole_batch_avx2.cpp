/// \file multipole_batch_avx2.cpp
/// \brief The tree code's batched expansions (multipole_batch.hpp), the AVX2 variant (compiled with -mavx2, called only where the CPU has it).
/// Same arithmetic as the other variants; flags in uvlm/CMakeLists.txt.
#include "uvlm/multipole_batch.hpp"

namespace flapsim::uvlm::detail {

void multipole_batch_avx2(MultipoleBatch& b) { multipole_batch_any_order(b); }

}  // namespace flapsim::uvlm::detail
