// A wing file the user may not read (another user's file, mode 600). Before: "wing.toml: cannot
// open the file for reading" — neither the case file's line and key that name it nor the
// cause. Now the case's line and key, and the system's reason.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "robustness_helpers.hpp"

using namespace flapsim::test;
namespace fs = std::filesystem;

namespace {

TEST(UnreadableInput, AWingFileThatCannotBeReadIsTheCasesErrorAtItsLine) {
  ScratchDir dir("unreadable_wing");
  fs::permissions(dir.path(), fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                  fs::perms::others_read | fs::perms::others_exec);
  fs::copy_file(kSourceDir + "/wings/flat_plate.toml", dir / "wing.toml");
  fs::permissions(dir / "wing.toml", fs::perms::none);
  std::ofstream(dir / "case.toml") << replace_once(small_plate_case("rigid", 1, 0),
                                                   kSourceDir + "/wings/flat_plate.toml", "wing.toml");
  fs::permissions(dir / "case.toml", fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                                         fs::perms::others_read);
  // Root reads any file: the command then runs as the unprivileged user "nobody" (65534).
  const std::string as_user = ::geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : "";
  const auto err = dir / "stderr.txt";
  const std::string cmd = "FLAPSIM_QUIET=1 " + as_user + "'" + std::string(FLAPSIM_BINARY) + "' check '" +
                          (dir / "case.toml").string() + "' > /dev/null 2> '" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  const std::string text = read_text(err);
  EXPECT_EQ(WEXITSTATUS(status), 2) << text;
  // small_plate_case names its wing on line 2.
  EXPECT_EQ(text, "flapsim: error: " + (dir / "case.toml").string() + ":2: key 'wing': cannot read " + (dir / "wing.toml").string() + ": "
                      "Permission denied\n");
}

}  // namespace
