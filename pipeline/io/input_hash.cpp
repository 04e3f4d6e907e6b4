#include "pipeline/io/input_hash.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "pipeline/io/csv_writer.hpp"
#include "wings/loader/input_error.hpp"

namespace flapsim::io {

// A field added to one of these structs must be added to canonical_inputs() below too,
// else two runs that differ in it would share a hash (and a sweep re-run would keep a
// stale result). The sizes catch most additions (x86-64, libstdc++); when one fails,
// serialise the new field below and update the size.
// Case::output.vtk_every is left out: it decides only which files a run writes (its ParaView
// series), not its numbers, so two runs that differ in it alone share a hash; a command that
// keeps runs by their hash and wants series checks for them (docs/sweeps.md, "Resuming a
// sweep").
// (Case::key_lines, Case::Structure::bodies_line, initial_angles_line, initial_rates_line, Vein::line and
// Vein::key locate messages, Case::warnings and Wing::warnings warn, Case::length_unit and length_scale word
// warnings (the points are read in metres and hashed), Wing::lattice_gap follows from the outline and refuses
// a run, SurfaceShape::line, Wing::clamp_y_line and element_size_line locate messages, Wing::drawing
// describes where the outline came from (the outline is hashed), PeriodicSignal::table_fit says how far a
// fitted table lies from its series (hashed by its samples); they change no result.)
static_assert(sizeof(Case) == 1768, "io::Case changed: add the new field to canonical_inputs()");
static_assert(sizeof(PointLoad) == 1096, "io::PointLoad changed: add the new field to canonical_inputs()");
static_assert(sizeof(Marker) == 64, "io::Marker changed: add the new field to canonical_inputs()");
static_assert(sizeof(wings::Wing) == 384 + sizeof(wings::SurfaceShape),
              "wings::Wing changed: add the new field to canonical_inputs()");
static_assert(sizeof(wings::Vein) == 200, "wings::Vein changed: add the new field to canonical_inputs()");
static_assert(sizeof(wings::Section) == 40,
              "wings::Section changed: add the new field to canonical_inputs()");
static_assert(sizeof(wings::SurfaceShape) == 56,
              "wings::SurfaceShape changed: add the new field to canonical_inputs()");
static_assert(sizeof(wings::Membrane) == 40,
              "wings::Membrane changed: add the new field to canonical_inputs()");

namespace {

class Canonical {
 public:
  void line(std::string_view name, double v) { text_ += std::string(name) + "=" + format_number(v) + "\n"; }
  void line(std::string_view name, int v) { text_ += std::string(name) + "=" + std::to_string(v) + "\n"; }
  void line(std::string_view name, bool v) { text_ += std::string(name) + (v ? "=true\n" : "=false\n"); }
  void line(std::string_view name, std::string_view v) {
    text_ += std::string(name) + "=" + std::to_string(v.size()) + ":" + std::string(v) + "\n";
  }
  template <typename Vec>
  void vector(std::string_view name, const Vec& v) {
    text_.append(name).append("=");
    for (Eigen::Index i = 0; i < v.size(); ++i) text_.append(i ? "," : "").append(format_number(v[i]));
    text_ += "\n";
  }
  // A periodic signal is known by its samples: value, d/ds, d²/ds² at s = k/64.
  void signal(std::string_view name, const mbd::PeriodicSignal& s) {
    text_ += std::string(name) + "=";
    for (int k = 0; k < 64; ++k) {
      const mbd::AngleSample a = s.at_phase(k / 64.0);
      text_ +=
          format_number(a.value) + "/" + format_number(a.rate) + "/" + format_number(a.acceleration) + ";";
    }
    text_ += "\n";
  }
  std::string& text() { return text_; }

