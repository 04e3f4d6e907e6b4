#include "pipeline/app/after_run_notes.hpp"

#include <cstdio>

#include "pipeline/app/flexibility_warnings.hpp"

namespace flapsim::app {

std::vector<std::string> after_run_notes(const RunResults& results) {
  std::vector<std::string> notes;
  if (std::string deflection = large_deflection_note(results); !deflection.empty())
    notes.push_back(std::move(deflection));
  // Each result's step is set with it (run_recorder.cpp).
  char text[160];
  if (shed_sheet_came_apart(results)) {
    std::snprintf(text, sizeof text, "shed sheet came apart: CL changed by %.3g in a step (into step %ld)",
                  results.number("largest_CL_jump"),
                  static_cast<long>(results.integer("largest_CL_jump_step")));
    notes.emplace_back(text);
  }
  if (tip_zigzagged(results)) {
    std::snprintf(text, sizeof text, "tip zigzags from step to step: %.2f deg (step %ld)",
                  results.number("largest_tip_zigzag_deg"),
                  static_cast<long>(results.integer("largest_tip_zigzag_step")));
    notes.emplace_back(text);
  }
  return notes;
}

std::string after_run_advice(const RunResults& results) {
  std::string advice;
  // Appended piece by piece: GCC 12's -Wrestrict misfires on `" " + std::string&&` (GCC bug 105329).
  const auto add = [&](const char* sentence) {
    if (!advice.empty()) advice += ' ';
    advice += sentence;
  };
  if (!large_deflection_note(results).empty())
    add("Its chain swung beyond the small rotations its joint springs represent, so the result it "
        "maximised is not the wing's: keep the search where the chain holds with "
        "`--constraint peak_tip_twist_deg<=30` (and `peak_tip_bend_deg<=30`), or run the wing's own FEM "
        "(`structure.kind = \"fem\"`).");
  if (shed_sheet_came_apart(results))
    add("Its leading-edge sheet came apart near the wing, so the result it maximised may be the broken "
        "sheet's: keep the search where the sheet holds with `--constraint largest_CL_jump<=10`, or use "
        "`numerics.leading_edge = \"separated\"` (docs/fsi.md, \"Failures\").");
  if (tip_zigzagged(results))
    add("Its tip zigzagged from step to step, a motion the steps do not resolve: lower "
        "`numerics.rho_infinity` or take more steps a cycle, or keep the search where it does not with "
        "`--constraint largest_tip_zigzag_deg<=1` (docs/fsi.md, \"A tip that zigzags from step to step\").");
  return advice;
}

}  // namespace flapsim::app
