// The hawkmoth wing (wings/hawkmoth.toml) through the geometrically nonlinear
// FEM (fem/nonlinear_dynamics.hpp), on a coarser mesh than the wing file's
// (element size 2 mm instead of 0.5 mm: 673 nodes instead of 4603; a step of the
// default mesh costs seconds, docs/fem.md). Everything is compared with the
// same coarse mesh:
// - small-amplitude free vibration released from a mode shape oscillates at
//   that mode's frequency from the modal solver of `flapsim modes`;
// - a rigid rotation of the whole wing at a constant angular acceleration
//   (1 rad/s²) leaves it stress-free, and its inertial loads are those of the
//   rigid body.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "fem/nodal_rotation.hpp"
#include "fem/nonlinear_dynamics.hpp"
#include "fem/wing_fem.hpp"
#include "wings/loader/wing_file.hpp"

namespace flapsim::fem {
namespace {

constexpr double kHawkmothCoarseElement = 2e-3;  // [m], membrane and veins

class HawkmothCorotational : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    wing_ = new wings::Wing(wings::load_wing_file(FLAPSIM_SOURCE_DIR "/wings/hawkmoth.toml"));
    MeshOptions mo;
    mo.element_size = kHawkmothCoarseElement;
    mo.vein_element_size = kHawkmothCoarseElement;
    fem_ = new WingFem(build_wing_fem(*wing_, mo));
    model_ = new CorotationalModel(make_corotational_model(fem_->model));
  }
  static void TearDownTestSuite() {
    delete model_;
    delete fem_;
    delete wing_;
  }
  static wings::Wing* wing_;
  static WingFem* fem_;
  static CorotationalModel* model_;
};
wings::Wing* HawkmothCorotational::wing_ = nullptr;
WingFem* HawkmothCorotational::fem_ = nullptr;
CorotationalModel* HawkmothCorotational::model_ = nullptr;

