#pragma once
/// \file outline_csv.hpp
/// \brief Reads a planform outline from a CSV file: optional comment lines starting
/// with '#', an "x,y" header, then one "x,y" pair per line (closed polygon, the last
/// point not repeated). Values are returned as written (the shipped outlines are in
/// units of the wing length R).

#include <string>

#include "wings/planform_geometry.hpp"

namespace flapsim::wings {

/// \param path CSV file
/// \param key  dotted key of the wing-file entry naming the file (for messages)
/// \throws flapsim::InputError naming the CSV file and line of the first bad row
Polygon read_outline_csv(const std::string& path, const std::string& key);

}  // namespace flapsim::wings
