// Gravity on the FEM structure (fem_structure.hpp, gravity_loads = M g): a horizontal
// cantilever plate held by a base at rest, damped, settles under its weight where the
// linear static FEM puts it (fem::StaticSolver under the same M g: an independent route, a
// deflection of 0.37 % of the span, where the geometric nonlinearity is of order 1e-5), and
// the base then carries the plate's weight: the readout's drive force is m g up, to the
// settling's remainder.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "fem/assembly.hpp"
#include "fem/constraints.hpp"
#include "fem/static_solver.hpp"
#include "fem/structured_mesh.hpp"
#include "fsi/plate_wing_fixtures.hpp"
#include "pipeline/fsi/coupled_step.hpp"
#include "pipeline/fsi/fem_structure.hpp"

namespace {

using namespace flapsim;

// An aluminium plate, 10 mm × 40 mm × 0.1 mm, clamped along y = 0: first bending
// f₁ = (1.875²/2π) √(EI/(m' L⁴)) = 51 Hz (EI = 5.8e-5 N m², m' = 2.7e-3 kg/m).
fem::StructuralModel gravity_plate() { return test::plate_shells(1e-4); }

TEST(FsiFemGravity, APlateSettlesWhereTheStaticFemPutsItAndTheBaseCarriesItsWeight) {
  const Eigen::Vector3d g(0.0, 0.0, -9.81);
  fem::StructuralModel sm = gravity_plate();
  std::vector<int> root = fem::nodes_at_or_below_y(sm.mesh, 1e-12);
  // The reference: the linear static FEM under the loads M g.
  const fem::AssembledSystem sys = fem::assemble(sm);
  Eigen::VectorXd weight_dofs = Eigen::VectorXd::Zero(sm.mesh.num_dofs());
  for (int n = 0; n < sm.mesh.num_nodes(); ++n) weight_dofs.segment<3>(fem::dof_index(n, fem::UX)) = g;
  const Eigen::VectorXd weight = sys.mass * weight_dofs;
  fem::Constraints clamp(sm.mesh.num_dofs());
  clamp.clamp_nodes(root);
  const Eigen::VectorXd u_static = fem::StaticSolver(sys.stiffness, clamp).solve(weight);
  int tip = 0;  // the node of largest static deflection
  for (int n = 0; n < sm.mesh.num_nodes(); ++n)
    if (std::abs(u_static(fem::dof_index(n, fem::UZ))) > std::abs(u_static(fem::dof_index(tip, fem::UZ)))) tip = n;
  const double w_static = u_static(fem::dof_index(tip, fem::UZ));
  ASSERT_LT(w_static, -1e-4);  // q L⁴/8EI = 0.146 mm for a beam

  // The same plate as the structure of a run in vacuum, its base at rest; stiffness damping
  // a₁ = 5 ms (ζ = a₁ω₁/2 = 0.8 in the first mode, more above) settles it in 0.4 s.
  fem::DynamicsOptions options;
  options.rho_infinity = 0.5;
  options.stiffness_damping = 0.005;
  const mbd::BaseMotion at_rest = [](double) { return mbd::BasePose{}; };
  auto structure = std::make_shared<fsi::FemStructureModel>(std::move(sm), root, at_rest, options,
                                                            Eigen::Matrix3Xd(3, 0), 1, 1, 0.040, g);
  const fsi::FsiModel m = test::vacuum_fsi_model(structure);
  fsi::FsiData d(m);
  fsi::initialize(m, d, 0.0);
  for (int n = 0; n < 400; ++n) fsi::coupled_step(m, d, 1e-3);

  const auto& fem_data = dynamic_cast<const fsi::FemStructureData&>(*d.structure);
  const Eigen::Vector3d x_tip = fem_data.dynamics().state.position[static_cast<std::size_t>(tip)];
  const double w = x_tip.z() - structure->structural.mesh.nodes[static_cast<std::size_t>(tip)].z();
  // Within 1 % of the linear static deflection (nonlinearity ~ (w/L)² ≈ 1e-5; what is left
  // of the release's oscillation after 20 periods at ζ = 0.8: nothing measurable).
  EXPECT_NEAR(w, w_static, 0.01 * std::abs(w_static)) << "tip node " << tip;
  std::printf("[fem gravity] tip %.4e m against the static FEM's %.4e m (%+.3f %%)\n", w, w_static,
              100.0 * (w / w_static - 1.0));
  // The drive carries the weight: F = Σ (M v̇ − f_ext) = −M g summed = −m g, up.
  const fsi::StructureReadout out = d.structure->readout();
  const double mass = sys.total_mass;  // 2700 · 1e-4 · 4e-4 = 1.08e-4 kg
  EXPECT_NEAR(mass, 1.08e-4, 1e-12);
  EXPECT_NEAR(out.drive_force.z(), mass * 9.81, 1e-3 * mass * 9.81);
  std::printf("[fem gravity] drive force %.6e N against m g %.6e N\n", out.drive_force.z(), mass * 9.81);
  EXPECT_NEAR(out.drive_force.x(), 0.0, 1e-9);
  // and its moment about the pivot: the weight acting at the plate's centroid (x̄, 0.02 m).
  EXPECT_NEAR(out.drive_moment.x(), -mass * 9.81 * 0.020 * -1.0, 1e-2 * mass * 9.81 * 0.020);
}

}  // namespace
