#include "pipeline/io/atomic_file.hpp"

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
  fs::create_directories(dir, ec);
  if (ec) throw OutputError(dir, "cannot create directory: " + ec.message());
  if (!fs::is_directory(dir, ec)) throw OutputError(dir, "exists and is not a directory");
}

fs::path temporary_path(const fs::path& path) {
  fs::path tmp = path;
  tmp += ".tmp." + std::to_string(static_cast<long>(::getpid()));
  return tmp;
}

void replace_file(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::rename(from, to, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(from, ignored);
    throw OutputError(to, "cannot rename the temporary file onto it: " + ec.message());
  }
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
    if (!out) throw OutputError(path, "write failed (disk full?)");
    out.close();
    if (out.fail()) throw OutputError(path, "closing the temporary file failed");
  }
  replace_file(tmp, path);
  guard.release();
}

void publish_file_atomically(const fs::path& path,
                             const std::function<void(const fs::path& tmp)>& write) {
  ensure_directory(path.parent_path());
  const fs::path tmp = temporary_path(path);
  TemporaryGuard guard(tmp);
  write(tmp);
  std::error_code ec;
  if (!fs::is_regular_file(tmp, ec)) throw OutputError(path, "the writer produced no file");
  replace_file(tmp, path);
  guard.release();
}

void write_text_atomically(const fs::path& path, std::string_view text) {
  write_file_atomically(path, [&](std::ostream& out) { out.write(text.data(), static_cast<std::streamsize>(text.size())); });
}

}  // namespace flapsim::io
