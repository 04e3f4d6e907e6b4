// One run per output folder: a rerun removes the previous outputs of the same command,
// another command's outputs are replaced only when forced.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/scratch_dir.hpp"
#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/output_manifest.hpp"

namespace fs = std::filesystem;
namespace io = flapsim::io;

namespace {

void touch(const fs::path& p) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << "x\n";
}

TEST(OutputManifest, ARerunRemovesEveryFileOfTheEarlierRun) {
  // The issue: 270 stale .vtp after a shorter rerun, and an earlier summary.json saying
  // "ok" next to an interrupted rerun.
  flapsim::test::ScratchDir dir("manifest_rerun");
  io::claim_output_folder(dir.path(), "run", false);
  for (int i = 0; i < 270; ++i) touch(dir / ("vtk/wing_" + std::to_string(i) + ".vtp"));
  touch(dir / "summary.json");
  touch(dir / "history.csv");
  touch(dir / "vtk/chain_000001.vtp.tmp.99");  // a temporary left by a killed run
  touch(dir / "notes.txt");                    // not flapsim's: kept
  touch(dir / "vtk/mine.txt");                 // not flapsim's: kept
  io::record_command_status(dir.path(), "run", "complete");
  io::claim_output_folder(dir.path(), "run", false);
  EXPECT_FALSE(fs::exists(dir / "summary.json"));
  EXPECT_FALSE(fs::exists(dir / "history.csv"));
  EXPECT_FALSE(fs::exists(dir / "vtk/wing_5.vtp"));
  EXPECT_FALSE(fs::exists(dir / "vtk/chain_000001.vtp.tmp.99"));
  EXPECT_TRUE(fs::exists(dir / "notes.txt"));
  EXPECT_TRUE(fs::exists(dir / "vtk/mine.txt"));
  const std::string manifest = [&] {
    std::ifstream in(dir / io::kManifestName);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  EXPECT_NE(manifest.find("[run]"), std::string::npos) << manifest;
  EXPECT_NE(manifest.find("running"), std::string::npos) << manifest;
}

TEST(OutputManifest, ARerunRemovesThePicturesDrawnFromTheEarlierRun) {
  // make run's preview.png, make snapshot's snapshots/ and make movie's movie.mp4 are drawn
  // from a run's frames; a rerun with vtk_every = 0 removed the frames and left the pictures
  // of the earlier run as if they were its own.
  flapsim::test::ScratchDir dir("manifest_pictures");
  io::claim_output_folder(dir.path(), "run", false);
  for (const char* f : {"preview.png", "movie.mp4", "snapshots/front_phase_0.25.png",
                        "snapshots/side_phase_0.50.png", "snapshots/phase_0.75.png"})
    touch(dir / f);
  touch(dir / "my_figure.png");  // not flapsim's: kept
  io::record_command_status(dir.path(), "run", "complete");
  io::claim_output_folder(dir.path(), "run", false);
  for (const char* f : {"preview.png", "movie.mp4", "snapshots"}) EXPECT_FALSE(fs::exists(dir / f)) << f;
  EXPECT_TRUE(fs::exists(dir / "my_figure.png"));
}

TEST(OutputManifest, AnotherCommandsOutputsAreReplacedOnlyWhenForced) {
  // run -o into a reduce folder replaced its summary.json.
  flapsim::test::ScratchDir dir("manifest_clash");
  io::claim_output_folder(dir.path(), "reduce", false);
  for (const auto& f : io::command_outputs("reduce")) touch(dir / f);
  io::record_command_status(dir.path(), "reduce", "complete");
  try {
    io::claim_output_folder(dir.path(), "run", false);
    ADD_FAILURE() << "run claimed a reduce folder";
  } catch (const io::OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("flapsim reduce"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--force"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::exists(dir / "summary.json"));
  EXPECT_TRUE(fs::exists(dir / "chain.toml"));
  io::claim_output_folder(dir.path(), "run", true);
  EXPECT_FALSE(fs::exists(dir / "summary.json"));
  EXPECT_FALSE(fs::exists(dir / "chain.toml"));  // the whole reduce output goes
}

TEST(OutputManifest, CommandsWithoutSharedNamesShareAFolder) {
  // make hawkmoth-model: mesh, modes and reduce into out/hawkmoth.
  flapsim::test::ScratchDir dir("manifest_share");
  for (const char* c : {"mesh", "modes", "reduce"}) {
    io::claim_output_folder(dir.path(), c, false);
    for (const auto& f : io::command_outputs(c)) touch(dir / f);
    io::record_command_status(dir.path(), c, "complete");
  }
  io::claim_output_folder(dir.path(), "mesh", false);  // rerun of mesh: only its files go
  EXPECT_FALSE(fs::exists(dir / "mesh.msh"));
  EXPECT_TRUE(fs::exists(dir / "fem.vtu"));
  EXPECT_TRUE(fs::exists(dir / "chain.toml"));
}

TEST(OutputManifest, AFolderWithoutManifestIsJudgedByItsFiles) {
  // Outputs of an older flapsim (no manifest): reduce's files make summary.json reduce's.
  flapsim::test::ScratchDir dir("manifest_none");
  touch(dir / "summary.json");
  touch(dir / "chain.toml");
  EXPECT_THROW(io::claim_output_folder(dir.path(), "run", false), io::OutputError);
  // An older run folder: its own summary.json is replaced.
  flapsim::test::ScratchDir run("manifest_none_run");
  touch(run / "summary.json");
  touch(run / "vtk/wing_000010.vtp");
  io::claim_output_folder(run.path(), "run", false);
  EXPECT_FALSE(fs::exists(run / "summary.json"));
  EXPECT_FALSE(fs::exists(run / "vtk/wing_000010.vtp"));
}

TEST(OutputManifest, ReduceAndOptimizeDoNotReplaceEachOthersReport) {
  // Both write report.md: optimize into a reduce folder, and reduce into an optimize folder,
  // each replaced the other's report (exit 0, the other command's report gone).
  flapsim::test::ScratchDir reduced("manifest_reduce_then_optimize");
  io::claim_output_folder(reduced.path(), "reduce", false);
  for (const auto& f : io::command_outputs("reduce")) touch(reduced / f);
  io::record_command_status(reduced.path(), "reduce", "complete");
  try {
    io::refuse_clashing_outputs(reduced.path(), "optimize");
    ADD_FAILURE() << "optimize took a reduce folder";
  } catch (const io::OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("'flapsim reduce' (report.md)"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::exists(reduced / "report.md"));

  flapsim::test::ScratchDir optimized("manifest_optimize_then_reduce");
  touch(optimized / "evaluations.csv");  // optimize keeps no manifest
  touch(optimized / "optimum.toml");
  touch(optimized / "report.md");
  touch(optimized / "runs/0123abcd/summary.json");
  io::refuse_clashing_outputs(optimized.path(), "optimize");  // its own rerun: resumed, not refused
  try {
    io::claim_output_folder(optimized.path(), "reduce", false);
    ADD_FAILURE() << "reduce claimed an optimize folder";
  } catch (const io::OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("'flapsim optimize' (report.md)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--force"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::exists(optimized / "report.md"));
  io::claim_output_folder(optimized.path(), "reduce", true);
  EXPECT_FALSE(fs::exists(optimized / "report.md"));
  EXPECT_FALSE(fs::exists(optimized / "evaluations.csv"));  // the optimisation's outputs go together
  EXPECT_TRUE(fs::exists(optimized / "runs/0123abcd/summary.json"));  // its runs' folders are theirs

  // A folder not made yet, or one with unrelated files, holds nothing to refuse.
  io::refuse_clashing_outputs(optimized / "not_yet", "optimize");
  flapsim::test::ScratchDir other("manifest_optimize_fresh");
  touch(other / "report.md");  // no command's own files beside it: the user's
  io::refuse_clashing_outputs(other.path(), "optimize");
}

TEST(OutputManifest, AnUnwritableFolderIsAnOutputError) {
  // A regular file where the folder should be (independent of the user's permissions).
  flapsim::test::ScratchDir dir("manifest_unwritable");
  touch(dir / "file");
  EXPECT_THROW(io::claim_output_folder(dir / "file" / "sub", "run", false), io::OutputError);
}

}  // namespace

namespace {

// The manifest is a file in the output folder, open to anyone who can write there. The
// names it lists are removed on a rerun, so only names a command writes are taken: a
// manifest listing "../victim.txt", an absolute path or "*" removes none of them.
TEST(OutputManifest, AManifestNamingOtherFilesRemovesNoneOfThem) {
  flapsim::test::ScratchDir dir("manifest_tampered");
  const fs::path out = dir / "out";
  const fs::path victim = dir / "victim.txt", absolute = dir / "absolute.txt";
  touch(victim);
  touch(absolute);
  touch(out / "notes.txt");
  touch(out / "history.csv");
  std::ofstream(out / io::kManifestName) << "[run]\nstatus = \"complete\"\noutputs = [\"../victim.txt\", \""
                                         << absolute.string() << "\", \"*\", \"history.csv\"]\n";
  io::claim_output_folder(out, "run", false);
  EXPECT_TRUE(fs::exists(victim));
  EXPECT_TRUE(fs::exists(absolute));
  EXPECT_TRUE(fs::exists(out / "notes.txt"));
  EXPECT_FALSE(fs::exists(out / "history.csv"));  // run's own: removed as before
}

// A manifest that toml++ 3.x would abort on (a header without a name) is an output error
// naming the manifest, like any unreadable manifest.
TEST(OutputManifest, AManifestTomlppCannotReadSafelyIsAnOutputError) {
  flapsim::test::ScratchDir dir("manifest_broken");
  std::ofstream(dir / io::kManifestName) << "[run]\nstatus = \"complete\"\n[#x]\n";
  try {
    io::claim_output_folder(dir.path(), "run", false);
    ADD_FAILURE() << "a broken manifest was read";
  } catch (const io::OutputError& e) {
    EXPECT_NE(std::string(e.what()).find(io::kManifestName), std::string::npos) << e.what();
  }
}

// A command that leaves by an exception after claiming its folder records "failed" (the
// issue's case: an output error in a run left "running" for good).
TEST(OutputManifest, ACommandEndedByAnExceptionIsRecordedFailed) {
  flapsim::test::ScratchDir dir("manifest_failed");
  const auto status = [&] {
    std::ifstream in(dir / io::kManifestName);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  try {
    io::OutputFolderClaim claim(dir.path(), "run");
    claim.claim(false);
    EXPECT_NE(status().find("'running'"), std::string::npos) << status();
    throw io::OutputError(dir / "history.csv", "no space left on device");
  } catch (const io::OutputError&) {
  }
  EXPECT_NE(status().find("'failed'"), std::string::npos) << status();
  {
    io::OutputFolderClaim claim(dir.path(), "run");
    claim.claim(false);
    claim.finish("complete");
  }
  EXPECT_NE(status().find("'complete'"), std::string::npos) << status();
}

}  // namespace
