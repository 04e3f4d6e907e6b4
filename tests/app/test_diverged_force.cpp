// A run whose aerodynamic force leaves every physical range stops as diverged, exit status 3
// (pipeline/app/diverged_force.hpp; docs/fsi.md, "Failures"), while a wing started
// impulsively in moving air, whose first step carries an impulse that grows as 1/Δt, runs on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <regex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "flat_plate_glide.hpp"
#include "history_csv.hpp"
#include "shipped_case_text.hpp"
#include "pipeline/app/diverged_force.hpp"
#include "pipeline/fsi/numerical_failure.hpp"
#include <Eigen/Geometry>

namespace {

using flapsim::test::read_text;

// The four corners of a 10 mm × 40 mm rectangle, leading edge at x = 2.5 mm, root on y = 0.
Eigen::Matrix3Xd corners_of_a_flat_plate() {
  Eigen::Matrix3Xd x(3, 4);
  x << 2.5e-3, 2.5e-3, -7.5e-3, -7.5e-3, 0.0, 40e-3, 40e-3, 0.0, 0.0, 0.0, 0.0, 0.0;
  return x;
}

TEST(DivergedForce, TheFastestPointIsTheFarthestCornerAtTheFastestInstant) {
  // Sweep φ(t) = Φ sin(2πft) about z: ω_max = 2πfΦ at t = 0 (a sampled instant), and the
  // farthest corner from the pivot is (−7.5, 40) mm: U_b = ω_max √(7.5² + 40²) mm.
  const double f = 25.0, amplitude = 1.0, T = 1.0 / f;
  const flapsim::mbd::BaseMotion sweep = [&](double t) {
    flapsim::mbd::BasePose p;
    const double phi = amplitude * std::sin(2 * std::numbers::pi * f * t);
    p.rotation = Eigen::AngleAxisd(phi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    p.angular_velocity = {0.0, 0.0, 2 * std::numbers::pi * f * amplitude * std::cos(2 * std::numbers::pi * f * t)};
    return p;
  };
  const double expected = 2 * std::numbers::pi * f * amplitude * std::hypot(7.5e-3, 40e-3);
  EXPECT_NEAR(flapsim::app::fastest_wing_point_speed(sweep, T, corners_of_a_flat_plate(), Eigen::Vector3d::Zero()), expected,
              1e-12 * expected);
  // A wing held still in U∞ and one translating at v through still air: |U∞ − v|.
  const flapsim::mbd::BaseMotion still = [](double) { return flapsim::mbd::BasePose{}; };
  EXPECT_DOUBLE_EQ(flapsim::app::fastest_wing_point_speed(still, T, corners_of_a_flat_plate(), {-5.0, 0.0, 0.0}), 5.0);
  const flapsim::mbd::BaseMotion moving = [](double) {
    flapsim::mbd::BasePose p;
    p.velocity = {3.0, 4.0, 0.0};
    return p;
  };
  EXPECT_DOUBLE_EQ(flapsim::app::fastest_wing_point_speed(moving, T, corners_of_a_flat_plate(), Eigen::Vector3d::Zero()), 5.0);
}

// A wing revolving ever faster (a ramp longer than the run's first period): its fastest
// speed is the last period's, Ω(t_end) times the farthest node's radius, not the first's.
TEST(DivergedForce, ARevolutionThatSpeedsUpIsSampledOverTheRunsLastPeriod) {
  const double T = 0.25, ramp = 2.0, omega = 2 * std::numbers::pi;  // s, s, rad/s
  const flapsim::mbd::BaseMotion speeding_up = [&](double t) {
    flapsim::mbd::BasePose p;
    const double rate = omega * std::min(1.0, t / ramp);
    p.angular_velocity = {0.0, 0.0, rate};
    return p;
  };
  const double radius = std::hypot(7.5e-3, 40e-3);  // m, the plate's farthest corner
  const double first = flapsim::app::fastest_wing_point_speed(speeding_up, T, corners_of_a_flat_plate(),
                                                              Eigen::Vector3d::Zero());
  EXPECT_LT(first, 0.13 * omega * radius);  // at most Ω T / ramp of the final speed
  // A run of 8 periods (2 s): the last instant sampled is 2 − T/400 s.
  const double whole = flapsim::app::fastest_wing_point_speed(speeding_up, T, corners_of_a_flat_plate(),
                                                              Eigen::Vector3d::Zero(), 400, 8 * T);
  EXPECT_NEAR(whole, omega * radius * (1.0 - T / 400 / ramp), 1e-12);
}

// The added-mass part of the bound: a wing that accelerates from rest. A plate turning
// about z with ω̇ = 10 rad/s² at ω = 0: its farthest corner accelerates at ω̇ r; the bound
// adds 20 (π/4) ρ c̄ a_b S to 20 ½ ρ U_b² S.
TEST(DivergedForce, AWingAcceleratingFromRestHasTheBoundOfItsAddedMass) {
  const flapsim::mbd::BaseMotion starting = [](double) {
    flapsim::mbd::BasePose p;
    p.angular_acceleration = {0.0, 0.0, 10.0};
    return p;
  };
  const double radius = std::hypot(7.5e-3, 40e-3);  // m
  const double a = flapsim::app::fastest_wing_point_acceleration(starting, 0.04, corners_of_a_flat_plate());
  EXPECT_NEAR(a, 10.0 * radius, 1e-12);
  const double rho = 1.225, area = 4e-4, chord = 0.01;
  EXPECT_NEAR(flapsim::app::diverged_force_limit(rho, 0.0, area, a, chord),
              20.0 * std::numbers::pi / 4 * rho * chord * a * area, 1e-18);
  EXPECT_EQ(flapsim::app::diverged_force_limit(rho, 4.0, area),
            flapsim::app::diverged_force_limit(rho, 4.0, area, 0.0, chord));
}

TEST(DivergedForce, AForceBeyondTheLimitIsAFailureOfItsStep) {
  // limit = 20 · ½ ρ U_b² S (diverged_force.hpp): 20 · 0.5 · 1.225 · 4² · 4e-4 = 0.0784 N.
  const double limit = flapsim::app::diverged_force_limit(1.225, 4.0, 4e-4);
  EXPECT_NEAR(limit, 0.0784, 1e-15);
  EXPECT_NO_THROW(flapsim::app::throw_if_force_diverged({0.0, 0.0, 0.99 * limit}, limit, 41, 0.1));
  try {
    flapsim::app::throw_if_force_diverged({0.6 * limit, 0.0, -0.9 * limit}, limit, 41, 0.1);  // |F| = 1.08 limit
    ADD_FAILURE() << "no failure at 1.08 times the limit";
  } catch (const flapsim::NumericalFailure& e) {
    EXPECT_EQ(e.step(), 41);
    EXPECT_NE(std::string(e.what()).find("the lattice has diverged"), std::string::npos) << e.what();
  }
}

TEST(DivergedForce, TheRigidHoverWithAShedLeadingEdgeStopsWhereItsLiftRunsAway) {
  // cases/bench_hover.toml (the rigid hawkmoth hover, free wake, 3 cycles of 100 steps) with
  // leading_edge = "shed": its sheet comes apart in the third wingbeat, where the lift ran
  // from the hover's ±10 mN to 20 N by step 280 and the run ended "ok" with a mean lift of
  // 498 mN (28 Nov). It must stop, exit status 3, at the first step whose force exceeds
  // 20 ½ρU_b²S (0.475 N for this wing and motion), with history.csv valid up to it.
  flapsim::test::ScratchDir dir("diverged_shed_hover");
  std::string toml = flapsim::test::shipped_case_text("bench_hover");
  // The sheet unmerged (sheet_merge_steps = 0, the default before 29 Nov): merged from 8
  // steps old (the default now) the same hover runs its 3 wingbeats through and comes apart
  // in the fourth (step 341 of 600, docs/uvlm.md, "Merging the sheet's older rings").
  toml = std::regex_replace(toml, std::regex("\\[numerics\\]\n"), "[numerics]\nleading_edge = \"shed\"\nsheet_merge_steps = 0\n");
  ASSERT_NE(toml.find("leading_edge = \"shed\""), std::string::npos);
  std::ofstream(dir / "case.toml") << toml;
  const auto outcome =
      flapsim::test::run_flapsim_capturing_stderr(dir.path(), "run " + (dir / "case.toml").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(outcome.status, 3) << outcome.err;
  EXPECT_NE(outcome.err.find("the lattice has diverged"), std::string::npos) << outcome.err;
  // and says what to change (diverged_lattice_advice; the next test shows the advice holds here)
  EXPECT_NE(outcome.err.find("numerics.sheet_core_radius = 0.5 keeps it together"), std::string::npos)
      << outcome.err;
  EXPECT_NE(read_text(dir / "out" / "summary.json").find("\"status\": \"failed\""), std::string::npos);
  // history.csv holds every step before the failing one (the step the message names; until
  // 2 Dec the failing step too, its force in summary.json's means), which is after the first
  // wingbeat; its force (the message's) is a runaway: over 10 times the largest of the first
  // wingbeat (the hover's own forces, 32 mN at most; the sheet's lift already grows through
  // the second), and above every step before it. Which step is a matter of
  // round-off once the sheet comes apart: 202 with the sheet summed in double precision,
  // 192 in the wake's single precision (28 Nov, night); the wingbeat frequency changed by
  // 4e-12…4e-10 of itself gave 166–298 (every build gives the same bits on every x86-64
  // CPU, so the test is not flaky, but the step is no physical quantity to assert).
  const flapsim::test::HistoryCsv h = flapsim::test::read_history_csv(dir / "out" / "history.csv");
  const std::size_t named = outcome.err.find("numerical failure: step ");
  ASSERT_NE(named, std::string::npos) << outcome.err;
  const std::size_t failed = std::stoul(outcome.err.substr(named + std::string("numerical failure: step ").size()));
  EXPECT_EQ(h.rows.size() + 1, failed);
  EXPECT_EQ(read_text(dir / "out" / "summary.json").find("\"steps\": " + std::to_string(failed) + ","),
            std::string::npos);
  EXPECT_NE(read_text(dir / "out" / "summary.json").find("\"steps\": " + std::to_string(failed - 1) + ","),
            std::string::npos);
  ASSERT_GT(h.rows.size(), 100u);
  EXPECT_LT(h.rows.size(), 300u);
  const std::size_t reached = outcome.err.find("the aerodynamic force reached ");
  ASSERT_NE(reached, std::string::npos) << outcome.err;
  const double diverged =
      std::stod(outcome.err.substr(reached + std::string("the aerodynamic force reached ").size()));
  const auto fx = h.column("Fx_N"), fy = h.column("Fy_N"), fz = h.column("Fz_N");
  auto force = [&](std::size_t k) { return std::sqrt(fx[k] * fx[k] + fy[k] * fy[k] + fz[k] * fz[k]); };
  double first = 0.0, before = 0.0;  // largest |F| of steps 1–100, and of all before the failing one
  for (std::size_t k = 0; k < fx.size(); ++k) {
    before = std::max(before, force(k));
    if (k < 100) first = std::max(first, force(k));
  }
  EXPECT_GT(diverged, 10.0 * first);
  EXPECT_GT(diverged, before);
}

// A run that fails within a step (here the loads of a rotation that jumps by 90° between two
// spline knots 1e-16 of a cycle apart are not finite at step 2): summary.json's time_s is the
// last recorded step's, as history.csv's last t_s, and its means' window ends there. The
// failed step had moved the structure's clock on: time_s was step 2's time after 1 step, and
// mean_window_cycles counted it (2 against 1 step of 24).
TEST(DivergedForce, AFailedRunsSummaryEndsAtItsLastRecordedStep) {
  flapsim::test::ScratchDir dir("failed_run_time");
  std::ofstream(dir / "case.toml")
      << "name = \"jump\"\nwing = \"" << FLAPSIM_SOURCE_DIR << "/wings/flat_plate.toml\"\n"
      << "[kinematics]\nfrequency_hz = 26.1\nsweep = { mean_deg = 10.0, cos_deg = [50.0] }\n"
      << "rotation = { phase = [0.0, 0.5, 0.5000000000000001, 0.75], deg = [90.0, 45.0, 135.0, 100.0] }\n"
      << "[structure]\nkind = \"rigid\"\n"
      << "[numerics]\nsteps_per_cycle = 24\ncycles = 1\nchordwise_panels = 3\nspanwise_panels = 4\n"
      << "[output]\nvtk_every = 0\n";
  const auto outcome = flapsim::test::run_flapsim_capturing_stderr(
      dir.path(), "run " + (dir / "case.toml").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(outcome.status, 3) << outcome.err;
  const flapsim::test::HistoryCsv h = flapsim::test::read_history_csv(dir / "out" / "history.csv");
  ASSERT_FALSE(h.rows.empty());
  const std::string summary = read_text(dir / "out" / "summary.json");
  EXPECT_EQ(flapsim::test::json_number(summary, "steps"), static_cast<double>(h.rows.size()));
  EXPECT_EQ(flapsim::test::json_number(summary, "time_s"), h.column("t_s").back());
  EXPECT_NEAR(flapsim::test::json_number(summary, "mean_window_cycles"), h.rows.size() / 24.0, 1e-12);
}

TEST(DivergedForce, WithTheSheetsCoreTheAdviceNamesTheSameHoverRunsThrough) {
  // The hover of the test above with numerics.sheet_core_radius = 0.5, what the failure's
  // advice names: its 3 wingbeats run through (1 Dec: last-wingbeat mean CL 2.500), and the
  // lift lies between the same case's with "none" and "separated" (2.077 and 2.791, measured
  // 1 Dec; the two models that bracket a leading-edge vortex's lift, docs/uvlm.md, "Leading
  // edge: validation and the default").
  flapsim::test::ScratchDir dir("shed_hover_half_chord_sheet_core");
  std::string toml = flapsim::test::shipped_case_text("bench_hover");
  toml = std::regex_replace(
      toml, std::regex("\\[numerics\\]\n"),
      "[numerics]\nleading_edge = \"shed\"\nsheet_merge_steps = 0\nsheet_core_radius = 0.5\n");
  ASSERT_NE(toml.find("sheet_core_radius = 0.5"), std::string::npos);
  std::ofstream(dir / "case.toml") << toml;
  const auto outcome = flapsim::test::run_flapsim_capturing_stderr(
      dir.path(), "run " + (dir / "case.toml").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const std::string summary = read_text(dir / "out" / "summary.json");
  const std::smatch cl = [&] {
    std::smatch m;
    std::regex_search(summary, m, std::regex("\"mean_CL\": ([-0-9.e+]+)"));
    return m;
  }();
  ASSERT_EQ(cl.size(), 2u) << summary;
  EXPECT_GT(std::stod(cl[1]), 2.077);
  EXPECT_LT(std::stod(cl[1]), 2.791);
}

// cases/hover_flexible.toml (its chain reduced in process from wings/hawkmoth.toml) in a
// 3 m/s forward flight, with leading_edge = "shed" and the leading-edge sheet in the wake's
// core, or in half a mean chord.
std::string shed_forward_flight_case(bool half_chord_sheet_core) {
  std::string toml = flapsim::test::shipped_case_text("hover_flexible");
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"freestream = [0.0, 0.0, 0.0]", "freestream = [-3.0, 0.0, 0.0]"},
        {"vtk_every = 2", "vtk_every = 0"},
        {"[numerics]\n", std::string("[numerics]\nleading_edge = \"shed\"\n") +
                             (half_chord_sheet_core ? "sheet_core_radius = 0.5\n" : "")}}) {
    const auto at = toml.find(from);
    if (at == std::string::npos)
      throw std::runtime_error("cases/hover_flexible.toml has changed: no " + from);
    toml.replace(at, from.size(), to);
  }
  return toml;
}

TEST(DivergedForce, AShedForwardFlightWhoseCouplingFailsNamesTheSheetsJumpsAndWhatToChange) {
  // The flexible hover in forward flight with "shed" (1 Dec): its per-step C_L (on the 3 m/s
  // free stream) jumps by 10–80 from the second wingbeat on, where with "separated" it moves by
  // 0.8 at most; the chain, driven by it, bends its tip by 117° and the coupling stops at step
  // 190 of 300 with C_L at most 87, under the force bound of 20 ½ρU_b²S, so the failure is
  // the coupling's, whose message named only the chain's range and the FEM. It must also name the lift's
  // jumps and the sheet's core; with that core (half a mean chord) the same flight runs its 3 wingbeats
  // through.
  flapsim::test::ScratchDir dir("shed_forward_flight");
  std::ofstream(dir / "narrow.toml") << shed_forward_flight_case(false);
  std::ofstream(dir / "wide.toml") << shed_forward_flight_case(true);
  const auto narrow = flapsim::test::run_flapsim_capturing_stderr(
      dir.path(), "run " + (dir / "narrow.toml").string() + " -o " + (dir / "narrow").string());
  EXPECT_EQ(narrow.status, 3) << narrow.err;
  EXPECT_NE(narrow.err.find("strong coupling did not converge"), std::string::npos) << narrow.err;
  const std::regex jump(
      "With leading_edge = \"shed\" the lift coefficient changed by up to ([0-9.e+]+) from one "
      "step to the next \\(into step ([0-9]+);");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(narrow.err, m, jump)) << narrow.err;
  EXPECT_NE(narrow.err.find("numerics.sheet_core_radius = 0.5 keeps it together"), std::string::npos)
      << narrow.err;
  // The jump it quotes is history.csv's: the largest change of CL between two of its rows.
  const std::vector<double> cl = flapsim::test::read_history_csv(dir / "narrow" / "history.csv").column("CL");
  double largest = 0.0;
  std::size_t into = 0;
  for (std::size_t k = 1; k < cl.size(); ++k)
    if (std::abs(cl[k] - cl[k - 1]) > largest) largest = std::abs(cl[k] - cl[k - 1]), into = k + 1;
  EXPECT_NEAR(std::stod(m[1]), largest, 1e-3 * largest);
  EXPECT_EQ(std::stoul(m[2]), into);
  EXPECT_GT(largest, 10.0);  // the sheet's jumps, an order above the flight's own (0.8 with "separated")
  const auto wide = flapsim::test::run_flapsim_capturing_stderr(
      dir.path(), "run " + (dir / "wide.toml").string() + " -o " + (dir / "wide").string());
  EXPECT_EQ(wide.status, 0) << wide.err;
}

TEST(DivergedForce, TheAdviceNamesTheSheetsCoreOnlyWhereItIsNarrow) {
  // diverged_lattice_advice: nothing for the models that shed no sheet; with "shed", the lift's
  // largest step-to-step change as evidence, the
  // sheet's core at half a mean chord while it is narrower (sheet_core_radius, or else
  // core_radius, in mean chords), and "separated" in every case.
  flapsim::io::Case::Numerics n;
  for (auto model : {flapsim::uvlm::LeadingEdge::None, flapsim::uvlm::LeadingEdge::Attached,
                     flapsim::uvlm::LeadingEdge::Separated}) {
    n.leading_edge = model;
    EXPECT_EQ(flapsim::app::diverged_lattice_advice(n, {12.5, 40}, 45), "");
  }
  n.leading_edge = flapsim::uvlm::LeadingEdge::Shed;
  auto names_core = [&] {
    const std::string a = flapsim::app::diverged_lattice_advice(n, {12.5, 40}, 45);
    EXPECT_NE(a.find("leading_edge = \"separated\""), std::string::npos) << a;
    // the evidence it quotes: the largest step-to-step change of C_L and where
    EXPECT_NE(a.find("changed by up to 12.5 from one step to the next (into step 40"), std::string::npos)
        << a;
    return a.find("sheet_core_radius = 0.5") != std::string::npos;
  };
  n.core_radius = 0.2;
  n.sheet_core_radius = 0.0;  // the wake's 0.2
  EXPECT_TRUE(names_core());
  n.sheet_core_radius = 0.3;
  EXPECT_TRUE(names_core());
  n.sheet_core_radius = 0.5;
  EXPECT_FALSE(names_core());
  n.sheet_core_radius = 0.0;
  n.core_radius = 0.6;  // the wake's, wider already
  EXPECT_FALSE(names_core());
  // A run stopped at its second step has no two steps to compare: no jump is quoted (it said
  // "changed by up to 0 ... (into step 0", of a step that does not exist).
  // A jump into the step that failed (measured, in no output): said to be that step's, with
  // where history.csv ends (it said "into step 113; history.csv CL" of a history of 112 steps).
  const std::string failed = flapsim::app::diverged_lattice_advice(n, {187.0, 113}, 112);
  EXPECT_NE(
      failed.find("changed by up to 187 from one step to the next (into step 113, the step that failed: "
                  "its lift is in no output, history.csv ends at step 112)"),
      std::string::npos)
      << failed;
  const std::string early = flapsim::app::diverged_lattice_advice(n, {}, 1);
  EXPECT_EQ(early.find("into step"), std::string::npos) << early;
  EXPECT_NE(early.find("before two steps could be compared"), std::string::npos) << early;
  EXPECT_NE(early.find("leading_edge = \"separated\""), std::string::npos) << early;
}

TEST(DivergedForce, AnImpulsiveStartInAFreeStreamRunsOn) {
  // wings/flat_plate.toml at 45° started in U∞ = 5 m/s: at 16 steps a chord (UΔt = 0.625 mm)
  // its first step carries C_F = 19 on U∞ (ρ ∂Γ/∂t of the impulsive start, growing as 1/Δt),
  // its second 3.4; at 64 steps a chord (here) 72 and 3.0, the first beyond the limit's 20.
  // The check starts at the second step, so the run ends ok.
  flapsim::test::ScratchDir dir("impulsive_start_runs_on");
  std::ofstream(dir / "case.toml") << flapsim::test::flat_plate_glide_case("start", 200.0, 45.0, 160, 1);
  const auto outcome =
      flapsim::test::run_flapsim_capturing_stderr(dir.path(), "run " + (dir / "case.toml").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  // The first step's force is beyond the limit indeed (else this test shows nothing).
  const double cl = flapsim::test::read_history_csv(dir / "out" / "history.csv").at(1, "CL");
  EXPECT_GT(std::abs(cl), 20.0) << "the first step's C_L on U∞ (= U_b here)";
}

}  // namespace
