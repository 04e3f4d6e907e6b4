#pragma once
/// \file svg_path_data.hpp
/// \brief SVG path data (1.1, ch. 8: moveto, lineto, horizontal and vertical lineto, cubic
/// and quadratic Bézier curves with their smooth forms, elliptical arcs, closepath,
/// absolute or relative) flattened into points, and the points of an ellipse. A Bézier
/// curve becomes n straight pieces, n from the bound (1/8) max|B''| / n² on the distance
/// between the curve and its chords, at kBezierFlatness of its control polygon (a quarter
/// circle: 29 pieces; at most 55 for any curve, as |p0 − 2p1 + p2| is at most the polygon); an arc
/// kArcPiecesPerTurn pieces a turn.

#include <Eigen/Core>
#include <cstddef>
#include <string_view>
#include <vector>

namespace flapsim::wings {

inline constexpr double kBezierFlatness = 2.5e-4;  ///< chords' distance from a curve / its control polygon
inline constexpr int kArcPiecesPerTurn = 96;       ///< a chord's distance from its circle 5.4e-4 r

/// One subpath: its points, consecutive duplicates removed.
struct SvgSubpath {
  std::vector<Eigen::Vector2d> points;
  bool closed = false;  ///< ended with closepath (Z)
};

/// The subpaths of a `d` attribute, in its own coordinates.
/// \param points_before the drawing's points so far: past kMaxDrawingPoints in all, refused
/// \throws SvgSyntaxError (wings/loader/svg_numbers.hpp) naming the character where it went wrong
std::vector<SvgSubpath> parse_svg_path_data(std::string_view d, std::size_t points_before);

/// kArcPiecesPerTurn points on the ellipse of centre c and radii rx, ry (axis-aligned).
std::vector<Eigen::Vector2d> svg_ellipse_points(const Eigen::Vector2d& c, double rx, double ry);

/// Appends p unless it repeats the last point.
void append_svg_point(std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& p);

}  // namespace flapsim::wings
