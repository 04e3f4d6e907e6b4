// A case's wing written relative to the folder the command runs in rather than to the case
// file's (a case kept outside the repository naming `wing = "wings/hawkmoth.toml"`, run from
// the repository). Before: "file not found: sub/wings/... (paths are relative to the case file's
// folder)", no way from there to the file. Now the message says the path from the case file's
// folder to the file that the written path reaches from the current folder.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace {

// `flapsim check CASE` run in DIR, its exit status and stderr.
flapsim::test::FlapsimOutcome check_in(const flapsim::test::ScratchDir& dir, const std::string& case_file) {
  const std::string cmd = "cd '" + dir.path().string() + "' && FLAPSIM_QUIET=1 '" +
                          std::string(FLAPSIM_BINARY) + "' check " + case_file + " > /dev/null 2> err.txt";
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, flapsim::test::read_text(dir / "err.txt")};
}

TEST(CaseFilePaths, AWingWrittenRelativeToTheCurrentFolderIsShownItsPathFromTheCase) {
  const flapsim::test::ScratchDir dir("case_file_paths");
  std::filesystem::create_directories(dir / "studies" / "a");
  std::filesystem::create_directories(dir / "wings");
  std::filesystem::copy_file(std::string(FLAPSIM_SOURCE_DIR) + "/wings/flat_plate.toml",
                             dir / "wings" / "plate.toml");
  std::ofstream(dir / "studies" / "a" / "case.toml")
      << "wing = \"wings/plate.toml\"\n[kinematics]\nfrequency_hz = 20.0\nsweep = { cos_deg = [50.0] }\n"
         "rotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n[structure]\nkind = \"rigid\"\n";
  const auto e = check_in(dir, "studies/a/case.toml");
  EXPECT_EQ(e.status, 2) << e.err;
  EXPECT_NE(e.err.find("studies/a/case.toml:1: key 'wing': file not found"), std::string::npos) << e.err;
  EXPECT_NE(e.err.find("from the case file's folder it is \"../../wings/plate.toml\""), std::string::npos)
      << e.err;
  // Written so, the case runs its check.
  std::ofstream(dir / "studies" / "a" / "fixed.toml")
      << "wing = \"../../wings/plate.toml\"\n[kinematics]\nfrequency_hz = 20.0\nsweep = { cos_deg = [50.0] "
         "}\n"
         "rotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n[structure]\nkind = \"rigid\"\n";
  EXPECT_EQ(check_in(dir, "studies/a/fixed.toml").status, 0);
  // A file found nowhere gets no such hint.
  std::ofstream(dir / "studies" / "a" / "nowhere.toml")
      << "wing = \"wings/none.toml\"\n[kinematics]\nfrequency_hz = 20.0\nsweep = 40.0\nrotation = 90.0\n"
         "[structure]\nkind = \"rigid\"\n";
  const auto none = check_in(dir, "studies/a/nowhere.toml");
  EXPECT_EQ(none.status, 2);
  EXPECT_EQ(none.err.find("from the case file's folder it is"), std::string::npos) << none.err;
  // The path as the case writes it, then where that is from the current folder (the message
  // showed only the latter: a case writing "../../wings/x.toml" read "../wings/x.toml").
  EXPECT_NE(
      none.err.find("file not found: wings/none.toml (paths are relative to the case file's folder, here "
                    "studies/a/wings/none.toml)"),
      std::string::npos)
      << none.err;
}

// The same for a wing's outline_file, relative to the wing file's folder.
TEST(CaseFilePaths, AnOutlineWrittenRelativeToTheCurrentFolderIsShownItsPathFromTheWing) {
  const flapsim::test::ScratchDir dir("wing_file_paths");
  std::filesystem::create_directories(dir / "outlines");
  std::filesystem::create_directories(dir / "my_wings");
  std::filesystem::copy_file(std::string(FLAPSIM_SOURCE_DIR) + "/wings/outlines/hawkmoth2_outline.csv",
                             dir / "outlines" / "hind.csv");
  std::ofstream(dir / "my_wings" / "hind.toml")
      << "length_unit = \"mm\"\n[planform]\noutline_file = \"outlines/hind.csv\"\nspan = 40.0\nclamp_y = "
         "1.0\n"
         "[materials.film]\nyoungs_modulus = 4.0e9\npoisson_ratio = 0.38\ndensity = 1390.0\n"
         "[membrane]\nthickness = 0.05\nmaterial = \"film\"\n";
  const auto e = check_in(dir, "my_wings/hind.toml");
  EXPECT_EQ(e.status, 2) << e.err;
  EXPECT_NE(e.err.find("my_wings/hind.toml:3: key 'planform.outline_file': file not found"),
            std::string::npos)
      << e.err;
  EXPECT_NE(e.err.find("from the wing file's folder it is \"../outlines/hind.csv\""), std::string::npos)
      << e.err;
}

}  // namespace
