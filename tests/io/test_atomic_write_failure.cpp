// Atomic writes when the disk is full: a file-size limit (RLIMIT_FSIZE, with SIGXFSZ
// ignored so that write() fails with EFBIG instead of killing the process) in a forked
// child. Every writer must report the failure and leave no file under the final name.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "common/scratch_dir.hpp"
#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/csv_writer.hpp"
#include "pipeline/io/vtk_writers.hpp"

namespace fs = std::filesystem;
namespace io = flapsim::io;

namespace {

// Runs `write` in a child limited to `limit` bytes per file. Returns 0 if it completed,
// 4 if it threw io::OutputError, 1 for any other exception, -1 if the child died.
int write_with_file_size_limit(rlim_t limit, const std::function<void()>& write) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    struct rlimit r {limit, limit};
    ::setrlimit(RLIMIT_FSIZE, &r);
    int status = 0;
    try {
      write();
    } catch (const io::OutputError&) {
      status = 4;
    } catch (...) {
      status = 1;
    }
    ::_exit(status);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(AtomicWriteFailure, ATextFileBeyondTheLimitIsAnOutputErrorAndNoFile) {
  flapsim::test::ScratchDir dir("atomic_fsize_text");
  const std::string text(64 * 1024, 'x');
  EXPECT_EQ(write_with_file_size_limit(4096, [&] { io::write_text_atomically(dir / "a.txt", text); }), 4);
  EXPECT_FALSE(fs::exists(dir / "a.txt"));
  EXPECT_TRUE(dir.temporaries().empty());
  // The same write with room completes (the limit is what failed it).
  EXPECT_EQ(write_with_file_size_limit(1 << 20, [&] { io::write_text_atomically(dir / "a.txt", text); }), 0);
  EXPECT_EQ(fs::file_size(dir / "a.txt"), text.size());
}

TEST(AtomicWriteFailure, AnEarlierCompleteFileIsKeptWhenItsReplacementFails) {
  flapsim::test::ScratchDir dir("atomic_fsize_keep");
  io::write_text_atomically(dir / "a.txt", "old\n");
  EXPECT_EQ(write_with_file_size_limit(4096, [&] { io::write_text_atomically(dir / "a.txt", std::string(65536, 'y')); }),
            4);
  std::ifstream in(dir / "a.txt");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "old");
}

TEST(AtomicWriteFailure, AVtkFileBeyondTheLimitIsAnOutputErrorAndNoFile) {
  // VTK's writer returned success with a truncated file; the file must end with
  // "</VTKFile>\n" and VTK's error code must be clear before the rename.
  flapsim::test::ScratchDir dir("atomic_fsize_vtk");
  io::PolyDataMesh mesh;
  const int n = 20000;
  mesh.points = Eigen::Matrix3Xd::Random(3, n);
  mesh.point_data.add_scalar("s", Eigen::VectorXd::Random(n));
  for (int i = 0; i + 2 < n; i += 3) mesh.polygons.push_back({i, i + 1, i + 2});
  EXPECT_EQ(write_with_file_size_limit(8192, [&] { io::write_vtp(dir / "m.vtp", mesh); }), 4);
  EXPECT_FALSE(fs::exists(dir / "m.vtp"));
  EXPECT_TRUE(dir.temporaries().empty());
  EXPECT_EQ(write_with_file_size_limit(RLIM_INFINITY, [&] { io::write_vtp(dir / "m.vtp", mesh); }), 0);
  EXPECT_TRUE(io::file_ends_with(dir / "m.vtp", "</VTKFile>\n"));
}

TEST(AtomicWriteFailure, ACsvTimeSeriesBeyondTheLimitFailsAndKeepsWholeRows) {
  flapsim::test::ScratchDir dir("atomic_fsize_csv");
  const int status = write_with_file_size_limit(4096, [&] {
    io::CsvTimeSeriesWriter w(dir / "h.csv", {"t_s", "lift_N", "cl"}, 5);
    for (int i = 0; i < 2000; ++i) w.append({i * 1e-3, 1.0 / (i + 1), 0.123456789 * i});
    w.close();
  });
  EXPECT_EQ(status, 4);
  // What is published is the header and whole rows.
  ASSERT_TRUE(fs::exists(dir / "h.csv"));
  EXPECT_TRUE(io::file_ends_with(dir / "h.csv", "\n"));
  EXPECT_LE(fs::file_size(dir / "h.csv"), 4096u);
}

// A series whose header cannot be published (the disk already full when a sweep's next case
// opens its history.csv) leaves no working file. Before: the constructor threw after creating
// history.csv.tmp.<pid>, and no destructor removed it (a sweep on a full tmpfs left
// 02_0.1/history.csv.tmp.<pid> behind).
TEST(AtomicWriteFailure, ACsvTimeSeriesWhoseHeaderCannotBePublishedLeavesNoFile) {
  flapsim::test::ScratchDir dir("atomic_fsize_csv_header");
  const std::vector<std::string> columns(200, "a_long_column_name_N");  // 4200 bytes of header
  const int status = write_with_file_size_limit(4096, [&] { io::CsvTimeSeriesWriter w(dir / "h.csv", columns); });
  EXPECT_EQ(status, 4);
  EXPECT_FALSE(fs::exists(dir / "h.csv"));
  EXPECT_TRUE(dir.temporaries().empty());
}

TEST(AtomicWriteFailure, PublishRefusesATruncatedFileFromAnExternalWriter) {
  // A writer that stops short (as gmsh does on a full disk, without an error).
  flapsim::test::ScratchDir dir("atomic_truncated");
  EXPECT_THROW(io::publish_file_atomically(
                   dir / "mesh.msh", [](const fs::path& tmp) { std::ofstream(tmp) << "$MeshFormat\n4.1 0 8\n$End"; },
                   "$EndElements\n"),
               io::OutputError);
  EXPECT_FALSE(fs::exists(dir / "mesh.msh"));
  EXPECT_TRUE(dir.temporaries().empty());
}

}  // namespace
