// One flapsim command writing into a folder at a time (pipeline/io/folder_lock.hpp). Before:
// two runs started at once into one folder (two cases with the same name into out/<name>)
// both exited 0; the folder kept the second's history.csv and summary.json (a 0.8 mm wing,
// 120 steps) and nothing of the first (a swept wing, 480 steps), which had reported success.
// Now the second stops before writing anything: exit 4, naming the folder.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "pipeline/io/folder_lock.hpp"
#include "robustness_helpers.hpp"

using namespace flapsim::test;

namespace {

TEST(FolderLock, ACommandFindingTheFolderInUseStopsWithStatus4WritingNothing) {
  ScratchDir dir("folder_lock");
  std::ofstream(dir / "case.toml") << small_plate_case("rigid", 1, 0);
  const auto out = dir / "out";
  std::filesystem::create_directories(out);
  const std::string in_use = "cannot write '" + out.string() + "': another flapsim command is writing into this folder now";
  {
    // This process stands for the command under way (the lock a run or sweep holds).
    const flapsim::io::FolderLock other(out, "run");
    ASSERT_TRUE(other.held());
    FlapsimOutcome r = run_flapsim_capturing_stderr(dir.path(), "run " + (dir / "case.toml").string() + " -o " + out.string());
    EXPECT_EQ(r.status, 4) << r.err;
    EXPECT_NE(r.err.find(in_use), std::string::npos) << r.err;
    r = run_flapsim_capturing_stderr(dir.path(), "sweep " + (dir / "case.toml").string() +
                                     " --vary kinematics.rotation_phase=0,0.1 -o " + out.string());
    EXPECT_EQ(r.status, 4) << r.err;
    EXPECT_NE(r.err.find(in_use), std::string::npos) << r.err;
    EXPECT_TRUE(std::filesystem::is_empty(out)) << "nothing written";
  }
  // Once the other command has ended (its lock goes with it), the folder is free.
  EXPECT_EQ(run_flapsim_capturing_stderr(dir.path(), "run " + (dir / "case.toml").string() + " -o " + out.string()).status, 0);
  EXPECT_TRUE(std::filesystem::exists(out / "summary.json"));
}

// An empty output folder the user made (a group's shared folder, setgid, mode 2770) is the
// one the run writes into. Before: the claim removed an empty output folder ("dir" / "" =
// "dir/" was taken for a series' sub-folder) and the outputs made it again with the default
// mode, 755 here: the group lost its access, and the folder's lock went with the old folder.
TEST(FolderLock, AnEmptyOutputFolderIsKeptWithItsMode) {
  ScratchDir dir("folder_mode");
  std::ofstream(dir / "case.toml") << small_plate_case("rigid", 1, 0);
  const auto out = dir / "shared";
  std::filesystem::create_directories(out);
  const auto mode = std::filesystem::perms::owner_all | std::filesystem::perms::group_all |
                    std::filesystem::perms::set_gid;  // 2770
  std::filesystem::permissions(out, mode);
  ASSERT_EQ(run_flapsim_capturing_stderr(dir.path(), "run " + (dir / "case.toml").string() + " -o " + out.string()).status, 0);
  EXPECT_TRUE(std::filesystem::exists(out / "summary.json"));
  EXPECT_EQ(std::filesystem::status(out).permissions() & std::filesystem::perms::mask, mode);
}

}  // namespace
