#pragma once
/// \file wing_file.hpp
/// \brief Reads and checks a wing file (TOML, format in docs/wing_file.md) into a
/// wings::Wing in SI units: planform from inline points or a CSV outline, scaled to
/// the span and optionally stretched chordwise to an area; veins as polylines in
/// (x, y) or (y/R, ξ) chord coordinates with hollow-circular or rectangular tapering
/// sections; membrane, materials, non-structural mass, mesh sizes and root clamp.

#include <string>

#include "wings/loader/toml_reader.hpp"
#include "wings/loader/wing_model.hpp"

namespace flapsim::wings {

/// Reads a wing file.
/// \param path wing file; a CSV outline path inside resolves against its folder
/// \throws flapsim::InputError naming file, line and key of the first problem
Wing load_wing_file(const std::string& path);

/// Reads a wing from an already parsed TOML document (the top-level table).
/// \throws flapsim::InputError
Wing read_wing(TomlTable root);

/// True if the top-level table looks like a wing file (it has a [planform] table).
bool is_wing_document(const TomlTable& root);

}  // namespace flapsim::wings
