// The end of a command's claim on its folder, recorded once: a signal watcher on another
// thread (pipeline/app/stage_monitor.hpp) and the command itself may both try to record how
// it ended; the first end stays (an "interrupted" is not overwritten by "complete").
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/scratch_dir.hpp"
#include "pipeline/io/output_manifest.hpp"

namespace io = flapsim::io;

namespace {

std::string manifest(const flapsim::test::ScratchDir& dir) {
  std::ifstream in(dir / io::kManifestName);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(OutputClaimEnd, AnInterruptionRecordedFirstIsNotOverwrittenByTheCommandsOwnEnd) {
  flapsim::test::ScratchDir dir("claim_end_interrupted");
  io::OutputFolderClaim claim(dir.path(), "reduce");
  EXPECT_EQ(claim.end_if_open("interrupted"), io::OutputFolderClaim::State::unclaimed);
  EXPECT_FALSE(std::filesystem::exists(dir / io::kManifestName));  // nothing written before the claim
  claim.claim(false);
  EXPECT_EQ(claim.end_if_open("interrupted"), io::OutputFolderClaim::State::open);
  claim.finish("complete");
  EXPECT_NE(manifest(dir).find("status = 'interrupted'"), std::string::npos) << manifest(dir);
  EXPECT_EQ(manifest(dir).find("complete"), std::string::npos) << manifest(dir);
}

TEST(OutputClaimEnd, ASignalAfterTheCommandsEndChangesNothing) {
  flapsim::test::ScratchDir dir("claim_end_complete");
  io::OutputFolderClaim claim(dir.path(), "mesh");
  claim.claim(false);
  claim.finish("complete");
  EXPECT_EQ(claim.end_if_open("interrupted"), io::OutputFolderClaim::State::ended);
  EXPECT_NE(manifest(dir).find("status = 'complete'"), std::string::npos) << manifest(dir);
}

}  // namespace
