// Step halving of the FEM structure (pipeline/fsi/fem_structure.hpp): a coupled step whose
// Newton fails is redone in 2, 4, … pieces. Here the failure is made on purpose, by a Newton
// allowed too few iterations for a whole step of a flapping plate, so that the pieces'
// answer can be compared with the same plate stepped finely by an unrestricted Newton.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "fsi/plate_wing_fixtures.hpp"
#include "pipeline/fsi/fem_structure.hpp"
#include "pipeline/fsi/stop_request.hpp"
#include "pipeline/fsi/structure.hpp"

namespace {

using namespace flapsim;

constexpr double kHalvingSpan = 0.040;       // [m]
constexpr double kHalvingFrequency = 26.1;   // [Hz], eq. 8

// A 0.2 mm aluminium plate, 10 × 40 mm, root clamped and flapped by eq. 8, in vacuum: its
// first bending is about 100 Hz, four times the wingbeat, so it bends visibly.
std::unique_ptr<fsi::FemStructureModel> halving_plate(int max_iterations) {
  fem::StructuralModel sm = test::plate_shells(2e-4);
  const std::vector<int> root = test::plate_root_nodes(sm.mesh);
  fem::DynamicsOptions o;
  o.rho_infinity = 0.5;
  o.max_iterations = max_iterations;
  // Newton as measured below: each new matrix's geometric terms from the current state (a
  // matrix from the corrections taken linearly converges in fewer iterations, and the
  // limited solver would then split its steps into 4 or 8 pieces, varying from step to step).
  o.linearised_geometric_force = false;
  return std::make_unique<fsi::FemStructureModel>(std::move(sm), root,
                                                  mbd::make_base_motion(test::eq8_kinematics(-0.1)), o,
                                                  Eigen::Matrix3Xd(3, 0), 0, 0, kHalvingSpan);
}

// The node positions at the end of each of `steps` steps of a wingbeat [m], every
// `keep`-th step kept.
std::vector<Eigen::Matrix3Xd> flapped_positions(fsi::StructureData& s, int steps, int keep) {
  const double dt = 1.0 / (kHalvingFrequency * steps);
  std::vector<Eigen::Matrix3Xd> kept;
  s.initialize(0.0);
  for (int n = 1; n <= steps; ++n) {
    s.set_external_loads(s.time() + dt);
    s.set_solve_accuracy(1.0);
    s.solve(dt);
    s.accept();
    if (n % keep == 0) kept.push_back(static_cast<const fsi::FemStructureData&>(s).trial_positions());
  }
  return kept;
}

TEST(FemStepHalving, AStepThatFailsWholeIsSolvedInPiecesAsAFinerStepWould) {
  // 20 steps a wingbeat, Newton limited to 4 iterations: a whole step of the turning plate,
  // and its halves, quarters and eighths, need more; sixteenths do not (measured: all 20
  // steps in 16 pieces, the count tried lower at every second step and raised again). In vacuum
  // the loads are the same in every piece, so the split run is the run of 320 steps a
  // wingbeat with Newton's usual 25 iterations, to Newton's tolerance (measured 6.2e-16 m
  // apart, the plate moving 64 mm); the same 20 steps solved whole are 3.6 mm off it.
  const auto limited = halving_plate(4);
  const auto usual = halving_plate(25);
  auto split_data = limited->make_data();
  auto whole_data = usual->make_data();
  auto fine_data = usual->make_data();
  const auto split = flapped_positions(*split_data, 20, 1);
  const auto whole = flapped_positions(*whole_data, 20, 1);
  const auto fine = flapped_positions(*fine_data, 320, 16);
  ASSERT_EQ(split.size(), fine.size());
  EXPECT_EQ(split_data->split_steps(), 20);
  EXPECT_EQ(split_data->max_step_pieces(), 16);
  EXPECT_EQ(whole_data->split_steps(), 0);
  double split_error = 0.0, whole_error = 0.0, excursion = 0.0;
  for (std::size_t k = 0; k < fine.size(); ++k) {
    split_error = std::max(split_error, (split[k] - fine[k]).lpNorm<Eigen::Infinity>());
    whole_error = std::max(whole_error, (whole[k] - fine[k]).lpNorm<Eigen::Infinity>());
    excursion = std::max(excursion, (fine[k] - fine[0]).lpNorm<Eigen::Infinity>());
  }
  std::printf("  %ld of 20 steps split (up to %d pieces); against 320 steps: split %.3e m, whole %.3e m "
              "(excursion %.3e m)\n",
              split_data->split_steps(), split_data->max_step_pieces(), split_error, whole_error, excursion);
  EXPECT_LT(split_error, 1e-9 * kHalvingSpan);  // Newton's tolerance, not the time step's error
  EXPECT_GT(whole_error, 1e-5 * kHalvingSpan);  // the time step's error, for contrast
  EXPECT_GT(excursion, 10.0 * whole_error);
}

TEST(FemStepHalving, AProgramThatWantsToStopIsAskedBeforeEachPiece) {
  // A step in many pieces can take minutes (a film's); `flapsim run` registers a check that
  // throws after SIGINT/SIGTERM (pipeline/fsi/stop_request.hpp). The plate above, Newton
  // limited to 4 iterations: its first step is tried whole, in 2, 4 and 8 pieces (each
  // failing within them) and solved in 16, so it asks once for each piece it begins: at
  // least 1 + 1 + 1 + 1 + 16 = 20 times, at most 1 + 2 + 4 + 8 + 16 = 31 (measured 23);
  // asked to stop at the 10th question the solve ends there with the check's exception.
  struct Stop {};
  const auto model = halving_plate(4);
  const double dt = 1.0 / (kHalvingFrequency * 20);
  int asked = 0;
  {
    const fsi::ScopedStopCheck counting([&] { ++asked; });
    auto data = model->make_data();
    data->initialize(0.0);
    data->set_external_loads(dt);
    data->solve(dt);
    data->accept();
    EXPECT_EQ(data->max_step_pieces(), 16);
  }
  EXPECT_GE(asked, 20);
  EXPECT_LE(asked, 31);
  asked = 0;
  const fsi::ScopedStopCheck stopping([&] {
    if (++asked == 10) throw Stop{};
  });
  auto data = model->make_data();
  data->initialize(0.0);
  data->set_external_loads(dt);
  EXPECT_THROW(data->solve(dt), Stop);
  EXPECT_EQ(asked, 10);
}

TEST(FemStepHalving, AfterASplitStepEachStepSolvedWithoutAFailureHalvesThePieces) {
  // The count of pieces is halved after kFemStepsBeforeJoining = 1 step solved without a
  // failure (docs/fsi.md, "Step halving of the FEM": the MAV film wing's five wingbeats
  // measured with 4 and 1). The plate with Newton's usual 25 iterations never fails; its first
  // step is refined to 16 pieces as after a stalled coupling, the next one (the first good
  // step) is solved in 16 as well, and the steps after it in 8, 4, 2 and then 1 piece: 5 split
  // steps of 8 (with 4 good steps before each halving, all 8).
  const auto model = halving_plate(25);
  auto data = model->make_data();
  data->initialize(0.0);
  for (int k = 0; k < 4; ++k) ASSERT_TRUE(data->refine_after_stall());
  const double dt = 1.0 / (kHalvingFrequency * 20);
  for (int n = 0; n < 8; ++n) {
    data->set_external_loads(data->time() + dt);
    data->set_solve_accuracy(1.0);
    data->solve(dt);
    data->accept();
  }
  EXPECT_EQ(data->max_step_pieces(), 16);
  EXPECT_EQ(data->split_steps(), 5);
}

TEST(FemStepHalving, AStepThatFailsInTheMostPiecesStopsNamingThem) {
  // Newton allowed no iteration at all fails in every number of pieces: the solve gives up
  // at kMaxFemStepPieces with a StructureFailure that says so (the run then stops with exit
  // status 3 naming the step: fsi::NumericalFailure, tests app.*).
  const auto model = halving_plate(0);
  auto data = model->make_data();
  data->initialize(0.0);
  const double dt = 1.0 / (kHalvingFrequency * 20);
  data->set_external_loads(dt);
  try {
    data->solve(dt);
    FAIL() << "a Newton without iterations converged";
  } catch (const fsi::StructureFailure& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("in " + std::to_string(fsi::kMaxFemStepPieces) + " pieces"), std::string::npos) << what;
  }
}

