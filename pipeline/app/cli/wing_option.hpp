#pragma once
/// \file wing_option.hpp
/// \brief `--wing WING.toml` of run and check: a case flown with another wing, its own
/// kinematics, air, structure and numerics kept ("a new wing in the hawkmoth's hover" in one
/// command, `make run WING=...`; docs/case_file.md, "Another wing for a case").

#include <filesystem>
#include <string>

namespace flapsim::wings {
class TomlTable;
}

namespace flapsim::cli {

/// Sets the case's `wing` to \p wing_file (a path from the current folder, as --chain's),
/// an override as a sweep's (TomlTable::apply_overrides); "" leaves the case as written.
/// \throws flapsim::InputError key "--wing" if the file does not exist or is not a regular
///         file; key "chain" of the case when the case flies a chain file of its own and
///         \p chain_file is "" (that chain was reduced from the case's wing, not this one)
void apply_wing_option(wings::TomlTable& case_root, const std::string& wing_file,
                       const std::string& chain_file);

/// run's default folder: out/<case name>, with --wing out/<case name>_<wing file's stem>
/// (the case's own run keeps its folder).
std::filesystem::path default_run_folder(const std::string& case_name, const std::string& wing_file);

}  // namespace flapsim::cli
