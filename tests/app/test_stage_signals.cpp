// SIGINT and SIGTERM during `flapsim mesh`, `modes` and `reduce`. Before: the default action
// killed the command at once and the folder's manifest kept `status = "running"` for a
// command that had ended. Now (pipeline/app/stage_monitor.hpp, docs/reliability.md): the
// manifest records "interrupted" (a valid file, written atomically), no temporary file is
// left, and the exit status is 128 + signal (130 SIGINT, 143 SIGTERM), as for `run`. A
// command interrupted before it claims its folder (mesh while gmsh meshes) leaves it as it was.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "robustness_helpers.hpp"
#include "signal_helpers.hpp"

namespace fs = std::filesystem;
using namespace flapsim::test;

namespace {

/// Starts `flapsim COMMAND WING -o DIR/out`, waits until the manifest says the command is
/// running, then \p delay_ms more, sends the signal and returns the exit status (-1: no normal
/// exit, -2: could not start, -3: ended before the signal).
int signal_stage_command(const ScratchDir& dir, const std::string& command, const std::string& wing,
                         int signal_number, int delay_ms) {
  const auto running = [&] {
    return read_text(dir / "out" / "flapsim_outputs.toml").find("running") != std::string::npos;
  };
  return signal_flapsim_when({command, wing, "-o", (dir / "out").string()}, running, signal_number,
                             std::chrono::milliseconds(5), std::chrono::seconds(60),
                             std::chrono::milliseconds(delay_ms));
}

void expect_interrupted(const ScratchDir& dir, const std::string& command) {
  const std::string manifest = read_text(dir / "out" / "flapsim_outputs.toml");
  EXPECT_NE(manifest.find("[" + command + "]\n"), std::string::npos) << manifest;
  EXPECT_NE(manifest.find("status = 'interrupted'"), std::string::npos) << manifest;
  EXPECT_EQ(manifest.find("running"), std::string::npos) << manifest;
  EXPECT_TRUE(dir.temporaries().empty());
  EXPECT_TRUE(truncated_files(dir, dir / "out").empty());
}

// The flat plate (wings/flat_plate.toml, 40 x 10 mm) with a 0.25 mm mesh: 14,748 triangles,
// a few seconds of FEM, so the signal comes in the middle of a stage.
std::string fine_plate(const ScratchDir& dir) {
  std::ifstream in(kSourceDir + "/wings/flat_plate.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text = replace_once(text, "\nelement_size = 1.0\n", "\nelement_size = 0.25\n");
  std::ofstream(dir / "fine_plate.toml") << replace_once(text, "\nvein_element_size = 1.0\n", "\nvein_element_size = 0.25\n");
  return (dir / "fine_plate.toml").string();
}

TEST(StageSignals, SigtermDuringReduceRecordsInterruptedAndExits143) {
  ScratchDir dir("stage_sigterm_reduce");
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(signal_stage_command(dir, "reduce", fine_plate(dir), SIGTERM, 300), 143);
  // At once: the FEM stage under way is not waited for.
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
  expect_interrupted(dir, "reduce");
}

TEST(StageSignals, SigintDuringModesRecordsInterruptedAndExits130) {
  ScratchDir dir("stage_sigint_modes");
  EXPECT_EQ(signal_stage_command(dir, "modes", fine_plate(dir), SIGINT, 300), 130);
  expect_interrupted(dir, "modes");
}

// `mesh` claims its folder once the wing is meshed (a wing error the mesher finds leaves the
// folder as it was, test app.FemCommands.AWingErrorFoundWhileMeshingLeavesTheFolderAsItWas):
// a signal while gmsh meshes ends it at once with the folder's earlier mesh and manifest as
// they were, and gmsh's staging file (in TMPDIR) removed.
TEST(StageSignals, SigtermWhileMeshingLeavesTheFolderAsItWasAndExits143) {
  ScratchDir dir("stage_sigterm_mesh");
  ASSERT_EQ(run_flapsim("mesh " + kSourceDir + "/wings/flat_plate.toml -o " + (dir / "out").string()), 0);
  const std::string manifest = read_text(dir / "out" / "flapsim_outputs.toml");
  const std::string msh = read_text(dir / "out" / "mesh.msh");
  ASSERT_NE(manifest.find("status = 'complete'"), std::string::npos) << manifest;
  // The plate on 0.1 mm elements: some 2.6 s of meshing (a 2-core AMD EPYC), the signal at 0.7 s.
  std::ifstream in(kSourceDir + "/wings/flat_plate.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text = replace_once(text, "\nelement_size = 1.0\n", "\nelement_size = 0.1\n");
  std::ofstream(dir / "finest_plate.toml")
      << replace_once(text, "\nvein_element_size = 1.0\n", "\nvein_element_size = 0.1\n");
  const fs::path tmp = dir / "tmp";
  fs::create_directories(tmp);
  const char* earlier_tmpdir = std::getenv("TMPDIR");
  const std::string restore = earlier_tmpdir ? earlier_tmpdir : "";
  ::setenv("TMPDIR", tmp.c_str(), 1);
  const int status = signal_flapsim_when(
      {"mesh", (dir / "finest_plate.toml").string(), "-o", (dir / "out").string(), "--force"},
      [] { return true; }, SIGTERM, std::chrono::milliseconds(5), std::chrono::seconds(60),
      std::chrono::milliseconds(700));
  if (earlier_tmpdir)
    ::setenv("TMPDIR", restore.c_str(), 1);
  else
    ::unsetenv("TMPDIR");
  EXPECT_EQ(status, 143);
  EXPECT_EQ(read_text(dir / "out" / "flapsim_outputs.toml"), manifest);
  EXPECT_EQ(read_text(dir / "out" / "mesh.msh"), msh);
  EXPECT_TRUE(dir.temporaries().empty());
  EXPECT_TRUE(fs::is_empty(tmp)) << "gmsh's staging file left in TMPDIR";
}

// `run` of a flexible case without a chain file reduces the wing first (seconds to a minute).
// Before: a signal then was only acted on after the setup and one step ("interrupted after
// step 1 of 24", history.csv and summary.json written, 10 s after the signal for an AR-0.17
// plate). Now the setup is watched like the stages above: exit 130 at once, nothing written.
TEST(StageSignals, SigintDuringARunsSetupEndsItAtOnceWritingNothing) {
  ScratchDir dir("stage_sigint_run_setup");
  std::ofstream(dir / "case.toml") << replace_once(small_plate_case("flexible", 1, 0),
                                                   kSourceDir + "/wings/flat_plate.toml", fine_plate(dir));
  const std::string binary = FLAPSIM_BINARY;
  std::vector<std::string> args{binary, "run", (dir / "case.toml").string(), "-o", (dir / "out").string(), "-q"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  ASSERT_EQ(::posix_spawn(&pid, binary.c_str(), nullptr, nullptr, argv.data(), environ), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(600));  // in the reduction of 14,748 triangles (~3 s)
  ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 130);
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "summary.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "history.csv"));
  EXPECT_TRUE(dir.temporaries().empty());
}

}  // namespace
