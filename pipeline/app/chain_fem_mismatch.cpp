#include "pipeline/app/chain_fem_mismatch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace flapsim::app {

bool misses_fem_mode(const reduction::ModeMatch& m) {
  return m.found && std::isfinite(m.relative_error) && std::abs(m.relative_error) > kChainFemMismatch;
}

bool misses_fem_static(const reduction::StaticMatch& m) {
  return std::isfinite(m.relative_error) && std::abs(m.relative_error) > kChainFemStaticMismatch;
}

bool bodies_shorter_than_elements(const reduction::ChainFemComparison& c) {
  return c.fem_element_size > 0.0 && c.body_length < c.fem_element_size;
}

std::string short_bodies_warning(const reduction::ChainFemComparison& c) {
  if (!bodies_shorter_than_elements(c)) return "";
  const int most = std::max(1, static_cast<int>(std::floor(c.flexible_span / c.fem_element_size)));
  char text[600];
  std::snprintf(
      text, sizeof text,
      "the chain's %d bodies are %.3g mm long, shorter than the FEM's mean element edge (%.3g mm): each "
      "body's section is measured from less than one element, and more bodies no longer approach the FEM "
      "(a 2.5 mm fruit-fly wing: first bending +0.95, +2.5, -0.87, -9.5 %% at 6, 24, 48, 100 bodies); use "
      "at most %d bodies, or a finer [mesh] element_size (docs/reduction.md, \"Bodies shorter than the "
      "elements\")",
      c.num_bodies, c.body_length * 1e3, c.fem_element_size * 1e3, most);
  return text;
}

std::string more_bodies_advice(const reduction::ChainFemComparison& c) {
  return bodies_shorter_than_elements(c)
             ? "bodies already shorter than the FEM's elements: fewer bodies or a finer [mesh] element_size"
             : "too few bodies: try more --bodies";
}

namespace {

// The static rows a chain misses, each named with both values and its error ("" if none).
std::string missed_static_rows(double measure_s, double bending_body_s,
                               const reduction::StaticMatch& deflection,
                               const reduction::StaticMatch& bending_rotation,
                               const reduction::StaticMatch& twist) {
  std::string missed;
  char at_measure[48], at_body[64];
  std::snprintf(at_measure, sizeof at_measure, " at s = %.2f mm", measure_s * 1e3);
  std::snprintf(at_body, sizeof at_body, " (from s = %.2f mm)", bending_body_s * 1e3);
  struct Row {
    const char* name;
    const char* where;
    const char* unit;
    const reduction::StaticMatch* m;
  };
  // The bending row is the rotation conjugate to a moment spread over the chain's tip body,
  // on both sides; the others are read at the measuring body (docs/reduction.md).
  for (const Row& r : {Row{"tip deflection under the tip force", at_measure, "m/N", &deflection},
                       Row{"bending rotation of the tip body under a moment spread over it", at_body,
                           "rad/(N m)", &bending_rotation},
                       Row{"twist under the tip torque", at_measure, "rad/(N m)", &twist}}) {
    if (!misses_fem_static(*r.m)) continue;
    char text[240];
    std::snprintf(text, sizeof text, "%s%s%s %+.1f %% (chain %.4g %s, FEM %.4g %s)", missed.empty() ? "" : "; ", r.name,
                  r.where, 100.0 * r.m->relative_error, r.m->chain, r.unit, r.m->fem, r.unit);
    missed += text;
  }
  return missed;
}

}  // namespace

std::string static_mismatch_warning(const reduction::ChainFemComparison& c, const std::string& report) {
  const std::string missed = missed_static_rows(c.measure_s, c.bending_body_s, c.tip_deflection,
                                                c.tip_bending_rotation, c.tip_twist);
  if (missed.empty()) return "";
  return "the chain's static response differs from the FEM's under the same load: " + missed +
         ". The chain takes a load on a body as a wrench at its joints; the FEM answers to where on the body "
         "it acts as well: " +
         more_bodies_advice(c) +
         ", or a wing that is not one beam (film beyond a rod that carries the load chordwise, a swept wing: "
         "more bodies converge slowly), and the chain's runs inherit the error (docs/reduction.md, "
         "\"Measured "
         "limitation\"); see " +
         report;
}

