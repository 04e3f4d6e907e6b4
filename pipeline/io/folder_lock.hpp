#pragma once
/// \file folder_lock.hpp
/// \brief One flapsim command writing into an output folder at a time. Two commands started
/// into the same folder (two cases with the same `name` run at once into out/<name>, a
/// second `make run` while the first runs, two sweeps with the same -o) used to both exit 0
/// with each other's files mixed: the second removed the first's outputs as it claimed the
/// folder, and the folder kept the last writer's history.csv next to files of the other.
/// The command holds an advisory lock (flock) on the folder itself while it writes; a second
/// command finds it held and stops before writing anything (io::OutputError, exit 4). The
/// lock is the kernel's: it goes with the process, however it ends (no stale lock file).
/// Where the file system cannot lock a folder (some network file systems) there is no lock,
/// as before.

#include <filesystem>
#include <string>

namespace flapsim::io {

class FolderLock {
 public:
  /// \brief Locks \p dir (which must exist) for \p command ("run", "sweep", ...).
  /// \throws OutputError naming the folder if another process holds its lock
  FolderLock(const std::filesystem::path& dir, const std::string& command);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

  /// Whether the lock is held (false where the file system cannot lock a folder).
  bool held() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

}  // namespace flapsim::io