// Period of q(t) from its zero crossings (both directions, linear
// interpolation between steps): twice the mean spacing of the crossings.
double period_from_zero_crossings(const std::vector<double>& t, const std::vector<double>& q) {
  std::vector<double> crossings;
  for (size_t k = 1; k < q.size(); ++k)
    if ((q[k - 1] < 0.0) != (q[k] < 0.0)) crossings.push_back(t[k - 1] + (t[k] - t[k - 1]) * q[k - 1] / (q[k - 1] - q[k]));
  if (crossings.size() < 2) return std::nan("");
  return 2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

TEST_F(HawkmothCorotational, SmallFreeVibrationAtTheModalFrequencies) {
  // Reference: the lowest modes of `flapsim modes` (wing_modes: solve_modes
  // with the linear FEM's K and M) on the same mesh. The co-rotational mass
  // differs from that M in the veins' rotary inertia (docs/fem.md); its own
  // modes, printed too, differ by about 0.01 %.
  const WingModes modes = wing_modes(*fem_, 2);
  ModalOptions mo;
  mo.num_modes = 2;
  const ModalResult own = solve_modes(fem_->system.stiffness, model_->mass, fem_->root_clamp, mo);
  const CorotationalModel& cm = *model_;
  DynamicsOptions opt;
  // Small motion, no applied moments: the symmetrised tangent (CHOLMOD LLᵀ),
  // twice as fast here as the consistent one.
  opt.tangent = TangentForm::SymmetricLower;
  const DynamicsModel dm = make_dynamics_model(cm, nodes_at_or_below_y(fem_->model.mesh, wing_->clamp_y), opt);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(cm.num_dofs());
  for (int k = 0; k < 2; ++k) {
    const double f = modes.modes.frequencies_hz(k);
    const Eigen::VectorXd phi = modes.modes.shapes.col(k);
    // Released at rest from ε φ, the largest nodal translation 1e-4 of the span
    // (4.8 µm): geometric nonlinearity shifts the frequency by O(ε²).
    double phi_max = 0.0;
    for (int i = 0; i < cm.num_nodes(); ++i) phi_max = std::max(phi_max, phi.segment<3>(6 * i).norm());
    const double eps = 1e-4 * wing_->span / phi_max;
    CorotationalState s0 = reference_state(cm);
    apply_increment(s0, Eigen::VectorXd(eps * phi));
    DynamicsData data(dm, s0, zero, zero);
    // 50 steps per period: generalized-α at ρ∞ = 1 (the trapezoidal rule)
    // lengthens the period by (ωΔt)²/12 = 0.13 % [Chung & Hulbert 1993],
    // within the 0.5 % asked. 1.3 periods: three zero crossings, at
    // T/4, 3T/4 and 5T/4.
    const int per_period = 50;
    const double h = 1.0 / (f * per_period);
    std::vector<double> t{0.0}, q{phi.dot(cm.mass * displacement_vector(cm, data.state))};
    for (int n = 0; n < 13 * per_period / 10; ++n) {
      const StepResult r = step(dm, data, h, zero, nullptr);
      ASSERT_TRUE(r.converged) << "mode " << k + 1 << ": " << r.failure;
      t.push_back(data.time);
      q.push_back(phi.dot(cm.mass * displacement_vector(cm, data.state)));  // modal coordinate
    }
    const double T = period_from_zero_crossings(t, q);
    std::printf("  mode %d (%s): flapsim modes %.3f Hz, co-rotational mass %.3f Hz; free vibration %.3f Hz "
                "(%+.3f %% from flapsim modes)\n",
                k + 1, to_string(modes.kinds[k]).c_str(), f, own.frequencies_hz(k), 1.0 / T, 100.0 * (1.0 / (f * T) - 1.0));
    EXPECT_NEAR(f * T, 1.0, 0.005) << "mode " << k + 1;  // issue 28: within 0.5 %
  }
}

TEST_F(HawkmothCorotational, RigidRotationAtConstantAngularAccelerationIsStressFree) {
  // In the ground frame with every node driven (fem/nonlinear_dynamics.hpp):
  // the whole wing turned about a skew axis n through the pivot (the wing
  // frame's origin), θ = αt²/2 with α = 1 rad/s², to t = 3 s (θ = 4.5 rad,
  // past π; ω = 3 rad/s). At each of 30 steps:
  // 1. Stress-free: the internal forces f_int and the strain energy of the
  //    driven configuration are at round-off. Scale: positions carry a
  //    round-off of ε·R (ε = DBL_EPSILON, R the wing's bounding-box diagonal), which the
  //    stiffest nodal spring k_max = max_i K_ii (translations, linear FEM)
  //    turns into a force f_ε = ε R k_max and an energy ½ ε² R² k_max. The
  //    linear K annihilates only infinitesimal rotations, so the linear FEM's
  //    spurious force max |K u| (u: the rigid motion's nodal displacements and
  //    rotation vectors) is printed too: a co-rotational frame that did not
  //    follow the element (or deformational rotations not measured from it)
  //    would count the rigid rotation as strain, with forces of that order
  //    (4.6e5 N on this mesh against f_ε = 6.7e-8 N). Asserted: below 10 f_ε
  //    (measured 0.17 f_ε and 0.09 of the energy scale).
  const CorotationalModel& cm = *model_;
  std::vector<int> all(static_cast<size_t>(cm.num_nodes()));
  for (int i = 0; i < cm.num_nodes(); ++i) all[static_cast<size_t>(i)] = i;
  const DynamicsModel dm = make_dynamics_model(cm, all);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(cm.num_dofs());
  DynamicsData data(dm, reference_state(cm), zero, zero);
  NonlinearAssembler internal(cm, Constraints(cm.num_dofs()));
  // Mass, centre of mass and inertia tensor about the pivot, from the element masses.
  double m = 0.0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (const ElementMass& e : fem_->system.element_masses) {
    m += e.mass;
    first += e.mass * e.centroid;
    second += e.second_moment + e.mass * e.centroid * e.centroid.transpose();
  }
  const Eigen::Vector3d c0 = first / m;
  const Eigen::Matrix3d I0 = second.trace() * Eigen::Matrix3d::Identity() - second;
  const Eigen::Vector3d n = Eigen::Vector3d(0.3, -0.2, 1.0).normalized();
  const double alpha = 1.0, t_end = 3.0;  // [rad/s², s]
  const int steps = 30;
  double k_max = 0.0;
  for (int i = 0; i < cm.num_dofs(); ++i)
    if (i % kDofsPerNode < 3) k_max = std::max(k_max, fem_->system.stiffness.coeff(i, i));
  const double f_eps = std::numeric_limits<double>::epsilon() * dm.size * k_max;  // [N]
  const double e_eps = 0.5 * f_eps * f_eps / k_max;                                // [J]
  double worst_force = 0.0, worst_energy = 0.0, worst_resultant = 0.0, worst_moment = 0.0, linear_force = 0.0;
  Eigen::VectorXd f_int(cm.num_dofs());
  for (int k = 1; k <= steps; ++k) {
    const double t = t_end * k / steps, theta = 0.5 * alpha * t * t, omega = alpha * t;
    const Eigen::Matrix3d Q = rotation_matrix(theta * n);
    const PrescribedMotion pm = rigid_prescribed_motion(dm, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                                        Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Q,
                                                        omega * n, alpha * n);
    const StepResult r = step(dm, data, t_end / steps, zero, &pm);
    ASSERT_TRUE(r.converged) << r.failure;
    // 1. Stress-free.
    const double energy = internal.evaluate(data.state, f_int, false);
    const Eigen::VectorXd u = displacement_vector(cm, data.state);
    linear_force = std::max(linear_force, (fem_->system.stiffness * u).cwiseAbs().maxCoeff());
    worst_force = std::max(worst_force, f_int.cwiseAbs().maxCoeff());
    worst_energy = std::max({worst_energy, energy, data.strain_energy()});
    // 2. Inertial loads.
    const Eigen::VectorXd drive = cm.mass * data.acceleration + f_int;
    Eigen::Vector3d F = Eigen::Vector3d::Zero(), M = Eigen::Vector3d::Zero();
    for (int i = 0; i < cm.num_nodes(); ++i) {
      F += drive.segment<3>(6 * i);
      M += data.state.position[i].cross(drive.segment<3>(6 * i)) + drive.segment<3>(6 * i + 3);
    }
    const Eigen::Vector3d c = Q * c0, w = omega * n, a = alpha * n;
    const Eigen::Vector3d F_rigid = m * (a.cross(c) + w.cross(w.cross(c)));
    const Eigen::Matrix3d I = Q * I0 * Q.transpose();
    const Eigen::Vector3d M_rigid = I * a + w.cross(I * w);
    worst_resultant = std::max(worst_resultant, (F - F_rigid).norm() / F_rigid.norm());
    worst_moment = std::max(worst_moment, (M - M_rigid).norm() / M_rigid.norm());
  }
  std::printf("  rigid rotation to %.1f rad: max|f_int| %.2e N = %.2f f_eps (f_eps %.2e N; linear max|K u| %.2e N), "
              "strain energy %.2e J = %.2f e_eps; inertial resultant %.1e, moment %.1e from the rigid body's\n",
              0.5 * alpha * t_end * t_end, worst_force, worst_force / f_eps, f_eps, linear_force, worst_energy,
              worst_energy / e_eps, worst_resultant, worst_moment);
  EXPECT_LT(worst_force, 10.0 * f_eps);
  EXPECT_LT(worst_energy, 10.0 * e_eps);
  EXPECT_LT(worst_resultant, 1e-10);
  EXPECT_LT(worst_moment, 1e-4);
}

}  // namespace
}  // namespace flapsim::fem
