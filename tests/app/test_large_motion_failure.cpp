// A run that fails once its chain has swung beyond small rotations says so, naming the joint
// and the angles; and the flapping's inertia alone beyond 30° is warned before the run.
// Before: a user's swept wing (5 outline points swept back about 30°, 15 µm PET, a carbon rod
// 0.8 → 0.4 mm along the leading edge; 6 bodies) flapped at 20 Hz in vacuum stopped at step 21
// with "quasi-Newton solve did not converge in 50 iterations (residual 3.7e+31 N m)" and no
// word of why; the same chain at 6400 steps per cycle (step-converged to 0.01° over the
// first quarter cycle) bends its tip 39.9° and twists it 64.5° in that quarter, the joint
// inboard of body 6 bent 98° at t = 0.03 s: the wing's motion, not the time step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/flexibility_warnings.hpp"
#include "pipeline/app/fsi_setup.hpp"
#include "one_joint_chain.hpp"
#include "swept_wing.hpp"

using namespace flapsim::test;

namespace {

std::string inertial_warning_at(const ScratchDir& dir, double frequency_hz) {
  const flapsim::io::Case c = load_one_joint_case(dir, frequency_hz, "rotation = 90.0");
  return flapsim::app::inertial_deflection_warning(c, flapsim::app::build_fsi_setup(c, {}));
}

// The one-joint chain (one_joint_chain.hpp) pitched 90°: the sweep axis is the bend axis, so
// the sweep's angular acceleration φ̈ = 50° (2π f)² loads the joint by (I_xx + m y_c r_c) φ̈,
// I_xx = 1e-9 kg m², m y_c r_c = 1e-4 · 0.01 · 0.03 kg m², and k θ = that (k = 1e-3 N m/rad):
// 15.67° at 16 Hz, twice 31.3° (warned); 13.77° at 15 Hz, twice 27.5° (not warned).
TEST(LargeMotionFailure, TheFlappingsInertiaBeyondThirtyDegreesIsWarnedBeforeTheRun) {
  ScratchDir dir("inertial_warning");
  const std::string at16 = inertial_warning_at(dir, 16.0);
  EXPECT_NE(at16.find("the flapping's inertia alone would bend the wing's tip by up to 31.3 deg and twist it by "
                      "up to 0.0 deg"),
            std::string::npos) << at16;
  EXPECT_NE(at16.find("(15.7 and 0.0 deg;"), std::string::npos) << at16;
  EXPECT_NE(at16.find("the joint inboard of body 2 bent by 15.7 deg"), std::string::npos) << at16;
  // The model of large rotations is named: the wing's own FEM (docs/case_file.md, "Warnings").
  EXPECT_NE(at16.find("structure.kind = \"fem\""), std::string::npos) << at16;
  EXPECT_EQ(inertial_warning_at(dir, 15.0), "");
}

TEST(LargeMotionFailure, ASweptWingsFailureNamesTheJointAndTheAngles) {
  ScratchDir dir("swept_failure");
  write_swept_vacuum_case(dir, 1);
  const FlapsimOutcome run =
      run_flapsim_capturing_stderr(dir.path(), "run " + (dir / "case.toml").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(run.status, 3) << run.err;
  EXPECT_NE(run.err.find("warning: the flapping's inertia alone would bend the wing's tip by up to"), std::string::npos)
      << run.err;
  const std::string said = "By then the wing had moved beyond what its chain represents: the joint inboard of body ";
  const auto at = run.err.find(said);
  ASSERT_NE(at, std::string::npos) << run.err;
  // "… body 6 twisted -44.7 deg at the last completed step (history.csv twist_6_rad)": the
  // angle is the last row's of history.csv, and beyond 30°.
  const std::string rest = run.err.substr(at + said.size());
  const auto column_at = rest.find("(history.csv ");
  ASSERT_NE(column_at, std::string::npos) << rest;
  const std::string column = rest.substr(column_at + 13, rest.find(')', column_at) - column_at - 13);
  const std::string verb = column.rfind("twist", 0) == 0 ? "twisted " : "bent ";
  const double said_deg = std::strtod(rest.c_str() + rest.find(verb) + verb.size(), nullptr);
  const std::string history = read_text(dir / "out" / "history.csv");
  const std::string header = history.substr(0, history.find('\n'));
  int index = 0;
  for (std::size_t p = 0; p < header.find(column); ++p) index += header[p] == ',';
  std::string last = history.substr(history.rfind('\n', history.size() - 2) + 1);
  for (int i = 0; i < index; ++i) last = last.substr(last.find(',') + 1);
  const double last_deg = std::strtod(last.c_str(), nullptr) * 180.0 / M_PI;
  EXPECT_NEAR(said_deg, last_deg, 0.05) << rest;
  EXPECT_GT(std::abs(said_deg), 30.0) << rest;
  // summary.json keeps the same explanation.
  EXPECT_NE(read_text(dir / "out" / "summary.json").find(said), std::string::npos);
}

}  // namespace

namespace {

// A run on the wing's FEM (structure.kind = "fem") whose Newton iterations stop: before, the
// message was the FEM's alone ("Newton did not converge in 25 iterations ... (the step in 256
// pieces)"), with no word of the wing's motion. A paddle-shaped 50 µm film wing (60 mm, FEM
// mode 1 at 30.5 Hz) flapped at 20 Hz in cases/hover_flexible.toml's stroke stopped so at
// t = 0.065 s with its tip bent 105.7° and twisted 23.5° (1 Dec; sooner with 200 steps a cycle,
// through at 12 Hz, pipeline/app/flexibility_warnings.cpp). Beyond 30° (kLargeTipDeflectionDeg)
// the failure now says how far the tip had swung and what to change; a chain's failure has its
// own sentence (above), and a FEM wing within 30° gets none.
TEST(LargeMotionFailure, AFemWingThatStopsAfterSwingingFarSaysHowFarAndWhatToChange) {
  flapsim::io::Case fem;
  fem.structure.kind = flapsim::io::Case::Structure::Kind::Fem;
  const std::string said = flapsim::app::fem_motion_at_failure(fem, 105.7, 23.5, /*in_structure=*/true);
  EXPECT_NE(said.find("the wing's tip had bent up to 105.7 deg and twisted up to 23.5 deg against its base"),
            std::string::npos)
      << said;
  EXPECT_NE(said.find("the FEM's Newton iterations stopped"), std::string::npos) << said;
  EXPECT_NE(said.find("lower frequency_hz or the amplitudes"), std::string::npos) << said;
  EXPECT_NE(flapsim::app::fem_motion_at_failure(fem, 12.0, 31.0, true), "");  // the twist alone beyond 30°
  EXPECT_EQ(flapsim::app::fem_motion_at_failure(fem, 29.0, 29.0, true), "");
  flapsim::io::Case chain = fem;
  chain.structure.kind = flapsim::io::Case::Structure::Kind::Flexible;
  EXPECT_EQ(flapsim::app::fem_motion_at_failure(chain, 105.7, 23.5, true), "");
}

// The same sentence used to follow any failure of a FEM wing beyond 30°, also one the FEM
// itself solved through: cases/film_wing_fem.toml with leading_edge = "shed" (5 Dec) stops in
// its coupling at step 247 (C_L jumping by 8.3 a step), its tip twisted 38.8° (17.7° with
// "separated"), and the message said "the FEM's Newton iterations stopped" and to stiffen
// the wing. A failure outside the structure's own solve now says how far the tip had swung,
// no more.
TEST(LargeMotionFailure, AFemWingWhoseCouplingFailsIsNotToldItsNewtonIterationsStopped) {
  flapsim::io::Case fem;
  fem.structure.kind = flapsim::io::Case::Structure::Kind::Fem;
  const std::string said = flapsim::app::fem_motion_at_failure(fem, 3.0, 38.8, /*in_structure=*/false);
  EXPECT_NE(said.find("the wing's tip had bent up to 3.0 deg and twisted up to 38.8 deg against its base"),
            std::string::npos)
      << said;
  EXPECT_EQ(said.find("Newton"), std::string::npos) << said;
  EXPECT_EQ(said.find("stiffen"), std::string::npos) << said;
  EXPECT_EQ(flapsim::app::fem_motion_at_failure(fem, 3.0, 29.0, false), "");
}

}  // namespace
