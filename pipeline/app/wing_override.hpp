#pragma once
/// \file wing_override.hpp
/// \brief A case's `wing` set to another wing file, as the override a case file is read with
/// (io::load_case_file's overrides): `run --wing` and `sweep --wing` (docs/case_file.md,
/// "Another wing for a case").

#include <string>
#include <utility>

namespace flapsim::app {

/// {"wing", TOML text of \p wing_file's absolute path}: a case resolves 'wing' against its own
/// folder, which leaves an absolute path as it is, so the file is the one the command line named.
std::pair<std::string, std::string> wing_file_override(const std::string& wing_file);

}  // namespace flapsim::app
