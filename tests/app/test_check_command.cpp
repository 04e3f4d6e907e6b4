// `flapsim check` as users run it: the summaries of the shipped files, and exit status
// 2 with file:line and nothing written for each kind of bad wing or case file.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {

const std::string kSource = FLAPSIM_SOURCE_DIR;
const std::string kBad = kSource + "/tests/data/bad_inputs/";

struct Result {
  int status = -1;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `flapsim ARGS` inside an empty working folder; stdout/stderr are captured in a
// separate folder so the working folder shows whether anything was written.
class CheckCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    root_ = fs::temp_directory_path() /
            ("flapsim_check_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(root_);
    fs::create_directories(root_ / "work");
    fs::create_directories(root_ / "capture");
  }
  void TearDown() override { fs::remove_all(root_); }

  Result run(const std::string& args) const {
    const std::string cmd = "cd '" + (root_ / "work").string() + "' && '" FLAPSIM_BINARY "' " + args +
                            " > '" + (root_ / "capture/out").string() + "' 2> '" +
                            (root_ / "capture/err").string() + "'";
    const int raw = std::system(cmd.c_str());
    Result r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(root_ / "capture/out");
    r.err = slurp(root_ / "capture/err");
    return r;
  }
  bool work_is_empty() const { return fs::is_empty(root_ / "work"); }

  // A bad file: exit 2, "FILE:LINE:" and the key in the message, nothing on stdout,
  // nothing written in the working folder.
  void expect_rejected(const std::string& name, int line, const std::string& key) {
    const Result r = run("check '" + kBad + name + "'");
    EXPECT_EQ(r.status, 2) << name << ": " << r.err;
    EXPECT_NE(r.err.find(name + ":" + std::to_string(line) + ":"), std::string::npos)
        << name << ": " << r.err;
    if (!key.empty()) {
      EXPECT_NE(r.err.find("key '" + key + "'"), std::string::npos) << r.err;
    }
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_TRUE(work_is_empty());
  }

  fs::path root_;
};

double number_after(const std::string& text, const std::string& label) {
  const std::regex re(label + R"(\s+([-+0-9.eE]+))");
  std::smatch m;
  if (!std::regex_search(text, m, re)) {
    ADD_FAILURE() << "no '" << label << "' in:\n" << text;
    return 0.0;
  }
  return std::stod(m[1]);
}

}  // namespace

TEST_F(CheckCommand, HawkmothWingSummary) {
  const Result r = run("check '" + kSource + "/wings/hawkmoth.toml'");
  ASSERT_EQ(r.status, 0) << r.err;
  // RP Table 2: span 48.3 mm, area 815.3 mm² (issue: within 0.5 %).
  EXPECT_NEAR(number_after(r.out, "span R"), 48.3, 48.3 * 0.005);
  EXPECT_NEAR(number_after(r.out, "area S"), 815.3, 815.3 * 0.005);
  // c̄ = S/R = 815.3 / 48.3 = 16.880 mm; AR = R²/S = 2.8614.
  EXPECT_NEAR(number_after(r.out, R"(mean chord S/R)"), 16.880, 0.001);
  EXPECT_NEAR(number_after(r.out, R"(aspect ratio R\^2/S)"), 2.8614, 0.0001);
  EXPECT_EQ(number_after(r.out, "veins"), 14);
  EXPECT_NEAR(number_after(r.out, "estimated mass"), 33.8, 0.05);  // RP Table 1 sum 33.76 mg
  EXPECT_TRUE(work_is_empty());
}

