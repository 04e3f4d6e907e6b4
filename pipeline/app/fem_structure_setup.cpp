#include "pipeline/app/fem_structure_setup.hpp"

#include "fem/constraints.hpp"
#include "fem/wing_fem.hpp"
#include "pipeline/app/film_wrinkle_warning.hpp"
#include "wings/input_error.hpp"
#include "wings/mesh_budget.hpp"

#include <cstdio>
#include <string>

namespace flapsim::app {

namespace {

std::string millimetres(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g mm", metres * 1e3);
  return text;
}

}  // namespace

void check_case_mesh_sizes(const io::Case& c, const wings::Wing& wing, const fem::MeshOptions& mesh) {
  if (mesh.element_size <= 0.0 && mesh.vein_element_size <= 0.0) return;  // the wing file's, checked there
  wings::Wing sized = wing;
  if (mesh.element_size > 0.0) sized.mesh.element_size = mesh.element_size;
  if (mesh.vein_element_size > 0.0) sized.mesh.vein_element_size = mesh.vein_element_size;
  // The key to blame: the veins' where they are the finer one given (as the wing file does).
  const bool element_given = c.structure.fem_element_size > 0.0, vein_given = c.structure.fem_vein_element_size > 0.0;
  const bool blame_vein =
      !element_given || (vein_given && sized.mesh.vein_element_size < sized.mesh.element_size);
  const std::string key = blame_vein ? "structure.vein_element_size_mm" : "structure.element_size_mm";
  const auto fail = [&](const std::string& k, const std::string& what) {
    throw InputError(c.file, c.line_of(k), k, what);
  };
  if (sized.mesh.vein_element_size > sized.mesh.element_size * (1 + 1e-12))
    fail(vein_given ? "structure.vein_element_size_mm" : "structure.element_size_mm",
         "the veins' element size (" + millimetres(sized.mesh.vein_element_size) + ") must not exceed the membrane's (" +
             millimetres(sized.mesh.element_size) + ")");
  if (mesh.element_size > 0.5 * wing.span)
    fail("structure.element_size_mm", "must not exceed half the span (" + millimetres(mesh.element_size) +
                                          " against a span of " + millimetres(wing.span) + ")");
  // The wing file's budget (wings/mesh_budget.hpp), before gmsh runs out of memory.
  if (const double n = wings::estimated_mesh_elements(sized); n > wings::kMaxMeshElements) {
    char what[200];
    std::snprintf(what, sizeof what,
                  "the FEM's mesh would have about %.3g elements, more than the budget of %.3g (docs/wing_file.md, "
                  "\"[mesh]\"); use a larger size",
                  n, wings::kMaxMeshElements);
    fail(key, what);
  }
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
  fem::DynamicsOptions options;
  options.rho_infinity = c.numerics.rho_infinity;
  options.stiffness_damping = c.structure.fem_stiffness_damping;
  options.linearised_geometric_force = c.structure.fem_linearised_geometric_terms;
  options.matrix_per_piece = c.structure.fem_matrix_per_piece;
  // Newton's stopping rule from the coupling's tolerance (fem_structure.hpp).
  options = fsi::coupled_dynamics_options(options, c.numerics.coupling_tolerance, c.numerics.steps_per_cycle);
  const int nc = c.numerics.chordwise_panels, ns = c.numerics.spanwise_panels;
  auto model = std::make_shared<fsi::FemStructureModel>(std::move(f.model), std::move(clamped), base, options,
                                                        lattice_nodes, nc, ns, span, c.structure.gravity);
  // A thin film (its membrane wrinkles at the mesh's wavelength: film_wrinkle_warning.hpp)
  // splits its steps, and the lumped added mass there slowed or stopped its coupling
  // (docs/fsi.md, "Added mass in the coupling"): it goes without.
  const std::optional<MembraneWrinkle> wrinkle = typical_membrane_wrinkle(model->structural);
  model->lumped_added_mass = !(wrinkle && wrinkle->strain < kFilmWrinkleStrain);
  return model;
}

}  // namespace flapsim::app
