// Kinematic angles in the wrong unit are accepted with a warning. Before: a case whose
// stroke was written in radians (`sweep = { cos_deg = [0.87] }`, `rotation = { mean_deg = 1.57,
// sin_deg = [-0.785] }`) ran without a word: a wing sweeping ±0.87° instead of ±50°. And
// `cos_deg = [500.0]` swept the wing through more than a turn. Now: the sweep and rotation never
// leaving ±2π degrees (2π = 6.28: what radians of any angle up to a turn look like in degrees)
// is warned as radians, a sweep past ±180° as a wrong amplitude; the shipped kinematics
// (±50–60° sweep, 90° ± 45° rotation) give no warning.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "inline_case.hpp"
#include "pipeline/io/case_file.hpp"

namespace {

std::string kinematics_case(const std::string& sweep, const std::string& rotation) {
  return "wing = \"valid_tiny_wing.toml\"\n[kinematics]\nfrequency_hz = 20.0\n"  // 1-3
         "sweep = " + sweep + "\nrotation = " + rotation +                         // 4-5
         "\n[structure]\nkind = \"rigid\"\n[numerics]\nsteps_per_cycle = 40\n"
         "far_wake_cycles = 0.5\n";  // no whole-free-wake hover warning (test_case_warnings.cpp)
}

TEST(CaseAngleWarnings, AnglesWrittenInRadiansAreWarned) {
  const flapsim::io::Case c =
      case_from_text(kinematics_case("{ cos_deg = [0.87] }", "{ mean_deg = 1.57, sin_deg = [-0.785] }"));
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_EQ(c.warnings[0].key, "kinematics.sweep");
  EXPECT_EQ(c.warnings[0].line, 4);
  // The largest value either angle takes: 1.57 + 0.785 = 2.355 degrees.
  EXPECT_NE(c.warnings[0].message.find("never exceed 2.35 degrees: were they written in radians?"),
            std::string::npos) << c.warnings[0].message;
}

// The stroke alone in radians: a slender wing, rigid, 15 Hz, `cos_deg = [0.96]` with the
// rotation 90 +- 45 degrees ran silently with mean CL 11.0 (on a reference speed of 0.035 m/s,
// the flapping speed of a +-0.96 degree stroke at r2). A sweep that does not swing (a constant
// 0 or 10 degrees: a plunging or pitching wing) is not warned.
// A wing in a free stream or a heaving one has small angles throughout: a plate held at 5°
// in a 5 m/s stream (the steady lattice's textbook case) and a plate heaving at 3° were told
// "were they written in radians?" until 3 Dec; the same angles in still air still are.
TEST(CaseAngleWarnings, SmallAnglesOfAWingInAFreeStreamOrHeavingAreNotWarned) {
  const std::string stream = "[air]\nfreestream = [-5.0, 0.0, 0.0]\n";
  EXPECT_TRUE(case_from_text(kinematics_case("0.0", "5.0") + stream).warnings.empty());
  EXPECT_TRUE(case_from_text(kinematics_case("0.0", "{ mean_deg = 3.0, sin_deg = [2.0] }") + stream)
                  .warnings.empty());
  const std::string heave = kinematics_case("0.0", "3.0");
  const std::string heaving = heave.substr(0, heave.find("[structure]")) + "heave = { sin_m = [0.005] }\n" +
                              heave.substr(heave.find("[structure]"));
  EXPECT_TRUE(case_from_text(heaving).warnings.empty());
  ASSERT_EQ(case_from_text(kinematics_case("0.0", "5.0")).warnings.size(), 1u);
  EXPECT_NE(case_from_text(kinematics_case("0.0", "5.0")).warnings[0].message.find("written in radians?"),
            std::string::npos);
}

TEST(CaseAngleWarnings, AStrokeAloneWrittenInRadiansIsWarned) {
  const flapsim::io::Case c = case_from_text(
      kinematics_case("{ mean_deg = 10.0, cos_deg = [0.96] }", "{ mean_deg = 90.0, sin_deg = [-45.0] }"));
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_EQ(c.warnings[0].key, "kinematics.sweep");
  EXPECT_EQ(c.warnings[0].line, 4);
  // 10 +- 0.96 degrees: from 9.04 to 10.96; the rotation reaches 90 + 45 = 135.
  EXPECT_NE(c.warnings[0].message.find("the sweep swings by only +-0.96 degrees (from 9.04 to 11) while the "
                                       "rotation reaches 135: was the stroke written in radians?"),
            std::string::npos)
      << c.warnings[0].message;
  EXPECT_TRUE(case_from_text(kinematics_case("10.0", "{ mean_deg = 90.0, sin_deg = [-45.0] }")).warnings.empty());
  EXPECT_TRUE(case_from_text(kinematics_case("0.0", "{ mean_deg = 90.0, sin_deg = [-45.0] }")).warnings.empty());
}

// The rotation alone in radians: `rotation = { mean_deg = 1.57, sin_deg = [-0.785] }` under
// a ±50-degree sweep ran a wing pitching by ±0.785 degrees without a word (until 3 Dec). A
// constant rotation (an angle of attack held) is not warned.
TEST(CaseAngleWarnings, ARotationAloneWrittenInRadiansIsWarned) {
  const flapsim::io::Case c =
      case_from_text(kinematics_case("{ cos_deg = [50.0] }", "{ mean_deg = 1.57, sin_deg = [-0.785] }"));
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_EQ(c.warnings[0].key, "kinematics.rotation");
  EXPECT_EQ(c.warnings[0].line, 5);
  // 1.57 +- 0.785: from 0.785 to 2.355 degrees under a sweep of +-50.
  EXPECT_NE(
      c.warnings[0].message.find("the rotation never exceeds 2.35 degrees (from 0.785 to 2.35) while the "
                                 "sweep swings by +-50: was the rotation written in radians?"),
      std::string::npos)
      << c.warnings[0].message;
  EXPECT_TRUE(case_from_text(kinematics_case("{ cos_deg = [50.0] }", "5.0")).warnings.empty());
}

// A revolving wing at a small incidence (the Robofly wing at 5 degrees, Dickinson et al.
// 1999's lowest angles) moves by its revolution: it was told "were they written in radians?"
// until 3 Dec; the same angles without the revolution still are.
TEST(CaseAngleWarnings, ARevolvingWingAtASmallIncidenceIsNotWarned) {
  const std::string still = kinematics_case("0.0", "5.0");
  const std::string revolving = still.substr(0, still.find("[structure]")) +
                                "revolution = { rate_deg_per_s = -360.0 }\n" +
                                still.substr(still.find("[structure]"));
  EXPECT_TRUE(case_from_text(revolving).warnings.empty());
  EXPECT_EQ(case_from_text(still).warnings.size(), 1u);
}

TEST(CaseAngleWarnings, ASweepBeyondHalfATurnIsWarned) {
  const flapsim::io::Case c =
      case_from_text(kinematics_case("{ mean_deg = 10.0, cos_deg = [500.0] }", "{ mean_deg = 90.0, sin_deg = [-45.0] }"));
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_NE(c.warnings[0].message.find("the sweep angle reaches 510 degrees"), std::string::npos)
      << c.warnings[0].message;
}

// A rotation beyond a whole turn: `rotation = { mean_deg = 1e300 }` ran to a lift of
// -0.7 mN without a word, where the sweep's 510 degrees was warned.
TEST(CaseAngleWarnings, ARotationBeyondAWholeTurnIsWarned) {
  const flapsim::io::Case c = case_from_text(kinematics_case("{ cos_deg = [50.0] }", "{ mean_deg = 1e300 }"));
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_EQ(c.warnings[0].key, "kinematics.rotation");
  EXPECT_EQ(c.warnings[0].line, 5);
  EXPECT_NE(c.warnings[0].message.find("the rotation angle reaches 1e+300 degrees"), std::string::npos)
      << c.warnings[0].message;
  // 90 + 270 = 360 degrees, a whole turn at most: not warned; 90 + 271 is.
  EXPECT_TRUE(
      case_from_text(kinematics_case("{ cos_deg = [50.0] }", "{ mean_deg = 90.0, sin_deg = [-270.0] }"))
          .warnings.empty());
  EXPECT_EQ(case_from_text(kinematics_case("{ cos_deg = [50.0] }", "{ mean_deg = 90.0, sin_deg = [-271.0] }"))
                .warnings.size(),
            1u);
}

TEST(CaseAngleWarnings, ThePlausibleKinematicsOfEveryShippedCaseAreNotWarned) {
  EXPECT_TRUE(case_from_text(kinematics_case("{ cos_deg = [50.0] }", "{ mean_deg = 90.0, sin_deg = [-45.0] }"))
                  .warnings.empty());
  EXPECT_TRUE(case_from_text(kinematics_case("{ cos_deg = [54.0] }", "90.0")).warnings.empty());
  int cases = 0;
  for (const auto& e : std::filesystem::directory_iterator(std::string(FLAPSIM_SOURCE_DIR) + "/cases")) {
    if (e.path().extension() != ".toml") continue;
    const flapsim::io::Case c = flapsim::io::load_case_file(e.path().string());
    for (const auto& w : c.warnings) {
      EXPECT_NE(w.key, "kinematics.sweep") << e.path() << ": " << w.text();
      EXPECT_NE(w.key, "kinematics.rotation") << e.path() << ": " << w.text();
    }
    ++cases;
  }
  EXPECT_GE(cases, 10);
}

}  // namespace
