// Nonlinear dynamics (fem/nonlinear_dynamics.hpp): free vibration of a clamped
// plate at the modal solver's first frequency, second order in Δt, a clamped
// plate driven in a rigid rotation about its root, a kept matrix's Newton that diverges stopped
// at its first correction, and a flapped plate's end state the same bits on 1, 2 and 3 threads. (Energy over 100
// periods of a large-amplitude free vibration: measured, not asserted; see
// docs/fem.md.)

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <omp.h>
#include <numbers>

#include "fem/modal_solver.hpp"
#include "fem/nodal_rotation.hpp"
#include "fem/nonlinear_dynamics.hpp"
#include "fem/nonlinear_static_solver.hpp"
#include "fem/section_properties.hpp"
#include "fem/static_solver.hpp"
#include "fem/structured_mesh.hpp"
#include "fem_test_helpers.hpp"

namespace flapsim::fem {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<int> nodes_at_x(const Mesh& m, double x) {
  std::vector<int> out;
  for (int i = 0; i < m.num_nodes(); ++i)
    if (std::abs(m.nodes[i].x() - x) < 1e-12) out.push_back(i);
  return out;
}

// First clamped frequency [Hz] of the co-rotational model's linearisation:
// the linear K with the co-rotational (rotation-invariant) mass.
double first_frequency(const StructuralModel& sm, const CorotationalModel& cm, const std::vector<int>& clamp,
                       Eigen::VectorXd* shape = nullptr) {
  Constraints c(cm.num_dofs());
  c.clamp_nodes(clamp);
  ModalOptions o;
  o.num_modes = 2;
  const ModalResult r = solve_modes(assemble(sm).stiffness, cm.mass, c, o);
  if (shape) *shape = r.shapes.col(0);
  return r.frequencies_hz(0);
}

// The cantilever aluminium plate 0.1 m × 0.1 m × 1 mm (8 × 8 mesh, clamped at x = 0): its
// co-rotational model and first clamped mode (f1 [Hz], shape phi). Built in place.
struct ClampedSquarePlate {
  static constexpr double a = 0.1;  // [m]
  StructuralModel sm =
      testing::uniform_shell_model(rectangle_mesh(0.0, 0.0, a, a, 8, 8), testing::shell(70e9, 0.3, 1e-3, 2700.0));
  CorotationalModel cm = make_corotational_model(sm);
  std::vector<int> root = nodes_at_x(sm.mesh, 0.0);
  Eigen::VectorXd phi;
  double f1 = first_frequency(sm, cm, root, &phi);
};

TEST(NonlinearDynamics, PlateFreeVibrationAtModalFrequency) {
  // Cantilever aluminium plate 0.1 m × 0.1 m × 1 mm, 8 × 8 mesh, released in
  // its first mode with an amplitude of 1e-4 of its side: the period from the
  // zero crossings must be 1/f₁ of solve_modes within 0.5 % (the trapezoidal
  // rule's period error is (ωΔt)²/12 = 8e-5 at 200 steps per period).
  const ClampedSquarePlate plate;
  const double a = plate.a, f1 = plate.f1;
  const StructuralModel& sm = plate.sm;
  const CorotationalModel& cm = plate.cm;
  const std::vector<int>& root = plate.root;
  const Eigen::VectorXd& phi = plate.phi;
  const double w1 = 2.0 * kPi * f1;
  const DynamicsModel dm = make_dynamics_model(cm, root);
  const Eigen::VectorXd v0 = (1e-4 * a / phi.cwiseAbs().maxCoeff()) * w1 * phi;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(cm.num_dofs());
  DynamicsData data(dm, reference_state(cm), v0, zero);
  const int tip = sm.mesh.num_nodes() - 1;  // corner (a, a)
  const int per_period = 200;
  const double h = 1.0 / (f1 * per_period);
  std::vector<double> crossings;
  double prev = 0.0;
  for (int k = 0; k < 3 * per_period + 20; ++k) {
    const StepResult r = step(dm, data, h, zero, nullptr);
    ASSERT_TRUE(r.converged) << r.failure;
    const double w = data.state.position[tip].z();
    if (k > 0 && prev < 0.0 && w >= 0.0) crossings.push_back(data.time - h * w / (w - prev));
    prev = w;
  }
  ASSERT_GE(crossings.size(), 2u);
  const double T = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  std::printf("  plate: f1 = %.4f Hz (modes), %.4f Hz (dynamics), %+.4f %%\n", f1, 1.0 / T, 100.0 * (f1 * T - 1.0));
  EXPECT_NEAR(f1 * T, 1.0, 0.005);
}

TEST(NonlinearDynamics, SecondOrderInTimeStep) {
  // The rod launched from its straight shape with the velocity of its first
  // mode (tip amplitude about 0.3 L, in and out of plane: a 3-D motion with
  // twist), tip position at t = T₁/2 with Δt, Δt/2, Δt/4: observed order
  // log₂(|q_h − q_h/2| / |q_h/2 − q_h/4|) = 2 (Chung & Hulbert 1993). A smooth
  // start: a release from a static deflection would put the stiff modes that
  // no step resolves (rotations of small rotary inertia) into motion.
  const StructuralModel sm = testing::soft_rod();
  const CorotationalModel cm = make_corotational_model(sm);
  Eigen::VectorXd phi;
  const double f1 = first_frequency(sm, cm, {0}, &phi);
  const double T1 = 1.0 / f1;
  Eigen::VectorXd v0 = (0.3 / phi.cwiseAbs().maxCoeff()) * 2.0 * kPi * f1 * phi;
  for (int i = 0; i < cm.num_nodes(); ++i) {  // the same shape sideways, at half the amplitude
    v0(6 * i + 1) = 0.5 * v0(6 * i + 2) + 0.5 * v0(6 * i + 1);
    v0(6 * i + 5) = -0.5 * v0(6 * i + 4) + 0.5 * v0(6 * i + 5);
  }
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(cm.num_dofs());
  DynamicsOptions opt;
  opt.rho_infinity = 1.0;
  opt.tolerance = 1e-13;
  const DynamicsModel dm = make_dynamics_model(cm, {0}, opt);
  Eigen::Vector3d tip[3];
  for (int level = 0; level < 3; ++level) {
    const int n = 40 << level;
    DynamicsData data(dm, reference_state(cm), v0, zero);
    for (int k = 0; k < n; ++k) {
      const StepResult r = step(dm, data, 0.5 * T1 / n, zero, nullptr);
      ASSERT_TRUE(r.converged) << r.failure;
    }
    tip[level] = data.state.position[10];
  }
  const double e1 = (tip[0] - tip[1]).norm(), e2 = (tip[1] - tip[2]).norm();
  const double p = std::log2(e1 / e2);
  std::printf("  tip at T1/2 (%.3f, %.3f, %.3f) m; differences %.3e, %.3e m, observed order %.3f\n", tip[2].x(),
              tip[2].y(), tip[2].z(), e1, e2, p);
  EXPECT_NEAR(p, 2.0, 0.15);
}

TEST(NonlinearDynamics, DrivenRigidRotationLeavesPlateUnstressed) {
  // A clamped aluminium plate (0.05 m square, 0.1 mm) whose root edge is driven
  // in a rotation about itself (the y axis) from rest, the angular
  // acceleration ramped linearly to α = 1 rad/s² over t_r = 0.2 s and then
  // held, for 1 s (0.455 rad). Measure: the largest distance of a node from
  // the rigid motion, against the linear quasi-static deflection u_qs under the
  // rigid motion's largest inertial loads (at the end: Euler α × r and
  // centripetal ω × (ω × r), body frame). Under a load ramped up over t_r an
  // undamped structure deflects by at most (1 + 2/(ω₁ t_r)) times its static
  // deflection (the ramp's dynamic load factor, Clough & Penzien, Dynamics of
  // Structures, §4-5); spurious stresses of a rigid rotation would show as a
  // deviation of the order of the rotation itself (0.46 rad × 0.05 m).
  const double a = 0.05;
  const StructuralModel sm =
      testing::uniform_shell_model(rectangle_mesh(0.0, 0.0, a, a, 6, 6), testing::shell(70e9, 0.3, 1e-4, 2700.0));
  const CorotationalModel cm = make_corotational_model(sm);
  const std::vector<int> root = nodes_at_x(sm.mesh, 0.0);
  const DynamicsModel dm = make_dynamics_model(cm, root);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(cm.num_dofs());
  const Eigen::Vector3d axis = Eigen::Vector3d::UnitY();
  const double alpha = 1.0;
  // Initial acceleration field of the rigid motion (at rest): v̇ = α × r.
  DynamicsData data(dm, reference_state(cm), zero, zero);
  const double f1 = first_frequency(sm, cm, root);
  const int n = 1000;  // about 29 steps per period of the first mode
  const double h = 1.0 / n;
  std::printf("  plate f1 = %.1f Hz, %.1f steps per period\n", f1, 1.0 / (f1 * h));
  double worst = 0.0;
  const double tr = 0.2;
  auto motion = [&](double t, double& th, double& om, double& al) {
    if (t < tr) {
      al = alpha * t / tr;
      om = alpha * t * t / (2.0 * tr);
      th = alpha * t * t * t / (6.0 * tr);
    } else {
      al = alpha;
      om = alpha * tr / 2.0 + alpha * (t - tr);
      th = alpha * tr * tr / 6.0 + alpha * tr / 2.0 * (t - tr) + 0.5 * alpha * (t - tr) * (t - tr);
    }
  };
  for (int k = 1; k <= n; ++k) {
    const double t = k * h;
    double th, om, al;
    motion(t, th, om, al);
    const Eigen::Matrix3d Q = rotation_matrix(th * axis);
    const PrescribedMotion pm = rigid_prescribed_motion(dm, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                                        Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Q,
                                                        om * axis, al * axis);
    const StepResult r = step(dm, data, h, zero, &pm);
    ASSERT_TRUE(r.converged) << r.failure;
    for (int i = 0; i < cm.num_nodes(); ++i)
      worst = std::max(worst, (data.state.position[i] - Q * cm.reference_positions[i]).norm());
  }
  // Quasi-static linear deflection under the end-time inertial loads.
  double th_end, w, al_end;
  motion(1.0, th_end, w, al_end);
  Eigen::VectorXd acc = Eigen::VectorXd::Zero(cm.num_dofs());
  for (int i = 0; i < cm.num_nodes(); ++i) {
    const Eigen::Vector3d r = cm.reference_positions[i];
    acc.segment<3>(6 * i) = alpha * axis.cross(r) + w * w * axis.cross(axis.cross(r));
    acc.segment<3>(6 * i + 3) = alpha * axis;
  }
  Constraints c(cm.num_dofs());
  c.clamp_nodes(root);
  const StaticSolver lin(assemble(sm).stiffness, c);
  const Eigen::VectorXd uqs = lin.solve(Eigen::VectorXd(-(cm.mass * acc)));
  double uqs_max = 0.0;
  for (int i = 0; i < cm.num_nodes(); ++i) uqs_max = std::max(uqs_max, uqs.segment<3>(6 * i).norm());
  const double dlf = 1.0 + 2.0 / (2.0 * kPi * f1 * tr);
  std::printf("  max deviation from the rigid motion %.3e m, quasi-static u_qs %.3e m (ratio %.3f, bound %.3f), "
              "rotation scale %.1e m\n",
              worst, uqs_max, worst / uqs_max, dlf, th_end * a);
  EXPECT_LT(worst, dlf * uqs_max);
}

TEST(NonlinearDynamics, ALoadDampingIsTheLoadItStandsFor) {
  // A NodalLoadDamping (load_damping.hpp) adds −s D (v_{n+1} − v_ref) to the loads of the
  // step: the cantilever plate of PlateFreeVibrationAtModalFrequency, released in its first
  // mode, ten steps with D = 50 I N s/m on every free node (s = 0.8, v_ref the release
  // velocity) against the same steps with that load computed from the damped run's answer
  // and given as an external load. The answers agree to Newton's tolerance (1e-9 of the
  // motion), and the damped run converges like the plain one (the term in its Newton matrix).
  const ClampedSquarePlate plate;
  const StructuralModel& sm = plate.sm;
  const CorotationalModel& cm = plate.cm;
  const double a = plate.a, f1 = plate.f1;
  const Eigen::VectorXd& phi = plate.phi;
  const std::vector<int>& root = plate.root;
  DynamicsOptions o;
  o.increment_tolerance = 1e-14;
  const DynamicsModel dm = make_dynamics_model(cm, root, o);
  const Eigen::VectorXd v0 = (1e-3 * a / phi.cwiseAbs().maxCoeff()) * 2.0 * kPi * f1 * phi;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(cm.num_dofs());
  Eigen::Matrix3Xd v_ref(3, cm.num_nodes());
  for (int n = 0; n < cm.num_nodes(); ++n) v_ref.col(n) = v0.segment<3>(dof_index(n, UX));
  NodalLoadDamping damping;
  for (int n = 0; n < cm.num_nodes(); ++n)
    if (std::abs(sm.mesh.nodes[static_cast<std::size_t>(n)].x()) > 1e-12) {
      damping.nodes.push_back(n);
      damping.blocks.push_back(50.0 * Eigen::Matrix3d::Identity());
    }
  damping.reference_velocity = &v_ref;
  damping.scale = 0.8;
  DynamicsData damped(dm, reference_state(cm), v0, zero), loaded(dm, reference_state(cm), v0, zero);
  const double h = 1.0 / (f1 * 50);
  Eigen::VectorXd load = zero;
  double apart = 0.0, motion = 0.0;
  int damped_iterations = 0, loaded_iterations = 0;
  for (int k = 0; k < 10; ++k) {
    const StepResult r = step(dm, damped, h, zero, nullptr, StepStart::Predictor, 1.0, &damping);
    ASSERT_TRUE(r.converged) << r.failure;
    damped_iterations += r.iterations;
    load.setZero();
    for (std::size_t i = 0; i < damping.nodes.size(); ++i) {
      const int n = damping.nodes[i];
      load.segment<3>(dof_index(n, UX)) =
          -damping.scale * damping.blocks[i] * (damped.velocity.segment<3>(dof_index(n, UX)) - v_ref.col(n));
    }
    const StepResult l = step(dm, loaded, h, load, nullptr);
    ASSERT_TRUE(l.converged) << l.failure;
    loaded_iterations += l.iterations;
    for (int n = 0; n < cm.num_nodes(); ++n) {
      apart = std::max(apart, (damped.state.position[static_cast<std::size_t>(n)] -
                               loaded.state.position[static_cast<std::size_t>(n)]).norm());
      motion = std::max(motion, (damped.state.position[static_cast<std::size_t>(n)] -
                                 cm.reference_positions[static_cast<std::size_t>(n)]).norm());
    }
  }
  std::printf("  positions %.2e of the motion apart; Newton iterations in 10 steps: %d damped, %d loaded\n",
              apart / motion, damped_iterations, loaded_iterations);
  EXPECT_LT(apart, 1e-9 * motion);
  // The damping's γ/(βh) D (here about 18 times c_M M) in the Newton matrix: at most one iteration
  // a step more than the same steps with the load given (without it the kept matrix's
  // corrections diverge: the test failed at the damped step's convergence).
  EXPECT_LE(damped_iterations, loaded_iterations + 10);
}

}  // namespace
}  // namespace flapsim::fem

