// The FEM structure's Newton matrix with its geometric terms from the corrections taken
// linearly (fem/nonlinear_dynamics.hpp, DynamicsOptions::linearised_geometric_force;
// docs/fem.md, "The geometric terms from the corrections taken linearly"): on a thin plate
// flapped by eq. 8 it reaches the same answer as the matrix from the current forces, with
// fewer new matrices.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include "fsi/plate_wing_fixtures.hpp"
#include "pipeline/fsi/fem_structure.hpp"
#include "pipeline/fsi/structure.hpp"

namespace {

using namespace flapsim;

struct FlappedPlate {
  Eigen::Matrix3Xd positions;  ///< the nodes at the end of the wingbeat [m]
  fem::SolverCounters counters;
};

// The 10 × 40 mm aluminium plate of `thickness`, root clamped, flapped by eq. 8 in vacuum
// for one wingbeat of `steps`, Newton to the usual tolerance.
FlappedPlate flap(double thickness, int steps, bool linearised) {
  fem::DynamicsOptions o;
  o.rho_infinity = 0.5;
  o.linearised_geometric_force = linearised;
  fem::StructuralModel sm = test::plate_shells(thickness);
  std::vector<int> root;
  for (int n = 0; n < sm.mesh.num_nodes(); ++n)
    if (sm.mesh.nodes[static_cast<std::size_t>(n)].y() < 1e-12) root.push_back(n);
  const fsi::FemStructureModel model(std::move(sm), root, mbd::make_base_motion(test::eq8_kinematics(-0.1)), o,
                                     Eigen::Matrix3Xd(3, 0), 0, 0, 0.040);
  auto data = model.make_data();
  const double dt = 1.0 / (26.1 * steps);
  data->initialize(0.0);
  for (int k = 1; k <= steps; ++k) {
    data->set_external_loads(data->time() + dt);
    data->set_solve_accuracy(1.0);
    data->solve(dt);
    data->accept();
  }
  const auto& fem_data = static_cast<const fsi::FemStructureData&>(*data);
  return {fem_data.trial_positions(), fem_data.dynamics().counters()};
}

TEST(FemNewtonGeometricTerms, TheLinearisedTermsGiveTheSameFlappedPlateWithFewerNewMatrices) {
  for (double thickness : {2e-4, 1e-4}) {
    const FlappedPlate current = flap(thickness, 40, false), linearised = flap(thickness, 40, true);
    const double gap = (linearised.positions - current.positions).lpNorm<Eigen::Infinity>();
    std::printf("  %.0f um: current terms %ld factorisations, %ld iterations; linearised %ld, %ld; end positions "
                "%.2e m apart\n",
                1e6 * thickness, current.counters.factorizations, current.counters.iterations,
                linearised.counters.factorizations, linearised.counters.iterations, gap);
    EXPECT_EQ(current.counters.steps, 40);  // no step split into pieces: the same time steps
    EXPECT_EQ(linearised.counters.steps, 40);
    EXPECT_LT(gap, 1e-9 * 0.040);  // Newton's tolerance, not the method's
    // Measured: 118 → 69 factorisations at 200 µm, 156 → 91 at 100 µm (0.58 both; the
    // hawkmoth's default mesh 2.30 → 1.39 a step in vacuum, 0.60). With the kernel ignoring
    // the given force (the kept matrix's one correction alone): 124 and 156, and this fails.
    EXPECT_LT(linearised.counters.factorizations, 0.75 * current.counters.factorizations);
  }
}

}  // namespace