TEST_F(CheckCommand, FlatPlateR2) {
  const Result r = run("check '" + kSource + "/wings/flat_plate.toml'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(number_after(r.out, "r2/R"), 1.0 / std::sqrt(3.0), 1e-4);  // rectangle from the pivot
  EXPECT_NEAR(number_after(r.out, R"(aspect ratio R\^2/S)"), 4.0, 1e-4);
}

// A plate that heaves in a stream and does not sweep has no strokes: its kinematics table says
// "no sweep", not "reversal" at every phase (as it did until 3 Dec).
TEST_F(CheckCommand, AHeavingPlateHasNoStrokeReversals) {
  const fs::path file = fs::path(root_) / "heave.toml";
  std::ofstream(file) << "name = \"heave\"\nwing = \"" << kSource
                      << "/wings/flat_plate.toml\"\n[kinematics]\nfrequency_hz = 10.0\nsweep = 0.0\n"
                         "rotation = 90.0\nheave = { sin_m = [0.005] }\n[structure]\nkind = \"rigid\"\n"
                         "[air]\nfreestream = [-5.0, 0.0, 0.0]\n[numerics]\ncycles = 1\n";
  const Result r = run("check '" + file.string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.find("reversal"), std::string::npos) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(0\.25\s+0\.00\s+0\.00\s+90\.00\s+-.*no sweep)")))
      << r.out;
  EXPECT_NE(r.out.find("'-': the span axis does not sweep"), std::string::npos) << r.out;
}

TEST_F(CheckCommand, HoverCaseKinematics) {
  const Result r = run("check '" + kSource + "/cases/hover.toml'");
  ASSERT_EQ(r.status, 0) << r.err;
  // Eq. 8, δψ = 0: phase 0.25 → φ = 10°, α = 45°, AoA 45° (downstroke);
  // phase 0.75 → φ = 10°, α = 135°, AoA 45° (upstroke).
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(0\.25\s+10\.00\s+0\.00\s+45\.00\s+45\.00\s+downstroke)")))
      << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(0\.75\s+10\.00\s+0\.00\s+135\.00\s+45\.00\s+upstroke)")))
      << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(0\.00\s+60\.00\s+0\.00\s+90\.00\s+-\s+reversal)"))) << r.out;
  EXPECT_NE(r.out.find("6 chordwise x 10 spanwise"), std::string::npos);
  EXPECT_NE(r.out.find("flexible, 10 bodies"), std::string::npos);
  EXPECT_NE(r.out.find("wing 'hawkmoth'"), std::string::npos);  // the case's wing is checked too
  // No chain file: the wing is reduced in the setup, whose FEM the estimate shows beside the
  // run's arrays (test RunEstimate.TheSetupsReductionOfTheWingIsEstimatedBesideTheRun).
  EXPECT_NE(r.out.find("before it, for the wing's FEM reduced in the setup"), std::string::npos) << r.out;
}

// check --kinematics writes the angles the run flies at its steps: Lua et al.'s eq. 7
// (cases/lua_rigid.toml, 26.1 Hz, 100 steps): phi = 60 cos 2πs, alpha = 90 − 60 sin 2πs, their
// rates and accelerations those of the series (−(2πf)² 60 cos 2πs deg/s² for phi); on a wing
// file it is a usage error and nothing is written.
TEST_F(CheckCommand, KinematicsOptionWritesTheWingbeatAtTheRunsSteps) {
  const Result r = run("check '" + kSource + "/cases/lua_rigid.toml' --kinematics kinematics.csv");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("kinematics of one wingbeat at the run's 100 steps"), std::string::npos) << r.out;
  std::ifstream in(root_ / "work/kinematics.csv");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("phase,t_s,phi_deg,theta_deg,alpha_deg,phi_rate_deg_per_s", 0), 0u) << line;
  int rows = 0;
  const double w = 2.0 * M_PI * 26.1;  // [rad/s]
  while (std::getline(in, line)) {
    double phase = 0, t = 0, phi = 0, theta = 0, alpha = 0, phi_rate = 0, theta_rate = 0, alpha_rate = 0,
           phi_acc = 0;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &phase, &t, &phi, &theta,
                          &alpha, &phi_rate, &theta_rate, &alpha_rate, &phi_acc),
              9)
        << line;
    EXPECT_NEAR(phase, rows / 100.0, 1e-12);
    EXPECT_NEAR(phi, 60.0 * std::cos(2.0 * M_PI * phase), 1e-9);
    EXPECT_NEAR(alpha, 90.0 - 60.0 * std::sin(2.0 * M_PI * phase), 1e-9);
    EXPECT_NEAR(phi_rate, -w * 60.0 * std::sin(2.0 * M_PI * phase), 1e-6);
    EXPECT_NEAR(phi_acc, -w * w * 60.0 * std::cos(2.0 * M_PI * phase), 1e-3);
    ++rows;
  }
  EXPECT_EQ(rows, 101);  // k = 0 … 100, the last the next wingbeat's start
  const Result wing = run("check '" + kSource + "/wings/hawkmoth.toml' --kinematics kinematics2.csv");
  EXPECT_EQ(wing.status, 1);
  EXPECT_NE(wing.err.find("--kinematics: applies to a case file"), std::string::npos) << wing.err;
  EXPECT_FALSE(fs::exists(root_ / "work/kinematics2.csv"));
}

