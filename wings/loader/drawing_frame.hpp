#pragma once
/// \file drawing_frame.hpp
/// \brief A wing from an SVG drawing (`outline_file = "wing.svg"`): which of the drawing's
/// shapes is the outline, where its pivot is, which way its tip and its leading edge point,
/// and the map from the drawing to the wing's frame that the outline and the veins written
/// with `drawing_id` share (docs/wing_file.md, "A wing from a drawing").
///
/// The wing's y runs from the pivot along the drawing's tip direction (`drawing_tip`,
/// default "right"), its x along the leading edge's (`drawing_leading_edge`, default 90°
/// counterclockwise from the tip as the drawing is seen: "up" for a tip to the right, a
/// right wing seen from above with the head up). The pivot is the centre of the shape whose
/// id or label is "pivot" (of its bounding box: a small circle's centre), else the outline's
/// root-most point (the leading-edge-most of a straight root). The drawing's units do not
/// matter: the outline is then scaled to `span` (required) as a CSV outline is.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "wings/loader/svg_drawing.hpp"
#include "wings/loader/toml_reader.hpp"

namespace flapsim::wings {

/// The drawing and its map to the wing's frame.
struct DrawingFrame {
  SvgDrawing drawing;
  Eigen::Vector2d pivot = Eigen::Vector2d::Zero();  ///< [drawing units]
  Eigen::Vector2d tip{1.0, 0.0};                    ///< unit direction of the wing's +y in the drawing
  Eigen::Vector2d leading_edge{0.0, -1.0};          ///< unit direction of the wing's +x in the drawing
  double scale = 1.0;      ///< wing length per drawing unit (set when the outline is scaled to the span)
  double x_stretch = 1.0;  ///< the chordwise stretch to `area` (1 without it)
  /// "outline the path 'path1' (label 'outline') (line 33) of drawn_wing.svg" and the pivot's
  /// "the circle 'pivot' (line 38)" or "its root-most point", for describe().
  std::string outline_source, pivot_source;

  /// A point of the drawing in the wing's frame [m once scale is set].
  Eigen::Vector2d to_wing(const Eigen::Vector2d& q) const;
  /// "right", "left", "up" or "down": a direction as the drawing is seen.
  static std::string direction_name(const Eigen::Vector2d& direction);
  /// What `check` prints: "outline the path … of drawn_wing.svg, tip right, leading edge up,
  /// pivot the circle 'pivot' (line 38); 1 drawing unit = 0.1957 mm" (the scale in the wing
  /// file's length unit, \p metres_per_unit of it).
  std::string describe(const std::string& length_unit, double metres_per_unit) const;
};

/// The outline of a drawing, in the wing's frame before scaling (drawing units).
struct DrawingOutline {
  DrawingFrame frame;
  std::vector<Eigen::Vector2d> outline;
  int line = 0;  ///< the outline's element's line in the drawing
};

/// Reads the drawing `svg_path` that `planform.outline_file` names and picks its outline
/// (`outline_id`, else the shape named "outline", else its one closed shape).
/// \throws flapsim::InputError naming the wing file's key, or the drawing's file and line
DrawingOutline read_drawing_outline(const TomlTable& planform, const std::string& svg_path);

/// The points of the vein `drawing_id` names, in the wing's frame [m], in the order that
/// puts its root-most end first.
std::vector<Eigen::Vector2d> drawing_vein_points(const TomlTable& vein, const DrawingFrame& frame);

/// Whether a path names an SVG file (by its extension, in any case).
bool is_svg_path(const std::string& path);

/// For a path whose extension names a drawing or picture format flapsim does not read (PDF,
/// DXF, EPS, a compressed SVG, a photo, ...), why and what to do instead, for outline_file's
/// message; "" for any other path (a CSV, whatever its extension, or an SVG).
std::string unread_outline_format(const std::string& path);

}  // namespace flapsim::wings