 private:
  std::string text_;
};

void material(Canonical& out, const std::string& p, const wings::Material& m) {
  out.line(p + ".E", m.youngs_modulus);
  out.line(p + ".nu", m.poisson_ratio);
  out.line(p + ".rho", m.density);
}

void section(Canonical& out, const std::string& p, const wings::Section& s) {
  out.line(p + ".shape", static_cast<int>(s.shape));
  out.line(p + ".D", s.outer_diameter);
  out.line(p + ".wall", s.wall);
  out.line(p + ".width", s.width);
  out.line(p + ".height", s.height);
}

/// The wing's fields; its names reach no result (they label the wing and its veins), and
/// clamp_y only a wing whose FEM is built (`fem_used`).
void wing_fields(Canonical& out, const wings::Wing& w, bool fem_used) {
  out.line("wing.outline.size", static_cast<int>(w.outline.size()));
  for (const auto& p : w.outline) out.vector("wing.outline", p);
  out.line("wing.span", w.span);
  out.line("wing.veins.size", static_cast<int>(w.veins.size()));
  for (std::size_t i = 0; i < w.veins.size(); ++i) {
    const wings::Vein& v = w.veins[i];
    const std::string p = "wing.veins[" + std::to_string(i) + "]";
    out.line(p + ".points.size", static_cast<int>(v.points.size()));
    for (const auto& q : v.points) out.vector(p + ".points", q);
    section(out, p + ".root", v.root_section);
    section(out, p + ".tip", v.tip_section);
    material(out, p + ".material", v.material);
  }
  out.line("wing.membrane.thickness", w.membrane.thickness);
  material(out, "wing.membrane.material", w.membrane.material);
  out.line("wing.membrane.nonstructural_mass_per_area", w.membrane.nonstructural_mass_per_area);
  out.line("wing.mesh.element_size", w.mesh.element_size);
  out.line("wing.mesh.vein_element_size", w.mesh.vein_element_size);
  if (fem_used) out.line("wing.clamp_y", w.clamp_y);
  if (!w.surface.flat()) {  // only then: the fingerprints of flat wings stay as they were
    out.line("wing.surface.twist_root", w.surface.twist_root);
    out.line("wing.surface.twist_tip", w.surface.twist_tip);
    out.line("wing.surface.twist_axis", w.surface.twist_axis);
    out.line("wing.surface.camber", w.surface.camber);
    out.line("wing.surface.camber_position", w.surface.camber_position);
    out.line("wing.surface.dihedral", w.surface.dihedral);
  }
}

void case_fields(Canonical& out, const Case& c) {  // the case's name reaches no result
  const mbd::WingKinematics& k = c.kinematics;
  out.line("kinematics.frequency", k.frequency);
  out.signal("kinematics.sweep", k.sweep);
  out.signal("kinematics.deviation", k.deviation);
  out.signal("kinematics.rotation", k.rotation);
  // δψ shifts the sweep and deviation against the rotation (WingKinematics::angles): with both
  // constant (a revolving wing, a pitching plate) it shifts nothing, and the same run has one hash.
  out.line("kinematics.rotation_phase",
           k.sweep.is_constant() && k.deviation.is_constant() ? 0.0 : k.rotation_phase);
  out.line("kinematics.stroke_plane_angle", k.stroke_plane_angle);
  out.signal("kinematics.surge", k.surge);
  out.signal("kinematics.lateral", k.lateral);
  out.signal("kinematics.heave", k.heave);
  if (k.revolution.active()) {  // only then: the fingerprints of flapping cases stay as they were
    out.line("kinematics.revolution.rate", k.revolution.rate);
    out.line("kinematics.revolution.ramp", k.revolution.ramp);
  }
  out.line("air.enabled", c.air.enabled);
  out.line("air.density", c.air.density);
  out.vector("air.freestream", c.air.freestream);
  out.line("structure.kind", static_cast<int>(c.structure.kind));
  out.line("structure.bodies", c.structure.bodies);
  out.vector("structure.gravity", c.structure.gravity);
  for (std::size_t i = 0; i < c.structure.initial_angles.size(); ++i)
    out.line("structure.initial_angles", c.structure.initial_angles[i]);
  for (std::size_t i = 0; i < c.structure.initial_rates.size(); ++i)
    out.line("structure.initial_rates", c.structure.initial_rates[i]);
  if (c.structure.kind == Case::Structure::Kind::Fem) {  // only then: earlier fingerprints stay
    out.line("structure.element_size", c.structure.fem_element_size);
    out.line("structure.vein_element_size", c.structure.fem_vein_element_size);
    out.line("structure.stiffness_damping", c.structure.fem_stiffness_damping);
    // Only when not the default: earlier fingerprints stay (the answer is the same to
    // Newton's tolerance either way, but not to the last digit).
    if (!c.structure.fem_linearised_geometric_terms) out.line("structure.newton_geometric_terms", 1);
    // newton_matrix_per_piece: in the hash when on until 30 Nov (then not the default), when
    // off since (the default).
    if (!c.structure.fem_matrix_per_piece) out.line("structure.newton_matrix_per_piece", 0);
    // Left out, a thin film's FEM takes its own ρ∞ and geometric terms (app::make_fem_structure):
    // a case with the key written and one without may differ.
    if (!c.numerics.rho_infinity_written) out.line("numerics.rho_infinity_left_out", 1);
    if (!c.structure.fem_geometric_terms_written) out.line("structure.newton_geometric_terms_left_out", 1);
  }
  const Case::Numerics& n = c.numerics;
  out.line("numerics.steps_per_cycle", n.steps_per_cycle);
  out.line("numerics.cycles", n.cycles);
  out.line("numerics.chordwise_panels", n.chordwise_panels);
  out.line("numerics.spanwise_panels", n.spanwise_panels);
  out.line("numerics.chordwise_spacing", static_cast<int>(n.chordwise_spacing));
  out.line("numerics.spanwise_spacing", static_cast<int>(n.spanwise_spacing));
  out.line("numerics.load_method", static_cast<int>(n.load_method));
  out.line("numerics.leading_edge", static_cast<int>(n.leading_edge));
  if (n.leading_edge == uvlm::LeadingEdge::Shed) out.line("numerics.lesp_critical", n.lesp_critical);
  if (n.leading_edge == uvlm::LeadingEdge::Shed) out.line("numerics.sheet_merge_steps", n.sheet_merge_steps);
  // (only when set: the runs before the key keep their hash)
  if (n.leading_edge == uvlm::LeadingEdge::Shed && n.sheet_merge_spread_steps > 1)
    out.line("numerics.sheet_merge_spread_steps", n.sheet_merge_spread_steps);
  if (n.leading_edge == uvlm::LeadingEdge::Shed && n.sheet_core_radius > 0.0)
    out.line("numerics.sheet_core_radius", n.sheet_core_radius);
  out.line("numerics.core_model", static_cast<int>(n.core_model));
  out.line("numerics.core_radius", n.core_radius);
  out.line("numerics.wake_order", n.wake_order);
  out.line("numerics.wake_max_rows", n.wake_max_rows);
  out.line("numerics.free_wake", n.free_wake);
  out.line("numerics.core_growth", n.core_growth);
  out.line("numerics.wake_precision", static_cast<int>(n.wake_precision));
  if (n.circulation_rate != CirculationRate::Bdf2)  // (only when set: the runs before the key keep their hash)
    out.line("numerics.circulation_rate", static_cast<int>(n.circulation_rate));
  out.line("numerics.core_growth_a1", n.core_growth_a1);
  out.line("numerics.kinematic_viscosity", n.kinematic_viscosity);
  out.line("numerics.near_wing_core", n.near_wing_core);
  out.line("numerics.frozen_wake_cycles", n.frozen_wake_cycles);
  out.line("numerics.far_wake_cycles", n.far_wake_cycles);
  out.line("numerics.wake_sum", static_cast<int>(n.wake_sum));
  out.line("numerics.tree_tolerance", n.tree_tolerance);
  // Only when not the default, so the cases hashed before the key existed keep their hash.
  if (n.coupling != CouplingMethod::Aitken) out.line("numerics.coupling", static_cast<int>(n.coupling));
  if (n.steady) out.line("numerics.steady", n.steady);  // only then: other fingerprints unchanged
  if (n.laminar_skin_friction) out.line("numerics.skin_friction", 1);  // only then (as steady)
  out.line("numerics.max_coupling_iterations", n.max_coupling_iterations);
  out.line("numerics.coupling_tolerance", n.coupling_tolerance);
  if (!n.added_mass) out.line("numerics.added_mass", n.added_mass);  // only when off (as steady)
  if (n.coupling_reuse_steps != 0) out.line("numerics.coupling_reuse_steps", n.coupling_reuse_steps);  // only when set
  out.line("numerics.rho_infinity", n.rho_infinity);
  // Only when set: the fingerprints of the cases written before the key existed stay as they were.
  if (n.structure_substeps != 1) out.line("numerics.structure_substeps", n.structure_substeps);
  out.line("loads.size", static_cast<int>(c.loads.size()));
  for (std::size_t i = 0; i < c.loads.size(); ++i) {
    const PointLoad& l = c.loads[i];
    const std::string p = "loads[" + std::to_string(i) + "]";
    out.line(p + ".body", l.body);
    out.vector(p + ".point", l.point);
    out.line(p + ".frame", static_cast<int>(l.frame));
    for (int j = 0; j < 3; ++j) {
      out.signal(p + ".force" + std::to_string(j), l.force[j]);
      out.signal(p + ".moment" + std::to_string(j), l.moment[j]);
    }
  }
  out.line("markers.size", static_cast<int>(c.markers.size()));
  for (std::size_t i = 0; i < c.markers.size(); ++i) {
    const std::string p = "markers[" + std::to_string(i) + "]";
    out.line(p + ".name", c.markers[i].name);
    out.line(p + ".body", c.markers[i].body);
    out.vector(p + ".point", c.markers[i].point);
  }
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "chain", "cannot open the chain file for reading");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

std::uint64_t fnv1a_64(std::string_view bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char b : bytes) {
    h ^= b;
    h *= 1099511628211ull;
  }
  return h;
}

std::string canonical_inputs(const Case& c, const wings::Wing* wing, const std::string& chain_file,
                             double spring_scale) {
  Canonical out;
  out.line("format", 1);
  case_fields(out, c);
  // A chain and its spring scale are inputs of a flexible wing only: another kind does not
  // use them (the commands warn), and a run with them is the run without them.
  const bool chain_used = c.structure.kind == Case::Structure::Kind::Flexible;
  const std::string chain = !chain_used ? std::string() : chain_file.empty() ? c.chain_file : chain_file;
  // The wing's FEM is built for kind = "fem" and for a flexible wing reduced in process.
  const bool fem_used = c.structure.kind == Case::Structure::Kind::Fem || (chain_used && chain.empty());
  out.line("wing.present", wing != nullptr);
  if (wing) wing_fields(out, *wing, fem_used);
  out.line("chain.present", !chain.empty());
  if (!chain.empty()) out.line("chain.bytes", file_bytes(chain));
  out.line("spring_scale", chain_used ? spring_scale : 1.0);
  return std::move(out.text());
}

std::string input_hash(const Case& c, const wings::Wing* wing, const std::string& chain_file,
                       double spring_scale) {
  char hex[17];
  std::snprintf(
      hex, sizeof hex, "%016llx",
      static_cast<unsigned long long>(fnv1a_64(canonical_inputs(c, wing, chain_file, spring_scale))));
  return hex;
}

}  // namespace flapsim::io
