#pragma once
/// \file planform_grid.hpp
/// \brief The lattice's surface grid from a planform outline: nc × ns panels between
/// the leading and the trailing edge, uniform or cosine spacing in each direction.
///
/// Node (i, j), i = 0..nc from the leading to the trailing edge, j = 0..ns from root
/// to tip, is column `i + (nc + 1) j` of the node matrix (wing frame: x toward the
/// leading edge, y along the span, z = 0).
///
/// Rounded ends: where the outline's chord goes to zero (a rounded tip, a pointed
/// root) the end station is moved inboard to where the local chord is
/// `min_end_chord` times the largest chord, so no panel degenerates to a triangle or
/// to zero area. The planform area this leaves out is reported (`area_lost`); for
/// the hawkmoth outline at the default 0.1 it is under 1 % of the wing.

#include <Eigen/Core>

#include <vector>

namespace flapsim::uvlm {

enum class Spacing { Uniform, Cosine };

/// An end whose chord reaches `min_end_chord` times the largest within this fraction of the
/// span from its end is square (a root edge off perpendicular by round-off): its station
/// sits that far in, with the chord there, not where a sub-micron slant passes the limit.
inline constexpr double kSquareEndFraction = 1e-6;

struct PlanformGridOptions {
  int chordwise = 6;                        ///< nc panels
  int spanwise = 10;                        ///< ns panels
  Spacing chordwise_spacing = Spacing::Uniform;
  Spacing spanwise_spacing = Spacing::Uniform;
  double min_end_chord = 0.1;  ///< end stations sit where chord ≥ this × largest chord [-]
};

struct PlanformGrid {
  int chordwise = 0, spanwise = 0;
  Eigen::Matrix3Xd nodes;     ///< (nc+1)(ns+1) node positions, wing frame [m]
  double y_root = 0.0;        ///< spanwise position of station j = 0 [m]
  double y_tip = 0.0;         ///< spanwise position of station j = ns [m]
  double outline_area = 0.0;  ///< area of the outline polygon [m²]
  double lattice_area = 0.0;  ///< area covered by the panels [m²]
  double area_lost() const { return outline_area - lattice_area; }
};

/// Area [m²] of a simple polygon (any orientation).
double polygon_area(const std::vector<Eigen::Vector2d>& outline);

/// Leading- and trailing-edge x [m] of the outline at span station y: the largest and
/// smallest x where the line y = const crosses the polygon (equal if it does not).
Eigen::Vector2d chord_extent(const std::vector<Eigen::Vector2d>& outline, double y);

/// Build the grid. \param outline closed polygon of (x, y) [m] (last point joins the
/// first), x toward the leading edge, y spanwise. \throws std::invalid_argument for
/// fewer than 3 points, non-positive panel counts, or an outline without area.
PlanformGrid make_planform_grid(const std::vector<Eigen::Vector2d>& outline,
                                const PlanformGridOptions& options);

/// Grid of a flat rectangle of chord c [m] and span b [m] with the root at y = 0 and the
/// leading edge at x = 0 (trailing edge at x = −c); the test and benchmark wing.
PlanformGrid make_rectangular_grid(double chord, double span, const PlanformGridOptions& options);

}  // namespace flapsim::uvlm
