// A device, FIFO or folder given where a TOML file belongs is refused at once. Before:
// `flapsim check /dev/zero` (or a FIFO) read without end (killed by a 10 s timeout), and a
// case naming `wing = "/dev/zero"` said "file not found". The outline CSV had this guard
// already (docs/reliability.md, failure 7); now the wing, case and chain files, --chain and
// --cases have it too, and a TOML file over 16 MiB is refused without parsing.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <fstream>
#include <string>

#include "robustness_helpers.hpp"

using namespace flapsim::test;

namespace {

// Exit status of `flapsim ARGS` under a 20 s timeout (124: it did not end).
int bounded(const std::string& args) { return run_flapsim_in_shell("exec timeout 20", args); }

TEST(SpecialFiles, DevicesFifosAndFoldersAreRefusedAtOnce) {
  ScratchDir dir("special_files");
  const std::string fifo = (dir / "input.fifo").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(bounded("check /dev/zero"), 2);
  EXPECT_EQ(bounded("check " + fifo), 2);
  EXPECT_EQ(bounded("check " + dir.path().string()), 2);
  std::ofstream(dir / "case.toml") << replace_once(small_plate_case(), "wing = \"" + kSourceDir + "/wings/flat_plate.toml\"",
                                                   "wing = \"/dev/zero\"");
  EXPECT_EQ(bounded("check " + (dir / "case.toml").string()), 2);
  std::ofstream(dir / "plate.toml") << small_plate_case();
  EXPECT_EQ(bounded("run " + (dir / "plate.toml").string() + " --chain /dev/zero -o " + (dir / "out").string()), 2);
  EXPECT_EQ(bounded("sweep " + (dir / "plate.toml").string() + " --cases " + fifo + " -o " + (dir / "out").string()), 2);
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

TEST(SpecialFiles, AHugeTomlFileIsRefusedWithoutParsing) {
  ScratchDir dir("special_files_huge");
  {
    std::ofstream big(dir / "big.toml");
    const std::string comment(1023, '#');
    for (int i = 0; i < 17 * 1024; ++i) big << comment << '\n';  // 17 MiB of comments
  }
  EXPECT_EQ(bounded("check " + (dir / "big.toml").string()), 2);
}

}  // namespace
