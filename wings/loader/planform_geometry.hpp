#pragma once
/// \file planform_geometry.hpp
/// \brief Plane-polygon geometry of a wing planform (x chordwise toward the leading
/// edge, y spanwise from the pivot): area, centroid, span moments, simplicity and
/// point-in-polygon tests, and the leading/trailing edge at a span station.
///
/// Definitions used throughout flapsim (docs/wing_file.md):
///  - span R: largest y of the outline (pivot to tip);
///  - mean chord c̄ = S / R (Ellington's convention for a wing measured from the pivot);
///  - aspect ratio AR = R² / S (one wing, measured from the pivot);
///  - non-dimensional radius of gyration of area r2 = sqrt(∫∫ y² dA / S) / R.

#include <Eigen/Core>

#include <optional>
#include <utility>
#include <vector>

namespace flapsim::wings {

using Polygon = std::vector<Eigen::Vector2d>;  ///< closed (last point not repeated)

/// Shoelace area, positive for counter-clockwise order [m²].
double polygon_signed_area(const Polygon& polygon);
/// |signed area| [m²].
double polygon_area(const Polygon& polygon);
/// Area centroid [m]; the polygon must have non-zero area.
Eigen::Vector2d polygon_centroid(const Polygon& polygon);
/// ∫∫ y² dA over the polygon [m⁴] (exact for straight edges).
double polygon_second_moment_y(const Polygon& polygon);

/// Area moments of a polygon about the origin, exact for straight edges (Green's theorem),
/// the same for either orientation.
struct PolygonMoments {
  double area = 0.0;                                ///< ∫∫ dA [m²]
  Eigen::Vector2d first = Eigen::Vector2d::Zero();  ///< (∫∫ x dA, ∫∫ y dA) [m³]
  double xx = 0.0;                                  ///< ∫∫ x² dA [m⁴]
  double yy = 0.0;                                  ///< ∫∫ y² dA [m⁴]
  double xy = 0.0;                                  ///< ∫∫ x y dA [m⁴]
};
PolygonMoments polygon_moments(const Polygon& polygon);

/// True if the closed segments [a, b] and [c, d] share at least one point.
bool segments_intersect(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                        const Eigen::Vector2d& c, const Eigen::Vector2d& d);

/// First pair of non-adjacent edges that touch or cross (edge i runs from point i to
/// point i+1), or nullopt if the polygon is simple. Also reports repeated points as
/// touching edges. O(n²), fine for a few hundred points.
std::optional<std::pair<int, int>> find_self_intersection(const Polygon& polygon);

/// The point of segment [a, b] nearest to p [m] (a itself for a segment of zero length).
Eigen::Vector2d nearest_point_on_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                         const Eigen::Vector2d& p);

/// The point of the polyline through \p points nearest to p [m]: of its segments between
/// consecutive points, and with \p closed also the one from the last point back to the
/// first (a polygon's boundary). The first of equally near points; the only point of a
/// polyline of one. \p points must not be empty.
Eigen::Vector2d nearest_point_on_polyline(const std::vector<Eigen::Vector2d>& points,
                                          const Eigen::Vector2d& p, bool closed = false);

/// Distance from p to the polygon boundary [m].
double distance_to_boundary(const Polygon& polygon, const Eigen::Vector2d& p);

/// The point of the polygon boundary nearest to p [m].
Eigen::Vector2d nearest_boundary_point(const Polygon& polygon, const Eigen::Vector2d& p);

/// True if p is inside the polygon or within `tolerance` [m] of its boundary.
bool contains_point(const Polygon& polygon, const Eigen::Vector2d& p, double tolerance);

/// Leading edge (largest x) and trailing edge (smallest x) where the line y = const
/// crosses the outline [m]; nullopt outside the outline's y range.
struct ChordLine {
  double leading_x = 0.0;
  double trailing_x = 0.0;
  double length() const { return leading_x - trailing_x; }
};
std::optional<ChordLine> chord_at(const Polygon& polygon, double y);

/// The outline's vertices on its leading edge (\p leading_edge) or trailing edge strictly
/// between the stations y = \p y_from and y = \p y_to, in order from the first to the
/// second [m]: the points a line along that edge passes through between them. A vertex is
/// on the leading (trailing) edge when it is chord_at's leading (trailing) crossing of its
/// own station, to 1e-9 of the outline's span.
std::vector<Eigen::Vector2d> edge_vertices_between(const Polygon& polygon, double y_from, double y_to,
                                                   bool leading_edge);

/// Summary numbers of a planform (see the definitions above).
struct PlanformProperties {
  double span = 0.0;          ///< R = max y [m]
  double root_y = 0.0;        ///< min y [m]
  double area = 0.0;          ///< S [m²]
  double mean_chord = 0.0;    ///< c̄ = S / R [m]
  double aspect_ratio = 0.0;  ///< R² / S [-]
  double r2 = 0.0;            ///< sqrt(∫∫ y² dA / S) / R [-]
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();  ///< [m]
};
PlanformProperties planform_properties(const Polygon& polygon);

/// Share of the outline's span range [root_y, span] that a root clamp up to \p clamp_y holds
/// [-] (0 for an outline without a span range).
double clamp_span_share(const PlanformProperties& props, double clamp_y);
/// A clamp holding more than this share holds most of the wing: the wing file warns of it,
/// and a reduction that finds no beam blames clamp_y (pipeline/app/reduction_input_limit.cpp).
inline constexpr double kClampHoldsMost = 0.5;

}  // namespace flapsim::wings
