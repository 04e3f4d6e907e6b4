// A full disk for every command that writes (issue: mesh exited 0 with a truncated
// mesh.msh and an empty mesh.vtu; modes left a truncated fem.vtu; run and reduce left
// truncated .vtp files under their final names). A file-size limit (ulimit -f) makes
// every write past it fail with EFBIG, as a full disk fails with ENOSPC: flapsim ignores
// SIGXFSZ, whose default (a user's shell's) killed it mid-write with the temporary files
// left (exit 153 from the shell, −1 here). Limits in 512-byte blocks (dash's ulimit -f); for each command several limits
// (the smallest fail the first files, the largest fit everything): the exit status is 0 (everything fitted)
// or 4 (output error), at least one limit gives 4, and no file under a final name is
// truncated; the manifest does not say "running".
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "robustness_helpers.hpp"

namespace fs = std::filesystem;
using namespace flapsim::test;

namespace {

void expect_exit_4_and_nothing_truncated(const std::string& name, const std::string& args_before_out,
                                         const std::vector<int>& limits) {
  ScratchDir dir(name);
  int failures = 0;
  for (int blocks : limits) {
    const fs::path out = dir / ("out_" + std::to_string(blocks));
    const int status = run_flapsim_with_file_limit(args_before_out + " -o " + out.string(), blocks);
    EXPECT_TRUE(status == 0 || status == 4) << name << ": limit " << blocks << " gave exit " << status;
    failures += status == 4;
    const auto bad = truncated_files(dir, out);
    EXPECT_TRUE(bad.empty()) << name << ": limit " << blocks << ": truncated " << bad.front();
    EXPECT_TRUE(dir.temporaries().empty()) << name << ": limit " << blocks << ": " << dir.temporaries().front();
    // A command that ended by an output error says so in the folder's manifest (when the
    // manifest could still be written), never "running".
    std::ifstream manifest(out / "flapsim_outputs.toml");
    const std::string text((std::istreambuf_iterator<char>(manifest)), {});
    EXPECT_EQ(text.find("'running'"), std::string::npos) << name << ": limit " << blocks << ":\n" << text;
  }
  EXPECT_GT(failures, 0) << name << ": no limit was small enough to fail a write";
}

const std::string kTinyWing = kSourceDir + "/tests/data/valid_tiny_wing.toml";

TEST(DiskFull, MeshExitsFourAndLeavesNoTruncatedFile) {
  expect_exit_4_and_nothing_truncated("diskfull_mesh", "mesh " + kTinyWing, {2, 64, 512});
}

TEST(DiskFull, ModesExitsFourAndLeavesNoTruncatedFile) {
  expect_exit_4_and_nothing_truncated("diskfull_modes", "modes " + kTinyWing + " --modes 4", {2, 64, 1024});
}

TEST(DiskFull, ReduceExitsFourAndLeavesNoTruncatedFile) {
  expect_exit_4_and_nothing_truncated("diskfull_reduce", "reduce " + kTinyWing + " --bodies 2 --modes 4", {2, 12, 64});
}

TEST(DiskFull, RunExitsFourAndLeavesNoTruncatedFile) {
  ScratchDir cases("diskfull_run_case");
  std::ofstream(cases / "case.toml") << small_plate_case("rigid", 1, 1);
  expect_exit_4_and_nothing_truncated("diskfull_run", "run " + (cases / "case.toml").string(), {2, 12, 64});
}

}  // namespace
