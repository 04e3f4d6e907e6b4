// flapsim optimize refuses a varied key that changes nothing in its runs, as flapsim sweep
// does (sweep/keys_that_change_nothing.hpp, optimize/bounds_check.hpp): exit 2, nothing
// written into -o DIR, the message naming the case file, the key and its bounds. Before,
// `--vary wing.mesh.element_size=LO:HI` of a FEM case whose structure.element_size_mm sets
// the mesh, and a key no run uses, ran the search on a flat objective; `--vary
// output.vtk_every=LO:HI` was refused as an integer key ("expected an integer"), not for
// what makes it useless: the optimisation's --vtk-every sets every run's series. Keys that
// reach the run stay accepted.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "app/stiff_plate_wing.hpp"
#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/optimize/bounds_check.hpp"
#include "sweep_test_helpers.hpp"
#include "wings/loader/input_error.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;

// The tiny flat plate case (sweep_test_helpers.hpp) flapping DIR/wing.toml: the shipped flat
// plate with a [surface] table whose twist is `twist_tip_deg` about the axis at 0.25.
std::string optimize_plate_case_with_surface(const test::ScratchDir& dir, double twist_tip_deg) {
  std::ifstream plate(std::string(FLAPSIM_SOURCE_DIR) + "/wings/flat_plate.toml");
  std::ofstream(dir / "wing.toml") << plate.rdbuf() << "[surface]\ntwist_tip_deg = " << twist_tip_deg
                                   << "\ntwist_axis = 0.25\n";
  std::string text = test::tiny_plate_case(12);
  const std::string shipped_wing = "\"" + std::string(FLAPSIM_SOURCE_DIR) + "/wings/flat_plate.toml\"";
  text.replace(text.find(shipped_wing), shipped_wing.size(), "\"wing.toml\"");
  const std::string case_file = (dir / "case.toml").string();
  std::ofstream(case_file) << text;
  return case_file;
}

// `flapsim optimize CASE OPTIONS --maximize mean_lift_N -o DIR/out`, its exit status and stderr.
test::FlapsimOutcome optimize_capturing_stderr(const test::ScratchDir& dir, const std::string& case_file,
                                               const std::string& options) {
  return test::run_flapsim_capturing_stderr(
      dir.path(),
      "optimize " + case_file + " " + options + " --maximize mean_lift_N -o " + (dir / "out").string());
}

