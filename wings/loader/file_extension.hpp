#pragma once
/// \file file_extension.hpp
/// \brief A file's extension in lower case (".svg" of "Wing.SVG"), by which the loaders tell
/// an outline CSV from a drawing and name a file given in the wrong place.

#include <cctype>
#include <filesystem>
#include <string>

namespace flapsim::wings {

/// \brief The extension of \p path with its dot, in lower case ("" if none).
inline std::string lower_case_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace flapsim::wings
