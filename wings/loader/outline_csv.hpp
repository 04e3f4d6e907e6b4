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

#include "wings/loader/planform_geometry.hpp"

namespace flapsim::wings {

inline constexpr std::size_t kMaxOutlineFileBytes = 4u << 20;  ///< 4 MiB
/// The most points of an outline, from any source (CSV, inline `outline`, `spline` control
/// points, `outline_points`). gmsh/OpenCASCADE builds one edge per point and its cost
/// grows about as n² (20,000 points: 36 CPU s of `check`, 40,000: 139 s; 5,000: 1.9 s on
/// a 2-core AMD EPYC machine shared with other builds, docs/wing_file.md); a longer outline
/// is refused before any of that work, and the limit is far above what a mesh resolves
/// (the default element size R/50 puts about 150 elements along a hawkmoth's edge).
inline constexpr std::size_t kMaxOutlinePoints = 5000;

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