namespace flapsim::fem {
namespace {

// The plate of ClampedSquarePlate under end moments about y, statically in one long step
// (h = 1 s: the plate's inertia c_M M negligible beside its stiffness); returns the step's
// result and the Newton iterations it took.
StepResult plate_under_end_moment(double linear_tip_rotation, long& iterations) {
  const ClampedSquarePlate p;
  const DynamicsModel dm = make_dynamics_model(p.cm, p.root);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(p.cm.num_dofs());
  // Pure bending of the plate: θ = M L / (D b), D = E t³ / (12 (1 − ν²)) [N m], b = L = a.
  const double D = 70e9 * 1e-9 / (12.0 * (1.0 - 0.3 * 0.3));
  const double moment = linear_tip_rotation * D;  // M = θ D b / L with b = L [N m]
  const std::vector<int> tip = nodes_at_x(p.sm.mesh, ClampedSquarePlate::a);
  Eigen::VectorXd load = zero;
  for (std::size_t k = 0; k < tip.size(); ++k) {  // the edge's nodes by their tributary width
    const bool corner = k == 0 || k + 1 == tip.size();
    load(6 * tip[k] + 4) = -moment / static_cast<double>(tip.size() - 1) * (corner ? 0.5 : 1.0);
  }
  DynamicsData data(dm, reference_state(p.cm), zero, zero);
  const StepResult r = step(dm, data, 1.0, load, nullptr);
  iterations = data.counters().iterations;
  return r;
}

TEST(NonlinearDynamics, ANewtonWithAKeptMatrixThatDivergesStopsAtOnce) {
  // A correction that asks to turn a node by more than π rad linearises nothing
  // (nonlinear_dynamics.cpp, kDivergedCorrection): a plate rolled up by end moments whose
  // linear tip rotation is 20 rad stops its attempt with the kept matrix at the first
  // correction and goes on to full Newton, which fails after its max_iterations (25): 26
  // iterations in all, not the 2 × 25 of both attempts run out. The same plate at 1 rad
  // (its first correction below π, scaled to 0.3 rad a correction) converges.
  long iterations = 0;
  const StepResult rolled = plate_under_end_moment(20.0, iterations);
  EXPECT_FALSE(rolled.converged);
  EXPECT_LE(iterations, 1 + DynamicsOptions{}.max_iterations) << rolled.failure;
  const StepResult bent = plate_under_end_moment(1.0, iterations);
  EXPECT_TRUE(bent.converged) << bent.failure;
}

// The end state of a 0.1 m square aluminium plate (0.5 mm, 24 × 24 mesh: 625 nodes, 1152
// shells, 3600 free DOFs) flapped about its clamped root edge (θ = 0.3 sin 2πft, f = 25 Hz,
// 8 steps of 1 ms) under a transverse tip load, on `threads` threads.
std::vector<double> flapped_plate_end_state(int threads) {
  const StructuralModel sm =
      testing::uniform_shell_model(rectangle_mesh(0.0, 0.0, 0.1, 0.1, 24, 24), testing::shell(70e9, 0.3, 5e-4, 2700.0));
  const CorotationalModel cm = make_corotational_model(sm);
  const std::vector<int> root = nodes_at_x(sm.mesh, 0.0);
  const DynamicsModel dm = make_dynamics_model(cm, root);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(cm.num_dofs());
  Eigen::VectorXd load = zero;
  for (int i : nodes_at_x(sm.mesh, 0.1)) load(6 * i + 2) = 0.05;  // [N]
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  DynamicsData data(dm, reference_state(cm), zero, zero);
  const double f = 25.0, h = 1e-3, amplitude = 0.3;
  const Eigen::Vector3d axis = Eigen::Vector3d::UnitY();
  for (int k = 1; k <= 8; ++k) {
    const double w = 2.0 * kPi * f, t = k * h;
    const PrescribedMotion pm = rigid_prescribed_motion(
        dm, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
        rotation_matrix(amplitude * std::sin(w * t) * axis), amplitude * w * std::cos(w * t) * axis,
        -amplitude * w * w * std::sin(w * t) * axis);
    const StepResult r = step(dm, data, h, load, &pm);
    EXPECT_TRUE(r.converged) << r.failure;
  }
  omp_set_num_threads(saved);
  std::vector<double> out;
  for (int i = 0; i < cm.num_nodes(); ++i) {
    for (int c = 0; c < 3; ++c) out.push_back(data.state.position[i](c));
    for (int c = 0; c < 9; ++c) out.push_back(data.state.rotation[i](c));
  }
  for (Eigen::Index i = 0; i < data.velocity.size(); ++i) out.push_back(data.velocity(i));
  return out;
}

TEST(NonlinearDynamics, AFlappedPlateEndsInTheSameBitsOnOneTwoAndThreeThreads) {
  // Everything a Newton iteration splits between threads — the elements' forces and
  // tangents, the tangent's values in two ranges, the nodes' updates, the Newton matrix in
  // two parts and their separator (3600 rows) — gives each number the same operations in
  // the same order on any number of threads (docs/fem.md, "Two parts on two threads").
  const std::vector<double> one = flapped_plate_end_state(1);
  for (int threads : {2, 3}) {
    const std::vector<double> more = flapped_plate_end_state(threads);
    ASSERT_EQ(one.size(), more.size());
    EXPECT_EQ(0, std::memcmp(one.data(), more.data(), sizeof(double) * one.size())) << threads << " threads";
  }
}

}  // namespace
}  // namespace flapsim::fem
