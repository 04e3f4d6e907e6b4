// The coupled step drives any structure through fsi::StructureModel / StructureData
// (pipeline/fsi/structure.hpp, docs/fsi.md "The structure interface"): here a structure
// written in the test alone, with nothing of mbd's chain — the rigid plate of
// test_fsi_coupling.cpp hung on a heave spring (one degree of freedom h along ground z,
// m ḧ + k h = F_z, trapezoidal rule).

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "fsi/plate_wing_fixtures.hpp"
#include "pipeline/fsi/coupled_step.hpp"
#include "pipeline/fsi/numerical_failure.hpp"
#include "pipeline/fsi/structure.hpp"

namespace {

using namespace flapsim;

struct HeaveState {
  double time = 0.0, h = 0.0, hd = 0.0, hdd = 0.0;  // [s], [m], [m/s], [m/s²]
};

class HeavePlateModel : public fsi::StructureModel {
 public:
  Eigen::Matrix3Xd nodes_wing;  // lattice nodes in the wing frame [m]
  mbd::BaseMotion motion;
  double mass = 0.0;       // [kg]
  double stiffness = 0.0;  // [N/m]
  double length = 0.040;   // scale of the change measure [m]
  int stall_refinements = -1;  // ≥ 0: a StallingHeavePlateData that may refine this often
  int refinements_to_smooth = 1;  // the refinements after which its answer no longer jumps
  bool solve_fails = false;    // a FailingHeavePlateData: its own solve fails (as a FEM's Newton)
  int num_dofs() const override { return 1; }
  int surface_nodes() const override { return static_cast<int>(nodes_wing.cols()); }
  const mbd::BaseMotion& base() const override { return motion; }
  std::unique_ptr<fsi::StructureData> make_data() const override;
  const Eigen::Matrix3Xd& reference_surface() const override { return nodes_wing; }
};

class HeavePlateData : public fsi::StructureData {
 public:
  explicit HeavePlateData(const HeavePlateModel& m) : m_(m) {}
  void initialize(double t0) override { accepted = trial = iterate = HeaveState{t0}; }
  double time() const override { return accepted.time; }
  void set_external_loads(double) override { force = 0.0; }
  void add_panel_loads(const uvlm::PanelLoads& panels) override { force += panels.total_force.z(); }
  void prescribe(double) override { ADD_FAILURE() << "a structure with a dof is never prescribed"; }
  void solve(double dt) override {
    // Trapezoidal rule: h₁ = h₀ + dt ḣ₀ + dt²/4 (ḧ₀ + ḧ₁), ḣ₁ = ḣ₀ + dt/2 (ḧ₀ + ḧ₁).
    const HeaveState& a = accepted;
    const double predicted = a.h + dt * a.hd + 0.25 * dt * dt * a.hdd;
    trial.time = a.time + dt;
    trial.hdd = (force - m_.stiffness * predicted) / (m_.mass + 0.25 * dt * dt * m_.stiffness);
    trial.h = predicted + 0.25 * dt * dt * trial.hdd;
    trial.hd = a.hd + 0.5 * dt * (a.hdd + trial.hdd);
    pose = trial;
  }
  void start_iterate() override { iterate = trial; }
  void pose_iterate() override { pose = iterate; }
  void surface(Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& v) const override {
    const mbd::BasePose p = m_.motion(pose.time);
    x = p.rotation * m_.nodes_wing;
    for (Eigen::Index k = 0; k < x.cols(); ++k) {
      v.col(k) = p.angular_velocity.cross(x.col(k)) + Eigen::Vector3d(0.0, 0.0, pose.hd);
      x(2, k) += pose.h;
    }
  }
  double change(double frequency) const override {
    const double rate = 2.0 * std::numbers::pi * frequency;
    return std::max(std::abs(trial.h - iterate.h), std::abs(trial.hd - iterate.hd) / rate) / m_.length;
  }
  void residual(Eigen::VectorXd& r) const override { r.setConstant(1, trial.hdd - iterate.hdd); }
  void trial_vector(Eigen::VectorXd& x) const override { x = Eigen::Vector3d(trial.h, trial.hd, trial.hdd); }
  void set_iterate(const Eigen::VectorXd& x) override { iterate = HeaveState{trial.time, x(0), x(1), x(2)}; }
  void relax(double w) override {
    iterate = HeaveState{trial.time, iterate.h + w * (trial.h - iterate.h), iterate.hd + w * (trial.hd - iterate.hd),
                         iterate.hdd + w * (trial.hdd - iterate.hdd)};
  }
  void accept() override { accepted = trial; }
  int interface_size() const override { return 1; }
  long split_steps() const override { return 0; }
  int max_step_pieces() const override { return 1; }
  fsi::StructureReadout readout() const override { return {}; }
  void joint_angles(Eigen::VectorXd& q) const override { q.resize(0); }

