#pragma once
/// \file corotational_kernel.hpp
/// \brief The element-independent co-rotational (EICR) kernel of Felippa &
/// Haugen 2005 ("A unified formulation of small-strain corotational finite
/// elements: I. Theory", CMAME 194:2285–2335), for an element of N nodes with
/// 6 DOF each whose response in its own reference axes is given: a LINEAR
/// stiffness k (eicr_force), or any energy W(d) of the deformational
/// displacements with its gradient and Hessian (eicr_force_with_law: the
/// tension-field membrane, corotational_shell.hpp); k below is that Hessian.
///
/// Given the co-rotated frame T_r (rows: current local axes) and its spin
/// derivative G (δω̃_r = G δũ, everything in current local components), with
/// x̄_a the current local node coordinates about the centroid and X̄_a the
/// reference ones:
///   deformational displacement  ū_a = x̄_a − X̄_a
///   deformational rotation      θ̄_a = log(T_r R_a T_0ᵀ)
///   projector                   P: δū_a = δx̃_a − δx̃_c + x̄̂_a G δũ,  δω̄_a = δω̃_a − G δũ
///   B = H P,  H = diag(I, H(θ̄_a))  (H = J_l⁻¹, nodal_rotation.hpp)
///   internal force              f = T̄ᵀ Bᵀ k d          (exactly ∂(½dᵀkd)/∂u in spins)
///   tangent                     K = T̄ᵀ [Bᵀ k B + sym(K_GR + K_GP)] T̄
///   K_GR = −F_nm G  (rotation of the frame carrying the nodal forces p = Pᵀ Hᵀ k d)
///   K_GP = Gᵀ F_nᵀ P  (variation of the lever arms x̄_a in P)
///   K_GM = Pᵀ Λ H P   (variation of Hᵀ, Λ = ∂(Hᵀm)/∂θ̄, nodal_rotation.hpp)
/// Left out: the variation of G itself, multiplied by the element's moment
/// out of balance in the current geometry (second order in the deformation).
/// In spin variables the consistent tangent is not symmetric (away from
/// equilibrium, and at equilibrium wherever moments are applied); on request
/// the geometric part is symmetrised, which costs Newton its quadratic
/// convergence under large applied moments (measured in docs/fem.md) but gives
/// an LLᵀ-factorisable matrix for dynamics. tests/fem/test_corotational_element
/// compares the tangent with finite differences of the force.

#include <array>

#include <Eigen/Core>

#include "fem/nodal_rotation.hpp"

