#include "pipeline/io/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>

#include "pipeline/io/atomic_file.hpp"

namespace flapsim::io {

FolderLock::FolderLock(const std::filesystem::path& dir, const std::string& command) {
  const std::filesystem::path folder = dir.empty() ? std::filesystem::path(".") : dir;
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;  // the folder's own errors are reported where it is written
  if (::flock(fd, LOCK_EX | LOCK_NB) == 0) {
    fd_ = fd;
    return;
  }
  const int error = errno;
  ::close(fd);
  if (error == EWOULDBLOCK)
    throw OutputError(folder, "another flapsim command is writing into this folder now; 'flapsim " + command +
                                  "' would replace or mix its files: wait until it ends, or choose another "
                                  "folder (-o; a case's default folder is out/<name>)");
  // ENOLCK, EBADF (a network file system that cannot lock a folder): no lock.
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);  // closing releases the lock
}

}  // namespace flapsim::io