  HeaveState accepted, trial, iterate, pose;
  double force = 0.0;  // F_z of the current loads [N]

 private:
  const HeavePlateModel& m_;
};

// The heave plate whose answer jumps by ±10 µm from one solve to the next (a structure
// with two shapes for the same loads, as a wrinkling film's FEM), so no relaxation converges
// its coupling, until refine_after_stall() (allowed `left` times) has been called `needed`
// times, which takes the jumps away.
class StallingHeavePlateData : public HeavePlateData {
 public:
  StallingHeavePlateData(const HeavePlateModel& m, int left, int needed)
      : HeavePlateData(m), left_(left), needed_(needed) {}
  void solve(double dt) override {
    HeavePlateData::solve(dt);
    if (!refined) trial.h += (++solves % 2 == 0 ? 1e-5 : -1e-5);
    pose = trial;
  }
  bool refine_after_stall() override {
    if (left_ == 0) return false;
    --left_;
    refined = ++done_ >= needed_;
    return true;
  }
  bool refined = false;
  long solves = 0;

 private:
  int left_, needed_, done_ = 0;
};

// The heave plate whose own solve fails, as a FEM step whose Newton iterations stop.
class FailingHeavePlateData : public HeavePlateData {
 public:
  using HeavePlateData::HeavePlateData;
  void solve(double) override { throw fsi::StructureFailure("heave plate: its solve failed"); }
};

std::unique_ptr<fsi::StructureData> HeavePlateModel::make_data() const {
  if (solve_fails) return std::make_unique<FailingHeavePlateData>(*this);
  if (stall_refinements >= 0)
    return std::make_unique<StallingHeavePlateData>(*this, stall_refinements, refinements_to_smooth);
  return std::make_unique<HeavePlateData>(*this);
}

struct HeaveRun {
  std::vector<double> h, lift;
  double iterations = 0.0;
  double worst_surface_gap = 0.0;  // [m]
};

// One cycle of the eq. 8 plate on the spring (in the second the plate meets its own wake); mass in kg, stiffness in N/m.
HeaveRun heave_run(double mass, double stiffness, fsi::CouplingMethod method, double tolerance,
                   int stall_refinements = -1, long* stall_retries = nullptr, bool solve_fails = false,
                   int refinements_to_smooth = 1) {
  const int nc = 3, ns = 6, steps = 40;
  const auto grid = test::plate_grid(nc, ns);
  auto structure = std::make_shared<HeavePlateModel>();
  structure->nodes_wing = grid.nodes;
  const auto kin = test::eq8_kinematics(-0.1);
  structure->motion = mbd::make_base_motion(kin);
  structure->mass = mass;
  structure->stiffness = stiffness;
  structure->stall_refinements = stall_refinements;
  structure->refinements_to_smooth = refinements_to_smooth;
  structure->solve_fails = solve_fails;
  fsi::FsiModel m;
  m.structure = structure;
  m.frequency = kin.frequency;
  m.lattice.chordwise = nc;
  m.lattice.spanwise = ns;
  m.lattice.core.radius = 0.2 * 0.010;
  m.lattice.wake_capacity = 2 * steps;
  m.coupling.method = method;
  m.coupling.tolerance = tolerance;
  m.coupling.max_iterations = 200;
  const double dt = 1.0 / (kin.frequency * steps);
  fsi::FsiData d(m);
  fsi::initialize(m, d, 0.0);
  HeaveRun r;
  Eigen::Matrix3Xd x(3, grid.nodes.cols()), v(3, grid.nodes.cols());
  for (int n = 0; n < steps; ++n) {
    fsi::coupled_step(m, d, dt);
    auto& s = dynamic_cast<HeavePlateData&>(*d.structure);
    r.h.push_back(s.accepted.h);
    r.lift.push_back(d.lattice->loads.total_force.z());
    // The lattice of the step's last solve sat on the iterate; the accepted state is within
    // the coupling tolerance of it (change() ≤ tolerance, measured in spans).
    s.pose = s.accepted;
    s.surface(x, v);
    r.worst_surface_gap = std::max(r.worst_surface_gap, (x - d.nodes).cwiseAbs().maxCoeff());
    fsi::shed_wake(m, d);
  }
  r.iterations = static_cast<double>(d.total_iterations) / steps;
  if (stall_retries) *stall_retries = d.stall_retries;
  return r;
}

TEST(FsiStructureInterface, AStructureOutsideMbdIsCoupledToItsFixedPoint) {
  // A plate of 10 mg (40 mm × 10 mm; the air's added mass ρ π c² b / 4 is 3.8 µg: a mass
  // ratio of 2600, well coupled) on a spring of 200 Hz in vacuum: the coupling must iterate,
  // and the accepted state must be the structure's answer to the loads of a lattice solved
  // within the tolerance of it (tolerance 1e-7 spans: the gap below 1e-7 × 40 mm).
  const double mass = 1e-5, stiffness = mass * std::pow(2.0 * std::numbers::pi * 200.0, 2);
  const double tolerance = 1e-7;
  const HeaveRun aitken = heave_run(mass, stiffness, fsi::CouplingMethod::Aitken, tolerance);
  EXPECT_GT(aitken.iterations, 2.0);  // it really iterated
  EXPECT_LE(aitken.worst_surface_gap, tolerance * 0.040 * (1.0 + 1e-9));
  double peak = 0.0;
  for (double h : aitken.h) peak = std::max(peak, std::abs(h));
  EXPECT_GT(peak, 1e-4);  // the air moved the plate (more than 0.1 mm; measured 0.59 mm)
  // IQN-ILS meets each step's fixed point as well, and the two histories agree to what the
  // tolerance lets accumulate over the cycle: a gap of 4 nm a step against a peak of 0.59 mm
  // (measured 2.3e-6 of the peak; 3.0 and 3.3 sub-iterations per step).
  const HeaveRun iqn = heave_run(mass, stiffness, fsi::CouplingMethod::InterfaceQuasiNewton, tolerance);
  EXPECT_LE(iqn.worst_surface_gap, tolerance * 0.040 * (1.0 + 1e-9));
  for (std::size_t n = 0; n < aitken.h.size(); ++n) EXPECT_NEAR(iqn.h[n], aitken.h[n], 1e-4 * peak) << "step " << n;
}

TEST(FsiStructureInterface, AStalledCouplingIsTriedAgainWithAFinerStructure) {
  // A structure whose answer jumps between two shapes (±10 µm, 2.5e-4 spans against the
  // tolerance of 1e-7) stalls the coupling of the first step: with a refinement to offer
  // (StructureData::refine_after_stall, the FEM's step in twice as many pieces) the step is
  // tried once more from its predictor and the run goes on, its states those of the structure
  // without jumps (within the tolerance's reach, as in the test above); with none the step
  // fails naming the stall.
  const double mass = 1e-5, stiffness = mass * std::pow(2.0 * std::numbers::pi * 200.0, 2);
  const double tolerance = 1e-7;
  const HeaveRun plain = heave_run(mass, stiffness, fsi::CouplingMethod::Aitken, tolerance);
  long retries = 0;
  const HeaveRun refined = heave_run(mass, stiffness, fsi::CouplingMethod::Aitken, tolerance, 1, &retries);
  EXPECT_EQ(retries, 1);
  // A step tried twice (its first retry stalls too) is one step retried: summary.json's
  // stalled_steps_retried counts steps (docs/fsi.md); it counted the tries (a film wing's
  // one stalled step read "2 steps stalled", 5 Dec).
  long twice = 0;
  heave_run(mass, stiffness, fsi::CouplingMethod::Aitken, tolerance, 2, &twice, false, 2);
  EXPECT_EQ(twice, 1);
  double peak = 0.0;
  for (double h : plain.h) peak = std::max(peak, std::abs(h));
  for (std::size_t n = 0; n < plain.h.size(); ++n) EXPECT_NEAR(refined.h[n], plain.h[n], 1e-4 * peak) << "step " << n;
  try {
    heave_run(mass, stiffness, fsi::CouplingMethod::Aitken, tolerance, 0);
    ADD_FAILURE() << "a stall with nothing finer to offer must fail";
  } catch (const NumericalFailure& e) {
    EXPECT_NE(std::string(e.what()).find("strong coupling did not converge"), std::string::npos) << e.what();
    EXPECT_FALSE(e.in_structure());  // the coupling's failure, not the structure's own solve
  }
}

TEST(FsiStructureInterface, AStructureWhoseOwnSolveFailsStopsTheStepSayingSo) {
  // The failure of the structure's own solve (a FEM step's Newton iterations) stops the
  // coupled step as a NumericalFailure that names the step and says it was the structure's
  // (in_structure()), which the run's message reads: only then does it speak of the FEM's
  // iterations (pipeline/app/flexibility_warnings.hpp, fem_motion_at_failure; the coupling's
  // failure of the test above is not).
  const double mass = 1e-5, stiffness = mass * std::pow(2.0 * std::numbers::pi * 200.0, 2);
  try {
    heave_run(mass, stiffness, fsi::CouplingMethod::Aitken, 1e-7, -1, nullptr, /*solve_fails=*/true);
    ADD_FAILURE() << "a structure whose solve fails must stop the step";
  } catch (const NumericalFailure& e) {
    EXPECT_TRUE(e.in_structure());
    EXPECT_EQ(e.step(), 0);
    EXPECT_NE(std::string(e.what()).find("heave plate: its solve failed"), std::string::npos) << e.what();
  }
}

}  // namespace
