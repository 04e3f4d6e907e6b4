#pragma once
/// \file free_space.hpp
/// \brief The space left on the file system a command writes to.

#include <filesystem>
#include <optional>

namespace flapsim::io {

/// \brief Bytes an unprivileged process may still write on the file system holding \p path,
/// or of its nearest existing parent folder (an output folder not made yet); nullopt when it
/// cannot be told.
std::optional<double> free_bytes_where(const std::filesystem::path& path);

}  // namespace flapsim::io