TEST(FemStepHalving, AStalledStepIsSolvedInTwiceThePiecesUpToTheMost) {
  // StructureData::refine_after_stall (docs/fsi.md, "A stalled coupling, tried again"): the
  // FEM solves the step in twice as many pieces each time it is asked, up to kMaxFemStepPieces
  // (1 → 256: 8 times), then has nothing finer. The step then taken in 256 pieces gives the
  // plate of a wingbeat of 20 × 256 steps: here its first step against 256 whole steps of
  // Δt/256, to Newton's tolerance (1e-9 of the span).
  const auto model = halving_plate(25);
  auto data = model->make_data();
  data->initialize(0.0);
  int refinements = 0;
  while (data->refine_after_stall()) ++refinements;
  EXPECT_EQ(refinements, 8);
  const double dt = 1.0 / (kHalvingFrequency * 20);
  data->set_external_loads(dt);
  data->set_solve_accuracy(1.0);
  data->solve(dt);
  data->accept();
  EXPECT_EQ(data->max_step_pieces(), fsi::kMaxFemStepPieces);
  EXPECT_EQ(data->split_steps(), 1);
  auto fine = model->make_data();
  fine->initialize(0.0);
  for (int k = 0; k < fsi::kMaxFemStepPieces; ++k) {
    fine->set_external_loads(fine->time() + dt / fsi::kMaxFemStepPieces);
    fine->set_solve_accuracy(1.0);
    fine->solve(dt / fsi::kMaxFemStepPieces);
    fine->accept();
  }
  const double apart = (static_cast<const fsi::FemStructureData&>(*data).trial_positions() -
                        static_cast<const fsi::FemStructureData&>(*fine).trial_positions())
                           .lpNorm<Eigen::Infinity>();
  EXPECT_LT(apart, 1e-9 * kHalvingSpan) << apart;
}

}  // namespace
