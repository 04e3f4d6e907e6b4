#pragma once
/// \file outline_csv.hpp
/// \brief Reads a planform outline from a CSV file: optional comment lines starting
/// with '#', an "x,y" header, then one "x,y" pair per line (closed polygon, the last
/// point not repeated). Values are returned as written (the shipped outlines are in
/// units of the wing length R).
///
/// The file must be a regular file of at most kMaxOutlineFileBytes bytes with at most
/// kMaxOutlinePoints points (a device such as /dev/zero or a huge file is refused before
/// it is read); every error names the CSV file and line.

#include <cstddef>
#include <string>
#include <vector>

#include "wings/planform_geometry.hpp"

namespace flapsim::wings {

inline constexpr std::size_t kMaxOutlineFileBytes = 4u << 20;  ///< 4 MiB
inline constexpr std::size_t kMaxOutlinePoints = 100000;

/// An outline with the CSV line of each point (for messages about a point).
struct OutlineCsv {
  Polygon points;
  std::vector<int> lines;  ///< 1-based line of points[i]
};

/// \param path CSV file
/// \param key  dotted key of the wing-file entry naming the file (for messages)
/// \throws flapsim::InputError naming the CSV file and line of the first bad row
OutlineCsv read_outline_csv_lines(const std::string& path, const std::string& key);

/// The points of read_outline_csv_lines.
Polygon read_outline_csv(const std::string& path, const std::string& key);

}  // namespace flapsim::wings
