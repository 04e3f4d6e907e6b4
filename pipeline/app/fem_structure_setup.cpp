#include "pipeline/app/fem_structure_setup.hpp"

#include "fem/constraints.hpp"
#include "fem/wing_fem.hpp"

namespace flapsim::app {

namespace {
// Newton's stopping rule in a coupled run: the residual within 1e-8 of the step's force scale,
// or corrections below 1e-11 of the wing's size (translations) and 1e-11 rad (rotations).
// The coupling stops at a relative change of coupling_tolerance (1e-6 by default), far above
// what either leaves; the library's 1e-10 / 1e-13 sat below the round-off floor of a film
// wing's residual (a 25 µm film on a carbon rod, fem.pvd of cases/mav_film_fem.toml: the
// residual stalled at 2e-10 of the force scale and the step failed).
constexpr double kNewtonTolerance = 1e-8;
constexpr double kNewtonIncrementTolerance = 1e-11;
}  // namespace

std::shared_ptr<const fsi::FemStructureModel> make_fem_structure(const io::Case& c, const wings::Wing& wing,
                                                                 const mbd::BaseMotion& base,
                                                                 const Eigen::Matrix3Xd& lattice_nodes,
                                                                 double span) {
  fem::MeshOptions mesh;
  mesh.element_size = c.structure.fem_element_size;
  mesh.vein_element_size = c.structure.fem_vein_element_size;
  if (mesh.element_size > 0.0 && mesh.vein_element_size == 0.0)
    mesh.vein_element_size = std::min(mesh.element_size, wing.mesh.vein_element_size);
  fem::WingFem f = fem::build_wing_fem(wing, mesh);
  std::vector<int> clamped = fem::nodes_at_or_below_y(f.model.mesh, wing.clamp_y);
  fem::DynamicsOptions options;
  options.rho_infinity = c.numerics.rho_infinity;
  options.stiffness_damping = c.structure.fem_stiffness_damping;
  options.tolerance = kNewtonTolerance;
  options.increment_tolerance = kNewtonIncrementTolerance;
  const int nc = c.numerics.chordwise_panels, ns = c.numerics.spanwise_panels;
  return std::make_shared<const fsi::FemStructureModel>(std::move(f.model), std::move(clamped), base, options,
                                                        lattice_nodes, nc, ns, span);
}

}  // namespace flapsim::app
