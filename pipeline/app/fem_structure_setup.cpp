#include "pipeline/app/fem_structure_setup.hpp"

#include "fem/constraints.hpp"
#include "fem/wing_fem.hpp"
#include "pipeline/app/film_wrinkle_warning.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/mesh_budget.hpp"
#include "wings/loader/planform_geometry.hpp"

namespace flapsim::app {

void check_case_mesh_sizes(const io::Case& c, const wings::Wing& wing, const fem::MeshOptions& mesh) {
  if (mesh.element_size <= 0.0 && mesh.vein_element_size <= 0.0) return;  // the wing file's, checked there
  wings::Wing sized = wing;
  if (mesh.element_size > 0.0) sized.mesh.element_size = mesh.element_size;
  if (mesh.vein_element_size > 0.0) sized.mesh.vein_element_size = mesh.vein_element_size;
  wings::MeshSizeKeys keys;  // the wing file's rules (wings/loader/mesh_budget.hpp), in the case's keys
  keys.element = "structure.element_size_mm";
  keys.vein = "structure.vein_element_size_mm";
  keys.element_given = c.structure.fem_element_size > 0.0;
  keys.vein_given = c.structure.fem_vein_element_size > 0.0;
  keys.length_scale = 1e-3;
  keys.unit = "mm";
  keys.element_not_given =
      "the membrane's element size of the wing file (" + wing.source_file + ", [mesh] element_size)";
  if (const auto problem = wings::mesh_size_problem(sized, keys))
    throw InputError(c.file, c.line_of(problem->key), problem->key, problem->what);
}

std::shared_ptr<const fsi::FemStructureModel> make_fem_structure(const io::Case& c, const wings::Wing& wing,
                                                                 const mbd::BaseMotion& base,
                                                                 const Eigen::Matrix3Xd& lattice_nodes,
                                                                 double span) {
  fem::MeshOptions mesh;
  mesh.element_size = c.structure.fem_element_size;
  mesh.vein_element_size = c.structure.fem_vein_element_size;
  if (mesh.element_size > 0.0 && mesh.vein_element_size == 0.0)
    mesh.vein_element_size = std::min(mesh.element_size, wing.mesh.vein_element_size);
  check_case_mesh_sizes(c, wing, mesh);
  fem::WingFem f = fem::build_wing_fem(wing, mesh);
  std::vector<int> clamped = fem::nodes_at_or_below_y(f.model.mesh, wing.clamp_y);
  // A thin film (its membrane wrinkles at the mesh's wavelength: film_wrinkle_warning.hpp)
  // splits its steps, and the lumped added mass there slowed or stopped its coupling
  // (docs/fsi.md, "Added mass in the coupling"): it goes without. Nor does Newton's stop
  // from the measured contraction help it (docs/fem.md, "Newton's stop from the measured
  // contraction": the MAV film wing's five wingbeats 12 % slower with it).
  const bool film =
      is_thin_film(typical_membrane_wrinkle(f.model), wings::planform_properties(wing.outline).mean_chord);
  fem::DynamicsOptions options;
  // ρ∞ where the case leaves it out: the FEM's own (kFemRhoInfinity), a film's 0 (below).
  options.rho_infinity = c.numerics.rho_infinity_written ? c.numerics.rho_infinity : kFemRhoInfinity;
  options.linearised_geometric_force = c.structure.fem_linearised_geometric_terms;
  // A film's own defaults, where the case leaves the keys out (docs/case_file.md,
  // "[structure]"): ρ∞ = 0, or its wrinkles ring undamped (a 50 µm swept film wing crawled,
  // 57 of 300 steps in 400 s, with 0.9 and flew 3 wingbeats in 38 s with 0), and the geometric terms at the
  // current state, where the film's stretching is its transverse stiffness.
  if (film && !c.numerics.rho_infinity_written) options.rho_infinity = kFilmRhoInfinity;
  if (film && !c.structure.fem_geometric_terms_written) options.linearised_geometric_force = false;
  options.stiffness_damping = c.structure.fem_stiffness_damping;
  options.matrix_per_piece = c.structure.fem_matrix_per_piece;
  // Newton's stopping rule from the coupling's tolerance (fem_structure.hpp).
  options = fsi::coupled_dynamics_options(options, c.numerics.coupling_tolerance, c.numerics.steps_per_cycle);
  options.contraction_stop = !film;
  const int nc = c.numerics.chordwise_panels, ns = c.numerics.spanwise_panels;
  auto model = std::make_shared<fsi::FemStructureModel>(std::move(f.model), std::move(clamped), base, options,
                                                        lattice_nodes, nc, ns, span, c.structure.gravity);
  model->lumped_added_mass = !film;
  // Nor does it keep a loose answer that met the full accuracy (docs/fsi.md, "One coupled
  // step": the MAV film wing's coupling then stalled at step 42).
  model->keep_met_loose_answers = !film;
  return model;
}

}  // namespace flapsim::app
