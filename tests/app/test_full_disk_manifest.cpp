// A command ended by a full disk still records how it ended. Before: `flapsim run` into a
// 300 KiB tmpfs with ParaView output every step exited 4 (right), but the folder's
// flapsim_outputs.toml kept `status = 'running'`: the last record needs a page of the disk
// that the run had filled. Now the claim keeps 64 KiB in reserve (a temporary file, released
// just before the last record; pipeline/io/output_manifest.hpp) and the manifest says 'failed'.
// Needs a small tmpfs: a private mount namespace (unshare -rm; root or user namespaces),
// else the test is skipped.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "robustness_helpers.hpp"

using namespace flapsim::test;

namespace {

/// Runs `flapsim ARGS` in a private mount namespace with a tmpfs of \p size at DIR/mnt,
/// after it `ls -aR` of the mount into DIR/listing.txt; stderr into DIR/stderr.txt. Returns
/// the exit status, or -99 if no tmpfs can be mounted here.
int run_on_small_tmpfs(const ScratchDir& dir, const std::string& size, const std::string& args) {
  const std::string mnt = (dir / "mnt").string();
  std::filesystem::create_directories(mnt);
  std::ofstream(dir / "in_namespace.sh")
      << "mount -t tmpfs -o size=" << size << " none '" << mnt << "' || exit 99\n"
      << "FLAPSIM_QUIET=1 OMP_NUM_THREADS=1 '" << FLAPSIM_BINARY << "' " << args << " > /dev/null 2> '"
      << (dir / "stderr.txt").string() << "'\ns=$?\n"
      << "ls -aR '" << mnt << "' > '" << (dir / "listing.txt").string() << "'\nexit $s\n";
  const int status = std::system(("unshare -rm sh '" + (dir / "in_namespace.sh").string() + "' 2> /dev/null").c_str());
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return code == 99 || code == 127 ? -99 : code;
}

// A sweep whose time series cannot be published on a full disk: exit 4, and the message says
// why. Before: "cannot copy the working file: Success" (the error code was overwritten by the
// clean-up before the message was made; pipeline/io/csv_writer.cpp).
TEST(FullDiskManifest, ASweepOnAFullDiskExitsFourWithTheCause) {
  ScratchDir dir("full_disk_sweep");
  std::ofstream(dir / "case.toml") << small_plate_case("rigid", 3, 0);
  const int code = run_on_small_tmpfs(dir, "40k", "sweep '" + (dir / "case.toml").string() +
                                                      "' --vary kinematics.rotation_phase=-0.1,0,0.1 -j 1 -o '" +
                                                      (dir / "mnt").string() + "/sw'");
  if (code == -99) GTEST_SKIP() << "no private tmpfs here (unshare -rm, mount)";
  EXPECT_EQ(code, 4);
  const std::string err = read_text(dir / "stderr.txt");
  EXPECT_NE(err.find("cannot write"), std::string::npos) << err;
  EXPECT_EQ(err.find(": Success"), std::string::npos) << err;
  // The case whose history.csv could not be published leaves no temporary file (before: its
  // history.csv.tmp.<pid>, the constructor of the series threw after creating it), and the
  // sweep stops at the first case that cannot write (before: a case folder that freed its
  // space let the next cases fail alike, and the sweep exited 0).
  const std::string listing = read_text(dir / "listing.txt");
  EXPECT_EQ(listing.find(".tmp."), std::string::npos) << listing;
  EXPECT_NE(err.find("so the sweep stops"), std::string::npos) << err;
}

TEST(FullDiskManifest, ARunThatFillsTheDiskRecordsFailedNotRunning) {
  ScratchDir dir("full_disk_manifest");
  std::ofstream(dir / "case.toml") << small_plate_case("rigid", 3, 1);
  const std::string mnt = (dir / "mnt").string();
  std::filesystem::create_directories(mnt);
  // Inside the namespace: mount, run, copy out what the folder holds (the mount ends with it).
  const std::string script =
      "mount -t tmpfs -o size=300k none '" + mnt + "' || exit 99; "
      "FLAPSIM_QUIET=1 OMP_NUM_THREADS=1 '" + std::string(FLAPSIM_BINARY) + "' run '" + (dir / "case.toml").string() +
      "' -o '" + mnt + "/run' > /dev/null 2> '" + (dir / "stderr.txt").string() + "'; s=$?; "
      "cp '" + mnt + "/run/flapsim_outputs.toml' '" + (dir / "manifest.txt").string() + "'; "
      "ls -a '" + mnt + "/run' > '" + (dir / "listing.txt").string() + "'; exit $s";
  std::ofstream(dir / "in_namespace.sh") << script << "\n";
  const int status = std::system(("unshare -rm sh '" + (dir / "in_namespace.sh").string() + "' 2> /dev/null").c_str());
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code == 99 || code == 1 || code == 127) GTEST_SKIP() << "no private tmpfs here (unshare -rm, mount): " << code;
  EXPECT_EQ(code, 4) << read_text(dir / "stderr.txt");
  const std::string manifest = read_text(dir / "manifest.txt");
  EXPECT_NE(manifest.find("status = 'failed'"), std::string::npos) << manifest;
  const std::string listing = read_text(dir / "listing.txt");
  EXPECT_EQ(listing.find(".tmp."), std::string::npos) << listing;
  // flapsim's message, not VTK's dump of its pipeline.
  const std::string err = read_text(dir / "stderr.txt");
  EXPECT_NE(err.find("flapsim: output error: cannot write"), std::string::npos) << err;
  EXPECT_EQ(err.find("vtkExecutive"), std::string::npos) << err;
}

TEST(FullDiskManifest, ADiskWithoutRoomForTheLastRecordIsRefusedBeforeAnythingIsWritten) {
  // A disk with less than the 64 KiB the claim keeps for the manifest's last record (a 48 KiB
  // tmpfs): before, the run started, filled the disk, exited 4 and left the manifest saying
  // 'running'; now the claim is refused (exit 4, naming the folder and the room) and no
  // manifest says 'running'.
  ScratchDir dir("full_disk_no_reserve");
  std::ofstream(dir / "case.toml") << small_plate_case("rigid", 3, 1);
  const std::string mnt = (dir / "mnt").string();
  std::filesystem::create_directories(mnt);
  const std::string script =
      "mount -t tmpfs -o size=48k none '" + mnt + "' || exit 99; "
      "FLAPSIM_QUIET=1 OMP_NUM_THREADS=1 '" + std::string(FLAPSIM_BINARY) + "' run '" + (dir / "case.toml").string() +
      "' -o '" + mnt + "/run' > /dev/null 2> '" + (dir / "stderr.txt").string() + "'; s=$?; "
      "cp '" + mnt + "/run/flapsim_outputs.toml' '" + (dir / "manifest.txt").string() + "' 2> /dev/null; exit $s";
  std::ofstream(dir / "in_namespace.sh") << script << "\n";
  const int status = std::system(("unshare -rm sh '" + (dir / "in_namespace.sh").string() + "' 2> /dev/null").c_str());
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code == 99 || code == 1 || code == 127) GTEST_SKIP() << "no private tmpfs here (unshare -rm, mount): " << code;
  const std::string err = read_text(dir / "stderr.txt");
  EXPECT_EQ(code, 4) << err;
  EXPECT_NE(err.find("64 KiB"), std::string::npos) << err;
  EXPECT_EQ(read_text(dir / "manifest.txt").find("running"), std::string::npos);
}

}  // namespace
