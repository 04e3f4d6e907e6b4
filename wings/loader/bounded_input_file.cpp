#include "wings/loader/bounded_input_file.hpp"

#include <filesystem>

#include "wings/loader/input_error.hpp"

namespace flapsim::wings {

void check_bounded_input_file(const std::string& path, const std::string& key, const std::string& what,
                              std::size_t max_bytes) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) throw InputError(path, 0, key, what + " does not exist");
  if (!std::filesystem::is_regular_file(status))
    throw InputError(path, 0, key, what + " is not a regular file (a device, FIFO or folder)");
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || size > max_bytes)
    throw InputError(path, 0, key, what + " is larger than " + std::to_string(max_bytes) + " bytes");
}

}  // namespace flapsim::wings
