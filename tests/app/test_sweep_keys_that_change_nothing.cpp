// A varied key that changes nothing in the runs is refused before any case runs: exit 2,
// nothing written into -o DIR, the message naming the key, its values and what sets what it
// would set (sweep/keys_that_change_nothing.hpp). Before: `--vary wing.mesh.element_size=...`
// of a FEM case whose structure.element_size_mm sets the mesh, and `--vary
// output.vtk_every=...` beside the sweep's --vtk-every, ran every case and gave identical
// rows. Sweeps of keys that reach the run stay accepted.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/stiff_plate_wing.hpp"
#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/sweep/keys_that_change_nothing.hpp"
#include "pipeline/app/sweep/sweep_runner.hpp"
#include "sweep_test_helpers.hpp"
#include "wings/loader/input_error.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;

// What refuse_keys_that_change_nothing says of the grid of `variations` on `case_file`, as
// run_sweep resolves it ("" when the sweep is accepted).
std::string refusal_of_grid(const std::string& case_file, const std::vector<sweep::Variation>& variations,
                            int vtk_every = 0) {
  const sweep::SweepInputs inputs{case_file, "", 1.0, ""};
  const sweep::SweepPlan plan = sweep::grid_plan(variations);
  std::vector<sweep::ResolvedCase> cases;
  for (const sweep::CasePoint& point : plan.points) cases.push_back(sweep::resolve_case(inputs, point));
  try {
    sweep::refuse_keys_that_change_nothing(inputs, plan, cases, vtk_every);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SweepKeysThatChangeNothing, AWingMeshSizeTheFemCaseSetsIsRefusedBeforeAnyCaseRuns) {
  const test::ScratchDir dir("sweep_unused_mesh_size");
  std::ofstream(dir / "wing.toml") << test::kStiffPlateWing;
  const std::string case_file = (dir / "case.toml").string();
  std::ofstream(case_file) << test::stiff_fem_plate_case("element_size_mm = 2.5\n");
  const test::FlapsimOutcome out = test::run_flapsim_capturing_stderr(
      dir.path(), "sweep " + case_file + " --vary wing.mesh.element_size=2.5,3 -o " + (dir / "out").string());
  EXPECT_EQ(out.status, 2) << out.err;  // bad input (pipeline/app/cli/exit_status.hpp)
  // The key, its values, and the case's key on the line after kind = "fem" (line 10).
  const std::string expected = case_file +
                               ": key 'wing.mesh.element_size': --vary wing.mesh.element_size = 2.5, 3: "
                               "the case's structure.element_size_mm (" +
                               case_file +
                               " line 10) sets the FEM's mesh, so the varied values change nothing; vary "
                               "structure.element_size_mm instead";
  EXPECT_NE(out.err.find(expected), std::string::npos) << out.err;
  EXPECT_FALSE(fs::exists(dir / "out"));  // nothing run, nothing written

  // Without the case's own size the wing file's sizes the FEM's mesh: accepted.
  std::ofstream(case_file) << test::stiff_fem_plate_case("");
  EXPECT_EQ(refusal_of_grid(case_file, {{"wing.mesh.element_size", {2.5, 3.0}}}), "");
}

TEST(SweepKeysThatChangeNothing, AParaViewIntervalTheSweepSetsIsRefusedForVaryAndTables) {
  const test::ScratchDir dir("sweep_unused_vtk_every");
  const std::string case_file = (dir / "case.toml").string();
  std::ofstream(case_file) << test::tiny_plate_case(12);
  const test::FlapsimOutcome vary = test::run_flapsim_capturing_stderr(
      dir.path(),
      "sweep " + case_file + " --vary output.vtk_every=1,5 --vtk-every 3 -o " + (dir / "out").string());
  EXPECT_EQ(vary.status, 2) << vary.err;  // bad input
  // The option's value as given (3), the key and its values.
  EXPECT_NE(
      vary.err.find(case_file + ": key 'output.vtk_every': --vary output.vtk_every = 1, 5: the sweep's "
                                "--vtk-every 3 sets every case's ParaView series in place of the case's, so "
                                "the varied values change nothing; give the sweep --vtk-every N instead"),
      std::string::npos)
      << vary.err;
  EXPECT_FALSE(fs::exists(dir / "out"));

  // A case table's column, named at the table's header (line 1), the option not given.
  std::ofstream(dir / "table.csv") << "output.vtk_every\n1\n5\n";
  const test::FlapsimOutcome table = test::run_flapsim_capturing_stderr(
      dir.path(),
      "sweep " + case_file + " --cases " + (dir / "table.csv").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(table.status, 2) << table.err;
  EXPECT_NE(
      table.err.find("table.csv:1: key 'output.vtk_every': the column's values 1, 5: the sweep's --vtk-every "
                     "(0 when not given: no series) sets every case's ParaView series"),
      std::string::npos)
      << table.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(SweepKeysThatChangeNothing, AKeyThatReachesNoInputIsRefusedUnlessItDoesForSomePoints) {
  const test::ScratchDir dir("sweep_unused_twist_axis");
  // The flat plate with a [surface] table that shapes nothing: no twist, camber or dihedral.
  std::ifstream plate(std::string(FLAPSIM_SOURCE_DIR) + "/wings/flat_plate.toml");
  std::ofstream(dir / "wing.toml") << plate.rdbuf() << "[surface]\ntwist_tip_deg = 0.0\ntwist_axis = 0.25\n";
  std::string text = test::tiny_plate_case(12);
  const std::string shipped_wing = "\"" + std::string(FLAPSIM_SOURCE_DIR) + "/wings/flat_plate.toml\"";
  text.replace(text.find(shipped_wing), shipped_wing.size(), "\"wing.toml\"");
  const std::string case_file = (dir / "case.toml").string();
  std::ofstream(case_file) << text;

  // The axis of a twist that is zero: both values give the same inputs (io::input_hash leaves
  // a flat surface's fields out), so the rows would be the same numbers.
  const std::string e = refusal_of_grid(case_file, {{"wing.surface.twist_axis", {0.25, 0.5}}});
  EXPECT_NE(
      e.find("key 'wing.surface.twist_axis': --vary wing.surface.twist_axis = 0.25, 0.5: every value gives "
             "the same inputs"),
      std::string::npos)
      << e;
  EXPECT_NE(e.find("drop it from the sweep"), std::string::npos) << e;
  // With a twist of 5 degrees for half the grid the axis moves the lattice there: accepted.
  EXPECT_EQ(refusal_of_grid(case_file, {{"wing.surface.twist_tip_deg", {0.0, 5.0}},
                                        {"wing.surface.twist_axis", {0.25, 0.5}}}),
            "");
}

// The clamp line of a rigid wing (the wing's FEM is not built): every value the same run.
// Until 3 Dec the inputs hash held it and `--vary wing.planform.clamp_y=1,2,3` on a rigid
// case ran three bit-identical cases (docs/sweeps.md promised the refusal).
TEST(SweepKeysThatChangeNothing, ARigidWingsClampLineIsRefused) {
  const test::ScratchDir dir("sweep_rigid_clamp");
  const std::string case_file = (dir / "case.toml").string();
  std::ofstream(case_file) << test::tiny_plate_case(12);
  const std::string e = refusal_of_grid(case_file, {{"wing.planform.clamp_y", {1.0, 2.0}}});
  EXPECT_NE(
      e.find("key 'wing.planform.clamp_y': --vary wing.planform.clamp_y = 1, 2: every value gives the same "
             "inputs"),
      std::string::npos)
      << e;
}

// A revolving wing's rotation phase: δψ shifts the sweep and deviation against the rotation,
// both constant here, so every value is the same run (its inputs hash leaves δψ out; the
// Robofly case over -0.1, 0 gave the same mean CL to the last digit and ran both).
TEST(SweepKeysThatChangeNothing, ARevolvingWingsRotationPhaseIsRefused) {
  const test::ScratchDir dir("sweep_revolving_phase");
  std::string text = test::tiny_plate_case(12);
  const std::string flapping =
      "sweep = { mean_deg = 10.0, cos_deg = [50.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n";
  text.replace(text.find(flapping), flapping.size(),
               "sweep = 0.0\nrotation = 45.0\nrevolution = { rate_deg_per_s = -720.0 }\n");
  const std::string revolving = (dir / "revolving.toml").string();
  std::ofstream(revolving) << text;
  const std::string e = refusal_of_grid(revolving, {{"kinematics.rotation_phase", {-0.1, 0.0}}});
  EXPECT_NE(
      e.find("key 'kinematics.rotation_phase': --vary kinematics.rotation_phase = -0.1, 0: every value gives "
             "the same inputs"),
      std::string::npos)
      << e;
}

TEST(SweepKeysThatChangeNothing, SweepsOfKeysThatReachTheRunAreAccepted) {
  const test::ScratchDir dir("sweep_used_keys");
  const std::string rigid = (dir / "rigid.toml").string();
  std::ofstream(rigid) << test::tiny_plate_case(12);
  std::string flexible_text = test::tiny_plate_case(12);
  flexible_text.replace(flexible_text.find("kind = \"rigid\""), 14, "kind = \"flexible\"\nbodies = 2");
  const std::string flexible = (dir / "flexible.toml").string();
  std::ofstream(flexible) << flexible_text;
  // Each of these sets an input of the run (docs/sweeps.md, "What can be varied").
  EXPECT_EQ(refusal_of_grid(flexible,
                            {{"kinematics.rotation_phase", {-0.1, 0.0, 0.1}}, {"spring_scale", {1.0, 2.0}}}),
            "");
  // A rigid wing has no springs: its spring_scale is no input of the run (it was counted in the
  // inputs hash, and such a sweep ran bit-identical rows with a warning).
  EXPECT_NE(
      refusal_of_grid(rigid, {{"kinematics.rotation_phase", {-0.1, 0.0}}, {"spring_scale", {1.0, 2.0}}})
          .find("key 'spring_scale': --vary spring_scale = 1, 2: the case's structure.kind = \"rigid\""),
      std::string::npos);
  EXPECT_EQ(refusal_of_grid(rigid, {{"kinematics.sweep.cos_deg[0]", {40.0, 50.0}}}), "");
  EXPECT_EQ(refusal_of_grid(rigid, {{"wing.membrane.thickness", {0.1, 0.2}}}), "");  // a rigid wing's mass
  EXPECT_EQ(refusal_of_grid(flexible, {{"wing.materials.pet.youngs_modulus", {2e9, 4e9}}}),
            "");  // reduced per value
}

}  // namespace
