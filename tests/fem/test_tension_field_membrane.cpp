// The tension-field (wrinkling) membrane law, fem/tension_field_membrane.hpp:
// its three regimes against the closed forms of tension-field theory (Kang & Im
// 1997; Pipkin 1986), its stress and tangent against finite differences of its
// energy, and the shell's local response built on it.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>

#include "fem/corotational_kernel.hpp"
#include "fem/corotational_shell.hpp"
#include "fem/nodal_rotation.hpp"
#include "fem/tension_field_membrane.hpp"

namespace flapsim::fem {
namespace {

constexpr double kFilmE = 4.0e9;   // Mylar [Pa]
constexpr double kFilmNu = 0.38;

/// A 25 µm Mylar triangle with 2 mm sides [m].
std::array<Eigen::Vector3d, 3> film_triangle_corners() {
  return {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2e-3, 0, 0), Eigen::Vector3d(0.6e-3, 1.8e-3, 0)};
}
CorotationalShell film_triangle() {
  ShellProperties props;
  props.thickness = 25e-6;
  props.youngs_modulus = kFilmE;
  props.poisson_ratio = kFilmNu;
  props.density = 1390.0;
  return make_corotational_shell({0, 1, 2}, film_triangle_corners(), props);
}

TEST(TensionFieldMembrane, ATautFilmIsTheLinearPlaneStressMaterial) {
  // Both principal stresses positive: σ = C ε exactly.
  const Eigen::Vector3d e(2e-4, 1e-4, 0.5e-4);
  const MembraneResponse r = tension_field_response(e, kFilmE, kFilmNu);
  EXPECT_EQ(r.state, MembraneState::Taut);
  EXPECT_LT((r.stress - plane_stress(kFilmE, kFilmNu) * e).norm(), 1e-12 * r.stress.norm());
}

TEST(TensionFieldMembrane, UniaxialStretchCarriesETimesTheStrainAndNothingAcross) {
  // Stretched along n = (cos 30°, sin 30°) and compressed across it beyond the Poisson
  // contraction: uniaxial tension E ε₁ along n (tension-field theory), zero across.
  const double th = std::numbers::pi / 6.0, c = std::cos(th), s = std::sin(th);
  const double e1 = 3e-4, e2 = -0.9 * e1;  // ε₂ + ν ε₁ < 0: wrinkled
  // ε = e1 n⊗n + e2 t⊗t in Voigt form (engineering shear).
  const Eigen::Vector3d e(e1 * c * c + e2 * s * s, e1 * s * s + e2 * c * c, 2.0 * (e1 - e2) * c * s);
  const MembraneResponse r = tension_field_response(e, kFilmE, kFilmNu);
  EXPECT_EQ(r.state, MembraneState::Wrinkled);
  const Eigen::Vector3d expected = kFilmE * e1 * Eigen::Vector3d(c * c, s * s, c * s);
  EXPECT_LT((r.stress - expected).norm(), 1e-12 * expected.norm());
  EXPECT_NEAR(r.energy_density, 0.5 * kFilmE * e1 * e1, 1e-12 * r.energy_density);
  // The regime boundary ε₂ = −ν ε₁ is continuous: the taut law gives the same stress there.
  const Eigen::Vector3d edge(e1, -kFilmNu * e1, 0.0);
  const MembraneResponse at = tension_field_response(edge * (1 + 1e-12), kFilmE, kFilmNu);
  EXPECT_NEAR(at.stress.x(), kFilmE * e1, 1e-9 * kFilmE * e1);
  EXPECT_NEAR(at.stress.y(), 0.0, 1e-9 * kFilmE * e1);
}

TEST(TensionFieldMembrane, ACompressedFilmIsSlack) {
  const MembraneResponse r = tension_field_response(Eigen::Vector3d(-1e-4, -2e-4, 1e-5), kFilmE, kFilmNu);
  EXPECT_EQ(r.state, MembraneState::Slack);
  EXPECT_EQ(r.stress.norm(), 0.0);
  EXPECT_EQ(r.energy_density, 0.0);
}

TEST(TensionFieldMembrane, StressAndTangentAreTheDerivativesOfTheEnergy) {
  // Central differences (step 1e-9 of a strain of 1e-4): the stress is ∂w/∂ε and the
  // tangent ∂σ/∂ε in every regime, away from its boundaries.
  const Eigen::Vector3d strains[] = {{2e-4, 1e-4, 0.5e-4}, {3e-4, -2e-4, 1e-4}, {-1e-4, 2e-4, -1.5e-4},
                                     {1e-4, -3e-4, 2e-4}, {-1e-4, -2e-4, 1e-5}};
  for (const Eigen::Vector3d& e : strains) {
    const MembraneResponse r = tension_field_response(e, kFilmE, kFilmNu);
    const double h = 1e-9;
    for (int j = 0; j < 3; ++j) {
      Eigen::Vector3d ep = e, em = e;
      ep(j) += h;
      em(j) -= h;
      const MembraneResponse rp = tension_field_response(ep, kFilmE, kFilmNu);
      const MembraneResponse rm = tension_field_response(em, kFilmE, kFilmNu);
      const double dw = (rp.energy_density - rm.energy_density) / (2 * h);
      EXPECT_NEAR(r.stress(j), dw, 1e-6 * kFilmE * e.norm() + 1e-3) << "strain " << e.transpose();
      const Eigen::Vector3d ds = (rp.stress - rm.stress) / (2 * h);
      EXPECT_LT((r.tangent.col(j) - ds).norm(), 1e-6 * kFilmE) << "strain " << e.transpose();
    }
    EXPECT_LT((r.tangent - r.tangent.transpose()).norm(), 1e-12 * kFilmE);
    EXPECT_GE(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(r.tangent).eigenvalues().minCoeff(), -1e-9 * kFilmE);
  }
}

TEST(TensionFieldMembrane, ACompressedTriangleCarriesNoForceInAnyOrientation) {
  // The co-rotational shell (EICR kernel) with the tension-field law: a 25 µm Mylar
  // triangle shrunk by 0.1 % in its plane carries nothing, turned by 40° or not; the
  // same triangle stretched by 0.1 % carries what the linear element carries.
  const std::array<Eigen::Vector3d, 3> p = film_triangle_corners();
  const CorotationalShell shell = film_triangle();
  const Eigen::Matrix3d turn = rotation_matrix(Eigen::Vector3d(0.3, -0.5, 0.4).normalized() * (40.0 * std::numbers::pi / 180));
  for (const double scale : {0.999, 1.001}) {
    for (const Eigen::Matrix3d& Q : {Eigen::Matrix3d(Eigen::Matrix3d::Identity()), turn}) {
      std::array<Eigen::Vector3d, 3> x;
      const std::array<Eigen::Matrix3d, 3> R{Q, Q, Q};
      for (int a = 0; a < 3; ++a) x[a] = Q * (scale * p[a]);
      Eigen::Matrix<double, 18, 1> f_tf, f_lin;
      eicr_force_with_law<3>(ShellTensionFieldLaw{shell}, shell.reference_local, shell.reference_axes,
                             shell_corotated_frame(x), x, R, f_tf, nullptr);
      eicr_force<3>(shell.local_stiffness, shell.reference_local, shell.reference_axes, shell_corotated_frame(x), x,
                    R, f_lin, nullptr);
      // Linear element: E h A ε ≈ 4e9 · 25e-6 · 1.8e-6 / 1.2e-3 · 1e-3 ~ 0.15 N of nodal force.
      ASSERT_GT(f_lin.norm(), 0.05);
      if (scale < 1.0)
        EXPECT_LT(f_tf.norm(), 1e-9 * f_lin.norm()) << "compressed by 0.1 %";
      else
        EXPECT_LT((f_tf - f_lin).norm(), 1e-9 * f_lin.norm()) << "stretched by 0.1 %";
    }
  }
}

TEST(TensionFieldMembrane, TheShellsLocalForceAndTangentAreThoseOfItsEnergy) {
  // A 25 µm Mylar triangle (2 mm sides) in a wrinkled state: the local force of
  // ShellTensionFieldLaw is ∂W/∂d and its tangent ∂f/∂d (central differences).
  const CorotationalShell shell = film_triangle();
  const ShellTensionFieldLaw law{shell};
  Eigen::Matrix<double, 18, 1> d = Eigen::Matrix<double, 18, 1>::Zero();
  d(6) = 6e-7;    // node 1 pulled along x: stretch
  d(13) = -9e-7;  // node 2 pushed down in y: compression across
  d(2) = 1e-6;    // some bending
  d(16) = 2e-4;
  EXPECT_EQ(tension_field_response(shell_membrane_strain(shell, d), kFilmE, kFilmNu).state,
            MembraneState::Wrinkled);
  Eigen::Matrix<double, 18, 1> f, fp, fm;
  Matrix18d k, unused;
  law(d, f, &k);
  for (int j = 0; j < 18; ++j) {
    const double h = (j % 6 < 3 ? 1e-12 : 1e-9);
    Eigen::Matrix<double, 18, 1> dp = d, dm = d;
    dp(j) += h;
    dm(j) -= h;
    const double wp = law(dp, fp, nullptr), wm = law(dm, fm, nullptr);
    EXPECT_NEAR(f(j), (wp - wm) / (2 * h), 1e-5 * f.cwiseAbs().maxCoeff()) << "dof " << j;
    EXPECT_LT((k.col(j) - (fp - fm) / (2 * h)).norm(), 1e-5 * k.cwiseAbs().maxCoeff()) << "dof " << j;
  }
  // With the membrane taut the law is the linear element: f = k d.
  Eigen::Matrix<double, 18, 1> taut = Eigen::Matrix<double, 18, 1>::Zero();
  taut(6) = 6e-7;
  taut(13) = 4e-7;
  law(taut, f, &unused);
  EXPECT_LT((f - shell.local_stiffness * taut).norm(), 1e-9 * f.norm());
}

}  // namespace
}  // namespace flapsim::fem