// What optimize::check_start_and_bounds says of `bounds` on `case_file` ("" when accepted).
std::string refusal_of_bounds(const std::string& case_file, const std::vector<optimize::Bound>& bounds,
                              int vtk_every = 0) {
  const optimize::PointEvaluator evaluator(sweep::SweepInputs{case_file, "", 1.0, ""},
                                           optimize::EvaluatorOptions{});
  optimize::Problem problem;
  problem.bounds = bounds;
  std::vector<double> start;
  for (const optimize::Bound& b : bounds) start.push_back(b.lo);
  try {
    optimize::check_start_and_bounds(evaluator, problem, start, vtk_every);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// The FEM case's structure.element_size_mm sets the mesh: the wing's mesh size changes
// nothing, and the message says which key of the case (and its line) sets it instead.
TEST(OptimizeKeysThatChangeNothing, AWingMeshSizeTheFemCaseSetsExitsTwoWithNothingWritten) {
  const test::ScratchDir dir("optimize_unused_mesh_size");
  std::ofstream(dir / "wing.toml") << test::kStiffPlateWing;
  const std::string case_file = (dir / "case.toml").string();
  std::ofstream(case_file) << test::stiff_fem_plate_case("element_size_mm = 2.5\n");
  const test::FlapsimOutcome out =
      optimize_capturing_stderr(dir, case_file, "--vary wing.mesh.element_size=2.5:3");
  EXPECT_EQ(out.status, 2) << out.err;  // bad input (pipeline/app/cli/exit_status.hpp)
  const std::string expected =
      case_file +
      ": key 'wing.mesh.element_size': --vary wing.mesh.element_size=2.5:3: the case's "
      "structure.element_size_mm (" +
      case_file +
      " line 10) sets the FEM's mesh, so the varied values change nothing; vary "
      "structure.element_size_mm instead";
  EXPECT_NE(out.err.find(expected), std::string::npos) << out.err;
  EXPECT_FALSE(fs::exists(dir / "out"));  // nothing run, nothing written

  // Without the case's own size the wing file's sizes the FEM's mesh: accepted.
  std::ofstream(case_file) << test::stiff_fem_plate_case("");
  EXPECT_EQ(refusal_of_bounds(case_file, {{"wing.mesh.element_size", 2.5, 3.0}}), "");
}

// output.vtk_every: the optimisation's --vtk-every (0 when not given) sets every run's series;
// the message says so before the key's inner value is refused as that of an integer key.
TEST(OptimizeKeysThatChangeNothing, AParaViewIntervalTheOptimisationSetsExitsTwo) {
  const test::ScratchDir dir("optimize_unused_vtk_every");
  const std::string case_file = (dir / "case.toml").string();
  std::ofstream(case_file) << test::tiny_plate_case(12);
  const test::FlapsimOutcome out =
      optimize_capturing_stderr(dir, case_file, "--vary output.vtk_every=1:5 --vtk-every 3");
  EXPECT_EQ(out.status, 2) << out.err;
  EXPECT_NE(out.err.find(case_file +
                         ": key 'output.vtk_every': --vary output.vtk_every=1:5: the optimisation's "
                         "--vtk-every 3 sets every case's ParaView series in place of the case's, so the "
                         "varied values change nothing; give the optimisation --vtk-every N instead"),
            std::string::npos)
      << out.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
  // Not given, the option is 0 (no series), and says so.
  EXPECT_NE(refusal_of_bounds(case_file, {{"output.vtk_every", 1.0, 5.0}})
                .find("the optimisation's --vtk-every (0 when not given: no series) sets every case's"),
            std::string::npos);
}

// The axis of a twist that is zero: the bounds, the inner value and the start give the same
// inputs hash, so the objective would be flat. With a twist the axis moves the lattice.
TEST(OptimizeKeysThatChangeNothing, AKeyThatReachesNoInputExitsTwoUnlessItDoes) {
  const test::ScratchDir dir("optimize_unused_twist_axis");
  const std::string case_file = optimize_plate_case_with_surface(dir, 0.0);
  const test::FlapsimOutcome out =
      optimize_capturing_stderr(dir, case_file, "--vary wing.surface.twist_axis=0.25:0.5");
  EXPECT_EQ(out.status, 2) << out.err;
  EXPECT_NE(
      out.err.find(case_file + ": key 'wing.surface.twist_axis': --vary wing.surface.twist_axis=0.25:0.5: "
                               "every value gives the same inputs"),
      std::string::npos)
      << out.err;
  EXPECT_NE(out.err.find("drop it from the optimisation"), std::string::npos) << out.err;
  EXPECT_FALSE(fs::exists(dir / "out"));

  // Beside a key that reaches the run, the one that does not is still named.
  EXPECT_NE(refusal_of_bounds(
                case_file, {{"kinematics.rotation_phase", -0.1, 0.1}, {"wing.surface.twist_axis", 0.25, 0.5}})
                .find("key 'wing.surface.twist_axis'"),
            std::string::npos);
  // A twist of 5 degrees: the axis moves the lattice, accepted.
  const std::string twisted = optimize_plate_case_with_surface(dir, 5.0);
  EXPECT_EQ(refusal_of_bounds(twisted, {{"wing.surface.twist_axis", 0.25, 0.5}}), "");
}

// The joint springs' factor of a rigid case: the case has no springs, but the inputs hash
// counts the factor, so the same-inputs rule did not see it, and the optimisation ran 7
// equal runs (mean lift the same to the last digit) and wrote an optimum of a flat objective.
TEST(OptimizeKeysThatChangeNothing, TheSpringFactorOfARigidCaseExitsTwo) {
  const test::ScratchDir dir("optimize_unused_spring_scale");
  const std::string case_file = (dir / "case.toml").string();
  std::ofstream(case_file) << test::tiny_plate_case(12);  // kind = "rigid"
  const test::FlapsimOutcome out = optimize_capturing_stderr(dir, case_file, "--vary spring_scale=0.5:2");
  EXPECT_EQ(out.status, 2) << out.err;
  EXPECT_NE(out.err.find(case_file + ": key 'spring_scale': --vary spring_scale=0.5:2: the case's "
                                     "structure.kind = \"rigid\""),
            std::string::npos)
      << out.err;
  EXPECT_NE(out.err.find("has no joint springs to scale, so the varied values change nothing"),
            std::string::npos)
      << out.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
  // Of a flexible case the factor scales its springs: accepted.
  std::string flexible = test::tiny_plate_case(12);
  flexible.replace(flexible.find("kind = \"rigid\""), 14, "kind = \"flexible\"\nbodies = 2");
  std::ofstream(case_file) << flexible;
  EXPECT_EQ(refusal_of_bounds(case_file, {{"spring_scale", 1.0, 2.0}}), "");
}

// Keys that set an input of the run are accepted (docs/optimize.md; the searches of the
// other optimize tests run them).
TEST(OptimizeKeysThatChangeNothing, KeysThatReachTheRunAreAccepted) {
  const test::ScratchDir dir("optimize_used_keys");
  const std::string case_file = (dir / "case.toml").string();
  std::ofstream(case_file) << test::tiny_plate_case(12);
  EXPECT_EQ(refusal_of_bounds(case_file, {{"kinematics.rotation_phase", -0.1, 0.1}}), "");
  EXPECT_EQ(refusal_of_bounds(case_file, {{"kinematics.sweep.cos_deg[0]", 40.0, 50.0}}), "");
  EXPECT_EQ(refusal_of_bounds(case_file, {{"wing.membrane.thickness", 0.1, 0.2}}),
            "");  // a rigid wing's mass
}

}  // namespace
