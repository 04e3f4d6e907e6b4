// The EICR elements (fem/corotational_*.hpp) one at a time: a large rigid
// motion leaves them stress-free, the internal force is the exact gradient of
// the strain energy, the tangent matches finite differences of the force, and
// at a small deformation the internal force is the linear element's K u; the
// geometric terms from a given local force (the FEM dynamics' linearised Newton
// matrix) and the three points of a correction that give it.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <utility>

#include "fem/block_rotation.hpp"
#include "fem/corotational_frame.hpp"
#include "fem/corotational_shell.hpp"
#include "fem/nodal_rotation.hpp"
#include "fem/section_properties.hpp"
#include "fem_test_helpers.hpp"

namespace flapsim::fem {
namespace {

const std::array<Eigen::Vector3d, 3> kTri{Eigen::Vector3d(0.01, -0.02, 0.003), Eigen::Vector3d(0.52, 0.05, -0.02),
                                          Eigen::Vector3d(0.13, 0.41, 0.04)};

FrameProperties tube() {
  wings::Section sec;
  sec.outer_diameter = 0.02;
  sec.wall = 0.003;
  FrameProperties f;
  f.youngs_modulus = 2e9;
  f.shear_modulus = 2e9 / 2.6;
  f.density = 1000.0;
  f.section = section_properties(sec);
  f.up = Eigen::Vector3d(0.1, 0.2, 1.0);
  return f;
}

// One element's state: positions and rotations, and its force and tangent.
template <int N>
struct Element {
  std::array<Eigen::Vector3d, N> x;
  std::array<Eigen::Matrix3d, N> R;
};

double shell_eval(const CorotationalShell& e, const Element<3>& s, Eigen::Matrix<double, 18, 1>& f, Matrix18d* K,
                  bool symmetric = true) {
  return eicr_force<3>(e.local_stiffness, e.reference_local, e.reference_axes, shell_corotated_frame(s.x), s.x, s.R,
                       f, K, {}, symmetric);
}
double frame_eval(const CorotationalFrame& e, const Element<2>& s, Eigen::Matrix<double, 12, 1>& f, Matrix12d* K,
                  bool symmetric = true) {
  return eicr_force<2>(e.local_stiffness, e.reference_local, e.reference_axes, frame_corotated_frame(e, s.x, s.R),
                       s.x, s.R, f, K, {}, symmetric);
}

template <int N>
Element<N> perturbed(const Element<N>& s, const Eigen::Matrix<double, 6 * N, 1>& du) {
  Element<N> t = s;
  for (int a = 0; a < N; ++a) {
    t.x[a] += du.template segment<3>(6 * a);
    t.R[a] = rotation_matrix(du.template segment<3>(6 * a + 3)) * t.R[a];
  }
  return t;
}

// A large rigid motion (rotation of 2.3 rad about a skew axis) plus a
// deformation of relative size `strain` on top.
template <int N>
Element<N> deformed(const std::array<Eigen::Vector3d, N>& X, double strain, unsigned seed) {
  std::srand(seed);
  const Eigen::Matrix3d Q = rotation_matrix(2.3 * Eigen::Vector3d(0.3, -0.8, 0.52).normalized());
  Element<N> s;
  for (int a = 0; a < N; ++a) {
    const Eigen::Vector3d dx = strain * Eigen::Vector3d::Random();
    const Eigen::Vector3d dth = strain * Eigen::Vector3d::Random();
    s.x[a] = Q * (X[a] + dx) + Eigen::Vector3d(0.4, -1.1, 2.0);
    s.R[a] = Q * rotation_matrix(dth);
  }
  return s;
}

TEST(CorotationalElement, RigidMotionIsStressFree) {
  const CorotationalShell sh = make_corotational_shell({0, 1, 2}, kTri, testing::shell(7e10, 0.3, 0.01, 2700));
  const Element<3> s = deformed<3>(kTri, 0.0, 1);
  Eigen::Matrix<double, 18, 1> f;
  const double E = shell_eval(sh, s, f, nullptr);
  // Scale: the linear element's spurious force K u for the same rigid motion.
  Eigen::Matrix<double, 18, 1> u;
  for (int a = 0; a < 3; ++a) {
    u.segment<3>(6 * a) = s.x[a] - kTri[a];
    u.segment<3>(6 * a + 3) = rotation_vector(s.R[a]);
  }
  const Matrix18d T = block_rotation<18>(sh.reference_axes);
  const double linear = (T.transpose() * sh.local_stiffness * T * u).cwiseAbs().maxCoeff();
  std::printf("  shell: |f| %.3e, linear K u %.3e, energy %.3e\n", f.cwiseAbs().maxCoeff(), linear, E);
  EXPECT_LT(f.cwiseAbs().maxCoeff(), 1e-12 * linear);

  const Eigen::Vector3d a(0.0, 0.0, 0.0), b(0.3, 0.4, 0.1);
  const CorotationalFrame fr = make_corotational_frame({0, 1}, a, b, tube());
  const Element<2> sf = deformed<2>({a, b}, 0.0, 2);
  Eigen::Matrix<double, 12, 1> ff;
  frame_eval(fr, sf, ff, nullptr);
  Eigen::Matrix<double, 12, 1> uf;
  uf << sf.x[0] - a, rotation_vector(sf.R[0]), sf.x[1] - b, rotation_vector(sf.R[1]);
  const Matrix12d Tf = block_rotation<12>(fr.reference_axes);
  const double linf = (Tf.transpose() * fr.local_stiffness * Tf * uf).cwiseAbs().maxCoeff();
  std::printf("  frame: |f| %.3e, linear K u %.3e\n", ff.cwiseAbs().maxCoeff(), linf);
  EXPECT_LT(ff.cwiseAbs().maxCoeff(), 1e-12 * linf);
}

// f·δ = dE/dε along random (translation, spin) directions: the force is the
// gradient of ½ dᵀ k d (central differences, O(ε²) ≈ 1e-10 relative).
template <int N, class Eval>
double gradient_error(const Element<N>& s, Eval eval) {
  Eigen::Matrix<double, 6 * N, 1> f, g;
  eval(s, f, nullptr);
  double worst = 0.0;
  for (int k = 0; k < 6; ++k) {
    Eigen::Matrix<double, 6 * N, 1> dir = Eigen::Matrix<double, 6 * N, 1>::Random();
    const double eps = 1e-6;
    const double Ep = eval(perturbed<N>(s, eps * dir), g, nullptr);
    const double Em = eval(perturbed<N>(s, -eps * dir), g, nullptr);
    const double fd = (Ep - Em) / (2.0 * eps);
    worst = std::max(worst, std::abs(fd - f.dot(dir)) / (f.norm() * dir.norm()));
  }
  return worst;
}

// ‖K δ − FD(f)‖ / ‖FD(f)‖, worst over random directions.
template <int N, class Eval>
double tangent_error(const Element<N>& s, Eval eval) {
  Eigen::Matrix<double, 6 * N, 1> f, fp, fm;
  Eigen::Matrix<double, 6 * N, 6 * N> K;
  eval(s, f, &K);
  double worst = 0.0;
  for (int k = 0; k < 6; ++k) {
    Eigen::Matrix<double, 6 * N, 1> dir = Eigen::Matrix<double, 6 * N, 1>::Random();
    const double eps = 1e-7;
    eval(perturbed<N>(s, eps * dir), fp, nullptr);
    eval(perturbed<N>(s, -eps * dir), fm, nullptr);
    const Eigen::Matrix<double, 6 * N, 1> fd = (fp - fm) / (2.0 * eps);
    worst = std::max(worst, (K * dir - fd).norm() / fd.norm());
  }
  return worst;
}

TEST(CorotationalElement, ForceIsEnergyGradientAndTangentMatchesDifferences) {
  const CorotationalShell sh = make_corotational_shell({0, 1, 2}, kTri, testing::shell(7e10, 0.3, 0.01, 2700));
  const Eigen::Vector3d a(0.0, 0.0, 0.0), b(0.3, 0.4, 0.1);
  const CorotationalFrame fr = make_corotational_frame({0, 1}, a, b, tube());
  auto se = [&](const Element<3>& s, Eigen::Matrix<double, 18, 1>& f, Matrix18d* K) { return shell_eval(sh, s, f, K); };
  auto fe = [&](const Element<2>& s, Eigen::Matrix<double, 12, 1>& f, Matrix12d* K) { return frame_eval(fr, s, f, K); };
  auto sc = [&](const Element<3>& s, Eigen::Matrix<double, 18, 1>& f, Matrix18d* K) {
    return shell_eval(sh, s, f, K, false);
  };
  auto fc = [&](const Element<2>& s, Eigen::Matrix<double, 12, 1>& f, Matrix12d* K) {
    return frame_eval(fr, s, f, K, false);
  };
  for (double strain : {1e-3, 3e-2}) {
    const Element<3> s3 = deformed<3>(kTri, strain, 3);
    const Element<2> s2 = deformed<2>({a, b}, strain, 4);
    const double gs = gradient_error<3>(s3, se), gf = gradient_error<2>(s2, fe);
    const double ts = tangent_error<3>(s3, se), tf = tangent_error<2>(s2, fe);
    const double cs = tangent_error<3>(s3, sc), cf = tangent_error<2>(s2, fc);
    std::printf("  deformation %.0e: gradient error shell %.2e frame %.2e; tangent error symmetrised: shell %.2e "
                "frame %.2e, consistent: shell %.2e frame %.2e\n",
                strain, gs, gf, ts, tf, cs, cf);
    EXPECT_LT(gs, 1e-7);
    EXPECT_LT(gf, 1e-7);
    // The symmetrised tangent drops the skew part, which is of the order of the
    // element forces, i.e. of the deformation.
    EXPECT_LT(ts, 10.0 * strain);
    EXPECT_LT(tf, 10.0 * strain);
    // The consistent tangent leaves out only the variation of G times the
    // element's out-of-balance moment, second order in the deformation.
    EXPECT_LT(cs, 10.0 * strain * strain);
    EXPECT_LT(cf, 10.0 * strain * strain);
  }
}

// The local deformation d of an element state (eicr_deformation).
template <int N>
Eigen::Matrix<double, 6 * N, 1> local_deformation(const std::array<Eigen::Vector3d, N>& Xbar,
                                                  const Eigen::Matrix3d& T0, const CorotatedFrame<N>& frame,
                                                  const Element<N>& s) {
  Eigen::Matrix<double, 6 * N, 1> d;
  std::array<Eigen::Vector3d, N> xbar;
  eicr_deformation<N>(Xbar, T0, frame.axes, s.x, s.R, xbar, d);
  return d;
}

// The element's force and tangent, once as usual and once with the geometric terms from its
// own local force k d (eicr_force's `geometric_force`): the force's difference (must be 0)
// and the tangents' relative difference.
template <int N>
std::pair<double, double> own_force_geometric_terms_gap(const Eigen::Matrix<double, 6 * N, 6 * N>& k,
                                                       const std::array<Eigen::Vector3d, N>& Xbar,
                                                       const Eigen::Matrix3d& T0, const CorotatedFrame<N>& frame,
                                                       const Element<N>& s, bool symmetric) {
  const Eigen::Matrix<double, 6 * N, 1> g = k * local_deformation<N>(Xbar, T0, frame, s);
  Eigen::Matrix<double, 6 * N, 1> f, fg;
  Eigen::Matrix<double, 6 * N, 6 * N> K, Kg;
  eicr_force<N>(k, Xbar, T0, frame, s.x, s.R, f, &K, {}, symmetric);
  eicr_force<N>(k, Xbar, T0, frame, s.x, s.R, fg, &Kg, {}, symmetric, &g);
  return {(fg - f).norm(), (Kg - K).norm() / K.norm()};
}

TEST(CorotationalElement, GeometricTermsFromTheElementsOwnLocalForceGiveItsTangent) {
  // The tangent's geometric terms taken from a given local force (the linearised Newton
  // matrix of fem/nonlinear_dynamics.hpp) are the usual ones when that force is the
  // element's own, k d: to round-off, for the shell and the frame, symmetrised and not.
  const CorotationalShell sh = make_corotational_shell({0, 1, 2}, kTri, testing::shell(7e10, 0.3, 0.01, 2700));
  const Eigen::Vector3d a(0.0, 0.0, 0.0), b(0.3, 0.4, 0.1);
  const CorotationalFrame fr = make_corotational_frame({0, 1}, a, b, tube());
  const Element<3> s3 = deformed<3>(kTri, 3e-2, 5);
  const Element<2> s2 = deformed<2>({a, b}, 3e-2, 6);
  for (bool symmetric : {true, false}) {
    const auto [shell_force, shell_tangent] = own_force_geometric_terms_gap<3>(
        sh.local_stiffness, sh.reference_local, sh.reference_axes, shell_corotated_frame(s3.x), s3, symmetric);
    const auto [frame_force, frame_tangent] = own_force_geometric_terms_gap<2>(
        fr.local_stiffness, fr.reference_local, fr.reference_axes, frame_corotated_frame(fr, s2.x, s2.R), s2,
        symmetric);
    EXPECT_EQ(shell_force, 0.0);  // the force itself is k d(u) either way
    EXPECT_EQ(frame_force, 0.0);
    EXPECT_LT(shell_tangent, 1e-12);
    EXPECT_LT(frame_tangent, 1e-12);
  }
}

TEST(CorotationalElement, ThreePointsOfACorrectionGiveItsLinearisedDeformation) {
  // NonlinearAssembler::record_correction_path: along a correction u(α) = u₀ ⊕ α Δu,
  // 4 d(½) − 2 d(0) − d(1) = d(0) + d'(0) + O(Δu³) (Taylor), where d(1) itself is off by
  // ½ d''(0), second order: a transverse correction's stretching of the membrane. d'(0)
  // here by central differences at α = ±1e-6.
  const CorotationalShell sh = make_corotational_shell({0, 1, 2}, kTri, testing::shell(7e10, 0.3, 0.01, 2700));
  const Element<3> s0 = deformed<3>(kTri, 1e-2, 7);
  std::srand(11);
  const Eigen::Matrix<double, 18, 1> direction = Eigen::Matrix<double, 18, 1>::Random();
  auto d_at = [&](const Eigen::Matrix<double, 18, 1>& du) {
    const Element<3> s = perturbed<3>(s0, du);
    return local_deformation<3>(sh.reference_local, sh.reference_axes, shell_corotated_frame(s.x),
                                s);
  };
  double previous = 0.0;
  for (double size : {4e-2, 2e-2, 1e-2}) {
    const Eigen::Matrix<double, 18, 1> du = size * direction;
    const double e = 1e-6;
    const Eigen::Matrix<double, 18, 1> linear = d_at(0.0 * du) + (d_at(e * du) - d_at(-e * du)) / (2.0 * e);
    const double three_points = (4.0 * d_at(0.5 * du) - 2.0 * d_at(0.0 * du) - d_at(du) - linear).norm();
    const double end_point = (d_at(du) - linear).norm();
    std::printf("  correction %.0e: three points %.2e, the end point %.2e off the linearised deformation\n", size,
                three_points, end_point);
    EXPECT_LT(three_points, 0.1 * end_point);
    if (previous > 0.0) {
      EXPECT_GT(previous / three_points, 6.0);  // third order: 8 per halving
    }
    previous = three_points;
  }
}

TEST(CorotationalElement, SmallDeformationGivesLinearForce) {
  // No rigid motion, deformation 1e-7: f = K_linear u to O(u²).
  const ShellProperties p = testing::shell(7e10, 0.3, 0.01, 2700);
  const CorotationalShell sh = make_corotational_shell({0, 1, 2}, kTri, p);
  const Matrix18d Klin = shell_element(kTri, p).stiffness;
  Eigen::Matrix<double, 18, 1> u = 1e-7 * Eigen::Matrix<double, 18, 1>::Random();
  Element<3> s{kTri, {Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Identity()}};
  s = perturbed<3>(s, u);
  Eigen::Matrix<double, 18, 1> f;
  shell_eval(sh, s, f, nullptr);
  const double err = (f - Klin * u).norm() / (Klin * u).norm();
  std::printf("  |f − K u| / |K u| = %.2e\n", err);
  EXPECT_LT(err, 1e-5);
}

TEST(CorotationalElement, ShellMembraneAndPlateProductsEqualTheWholeLocalStiffness) {
  // The shell's local k (OPT membrane on u, v, θz; DKT plate on w, θx, θy: shell_element.hpp)
  // has exactly zero coupling, so ShellLinearLaw's two 9 × 9 products equal k d up to the
  // order of the sums (a few ulps); and k is the global element stiffness in the element's
  // own axes, T K Tᵀ, to round-off.
  const ShellProperties p = testing::shell(7e10, 0.3, 0.01, 2700);
  const CorotationalShell sh = make_corotational_shell({0, 1, 2}, kTri, p);
  const Matrix18d& k = sh.local_stiffness;
  double coupling = 0.0;
  for (int r = 0; r < 18; ++r)
    for (int c = 0; c < 18; ++c) {
      const bool r_membrane = r % 6 == 0 || r % 6 == 1 || r % 6 == 5;
      const bool c_membrane = c % 6 == 0 || c % 6 == 1 || c % 6 == 5;
      if (r_membrane != c_membrane) coupling = std::max(coupling, std::abs(k(r, c)));
    }
  EXPECT_EQ(coupling, 0.0);
  const Matrix18d T = block_rotation<18>(sh.reference_axes);
  EXPECT_LT((T * shell_element(kTri, p).stiffness * T.transpose() - k).norm(), 1e-13 * k.norm());
  std::srand(3);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Matrix<double, 18, 1> d = Eigen::Matrix<double, 18, 1>::Random();
    Eigen::Matrix<double, 18, 1> f;
    Matrix18d kt;
    const double energy = ShellLinearLaw{sh}(d, f, &kt);
    const Eigen::Matrix<double, 18, 1> whole = k * d;
    EXPECT_LT((f - whole).norm(), 1e-14 * k.norm() * d.norm());
    EXPECT_NEAR(energy, 0.5 * d.dot(whole), 1e-14 * k.norm() * d.squaredNorm());
    EXPECT_EQ(kt, k);
  }
}

}  // namespace
}  // namespace flapsim::fem