std::string saved_chain_static_warning(const FsiSetup& setup) {
  if (!setup.chain_fem || !setup.chain_fem->statics) return "";
  const io::ChainFemRecord::StaticRows& r = *setup.chain_fem->statics;
  // The rows of the chain as reduced: a spring scale other than 1 is the user's choice of
  // another wing, which the modes' warning names.
  const std::string missed = missed_static_rows(r.measure_s, r.bending_body_s, r.tip_deflection,
                                                r.tip_bending_rotation, r.tip_twist);
  if (missed.empty()) return "";
  const std::string wing = setup.chain_fem->wing_file.empty() ? "its wing" : setup.chain_fem->wing_file;
  const std::string subject =
      setup.chain_file.empty() ? "the chain reduced in process" : "the chain file " + setup.chain_file;
  const std::string source = setup.chain_file.empty() ? "as 'flapsim reduce' warns"
                                                      : "as 'flapsim reduce' found when it made the chain";
  return subject + " responds to a static load otherwise than the FEM of " + wing + " (" + source +
         "): " + missed +
         ". The run inherits the difference where the air loads the wing as these loads do: more bodies, or "
         "for a "
         "wing that is not one beam (film beyond a rod) the wing's own FEM as the structure (structure.kind "
         "= "
         "\"fem\"; docs/reduction.md, \"Measured limitation\"; docs/fsi.md)";
}

std::string saved_chain_fem_warning(const FsiSetup& setup) {
  if (!setup.chain_fem) return "";
  const double factor = std::sqrt(setup.spring_scale);  // ω ∝ √k at fixed masses
  std::string missed;
  bool missed_unscaled = false;  // the chain as reduced, springs × 1, misses a mode too
  for (const auto& [kind, record] : {std::pair{"bending", setup.chain_fem->bending},
                                     std::pair{"torsion", setup.chain_fem->torsion}}) {
    reduction::ModeMatch m = record;
    missed_unscaled = missed_unscaled || misses_fem_mode(m);
    m.chain_hz *= factor;
    m.relative_error = reduction::relative_error(m.chain_hz, m.fem_hz);
    if (!misses_fem_mode(m)) continue;
    char text[400];
    std::snprintf(text, sizeof text, "%s first %s mode by %+.1f %% (%.4g Hz against %.4g Hz, MAC %.3f)",
                  missed.empty() ? " the FEM's" : " and its", kind, 100.0 * m.relative_error, m.chain_hz, m.fem_hz, m.mac);
    missed += text;
  }
  if (missed.empty()) return "";
  std::string scale_note;
  if (setup.spring_scale != 1.0) {
    char buf[160];
    std::snprintf(buf, sizeof buf, ", with the springs x %g (frequencies x %.4g)", setup.spring_scale, factor);
    scale_note = buf;
  }
  const std::string wing = setup.chain_fem->wing_file.empty() ? "its wing" : setup.chain_fem->wing_file;
  const std::string subject = setup.chain_file.empty() ? "the chain reduced in process" : "the chain file " + setup.chain_file;
  const std::string source = setup.chain_file.empty() ? " (of " + wing + ", as 'flapsim reduce' warns)"
                                                      : " (of " + wing + ", as 'flapsim reduce' found when it made the chain)";
  // The chain as reduced matches the FEM and the spring scale alone moves it away: more
  // bodies would not help (they were advised until 3 Dec); the scale is the user's choice.
  if (!missed_unscaled)
    return subject + " misses" + missed + scale_note + source +
           ": with its springs as reduced the chain matches the FEM, so the spring scale alone makes the "
           "difference: the run is of a wing stiffer or softer than the wing file's (intended in a stiffness "
           "study; else leave --spring-scale or spring_scale at 1; docs/fsi.md, --spring-scale)";
  return subject + " misses" + missed + scale_note + source + ": the chain does not represent the wing well (too "
         "few bodies: reduce again with more --bodies; or a beam cannot: a low aspect ratio, a film that "
         "cambers; docs/reduction.md)";
}

}  // namespace flapsim::app
