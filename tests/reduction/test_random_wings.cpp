// Property test of the joint stiffness by reciprocity (issue 17): over 50 random wings —
// random quadrilateral outlines, a leading-edge rod and random cross veins of random
// sections and materials, film thicknesses from 8 µm to 200 µm — the reduction never
// fails and K is always symmetric positive definite (docs/reduction.md: by construction,
// K = (T C Tᵀ)⁻¹ (T: chord slopes and twist differences) with C = Aᵀ K_FEM⁻¹ A). Coarse meshes keep it fast.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstdio>
#include <random>

#include "fem/wing_fem.hpp"
#include "reduction/chain_lumping.hpp"
#include "wings/loader/wing_model.hpp"

namespace flapsim::reduction {
namespace {

wings::Material material(std::mt19937& rng, double e_lo, double e_hi, double rho) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  wings::Material m;
  m.youngs_modulus = e_lo * std::pow(e_hi / e_lo, u(rng));
  m.poisson_ratio = 0.3 + 0.1 * u(rng);
  m.density = rho * (0.8 + 0.4 * u(rng));
  return m;
}

wings::Section section(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  wings::Section s;
  if (u(rng) < 0.7) {
    s.outer_diameter = (0.2 + 1.3 * u(rng)) * 1e-3;
    s.wall = u(rng) < 0.5 ? 0.5 * s.outer_diameter : (0.1 + 0.3 * u(rng)) * s.outer_diameter;
  } else {
    s.shape = wings::Section::Shape::Rectangle;
    s.width = (0.3 + 1.5 * u(rng)) * 1e-3;
    s.height = (0.1 + 0.6 * u(rng)) * 1e-3;
  }
  return s;
}

// A random wing in the wing frame: root edge at y = r0, leading edge near x = 0,
// trailing edge at x < 0; veins from the leading edge to the trailing edge.
wings::Wing random_wing(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  wings::Wing w;
  w.name = "random";
  const double r0 = (1.0 + 5.0 * u(rng)) * 1e-3, span = (30.0 + 70.0 * u(rng)) * 1e-3;
  const double c_root = span * (0.25 + 0.35 * u(rng)), c_tip = c_root * (0.2 + 0.8 * u(rng));
  const double le_tip = span * 0.1 * (u(rng) - 0.5);
  const Eigen::Vector2d le0(0.0, r0), le1(le_tip, span), te1(le_tip - c_tip, span), te0(-c_root, r0);
  w.outline = {le0, le1, te1, te0};
  w.span = span;
  w.clamp_y = r0 + (0.3 + 1.5 * u(rng)) * 1e-3;
  w.membrane.thickness = 8e-6 * std::pow(25.0, u(rng));  // 8 … 200 µm
  w.membrane.material = material(rng, 1e9, 8e9, 1300.0);
  w.membrane.nonstructural_mass_per_area = u(rng) < 0.5 ? 0.0 : 0.02 * u(rng);
  w.mesh.element_size = span / 14.0;
  w.mesh.vein_element_size = span / 14.0;
  const wings::Material rod = material(rng, 5e9, 2e11, 1500.0);
  wings::Vein le{"leading edge", {le0, le1}, section(rng), section(rng), rod, 0, ""};
  le.tip_section = le.root_section;
  le.tip_section.outer_diameter *= 0.5;
  le.tip_section.wall *= 0.5;
  le.tip_section.width *= 0.5;
  le.tip_section.height = std::max(0.5 * le.tip_section.height, 0.0);
  w.veins.push_back(le);
  const int cross = static_cast<int>(3.0 * u(rng));
  for (int v = 0; v < cross; ++v) {
    const double a = 0.1 + 0.8 * u(rng), b = 0.1 + 0.8 * u(rng);
    const Eigen::Vector2d p = le0 + a * (le1 - le0), q = te0 + b * (te1 - te0);
    const wings::Section s = section(rng);
    w.veins.push_back({"cross", {p, q}, s, s, material(rng, 5e9, 2e11, 1500.0), 0, ""});
  }
  return w;
}

TEST(RandomWings, JointStiffnessIsAlwaysPositiveDefinite) {
  std::mt19937 rng(17);
  int done = 0;
  double worst_ratio = 1e300;
  for (int i = 0; i < 50; ++i) {
    const wings::Wing w = random_wing(rng);
    const int nb = 4 + 2 * (i % 3);
    const fem::WingFem fem = fem::build_wing_fem(w);
    const ClampedWingAnalysis analysis(fem.model.mesh, fem.system, fem.root_clamp);
    const LumpedChain lc = lump_into_chain(analysis, nb);
    const Eigen::MatrixXd& k = lc.chain.stiffness_matrix;
    ASSERT_EQ(k.rows(), lc.chain.num_dofs()) << "wing " << i;
    EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-12 * k.cwiseAbs().maxCoeff()) << "wing " << i;
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(k, Eigen::EigenvaluesOnly);
    EXPECT_GT(es.eigenvalues()(0), 0.0) << "wing " << i << ", film " << w.membrane.thickness * 1e6 << " um";
    worst_ratio = std::min(worst_ratio, es.eigenvalues()(0) / es.eigenvalues()(k.rows() - 1));
    ++done;
  }
  std::printf("random wings reduced: %d of 50; smallest eigenvalue ratio of K %.3e\n", done, worst_ratio);
  EXPECT_EQ(done, 50);
}

}  // namespace
}  // namespace flapsim::reduction
