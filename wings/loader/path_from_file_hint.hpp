#pragma once
/// \file path_from_file_hint.hpp
/// \brief A file path that an input file names relative to its own folder (a case's `wing`,
/// a wing's `outline_file`) but that the user wrote relative to the folder the command runs
/// in: the hint for the "file not found" message, with the path as it should be written.

#include <string>

namespace flapsim::wings {

/// \brief "" unless \p written is a relative path to a regular file from the current folder;
/// then "; \"WRITTEN\" is a file relative to the folder this command runs in: from the
/// \p what file's folder it is \"PATH\"", PATH relative to the folder of \p referring_file.
/// \param what  the kind of the referring file ("case", "wing")
std::string path_from_file_hint(const std::string& written, const std::string& referring_file,
                                const std::string& what);

}  // namespace flapsim::wings
