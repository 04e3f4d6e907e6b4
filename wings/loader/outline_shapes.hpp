#pragma once
/// \file outline_shapes.hpp
/// \brief Planform outlines without a list of points (docs/wing_file.md, "Outlines from
/// shapes and splines"): a closed spline through a few control points, and the simple
/// parametric planforms ellipse, half-ellipse and rectangle with rounded tip corners.
/// Every function returns a closed polygon (last point not repeated), counter-clockwise,
/// in the units of its arguments.

#include <optional>

#include "wings/loader/planform_geometry.hpp"

namespace flapsim::wings {

/// \brief The closed, C²-continuous interpolating cubic spline through \p control
/// (periodic cubic spline of x(t) and y(t), t the cumulative chord length between
/// control points), sampled at \p samples points, every control point among them.
/// \param control  at least 3 distinct points in order around the outline (the first
///                 point not repeated at the end)
/// \param samples  number of points of the result, at least control.size()
/// \throws std::invalid_argument on fewer than 3 points or coincident neighbours
Polygon closed_spline(const Polygon& control, int samples);

/// The parametric planforms.
enum class OutlineShape {
  ellipse,            ///< a whole ellipse between root and tip, largest chord half-way
  half_ellipse,       ///< a straight root edge of full chord, elliptic to the tip
  rounded_rectangle,  ///< constant chord, the two tip corners rounded with tip_radius
};

/// Size and place of a parametric planform: it spans y from root_y to tip_y, its
/// largest chord is `chord`, its foremost point lies at x = leading_edge_x.
struct ShapeSize {
  double root_y = 0.0;          ///< y of the innermost point [length]
  double tip_y = 0.0;           ///< y of the tip, the span R [length]
  double chord = 0.0;           ///< largest chord [length]
  double leading_edge_x = 0.0;  ///< largest x of the outline [length]
  double tip_radius = 0.0;      ///< rounded_rectangle only: radius of the tip corners, <= chord/2
};

/// \brief The polygon of a parametric planform with about \p samples points
/// (at least 16). Points on the curved parts lie on the exact curve, so the area is
/// the inscribed polygon's: for the ellipse (n/2π)·sin(2π/n)·π·chord·L/4 with
/// n = samples and L = tip_y − root_y.
/// \throws std::invalid_argument on a non-positive chord or length, or a tip radius
///         outside (0, min(chord/2, L)]
Polygon shape_outline(OutlineShape shape, const ShapeSize& size, int samples);

/// \brief The outline with its last point removed if it repeats the first within
/// \p tolerance (a closing point written out, as many drawing programs do).
/// \return true if a point was removed
bool drop_closing_point(Polygon& outline, double tolerance);

}  // namespace flapsim::wings
