#pragma once
// A fresh, empty directory per test under the system temp dir, removed afterwards.

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

namespace flapsim::test {

class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name)
      : path_(std::filesystem::weakly_canonical(std::filesystem::temp_directory_path()) /
              ("flapsim_" + name + "_" + std::to_string(static_cast<long>(::getpid())))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

  /// Every file name under the directory (recursive), relative to it.
  std::vector<std::string> files() const {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::recursive_directory_iterator(path_))
      if (e.is_regular_file()) out.push_back(e.path().lexically_relative(path_).generic_string());
    return out;
  }
  /// Files whose name contains ".tmp." (left-over temporaries).
  std::vector<std::string> temporaries() const {
    std::vector<std::string> out;
    for (const auto& f : files())
      if (f.find(".tmp.") != std::string::npos) out.push_back(f);
    return out;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace flapsim::test