namespace flapsim::fem {
namespace {

// Stiffness-proportional damping of the element's own deformation rate (EicrDamping):
// (a₁/h) k (d − d_n). Under a rigid motion of the element from its step-start state d does not
// change, so it adds nothing (the damping of the nodes' velocities it replaced damped the
// integrator's non-rigid residue of a rigid flapping: a 0.2 mm PET plate flapped at 10 Hz in
// steps of T/40 split 27 to 40 of 40 steps with a₁ = 1e-5 to 1e-3 s, and its drive power fell
// by 33 % at 1e-5; docs/fem.md "Damping"); its tangent is the damped force's derivative.
TEST(CorotationalElement, TheDampingOfTheDeformationRateIsZeroUnderARigidMotionAndItsTangentIsConsistent) {
  const CorotationalShell sh =
      make_corotational_shell({0, 1, 2}, kTri, testing::shell(7e10, 0.3, 0.01, 2700));
  const Element<3> start = deformed<3>(kTri, 1e-3, 5);
  const Eigen::Matrix<double, 18, 1> d_n =
      local_deformation<3>(sh.reference_local, sh.reference_axes, shell_corotated_frame(start.x), start);
  // The start moved rigidly: turned by 0.7 rad about a skew axis and shifted.
  const Eigen::Matrix3d Q = rotation_matrix(0.7 * Eigen::Vector3d(0.6, 0.2, -0.77).normalized());
  Element<3> moved = start;
  for (int a = 0; a < 3; ++a) {
    moved.x[a] = Q * start.x[a] + Eigen::Vector3d(0.05, -0.3, 0.2);
    moved.R[a] = Q * start.R[a];
  }
  const EicrDamping<3> damping{&d_n, 10.0};  // a₁/h = 10: a₁ = 1e-3 s at h = 1e-4 s
  auto damped = [&](const Element<3>& s, Eigen::Matrix<double, 18, 1>& f, Matrix18d* K) {
    return eicr_force<3>(sh.local_stiffness, sh.reference_local, sh.reference_axes,
                         shell_corotated_frame(s.x), s.x, s.R, f, K, damping, false);
  };
  Eigen::Matrix<double, 18, 1> with, without;
  damped(moved, with, nullptr);
  shell_eval(sh, moved, without, nullptr);
  EXPECT_LT((with - without).norm(), 1e-10 * without.norm())
      << (with - without).norm() << " of " << without.norm();
  // Deformed further from the start: the damping force is there, 10 times the elastic force of
  // the change, and the consistent tangent (1 + a₁/h) Bᵀ k B + K_G(f) is its derivative to the
  // order of the undamped element's (second order in the deformation).
  const Element<3> further = deformed<3>(kTri, 3e-3, 6);
  damped(further, with, nullptr);
  shell_eval(sh, further, without, nullptr);
  EXPECT_GT((with - without).norm(), without.norm());
  const double error = tangent_error<3>(further, damped);
  std::printf("  damped shell: tangent error %.2e\n", error);
  EXPECT_LT(error, 10.0 * 3e-3 * 3e-3);
}

}  // namespace
}  // namespace flapsim::fem
