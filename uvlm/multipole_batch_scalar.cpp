/// \file multipole_batch_scalar.cpp
/// \brief The tree code's batched expansions (multipole_batch.hpp), the baseline x86-64 (SSE2) variant.
/// Same arithmetic as the other variants; flags in uvlm/CMakeLists.txt.
#include "uvlm/multipole_batch.hpp"

namespace flapsim::uvlm::detail {

void multipole_batch_scalar(MultipoleBatch& b) { multipole_batch_any_order(b); }

}  // namespace flapsim::uvlm::detail