TEST_F(CheckCommand, HelpDescribesTheCommand) {
  const Result r = run("check --help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("wing or case file"), std::string::npos);
}

TEST_F(CheckCommand, NeitherWingNorCase) {
  std::ofstream(root_ / "capture/other.toml") << "title = \"x\"\n";
  const Result r = run("check '" + (root_ / "capture/other.toml").string() + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("other.toml:1:"), std::string::npos) << r.err;
}

TEST_F(CheckCommand, MissingFile) {
  const Result r = run("check no_such_file.toml");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("no_such_file.toml"), std::string::npos) << r.err;
  EXPECT_TRUE(work_is_empty());
}

// Line numbers: see the fixture files (each breaks one line of valid_tiny_*.toml).
TEST_F(CheckCommand, WingMissingKey) { expect_rejected("wing_missing_key.toml", 14, "membrane.thickness"); }
TEST_F(CheckCommand, WingNegativeThickness) {
  expect_rejected("wing_negative_thickness.toml", 15, "membrane.thickness");
}
TEST_F(CheckCommand, WingSelfIntersectingOutline) {
  expect_rejected("wing_self_intersecting.toml", 6, "planform.outline");
}
TEST_F(CheckCommand, WingVeinOutsideOutline) { expect_rejected("wing_vein_outside.toml", 20, "veins[0].points"); }
TEST_F(CheckCommand, WingUnknownUnit) { expect_rejected("wing_unknown_unit.toml", 3, "length_unit"); }
TEST_F(CheckCommand, WingStringForNumber) {
  expect_rejected("wing_string_number.toml", 12, "materials.film.density");
}
TEST_F(CheckCommand, WingTruncated) { expect_rejected("wing_truncated.toml", 20, ""); }

TEST_F(CheckCommand, CaseMissingKey) { expect_rejected("case_missing_key.toml", 6, "kinematics.frequency_hz"); }
TEST_F(CheckCommand, CaseNegativeSteps) {
  expect_rejected("case_negative_steps.toml", 17, "numerics.steps_per_cycle");
}
TEST_F(CheckCommand, CaseUnknownUnit) { expect_rejected("case_unknown_unit.toml", 4, "length_unit"); }
TEST_F(CheckCommand, CaseStringForNumber) {
  expect_rejected("case_string_number.toml", 7, "kinematics.frequency_hz");
}
TEST_F(CheckCommand, CaseUnknownKey) { expect_rejected("case_unknown_key.toml", 18, "numerics.cylces"); }
TEST_F(CheckCommand, CaseBodyOutOfRange) { expect_rejected("case_body_out_of_range.toml", 22, "markers[0].body"); }
TEST_F(CheckCommand, CaseMissingWingFile) { expect_rejected("case_missing_wing_file.toml", 3, "wing"); }
TEST_F(CheckCommand, CaseFloatForInteger) { expect_rejected("case_float_for_int.toml", 14, "structure.bodies"); }
TEST_F(CheckCommand, CaseTruncated) { expect_rejected("case_truncated.toml", 10, ""); }
// A misspelled defining table ([planfrom], [kinematic]) is named at its line as the unknown
// key it is, by the reader of the kind of file the other tables say it is: it was "not a wing
// file (no [planform] table) nor a case file" at line 1.
TEST_F(CheckCommand, WingTableTypo) { expect_rejected("wing_table_typo.toml", 5, "planfrom"); }
TEST_F(CheckCommand, CaseTableTypo) { expect_rejected("case_table_typo.toml", 6, "kinematic"); }

TEST_F(CheckCommand, ValidTinyCaseWithAdvancedRotation) {
  const Result r = run("check '" + kSource + "/tests/data/valid_tiny_case.toml'");
  ASSERT_EQ(r.status, 0) << r.err;
  // δψ = −0.1: sweep φ(s) = 10° + 50° cos 2π(s − 0.1); at s = 0: 10 + 50 cos 36° = 50.45°.
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(0\.00\s+50\.45)"))) << r.out;
}
