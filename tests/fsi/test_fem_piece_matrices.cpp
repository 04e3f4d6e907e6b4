// A step solved in pieces keeps a Newton matrix for each piece with
// DynamicsOptions::matrix_per_piece (fem/nonlinear_dynamics.hpp; docs/fem.md, "A kept matrix
// for each piece"): when the
// coupling's next sub-iteration solves the pieces again with slightly other loads, each
// piece finds the matrix made for it instead of the last piece's. (That the pieces' answer is
// the loads' whatever the matrices: fsi.FemStepHalving, to Newton's tolerance.)
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include "fsi/plate_wing_fixtures.hpp"
#include "pipeline/fsi/fem_structure.hpp"
#include "pipeline/fsi/structure.hpp"

namespace {

using namespace flapsim;

constexpr int kPieceChordwise = 3, kPieceSpanwise = 6, kPieceSteps = 10;
constexpr double kPieceSpan = 0.040;  // [m]

// The 0.2 mm aluminium plate of fsi.FemStepHalving, root clamped and flapped by eq. 8 at 20
// steps a wingbeat, Newton limited to 4 iterations: its steps are solved in 16 pieces. With
// the plate's lattice, to take panel loads.
std::unique_ptr<fsi::FemStructureModel> split_plate(bool matrix_per_piece) {
  fem::StructuralModel sm = test::plate_shells(2e-4);
  const std::vector<int> root = test::plate_root_nodes(sm.mesh);
  fem::DynamicsOptions o;
  o.rho_infinity = 0.5;
  o.max_iterations = 4;
  o.linearised_geometric_force = false;
  o.matrix_per_piece = matrix_per_piece;
  return std::make_unique<fsi::FemStructureModel>(
      std::move(sm), root, mbd::make_base_motion(test::eq8_kinematics(-0.1)), o,
      test::plate_grid(kPieceChordwise, kPieceSpanwise).nodes, kPieceChordwise, kPieceSpanwise, kPieceSpan);
}

void solve_with(fsi::FemStructureData& s, double t, double dt, double newtons) {
  s.set_external_loads(t);
  s.add_panel_loads(test::uniform_panel_lift(kPieceChordwise * kPieceSpanwise, newtons));
  s.set_solve_accuracy(1.0);
  s.solve(dt);
}

}  // namespace

// New matrices of the first and of the second solves of the 10 steps, each step solved as two
// sub-iterations do: 2 µN a panel, then 2.02 µN at the first answer's pose.
struct MatricesMade {
  long first = 0, second = 0;
  int max_pieces = 0;
};
MatricesMade solve_twice(bool matrix_per_piece) {
  const auto plate = split_plate(matrix_per_piece);
  auto data = plate->make_data();
  auto& s = static_cast<fsi::FemStructureData&>(*data);
  const double dt = 1.0 / (26.1 * 20);
  s.initialize(0.0);
  MatricesMade out;
  for (int k = 1; k <= kPieceSteps; ++k) {
    const double t = k * dt;
    long before = s.dynamics().counters().factorizations;
    solve_with(s, t, dt, 2e-6);
    out.first += s.dynamics().counters().factorizations - before;
    s.start_iterate();  // as the coupling: the next loads at the iterate's pose
    s.pose_iterate();
    before = s.dynamics().counters().factorizations;
    solve_with(s, t, dt, 2.02e-6);
    out.second += s.dynamics().counters().factorizations - before;
    s.accept();
  }
  out.max_pieces = s.max_step_pieces();
  return out;
}

TEST(FemPieceMatrices, ASecondSubIterationFindsEachPiecesMatrix) {
  // Measured: every step in 16 pieces; with a matrix for each piece the second solves made
  // 0 new matrices against 871 in the first; with one kept matrix (the default) 653.
  const MatricesMade per_piece = solve_twice(true), one = solve_twice(false);
  std::printf("  up to %d pieces; new matrices: first solves %ld, second %ld; with one kept matrix %ld, %ld\n",
              per_piece.max_pieces, per_piece.first, per_piece.second, one.first, one.second);
  EXPECT_EQ(per_piece.max_pieces, 16);
  EXPECT_EQ(one.max_pieces, 16);
  EXPECT_LT(per_piece.second, per_piece.first / 10);
  EXPECT_GT(one.second, one.first / 2);  // what the option saves
}
