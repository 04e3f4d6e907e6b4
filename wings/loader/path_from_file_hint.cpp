#include "wings/loader/path_from_file_hint.hpp"

#include <filesystem>
#include <system_error>

namespace flapsim::wings {

std::string path_from_file_hint(const std::string& written, const std::string& referring_file,
                                const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (written.empty() || !fs::path(written).is_relative() || !fs::is_regular_file(written, ec)) return "";
  const fs::path folder = fs::absolute(referring_file, ec).lexically_normal().parent_path();
  if (ec) return "";
  const fs::path from_file = fs::absolute(written, ec).lexically_normal().lexically_relative(folder);
  if (ec || from_file.empty()) return "";
  return "; \"" + written + "\" is a file relative to the folder this command runs in: from the " + what +
         " file's folder it is \"" + from_file.string() + "\"";
}

}  // namespace flapsim::wings