namespace flapsim::fem {

/// Co-rotated frame of an element in its current configuration.
template <int N>
struct CorotatedFrame {
  Eigen::Matrix3d axes;                       ///< T_r: rows are current local axes (global comps.)
  Eigen::Matrix<double, 3, 6 * N> spin_map;   ///< G: δω̃_r = G δũ (local components)
};

/// Optional stiffness-proportional damping of the element's own deformation rate: the local
/// force gains a₁ k ḋ with ḋ = (d − d_n)/h, d_n the element's deformation at the step's start
/// (first order in h). d does not change under any rigid motion, so a wing flapped rigidly
/// feels none of it (damping the nodes' velocities instead, B ḋ from v, left the integrator's
/// non-rigid residue of the flapping, O(h² ω ω̇), damped by the membrane's stiffness: forces as
/// large as the wing's own, docs/fem.md "Damping"); its work a₁/h Δdᵀ k Δd is not negative.
template <int N>
struct EicrDamping {
  const Eigen::Matrix<double, 6 * N, 1>* start_deformation = nullptr;  ///< d_n [m, rad]
  double coefficient = 0.0;  ///< a₁/h [-]: local force (a₁/h) k (d − d_n), tangent (1 + a₁/h) Bᵀ k B
};

/// \brief The deformational displacements d = (ū_a, θ̄_a) of an element in its co-rotated
/// frame (the first lines of eicr_force_with_law, which calls it); x̄_a the current local node
/// coordinates about the centroid [m].
template <int N>
void eicr_deformation(const std::array<Eigen::Vector3d, N>& Xbar, const Eigen::Matrix3d& T0,
                      const Eigen::Matrix3d& Tr, const std::array<Eigen::Vector3d, N>& x,
                      const std::array<Eigen::Matrix3d, N>& R, std::array<Eigen::Vector3d, N>& xbar,
                      Eigen::Matrix<double, 6 * N, 1>& d) {
  Eigen::Vector3d xc = Eigen::Vector3d::Zero();
  for (int a = 0; a < N; ++a) xc += x[a];
  xc /= N;
  for (int a = 0; a < N; ++a) {
    xbar[a] = Tr * (x[a] - xc);
    d.template segment<3>(6 * a) = xbar[a] - Xbar[a];
    d.template segment<3>(6 * a + 3) = rotation_vector(Tr * R[a] * T0.transpose());
  }
}

/// \brief Internal force (global, conjugate to δx and spatial spins), optional
/// tangent and strain energy of one element.
/// \param law     the element's response in its co-rotated frame:
///                 `double law(const Vec& d, Vec& f_local, Mat* k_local)` returns the strain
///                 energy [J], the local force f̄ = ∂W/∂d and, if asked, its tangent k = ∂f̄/∂d
///                 (symmetric); a linear element is W = ½ dᵀ k d (LinearLocalLaw below)
/// \param Xbar    reference local node coordinates about the centroid [m]
/// \param T0      reference axes (rows) [-]
/// \param frame   current co-rotated frame and its spin map
/// \param x, R    current node positions [m] and nodal rotations
/// \param symmetric  symmetrise the geometric part (else the consistent,
///                   non-symmetric spin-variable tangent)
/// \param geometric_force  if given, the local force f̄ the geometric terms (K_GR, K_GP,
///                   K_GM) are formed from, instead of the law's (the linearised Newton
///                   matrix, nonlinear_dynamics.hpp); f itself is always the law's
template <int N, class LocalLaw>
double eicr_force_with_law(const LocalLaw& law, const std::array<Eigen::Vector3d, N>& Xbar,
                           const Eigen::Matrix3d& T0, const CorotatedFrame<N>& frame,
                           const std::array<Eigen::Vector3d, N>& x, const std::array<Eigen::Matrix3d, N>& R,
                           Eigen::Matrix<double, 6 * N, 1>& f, Eigen::Matrix<double, 6 * N, 6 * N>* K,
                           const EicrDamping<N>& damping = {}, bool symmetric = true,
                           const Eigen::Matrix<double, 6 * N, 1>* geometric_force = nullptr) {
  constexpr int n = 6 * N;
  using Vec = Eigen::Matrix<double, n, 1>;
  using Mat = Eigen::Matrix<double, n, n>;
  const Eigen::Matrix3d& Tr = frame.axes;
  const auto& G = frame.spin_map;
  std::array<Eigen::Vector3d, N> xbar;
  std::array<Eigen::Matrix3d, N> H;
  Vec d;
  eicr_deformation<N>(Xbar, T0, Tr, x, R, xbar, d);
  for (int a = 0; a < N; ++a) H[a] = inverse_tangent(d.template segment<3>(6 * a + 3));
  // P and B = H P are formed only for the tangent: the force alone (every iteration of a
  // modified Newton, nonlinear_dynamics.hpp) applies Pᵀ in closed form.
  const bool damped = damping.start_deformation != nullptr && damping.coefficient != 0.0;
  Mat P, B;
  if (K != nullptr) {
    P.setZero();
    for (int a = 0; a < N; ++a) {
      for (int b = 0; b < N; ++b)
        P.template block<3, 3>(6 * a, 6 * b).diagonal().setConstant((a == b ? 1.0 : 0.0) - 1.0 / N);
      P.template block<3, n>(6 * a, 0) += skew(xbar[a]) * G;
      P.template block<3, 3>(6 * a + 3, 6 * a + 3).setIdentity();
      P.template block<3, n>(6 * a + 3, 0) -= G;
    }
    B = P;
    for (int a = 0; a < N; ++a) B.template block<3, n>(6 * a + 3, 0) = H[a] * P.template block<3, n>(6 * a + 3, 0);
  }

  Vec fl;
  Mat k;  // the local tangent, formed only when the tangent or the damping needs it
  const double energy = law(d, fl, (K != nullptr || damped) ? &k : nullptr);
  if (damped) fl += damping.coefficient * (k * (d - *damping.start_deformation));
  Vec fbar = fl;
  for (int a = 0; a < N; ++a) fbar.template segment<3>(6 * a + 3) = H[a].transpose() * fl.template segment<3>(6 * a + 3);
  // p = Pᵀ f̄: with n_a, m_a the force and moment parts of f̄,
  //   p_t,b = n_b − (1/N) Σ n_a,  p_r,b = m_b,  p += Gᵀ Σ_a (n_a × x̄_a − m_a).
  Vec p;
  Eigen::Vector3d nsum = Eigen::Vector3d::Zero(), lever = Eigen::Vector3d::Zero();
  for (int a = 0; a < N; ++a) {
    const Eigen::Vector3d na = fbar.template segment<3>(6 * a), ma = fbar.template segment<3>(6 * a + 3);
    nsum += na;
    lever += na.cross(xbar[a]) - ma;
  }
  for (int a = 0; a < N; ++a) {
    p.template segment<3>(6 * a) = fbar.template segment<3>(6 * a) - nsum / N;
    p.template segment<3>(6 * a + 3) = fbar.template segment<3>(6 * a + 3);
  }
  p.noalias() += G.transpose() * lever;
  for (int i = 0; i < 2 * N; ++i) f.template segment<3>(3 * i) = Tr.transpose() * p.template segment<3>(3 * i);

  if (K != nullptr) {
    // Products of fixed 18 × 18 matrices coefficient by coefficient: Eigen's blocked
    // matrix–matrix kernel packs its operands for sizes this small (docs/fem.md, "The
    // elements' forces and tangents").
    const Mat kB = k.lazyProduct(B);
    Mat Kl = B.transpose().lazyProduct(kB);
    if (geometric_force != nullptr) {  // the geometric terms from a given local force
      fl = *geometric_force;
      fbar = fl;
      for (int a = 0; a < N; ++a) fbar.template segment<3>(6 * a + 3) = H[a].transpose() * fl.template segment<3>(6 * a + 3);
      p.noalias() = P.transpose() * fbar;
    }
    if (damped) Kl *= 1.0 + damping.coefficient;
    Eigen::Matrix<double, 3, n> FnT = Eigen::Matrix<double, 3, n>::Zero();
    Mat Kg;
    for (int i = 0; i < 2 * N; ++i) Kg.template block<3, n>(3 * i, 0) = -skew(p.template segment<3>(3 * i)) * G;
    for (int a = 0; a < N; ++a) FnT.template block<3, 3>(0, 6 * a) = skew(fbar.template segment<3>(6 * a));
    const Eigen::Matrix<double, 3, n> FnTP = FnT.lazyProduct(P);
    Kg += G.transpose().lazyProduct(FnTP);
    // K_GM = Pᵀ [Λ_a H_a P_a]: the bracket has rotation rows only, M_a = Λ_a B_a (3 × n), and
    // P's rotation rows are E_a − G (E_a: the identity at node a's rotations), so
    // K_GM = Σ_a E_aᵀ M_a − Gᵀ Σ_a M_a.
    Eigen::Matrix<double, 3, n> Msum = Eigen::Matrix<double, 3, n>::Zero();
    for (int a = 0; a < N; ++a) {
      const Eigen::Matrix<double, 3, n> Ma =
          inverse_tangent_derivative(d.template segment<3>(6 * a + 3), fl.template segment<3>(6 * a + 3))
              .lazyProduct(B.template block<3, n>(6 * a + 3, 0));
      Kg.template block<3, n>(6 * a + 3, 0) += Ma;
      Msum += Ma;
    }
    Kg -= G.transpose().lazyProduct(Msum);
    if (symmetric)
      Kl += 0.5 * (Kg + Kg.transpose());
    else
      Kl += Kg;
    for (int i = 0; i < 2 * N; ++i)
      for (int j = 0; j < 2 * N; ++j)
        K->template block<3, 3>(3 * i, 3 * j) = Tr.transpose() * Kl.template block<3, 3>(3 * i, 3 * j) * Tr;
  }
  return energy;
}

/// The linear local response W = ½ dᵀ k d of a small-strain element.
template <int N>
struct LinearLocalLaw {
  const Eigen::Matrix<double, 6 * N, 6 * N>& k;
  double operator()(const Eigen::Matrix<double, 6 * N, 1>& d, Eigen::Matrix<double, 6 * N, 1>& fl,
                    Eigen::Matrix<double, 6 * N, 6 * N>* kt) const {
    // Coefficient by coefficient: the same sums in the same order as Eigen's matrix–vector
    // kernel (the hover's histories identical), without its blocking for 18 × 18.
    fl.noalias() = k.lazyProduct(d);
    if (kt != nullptr) *kt = k;
    return 0.5 * d.dot(fl);
  }
};

/// \brief eicr_force_with_law for a linear local stiffness k (reference local axes).
template <int N>
double eicr_force(const Eigen::Matrix<double, 6 * N, 6 * N>& k, const std::array<Eigen::Vector3d, N>& Xbar,
                  const Eigen::Matrix3d& T0, const CorotatedFrame<N>& frame,
                  const std::array<Eigen::Vector3d, N>& x, const std::array<Eigen::Matrix3d, N>& R,
                  Eigen::Matrix<double, 6 * N, 1>& f, Eigen::Matrix<double, 6 * N, 6 * N>* K,
                  const EicrDamping<N>& damping = {}, bool symmetric = true,
                  const Eigen::Matrix<double, 6 * N, 1>* geometric_force = nullptr) {
  return eicr_force_with_law<N>(LinearLocalLaw<N>{k}, Xbar, T0, frame, x, R, f, K, damping, symmetric,
                                geometric_force);
}

}  // namespace flapsim::fem
