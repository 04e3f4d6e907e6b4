#pragma once
/// \file optimum_case.hpp
/// \brief The case files at a point of the varied keys, as text a user keeps: the start of
/// `flapsim optimize` (the values the case and its wing file give the varied keys) and
/// DIR/optimum.toml, the case at the optimum, ready for `flapsim run` (docs/optimize.md).

#include <filesystem>
#include <optional>
#include <string>

#include "pipeline/app/sweep/sweep_case.hpp"

namespace flapsim::optimize {

/// \brief The value the inputs give \p key: the case file's (a case key), the wing file's
/// (`wing.<key>`), the spring factor (`spring_scale`); std::nullopt when the file does not
/// write the key (its default applies) or the value is not a number.
/// \throws flapsim::InputError when a file does not read
std::optional<double> value_in_inputs(const sweep::SweepInputs& inputs, const std::string& key);

/// What write_case_at writes.
struct WrittenCase {
  std::filesystem::path case_file;   ///< DIR/<name>.toml
  std::filesystem::path wing_file;   ///< DIR/<name>_wing.toml when a wing key is varied, else empty
  double spring_scale = 1.0;         ///< to pass as `flapsim run --spring-scale` (1: none)
};

/// \brief Writes the case at \p point as DIR/<name>.toml (and, when a wing key is varied,
/// the wing as DIR/<name>_wing.toml): the case file with the point's values set, its wing
/// and chain paths made relative to DIR (so the file runs from there), and a header saying
/// where it came from. The spring factor has no case key: the header and the report give
/// the `--spring-scale` to run it with. Comments of the original are not kept.
/// \throws io::OutputError, flapsim::InputError when the case or wing file does not read
WrittenCase write_case_at(const sweep::SweepInputs& inputs, const sweep::CasePoint& point,
                          const std::filesystem::path& dir, const std::string& name, const std::string& header);

}  // namespace flapsim::optimize
