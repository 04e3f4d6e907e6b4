#include "pipeline/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

namespace flapsim::io {

namespace fs = std::filesystem;

void ensure_directory(const fs::path& dir) {
  if (dir.empty()) return;
  std::error_code ec;
  if (fs::is_directory(dir, ec)) return;
  // A file of that name (an -o that names a file): said as such, not as the system's
  // "Not a directory" of create_directories.
  if (fs::exists(dir, ec)) throw OutputError(dir, "exists and is not a directory");
  fs::create_directories(dir, ec);
  if (ec) throw OutputError(dir, "cannot create directory: " + ec.message());
  if (!fs::is_directory(dir, ec)) throw OutputError(dir, "exists and is not a directory");
}

void prepare_output_directory(const fs::path& dir) {
  ensure_directory(dir);
  const fs::path probe = temporary_path(dir / ".flapsim_write_probe");
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw OutputError(dir, std::string("the output folder is not writable: ") + std::strerror(errno));
  ::close(fd);
  std::error_code ignored;
  fs::remove(probe, ignored);
}

fs::path temporary_path(const fs::path& path) {
  fs::path tmp = path;
  tmp += ".tmp." + std::to_string(static_cast<long>(::getpid()));
  return tmp;
}

void remove_stale_temporaries(const fs::path& dir) {
  const std::string own = ".tmp." + std::to_string(static_cast<long>(::getpid()));
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    if (it.depth() > 1) {
      it.disable_recursion_pending();
      continue;
    }
    const std::string name = it->path().filename().string();
    const auto at = name.rfind(".tmp.");
    if (at == std::string::npos || !it->is_regular_file(ec)) continue;
    if (name.compare(at, std::string::npos, own) == 0) continue;  // this process's own, in use
    std::error_code rm;
    fs::remove(it->path(), rm);
    if (rm) throw OutputError(it->path(), "cannot remove a temporary file a killed run left: " + rm.message());
  }
}

void sync_file(const fs::path& file, const fs::path& reported) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw OutputError(reported, std::string("cannot open the written file: ") + std::strerror(errno));
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0) throw OutputError(reported, std::string("flushing to disk failed: ") + std::strerror(err));
}

bool file_ends_with(const fs::path& file, std::string_view tail) {
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in) return false;
  const std::streamoff size = in.tellg();
  if (size < static_cast<std::streamoff>(tail.size())) return false;
  std::string end(tail.size(), '\0');
  in.seekg(size - static_cast<std::streamoff>(tail.size()));
  in.read(end.data(), static_cast<std::streamsize>(end.size()));
  return in && end == tail;
}

namespace {
/// Synchronises a directory's entries (a rename in it) with the disk; best effort: some
/// file systems refuse fsync on a directory, and the data itself is already on disk.
void sync_directory(const fs::path& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  (void)::fsync(fd);
  ::close(fd);
}
}  // namespace

void replace_file(const fs::path& from, const fs::path& to, bool sync_dir) {
  std::error_code ec;
  fs::rename(from, to, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(from, ignored);
    throw OutputError(to, "cannot rename the temporary file onto it: " + ec.message());
  }
  if (sync_dir) sync_directory(to.parent_path());
}

void sync_file_system(const fs::path& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw OutputError(dir, std::string("cannot open the folder to flush it: ") + std::strerror(errno));
  const int rc = ::syncfs(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0) throw OutputError(dir, std::string("flushing to disk failed: ") + std::strerror(err));
}

namespace {

/// Removes a temporary file unless released: cleans up on every error path.
class TemporaryGuard {
 public:
  explicit TemporaryGuard(fs::path p) : path_(std::move(p)) {}
  ~TemporaryGuard() {
    if (!released_) {
      std::error_code ignored;
      fs::remove(path_, ignored);
    }
  }
  void release() { released_ = true; }

 private:
  fs::path path_;
  bool released_ = false;
};

}  // namespace

void write_file_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  ensure_directory(path.parent_path());
  const fs::path tmp = temporary_path(path);
  TemporaryGuard guard(tmp);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw OutputError(path, std::string("cannot open a temporary file: ") + std::strerror(errno));
    write(out);
    out.flush();
    if (!out) throw OutputError(path, "write failed (disk full or file-size limit?)");
    out.close();
    if (out.fail()) throw OutputError(path, "closing the temporary file failed (disk full?)");
  }
  sync_file(tmp, path);
  replace_file(tmp, path);
  guard.release();
}

void publish_file_atomically(const fs::path& path, const std::function<void(const fs::path& tmp)>& write,
                             std::string_view required_tail, Flush flush) {
  ensure_directory(path.parent_path());
  const fs::path tmp = temporary_path(path);
  TemporaryGuard guard(tmp);
  write(tmp);
  std::error_code ec;
  if (!fs::is_regular_file(tmp, ec)) throw OutputError(path, "the writer produced no file");
  if (!required_tail.empty() && !file_ends_with(tmp, required_tail))
    throw OutputError(path, "the written file is incomplete (disk full or file-size limit?)");
  if (flush == Flush::now) sync_file(tmp, path);
  replace_file(tmp, path, flush == Flush::now);
  guard.release();
}

void write_text_atomically(const fs::path& path, std::string_view text) {
  write_file_atomically(path, [&](std::ostream& out) { out.write(text.data(), static_cast<std::streamsize>(text.size())); });
}

}  // namespace flapsim::io
