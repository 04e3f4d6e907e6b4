// A sweep checks every case as `flapsim check` and `flapsim run` do, before any case runs.
// Before, pipeline/app/sweep/sweep_case.cpp read only the case and wing files: a sweep ran
// what run refuses and exited 0 with status=error rows: a broken --chain (a joint-stiffness
// matrix that is not positive semi-definite), a chain of another body count than the case's,
// frequency_hz = 1e-300 (no reference speed for the coefficients), and a --cases row of
// 1000 x 1000 panels (std::bad_alloc in the case; check refuses it at 1.6e4 GB). Now each
// stops the sweep with exit status 2 naming file, line and key, before anything is run or
// written (README.md, "Exit status"; docs/sweeps.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "sweep_test_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;

// A flexible 2-body plate (the tiny plate of sweep_test_helpers.hpp, 12 steps).
std::string flexible_plate(int bodies = 2) {
  std::string c = test::tiny_plate_case(12);
  c.replace(c.find("kind = \"rigid\""), 14, "kind = \"flexible\"\nbodies = " + std::to_string(bodies));
  return c;
}

// Two bodies, the first welded to the root; the springs of the one joint as a matrix.
std::string two_body_chain(const std::string& stiffness_rows) {
  const std::string inertia = "inertia = [[1e-10, 0, 0], [0, 1e-11, 0], [0, 0, 1e-10]]\n";
  return "root = \"rigid\"\njoint_stiffness = " + stiffness_rows +
         "\n[[bodies]]\nlength = 0.01\nmass = 1e-5\ncenter_of_mass = [0, 0.005, 0]\n" + inertia +
         "[[bodies]]\nlength = 0.01\nmass = 1e-5\ncenter_of_mass = [0, 0.005, 0]\n" + inertia;
}

// The sweep stopped before it ran or wrote anything.
void expect_nothing_run(const fs::path& out) {
  EXPECT_FALSE(fs::exists(out / "sweep.csv"));
  if (fs::exists(out))
    for (const auto& entry : fs::directory_iterator(out)) ADD_FAILURE() << "written: " << entry.path();
}

TEST(SweepCheckedLikeRun, ABrokenChainStopsTheSweepWithStatus2) {
  const test::ScratchDir dir("sweep_like_run_chain");
  std::ofstream(dir / "case.toml") << flexible_plate();
  // Eigenvalues 1e-3 and -1e-4: not positive semi-definite (mbd::ChainModel::validate).
  std::ofstream(dir / "chain.toml") << two_body_chain("[[1e-3, 0], [0, -1e-4]]");
  const std::string chain = (dir / "chain.toml").string();
  // run refuses it (the reference behaviour the sweep must match) ...
  const auto run = test::run_flapsim_capturing_stderr(
      dir.path(), "run " + (dir / "case.toml").string() + " --chain " + chain + " -o " + (dir / "run").string());
  EXPECT_EQ(run.status, 2) << run.err;
  // ... and so does the sweep, naming the chain file, its line and key.
  const auto sweep = test::run_flapsim_capturing_stderr(
      dir.path(), "sweep " + (dir / "case.toml").string() + " --chain " + chain +
                      " --vary kinematics.rotation_phase=0,0.1 -o " + (dir / "out").string());
  EXPECT_EQ(sweep.status, 2) << sweep.err;
  EXPECT_NE(sweep.err.find(chain + ":2: key 'joint_stiffness'"), std::string::npos) << sweep.err;
  expect_nothing_run(dir / "out");
}

TEST(SweepCheckedLikeRun, AChainOfAnotherBodyCountStopsTheSweepWithStatus2) {
  const test::ScratchDir dir("sweep_like_run_bodies");
  std::ofstream(dir / "case.toml") << flexible_plate(3);  // the chain has 2
  std::ofstream(dir / "chain.toml") << two_body_chain("[[1e-3, 0], [0, 1e-4]]");
  const auto sweep = test::run_flapsim_capturing_stderr(
      dir.path(), "sweep " + (dir / "case.toml").string() + " --chain " + (dir / "chain.toml").string() +
                      " --vary kinematics.rotation_phase=0,0.1 -o " + (dir / "out").string());
  EXPECT_EQ(sweep.status, 2) << sweep.err;
  // structure.bodies is on line 10 of the case (flexible_plate: kind on line 9).
  EXPECT_NE(sweep.err.find((dir / "case.toml").string() + ":10: key 'structure.bodies'"), std::string::npos)
      << sweep.err;
  EXPECT_NE(sweep.err.find("with kinematics.rotation_phase = 0:"), std::string::npos) << sweep.err;
  expect_nothing_run(dir / "out");
}

TEST(SweepCheckedLikeRun, AValueThatLeavesNoReferenceSpeedStopsTheSweepWithStatus2) {
  // At 1e-300 Hz the wing does not move within a cycle's time step resolution: the
  // cycle-mean speed at r2 R is 0 and, without a free stream, CL has no reference speed.
  const test::ScratchDir dir("sweep_like_run_frequency");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(12);
  const auto sweep = test::run_flapsim_capturing_stderr(
      dir.path(), "sweep " + (dir / "case.toml").string() + " --vary kinematics.frequency_hz=26.1,1e-300 -o " +
                      (dir / "out").string());
  EXPECT_EQ(sweep.status, 2) << sweep.err;
  EXPECT_NE(sweep.err.find("with kinematics.frequency_hz = 1e-300"), std::string::npos) << sweep.err;
  EXPECT_NE(sweep.err.find((dir / "case.toml").string() + ":"), std::string::npos) << sweep.err;
  expect_nothing_run(dir / "out");
}

TEST(SweepCheckedLikeRun, ARowTooLargeForTheMemoryIsRefusedAtItsLine) {
  // 1000 x 1000 panels: the dense influence matrix and its LU alone are 2 x (1e6)^2 x 8 B
  // = 1.6e13 B, more than any machine this runs on (app::refuse_if_it_cannot_fit).
  const test::ScratchDir dir("sweep_like_run_memory");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(12);
  std::ofstream(dir / "cases.csv") << "numerics.chordwise_panels,numerics.spanwise_panels\n3,4\n1000,1000\n";
  const auto sweep = test::run_flapsim_capturing_stderr(
      dir.path(), "sweep " + (dir / "case.toml").string() + " --cases " + (dir / "cases.csv").string() + " -o " +
                      (dir / "out").string());
  EXPECT_EQ(sweep.status, 2) << sweep.err;
  EXPECT_NE(sweep.err.find((dir / "cases.csv").string() + ":3: key 'numerics."), std::string::npos) << sweep.err;
  expect_nothing_run(dir / "out");
}

}  // namespace
