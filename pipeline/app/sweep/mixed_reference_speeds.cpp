#include "pipeline/app/sweep/mixed_reference_speeds.hpp"

#include <cstddef>
#include <map>

namespace flapsim::sweep {

std::string mixed_reference_speeds_note(const std::vector<SweepRow>& rows) {
  std::map<std::string, std::size_t> kinds;  // reference_kind → rows
  for (const SweepRow& r : rows)
    if (r.done && r.outcome.results.has("reference_kind")) ++kinds[r.outcome.results.text("reference_kind")];
  if (kinds.size() < 2) return "";
  std::string counts;
  for (const auto& [kind, n] : kinds) {
    if (!counts.empty()) counts += ", ";
    counts += std::to_string(n) + (n == 1 ? " row on " : " rows on ") + kind;
  }
  return "note: the mean CL and CD of these rows are on different reference speeds (" + counts +
         ": the free stream where there is one, else the flapping speed at r2), so they do not compare "
         "down the column; compare the mean lift and drag in N, or each case's summary.json "
         "(mean_CL_on_flapping_speed: a flapping wing's CL on its flapping speed in a free stream) "
         "(docs/sweeps.md, \"Coefficients on different reference speeds\")";
}

}  // namespace flapsim::sweep
