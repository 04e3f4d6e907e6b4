// `flapsim check` of a case whose wing is reduced in process builds the chain as `run` does
// (its FEM: seconds to a minute). Before: check showed nothing meanwhile (run shows "run:
// setup (the wing's FEM, reduction and modes) (stage 1 of 1): 14 s, 14 s in all"), and Ctrl-C
// killed it by the signal's default action (no message, no exit status 130). Now the setup
// is watched as run's is (pipeline/app/watched_setup.hpp, stage_monitor.hpp).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "common/file_contents.hpp"
#include "pipeline/app/watched_setup.hpp"
#include "pipeline/io/case_file.hpp"
#include "robustness_helpers.hpp"

extern char** environ;

using namespace flapsim;
using namespace flapsim::test;
using namespace std::chrono_literals;

namespace {

TEST(CheckProgress, TheSetupOfAWingReducedInProcessIsShownAsRunShowsIt) {
  ScratchDir dir("check_progress");
  std::ofstream(dir / "case.toml") << small_plate_case("flexible", 1, 0);  // the flat plate, 2 bodies
  const io::Case c = io::load_case_file((dir / "case.toml").string());
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  app::StageMonitor::Options o;
  o.show_after = 1ms;  // the plate's FEM lasts ~0.3 s; the commands show a stage after 2 s
  o.display = app::StageMonitor::Options::Display::log;
  o.stream = f;
  o.watch_signals = false;
  const app::FsiSetup setup = app::build_fsi_setup_watched(c, {}, "check", {}, o);
  const std::string text = file_contents(f);
  std::fclose(f);
  EXPECT_EQ(setup.chain().num_bodies(), 2);
  EXPECT_EQ(text.rfind("check: setup (the wing's FEM, reduction and modes) (stage 1 of 1): ", 0), 0u) << text;
}

// The fine plate of StageSignals (0.25 mm mesh, 14,748 triangles, ~3 s of FEM): SIGINT
// 0.6 s into check ends it at once, exit 130, as the model stages and run's setup.
TEST(CheckProgress, SigintDuringChecksReductionEndsItWithStatus130) {
  ScratchDir dir("check_sigint");
  std::ifstream in(kSourceDir + "/wings/flat_plate.toml");
  std::string wing((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  wing = replace_once(wing, "\nelement_size = 1.0\n", "\nelement_size = 0.25\n");
  std::ofstream(dir / "fine_plate.toml") << replace_once(wing, "\nvein_element_size = 1.0\n", "\nvein_element_size = 0.25\n");
  std::ofstream(dir / "case.toml") << replace_once(small_plate_case("flexible", 1, 0),
                                                   kSourceDir + "/wings/flat_plate.toml",
                                                   (dir / "fine_plate.toml").string());
  const auto err = dir / "stderr.txt";
  // Spawned (not a shell's background job, which would start with SIGINT ignored), its
  // stderr into a file.
  const std::string binary = FLAPSIM_BINARY, case_file = (dir / "case.toml").string();
  std::vector<char*> argv{const_cast<char*>(binary.c_str()), const_cast<char*>("check"),
                          const_cast<char*>(case_file.c_str()), nullptr};
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&files, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const char* was = std::getenv("FLAPSIM_QUIET");
  const std::string saved = was ? was : "";
  ::setenv("FLAPSIM_QUIET", "1", 1);
  pid_t pid = 0;
  const int spawned = ::posix_spawn(&pid, binary.c_str(), &files, nullptr, argv.data(), environ);
  // Only the child is quiet: the tests after this one (a sweep's progress lines,
  // app.SweepProgress.*) must not inherit FLAPSIM_QUIET from this process.
  if (was) ::setenv("FLAPSIM_QUIET", saved.c_str(), 1);
  else ::unsetenv("FLAPSIM_QUIET");
  ASSERT_EQ(spawned, 0);
  posix_spawn_file_actions_destroy(&files);
  std::this_thread::sleep_for(600ms);
  ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by the signal's default action";
  EXPECT_EQ(WEXITSTATUS(status), 130) << read_text(err);
  EXPECT_NE(read_text(err).find("flapsim: check interrupted by SIGINT during setup (the wing's FEM, reduction and modes)"),
            std::string::npos)
      << read_text(err);
}

}  // namespace
