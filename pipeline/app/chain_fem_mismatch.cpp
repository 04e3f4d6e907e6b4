#include "pipeline/app/chain_fem_mismatch.hpp"

#include <cmath>
#include <cstdio>

namespace flapsim::app {

bool misses_fem_mode(const reduction::ModeMatch& m) {
  return m.found && std::isfinite(m.relative_error) && std::abs(m.relative_error) > kChainFemMismatch;
}

std::string saved_chain_fem_warning(const FsiSetup& setup) {
  if (!setup.chain_fem) return "";
  const double factor = std::sqrt(setup.spring_scale);  // ω ∝ √k at fixed masses
  std::string missed;
  for (const auto& [kind, record] : {std::pair{"bending", setup.chain_fem->bending},
                                     std::pair{"torsion", setup.chain_fem->torsion}}) {
    reduction::ModeMatch m = record;
    m.chain_hz *= factor;
    m.relative_error = reduction::relative_error(m.chain_hz, m.fem_hz);
    if (!misses_fem_mode(m)) continue;
    char text[200];
    std::snprintf(text, sizeof text, "%s first %s mode by %+.1f %% (%.4g Hz against %.4g Hz, MAC %.3f)",
                  missed.empty() ? " the FEM's" : " and its", kind, 100.0 * m.relative_error, m.chain_hz, m.fem_hz, m.mac);
    missed += text;
  }
  if (missed.empty()) return "";
  std::string scale_note;
  if (setup.spring_scale != 1.0) {
    char buf[96];
    std::snprintf(buf, sizeof buf, ", with the springs x %g (frequencies x %.4g)", setup.spring_scale, factor);
    scale_note = buf;
  }
  const std::string wing = setup.chain_fem->wing_file.empty() ? "its wing" : setup.chain_fem->wing_file;
  const std::string subject = setup.chain_file.empty() ? "the chain reduced in process" : "the chain file " + setup.chain_file;
  const std::string source = setup.chain_file.empty() ? " (of " + wing + ", as 'flapsim reduce' warns)"
                                                      : " (of " + wing + ", as 'flapsim reduce' found when it made the chain)";
  return subject + " misses" + missed + scale_note + source + ": the chain does not represent the wing well (too "
         "few bodies: reduce again with more --bodies; or a beam cannot: a low aspect ratio, a film that "
         "cambers; docs/reduction.md)";
}

}  // namespace flapsim::app
