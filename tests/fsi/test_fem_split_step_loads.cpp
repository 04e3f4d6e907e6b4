// The loads of a step split into pieces (pipeline/fsi/fem_structure.hpp, "Step halving"):
// interpolated linearly in time from the accepted step's to the new ones, except their
// unsteady part, the pressure's ρ (∂Γ/∂t) A n (uvlm::PanelLoads::unsteady_force), which every
// piece takes whole: it is the step's mean rate, and interpolated from the last step's it
// lagged half a step, which on a wing as light as its added mass grew a sawtooth of period
// 2Δt (docs/fsi.md, "Split steps: the unsteady load held").
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include "fsi/plate_wing_fixtures.hpp"
#include "pipeline/fsi/fem_structure.hpp"
#include "pipeline/fsi/structure.hpp"

namespace {

using namespace flapsim;

constexpr int kHeldChordwise = 3, kHeldSpanwise = 6, kHeldPieces = 8;
constexpr double kHeldSpan = 0.040;      // [m]
constexpr double kHeldStep = 2e-4;       // [s]: a tenth of the plate's first bending period (~500 Hz at 1 mm)
constexpr double kHeldPanelForce = 2e-4; // [N] on each panel, along z

// The 1 mm aluminium plate of the fixtures with its lattice, root clamped to a base at rest.
std::unique_ptr<fsi::FemStructureModel> plate_at_rest() {
  fem::StructuralModel sm = test::plate_shells(1e-3);
  const std::vector<int> root = test::plate_root_nodes(sm.mesh);
  mbd::WingKinematics still;
  still.frequency = 26.1;
  still.sweep = mbd::PeriodicSignal::harmonic(0.0, {}, {});
  still.deviation = mbd::PeriodicSignal::harmonic(0.0, {}, {});
  still.rotation = mbd::PeriodicSignal::harmonic(0.0, {}, {});  // the plate flat
  fem::DynamicsOptions o;
  o.rho_infinity = 0.0;  // as the film cases
  return std::make_unique<fsi::FemStructureModel>(std::move(sm), root, mbd::make_base_motion(still), o,
                                                  test::plate_grid(kHeldChordwise, kHeldSpanwise).nodes,
                                                  kHeldChordwise, kHeldSpanwise, kHeldSpan);
}

// kHeldPanelForce on every panel, all of it unsteady or none of it.
uvlm::PanelLoads panel_lift(bool unsteady) {
  uvlm::PanelLoads load = test::uniform_panel_lift(kHeldChordwise * kHeldSpanwise, kHeldPanelForce);
  if (unsteady) load.unsteady_force = load.force;
  return load;
}

// The largest node displacement from `rest` [m].
double tip_z(const fsi::StructureData& s, const Eigen::Matrix3Xd& rest) {
  return (static_cast<const fsi::FemStructureData&>(s).trial_positions() - rest).colwise().norm().maxCoeff();
}

// The node positions at rest [m].
Eigen::Matrix3Xd rest_positions(const fsi::FemStructureModel& model) {
  auto s = model.make_data();
  s->initialize(0.0);
  return static_cast<const fsi::FemStructureData&>(*s).trial_positions();
}

// One step from rest under `load`, in kHeldPieces pieces (refine_after_stall doubles them).
double one_split_step(const fsi::FemStructureModel& model, bool unsteady) {
  auto s = model.make_data();
  s->initialize(0.0);
  for (int p = 1; p < kHeldPieces; p *= 2) s->refine_after_stall();
  s->set_external_loads(kHeldStep);
  s->add_panel_loads(panel_lift(unsteady));
  s->set_solve_accuracy(1.0);
  s->solve(kHeldStep);
  s->accept();
  EXPECT_EQ(s->max_step_pieces(), kHeldPieces);
  return tip_z(*s, rest_positions(model));
}

TEST(FemSplitStepLoads, TheUnsteadyPartIsHeldOverThePiecesAsAStepSolvedWholeTakesIt) {
  // From rest, a load that appears in the step: held over its pieces, the plate moves as in
  // kHeldPieces whole steps of Δt/8 under the same load (each takes its load at its end);
  // ramped from zero (the part that is not unsteady) it gets less: a third for a free mass
  // (u = F t²/6m against F t²/2m), 0.61 for this clamped plate (measured: 8.35e-8 against
  // 1.370e-7 m).
  const auto model = plate_at_rest();
  const double held = one_split_step(*model, true);
  const double ramped = one_split_step(*model, false);
  auto fine = model->make_data();
  fine->initialize(0.0);
  for (int k = 1; k <= kHeldPieces; ++k) {
    fine->set_external_loads(k * kHeldStep / kHeldPieces);
    fine->add_panel_loads(panel_lift(false));
    fine->set_solve_accuracy(1.0);
    fine->solve(kHeldStep / kHeldPieces);
    fine->accept();
  }
  const double whole_steps = tip_z(*fine, rest_positions(*model));
  std::printf("  largest deflection after one step: held %.6e m, %d whole steps %.6e m, ramped %.6e m\n", held,
              kHeldPieces, whole_steps, ramped);
  ASSERT_GT(whole_steps, 1e-7);  // the load moves the plate (measured below)
  // The same loads piece by piece; the loads' transfer depends on the pose, which differs
  // by the deflection itself (0.1 µm), so not to the bit (measured equal to 7 digits).
  EXPECT_NEAR(held, whole_steps, 1e-4 * whole_steps);
  EXPECT_LT(ramped, 0.7 * whole_steps);
  EXPECT_GT(ramped, 0.5 * whole_steps);
}

}  // namespace
