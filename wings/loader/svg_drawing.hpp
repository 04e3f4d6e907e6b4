#pragma once
/// \file svg_drawing.hpp
/// \brief The shapes of an SVG drawing: a wing traced in a drawing program (Inkscape and
/// others), read as points for an outline and its veins (docs/wing_file.md, "A wing from a
/// drawing").
///
/// Every `<path>`, `<polygon>`, `<polyline>`, `<line>`, `<rect>`, `<circle>` and `<ellipse>`
/// outside `<defs>`, `<clipPath>`, `<mask>`, `<marker>`, `<pattern>`, `<symbol>` and
/// `<metadata>` is one shape (or a hidden one, SvgDrawing::hidden), and every `<use>` (a clone)
/// draws copies of the shapes it refers to (wings/loader/svg_clones.hpp), flattened to points in the
/// drawing's user units after the `transform` of the element and of every group around it (matrix, translate,
/// scale, rotate, skewX, skewY: wings/loader/svg_transform.hpp). Path data as SVG 1.1 defines it, curves
/// flattened into straight pieces (wings/loader/svg_path_data.hpp: a Bézier curve's chords within 2.5e-4 of
/// its control polygon, a quarter circle in 29 pieces, a wing's area within 1e-3; arcs, circles and ellipses
/// 96 pieces a turn), the tags as wings/loader/svg_xml_tags.hpp reads them. The frame is SVG's: x to the
/// right, y downward. A regular file of at most kMaxDrawingFileBytes; every error names the file and the line
/// of the element it concerns.

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

namespace flapsim::wings {

inline constexpr std::size_t kMaxDrawingFileBytes = 16u << 20;  ///< 16 MiB (an embedded photo)
/// The most points a drawing's shapes flatten into, all together (16 MB of them): a Bézier
/// curve is at most 55 pieces, so 16 MiB of short curve commands could otherwise ask for
/// 10⁸. An outline or a vein is refused beyond 5,000 (kMaxOutlinePoints) anyway.
inline constexpr std::size_t kMaxDrawingPoints = 1'000'000;
/// The message of a drawing past kMaxDrawingPoints.
inline std::string too_many_drawing_points() {
  return "the drawing flattens into more than " + std::to_string(kMaxDrawingPoints) + " points";
}

/// One shape of the drawing.
struct SvgShape {
  std::string element;  ///< "path", "polygon", "polyline", "line", "rect", "circle", "ellipse"
  std::string id;       ///< its `id` ("" if none)
  std::string label;    ///< its `inkscape:label` ("" if none): the name Inkscape's Objects panel shows
  int line = 0;         ///< the line of its start tag in the file (1-based)
  bool closed = false;  ///< its first subpath is closed (Z; a polygon, rect, circle or ellipse)
  int subpaths = 0;     ///< the number of a path's subpaths (1 for the other elements)
  /// The first subpath's points, consecutive duplicates removed; a closed one's last point
  /// does not repeat its first. [user units, SVG frame]
  std::vector<Eigen::Vector2d> points;
  /// The ids and labels of the groups (and other elements) around it, outermost first.
  std::vector<std::string> group_names;
  /// Of a clone's shape (a `<use>`, wings/loader/svg_clones.hpp): how its original is named,
  /// "the path 'path5' (line 12)"; "" for a shape drawn as itself. Its line is the use's.
  std::string clone_of;
  /// "the path 'R1' (line 12)", "the clone 'use3' (line 30) of the path 'R1' (line 12)":
  /// how messages name it.
  std::string describe() const;
};

/// The shapes of an SVG file, in document order.
struct SvgDrawing {
  std::string file;
  std::vector<SvgShape> shapes;
  /// The shapes not drawn: `display:none` (style or attribute) on them or on a group around
  /// them, as Inkscape hides a layer or an object. Not read as the outline, a vein or the
  /// pivot; kept so that a message can say that a name not found is hidden.
  std::vector<SvgShape> hidden;
  /// A `<use>` that draws nothing, and why (wings/loader/svg_clones.hpp).
  struct UnreadClone {
    SvgShape use;
    std::string why;
  };
  std::vector<UnreadClone> unread_clones;
};

/// \param path SVG file
/// \param key  dotted key of the entry naming the file (for messages)
/// \throws flapsim::InputError naming the file and line of what is wrong
SvgDrawing read_svg_drawing(const std::string& path, const std::string& key);

/// The shapes of an SVG text (for tests; \p file names it in messages).
SvgDrawing parse_svg_drawing(std::string_view text, const std::string& file, const std::string& key);

/// The shapes whose `id` or `inkscape:label` is \p name; if none, the shapes inside a group
/// (or any element) of that name: matplotlib names a patch's `<g>`, not its path (`gid`),
/// and a group of one shape is the shape. Shapes drawn only (\p shapes, not \p hidden).
std::vector<const SvgShape*> find_svg_shapes(const SvgDrawing& drawing, std::string_view name);

/// For a name find_svg_shapes does not find: " (the path 'R1' (line 12) of it is hidden,
/// display:none: show it in the drawing)" if a hidden shape has it, " (the use 'use3' (line
/// 30) is a clone that is not read: …)" if a clone that draws nothing has it, else "".
std::string missing_shape_note(const SvgDrawing& drawing, std::string_view name);

}  // namespace flapsim::wings
