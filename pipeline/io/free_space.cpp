#include "pipeline/io/free_space.hpp"

namespace flapsim::io {

std::optional<double> free_bytes_where(const std::filesystem::path& path) {
  std::filesystem::path at = std::filesystem::absolute(path);
  std::error_code ec;
  while (!std::filesystem::exists(at, ec)) {
    if (!at.has_parent_path() || at.parent_path() == at) return std::nullopt;
    at = at.parent_path();
  }
  const std::filesystem::space_info s = std::filesystem::space(at, ec);
  if (ec || s.available == static_cast<std::uintmax_t>(-1)) return std::nullopt;
  return static_cast<double>(s.available);
}

}  // namespace flapsim::io
