#include "pipeline/app/setup_warnings.hpp"

#include "fem/mesh_quality.hpp"
#include "fem/root_clamp_warning.hpp"
#include "pipeline/app/chain_fem_mismatch.hpp"
#include "pipeline/app/chain_wing_match.hpp"
#include "pipeline/app/compressibility_warning.hpp"
#include "pipeline/app/coupling_tolerance_warning.hpp"
#include "pipeline/app/far_point_warning.hpp"
#include "pipeline/app/fem_mesh_resolution_warning.hpp"
#include "pipeline/app/fem_resonance_warning.hpp"
#include "pipeline/app/film_wrinkle_warning.hpp"
#include "pipeline/app/flexibility_warnings.hpp"
#include "pipeline/app/lattice_coverage_warning.hpp"
#include "pipeline/app/low_reynolds_warning.hpp"
#include "pipeline/app/slow_stream_hover_warning.hpp"
#include "pipeline/app/small_wing_precision_warning.hpp"
#include "pipeline/app/steep_stream_warning.hpp"
#include "pipeline/app/trailing_edge_first_warning.hpp"

namespace flapsim::app {

std::vector<std::string> setup_warnings(const io::Case& c, const FsiSetup& setup) {
  std::vector<std::string> out;
  for (std::string w : {compressibility_warning(c, setup),
                        low_reynolds_warning(c, setup),
                        trailing_edge_first_warning(c, setup),
                        lattice_coverage_warning(setup),
                        chain_wing_mismatch_warning(setup),
                        saved_chain_fem_warning(setup),
                        saved_chain_static_warning(setup),
                        soft_chain_warning(c, setup),
                        near_resonance_warning(c, setup),
                        fem_near_resonance_warning(c, setup),
                        inertial_deflection_warning(c, setup),
                        fluid_load_deflection_warning(c, setup),
                        coupling_tolerance_warning(setup),
                        small_wing_precision_warning(setup),
                        slow_stream_hover_warning(c, setup),
                        steep_stream_warning(c),
                        film_wrinkle_warning(c, setup),
                        fem_mesh_resolution_warning(setup),
                        setup.fem_structure && setup.wing
                            ? fem::sliver_warning(setup.fem_structure->structural.mesh, *setup.wing)
                            : std::string(),
                        setup.fem_structure && setup.wing
                            ? fem::root_clamp_warning(setup.fem_structure->structural.mesh, *setup.wing)
                            : std::string()})
    if (!w.empty()) out.push_back(std::move(w));
  for (std::string& w : far_point_warnings(c, setup)) out.push_back(std::move(w));
  return out;
}

std::string warning_headline(const std::string& warning) { return warning.substr(0, warning.find(": ")); }

std::vector<std::string> file_warning_notes(const io::Case& c, const wings::Wing* wing) {
  std::vector<std::string> notes;
  for (const InputWarning& w : c.warnings) notes.push_back(w.key + ": " + warning_headline(w.message));
  if (wing != nullptr)
    for (const InputWarning& w : wing->warnings) notes.push_back("wing." + w.key + ": " + warning_headline(w.message));
  return notes;
}

std::string join_notes(const std::vector<std::string>& notes) {
  std::string joined;
  for (const std::string& note : notes) joined += (joined.empty() ? "" : "; ") + note;
  return joined;
}

}  // namespace flapsim::app
