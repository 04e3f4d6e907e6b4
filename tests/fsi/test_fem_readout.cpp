// The FEM's tip and outer sections (fem_readout.cpp) on a coarse mesh. A wing at rest
// relative to a base turned by R reads, by definition, a tip and an outer section turned
// by R and no bend or twist (docs/fsi.md, "The FEM as the structure", the readout table).
// On a plate of one element across the chord and four along the span, the tip band
// (y >= 0.9 R) holds the two nodes of the tip edge, a line, and the outer band (5/6 R ±
// R/20) none: until 2 Dec 2026 both read as the identity (the ground frame), and a stiff
// delta wing on 5 mm elements reported a tip bent by 60° and twisted by 135°.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <memory>

#include "fem/structured_mesh.hpp"
#include "fsi/plate_wing_fixtures.hpp"
#include "pipeline/fsi/coupled_step.hpp"
#include "pipeline/fsi/fem_structure.hpp"

namespace {

using namespace flapsim;

// The plate of plate_wing_fixtures.hpp (10 mm × 40 mm, 0.1 mm aluminium) on nx × ny cells,
// at rest relative to a base turned by 30° about x, then 20° about y.
fsi::StructureReadout readout_of_a_turned_plate(int nx, int ny, Eigen::Matrix3d& turn) {
  fem::StructuralModel sm = test::plate_shells(1e-4);
  sm.mesh = fem::rectangle_mesh(0.0025 - 0.010, 0.0, 0.010, 0.040, nx, ny);
  sm.shell.resize(sm.mesh.triangles.size(), sm.shell.front());
  std::vector<int> root = test::plate_root_nodes(sm.mesh);
  turn = (Eigen::AngleAxisd(0.5236, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(0.3491, Eigen::Vector3d::UnitY()))
             .toRotationMatrix();
  const Eigen::Matrix3d r = turn;
  const mbd::BaseMotion turned = [r](double) {
    mbd::BasePose p;
    p.rotation = r;
    return p;
  };
  auto structure = std::make_shared<fsi::FemStructureModel>(
      std::move(sm), root, turned, fem::DynamicsOptions{}, Eigen::Matrix3Xd(3, 0), 1, 1, 0.040);
  const fsi::FsiModel m = test::vacuum_fsi_model(structure);
  fsi::FsiData d(m);
  fsi::initialize(m, d, 0.0);
  return d.structure->readout();
}

TEST(FemReadout, ACoarseMeshsSectionsTurnWithTheBase) {
  for (const auto& [nx, ny] : {std::pair{1, 4}, std::pair{3, 8}}) {
    Eigen::Matrix3d turn;
    const fsi::StructureReadout r = readout_of_a_turned_plate(nx, ny, turn);
    EXPECT_LT((r.tip_rotation - turn).norm(), 1e-12) << nx << " x " << ny;
    EXPECT_LT((r.outer_rotation - turn).norm(), 1e-12) << nx << " x " << ny;
    EXPECT_NEAR(r.tip_bend, 0.0, 1e-12) << nx << " x " << ny;
    EXPECT_NEAR(r.tip_twist, 0.0, 1e-12) << nx << " x " << ny;
  }
}

}  // namespace
