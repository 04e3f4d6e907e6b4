#pragma once
/// \file drawn_vein_ends.hpp
/// \brief The ends of a vein traced in a drawing that pass the outline's edge a little (a
/// hand-drawn vein overshoots the edge it meets by a few pixels) cut at the edge, so that the
/// drawing need not be exact to the pixel (docs/wing_file.md, "A wing from a drawing").

#include <Eigen/Core>
#include <array>
#include <vector>

#include "wings/loader/planform_geometry.hpp"

namespace flapsim::wings {

/// The most a drawn vein's end may pass the outline's edge and be cut there, as a fraction of
/// the span: 2 % (a convention for a hand-traced overshoot; beyond it the vein is refused as
/// one written with points is: it is drawn somewhere else than meant).
inline constexpr double kDrawnVeinOvershoot = 0.02;

/// Cuts each end of \p points that lies outside \p outline (beyond \p tolerance, within
/// which read_vein moves a point onto the edge) where the vein crosses the edge, when that
/// end reaches at most \p limit outside it; other points are left as they are. \returns how
/// far each end reached outside, {start, end} [m] (0: not cut).
std::array<double, 2> cut_overshooting_ends(std::vector<Eigen::Vector2d>& points, const Polygon& outline,
                                            double tolerance, double limit);

}  // namespace flapsim::wings
