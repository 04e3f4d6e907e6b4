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

/// An end of a drawn vein joined to another vein (join_drawn_vein_ends).
struct DrawnVeinJoin {
  std::size_t vein = 0, other = 0;  ///< indices into the veins
  int end = 0;                      ///< 0 its root end (its first point), 1 its outer end
  double distance = 0.0;            ///< how far the end was from the other vein, or went on past it [m]
  bool crossed = false;             ///< the end passed the other vein (cut where it crosses)
};

/// Joins the ends of the drawn veins (\p drawn[i]) that stop short of another vein or pass it
/// by at most \p limit, as a hand-traced branch does. The mesher's own junction rule
/// (vein_junctions.hpp) closes gaps of a sliver's size for every vein; this one reaches
/// further for drawn veins only, so it leaves ends on the outline's edge alone (two veins
/// reaching the margin side by side stay apart), cuts an end that crosses a vein, and says
/// what it joined: an end passing another vein within
/// \p limit of arc length is cut where it crosses it, else an end within \p limit of another
/// vein's line (and farther than \p tolerance, which the mesher closes itself) is moved onto
/// its nearest point. An end on the outline's edge (within \p tolerance) stays. Veins in
/// order, each end to the nearest such vein; \returns what was joined.
std::vector<DrawnVeinJoin> join_drawn_vein_ends(std::vector<std::vector<Eigen::Vector2d>>& veins,
                                                const std::vector<bool>& drawn, const Polygon& outline,
                                                double tolerance, double limit);

}  // namespace flapsim::wings
