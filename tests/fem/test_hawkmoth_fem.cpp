// The hawkmoth forewing (wings/hawkmoth.toml) through the FEM: node count, total
// mass against the papers' 33.8 mg, mass over span thirds, lowest modes.

#include <gtest/gtest.h>

#include <cstdio>

#include "fem/wing_fem.hpp"
#include "wings/loader/wing_file.hpp"

namespace flapsim::fem {
namespace {

class HawkmothFem : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    wing_ = new wings::Wing(wings::load_wing_file(FLAPSIM_SOURCE_DIR "/wings/hawkmoth.toml"));
    fem_ = new WingFem(build_wing_fem(*wing_));
  }
  static void TearDownTestSuite() {
    delete fem_;
    delete wing_;
  }
  static wings::Wing* wing_;
  static WingFem* fem_;
};
wings::Wing* HawkmothFem::wing_ = nullptr;
WingFem* HawkmothFem::fem_ = nullptr;

TEST_F(HawkmothFem, MeshSizeAndTotalMass) {
  const Mesh& mesh = fem_->model.mesh;
  std::printf("  hawkmoth: %d nodes, %zu triangles, %zu vein elements\n", mesh.num_nodes(),
              mesh.triangles.size(), mesh.beams.size());
  // The multibody paper §3.1: "about 4000 nodes".
  EXPECT_GT(mesh.num_nodes(), 3000);
  EXPECT_LT(mesh.num_nodes(), 6000);
  // Structural mass 33.8 mg: rotation-phase paper Table 1 (13.27 + 13.01 + 7.48
  // mg) and the multibody paper §3.1 (0.033 g); within 1 %.
  const double m = fem_->system.total_mass;
  std::printf("  FEM mass %.4f mg (target 33.8 mg, %+.2f %%)\n", m * 1e6, 100.0 * (m / 33.8e-6 - 1.0));
  EXPECT_NEAR(m / 33.8e-6, 1.0, 0.01);
}

TEST_F(HawkmothFem, MassOverSpanThirdsBesideTable1) {
  // Strip sums of element masses by centroid over thirds of the span R (from the pivot),
  // against the rotation-phase paper's Table 1: 13.27 / 13.01 / 7.48 mg. Measured +13.8 /
  // −3.4 / −18.1 % (docs/fem.md, "The hawkmoth": the calibrated veins are heavy at the root,
  // the scale mass is uniform per area, and Table 1's bodies come from the paper's own
  // lumping). The tolerance, 20 % per third, is that known difference: a mass model that
  // moved more mass along the span fails.
  const double R = wing_->span;
  double third[3] = {0.0, 0.0, 0.0};
  for (const ElementMass& e : fem_->system.element_masses)
    third[std::clamp(static_cast<int>(e.centroid.y() / (R / 3.0)), 0, 2)] += e.mass;
  const double table1_mg[3] = {13.27, 13.01, 7.48};
  std::printf("  span thirds: %.3f / %.3f / %.3f mg (RP Table 1: 13.27 / 13.01 / 7.48)\n", third[0] * 1e6,
              third[1] * 1e6, third[2] * 1e6);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(third[k] * 1e6 / table1_mg[k], 1.0, 0.20) << "third " << k + 1;
  // The mass falls toward the tip, as in Table 1.
  EXPECT_GT(third[0], third[1]);
  EXPECT_GT(third[1], third[2]);
}

TEST_F(HawkmothFem, LowestModes) {
  const WingModes m = wing_modes(*fem_, 8);
  for (int k = 0; k < 8; ++k)
    std::printf("  mode %d: %8.2f Hz  %s\n", k + 1, m.modes.frequencies_hz(k), to_string(m.kinds[k]).c_str());
  // Clamped root, stiff leading-edge veins: the fundamental is spanwise bending
  // and a torsion mode follows among the first few.
  EXPECT_EQ(m.kinds[0], ModeKind::Bending);
  EXPECT_GT(m.modes.frequencies_hz(0), 0.0);
  bool torsion = false;
  for (int k = 1; k < 4; ++k) torsion = torsion || m.kinds[k] == ModeKind::Torsion;
  EXPECT_TRUE(torsion);
  // Mode 3 (435 Hz) is the second bending mode: its sections' mean deflection changes sign
  // once along the span (beam theory's second bending shape) and the chain's joints store
  // its strain energy mostly in bending (the stations' naming, docs/reduction.md); its
  // sections also twist about an axis inside the chord, which the strip fits used to call
  // torsion (fem.vtu: kind "bending", shape_kind "torsion"). The fits now weigh the
  // sections' translation against their rotation (docs/fem.md): bending, torsion, bending.
  const std::vector<double> w = nodal_masses(fem_->model.mesh, fem_->system);
  EXPECT_EQ(measure_mode_shape(fem_->model.mesh, w, m.modes.shapes.col(2)).spanwise_sign_changes, 1);
  EXPECT_EQ(m.kinds[1], ModeKind::Torsion);
  EXPECT_EQ(m.kinds[2], ModeKind::Bending);
  // Mass-normalised shapes: φᵀ M φ = 1 and φ_iᵀ M φ_j = 0.
  const Eigen::MatrixXd G = m.modes.shapes.transpose() * (fem_->system.mass * m.modes.shapes);
  EXPECT_LT((G - Eigen::MatrixXd::Identity(8, 8)).cwiseAbs().maxCoeff(), 1e-8);
}

}  // namespace
}  // namespace flapsim::fem
