#include "wings/loader/drawing_frame.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <filesystem>

#include "wings/loader/file_extension.hpp"
#include "wings/loader/outline_csv.hpp"

namespace flapsim::wings {

namespace {

using Vec = Eigen::Vector2d;

// A direction as the drawing is seen: SVG's y points down.
Vec screen_direction(const std::string& name) {
  if (name == "right") return {1.0, 0.0};
  if (name == "left") return {-1.0, 0.0};
  if (name == "up") return {0.0, -1.0};
  return {0.0, 1.0};  // "down"
}

// Up to eight shapes, for a message listing them.
std::string list_shapes(const std::vector<const SvgShape*>& shapes) {
  std::string s;
  for (std::size_t i = 0; i < shapes.size() && i < 8; ++i) s += (i ? "; " : "") + shapes[i]->describe();
  if (shapes.size() > 8) s += "; and " + std::to_string(shapes.size() - 8) + " more";
  return s;
}

// A closed shape, or an open one that ends where it starts (to 1e-9 of its size: a curve
// drawn back to its first point without a closepath, as some programs save it).
bool encloses(const SvgShape& s) {
  if (s.closed) return true;
  if (s.points.size() < 4) return false;
  double extent = 0.0;
  for (const Vec& q : s.points) extent = std::max(extent, (q - s.points.front()).cwiseAbs().maxCoeff());
  return (s.points.back() - s.points.front()).cwiseAbs().maxCoeff() <= 1e-9 * extent;
}

const SvgShape& pick_outline(const TomlTable& p, const SvgDrawing& d) {
  const std::string& file = d.file;
  if (p.has("outline_id")) {
    const std::string name = p.get_string("outline_id");
    const auto found = find_svg_shapes(d, name);
    if (found.empty()) {
      std::vector<const SvgShape*> all;
      for (const SvgShape& s : d.shapes) all.push_back(&s);
      p.fail("outline_id", "no shape with the id or label '" + name + "' in " + file +
                               missing_shape_note(d, name) +
                               (all.empty() ? " (it has no shapes)" : "; its shapes: " + list_shapes(all)));
    }
    if (found.size() > 1)
      p.fail("outline_id", "several shapes of " + file + " are '" + name + "': " + list_shapes(found));
    return *found.front();
  }
  if (const auto named = find_svg_shapes(d, "outline"); !named.empty()) {
    if (named.size() > 1)
      p.fail("outline_file", "several shapes of " + file + " are 'outline': " + list_shapes(named));
    return *named.front();
  }
  std::vector<const SvgShape*> closed;
  for (const SvgShape& s : d.shapes)
    if (encloses(s) && s.id != "pivot" && s.label != "pivot") closed.push_back(&s);
  if (closed.empty())
    p.fail("outline_file",
           file +
               " has no closed shape for the outline: draw it as a closed path (ending with Z), "
               "a polygon, rect or ellipse, or name the shape with outline_id" +
               (d.hidden.empty() ? std::string()
                                 : " (its " + std::to_string(d.hidden.size()) +
                                       (d.hidden.size() == 1 ? " hidden shape, display:none, is"
                                                             : " hidden shapes, display:none, are") +
                                       " not read: show the outline)") +
               (d.unread_clones.empty()
                    ? std::string()
                    : " (" + d.unread_clones.front().use.describe() +
                          " is a clone that draws nothing: " + d.unread_clones.front().why + ")"));
  if (closed.size() > 1)
    p.fail("outline_file",
           file + " has " + std::to_string(closed.size()) +
               " closed shapes: name the outline's with outline_id, or give it the id or label "
               "'outline' (" +
               list_shapes(closed) + ")");
  return *closed.front();
}

}  // namespace

Vec DrawingFrame::to_wing(const Vec& q) const {
  const Vec d = q - pivot;
  return {scale * x_stretch * d.dot(leading_edge), scale * d.dot(tip)};
}

std::string DrawingFrame::direction_name(const Vec& d) {
  return d.x() > 0.5 ? "right" : d.x() < -0.5 ? "left" : d.y() < 0.0 ? "up" : "down";
}

std::string DrawingFrame::describe(const std::string& length_unit, double metres_per_unit) const {
  char unit_scale[64];
  std::snprintf(unit_scale, sizeof unit_scale, "%.4g", scale / metres_per_unit);
  const std::size_t hidden = drawing.hidden.size(), unread = drawing.unread_clones.size();
  return outline_source + ", tip " + direction_name(tip) + ", leading edge " + direction_name(leading_edge) +
         ", pivot " + pivot_source + "; 1 drawing unit = " + unit_scale + " " + length_unit +
         (hidden == 0 ? std::string()
                      : "; " + std::to_string(hidden) + (hidden == 1 ? " hidden shape" : " hidden shapes") +
                            " (display:none) not read") +
         (unread == 0 ? std::string()
                      : "; " + std::to_string(unread) + (unread == 1 ? " clone draws" : " clones draw") +
                            " nothing (" + drawing.unread_clones.front().use.describe() + ": " +
                            drawing.unread_clones.front().why + ")");
}

bool is_svg_path(const std::string& path) { return lower_case_extension(path) == ".svg"; }

std::string unread_outline_format(const std::string& path) {
  constexpr const char* kSaveAsSvg =
      ", which is not read: outline_file takes a CSV of points or an SVG drawing; open it in a drawing "
      "program "
      "(Inkscape opens PDF, DXF, EPS and AI files) and save it as SVG";
  struct Format {
    const char* extensions;  // space-separated, each with a leading and a trailing space
    const char* name;
    const char* what_to_do;
  };
  static constexpr Format kFormats[] = {
      {" .svgz ", "a compressed SVG drawing",
       ", which is not read: save it as plain SVG (Inkscape: File > Save As, 'Inkscape SVG' or 'Plain SVG')"},
      {" .pdf ", "a PDF", kSaveAsSvg},
      {" .dxf .dwg ", "a CAD drawing", kSaveAsSvg},
      {" .eps .ps .ai ", "a PostScript or Illustrator drawing", kSaveAsSvg},
      {" .emf .wmf .cdr .vsd .vsdx ", "a drawing", kSaveAsSvg},
      {" .png .jpg .jpeg .tif .tiff .bmp .gif .webp ", "a picture",
       ", which is not read: outline_file takes a CSV of points or an SVG drawing; trace the wing's outline "
       "over the picture in a drawing program (Inkscape: Path > Trace Bitmap, or draw it with the Bézier "
       "tool) "
       "and save the drawing as SVG"},
  };
  const std::string ext = lower_case_extension(path);
  for (const Format& f : kFormats)
    if (!ext.empty() && std::string(f.extensions).find(" " + ext + " ") != std::string::npos)
      return std::string(f.name) + f.what_to_do;
  return "";
}

DrawingOutline read_drawing_outline(const TomlTable& p, const std::string& svg_path) {
  DrawingOutline out;
  DrawingFrame& f = out.frame;
  f.drawing = read_svg_drawing(svg_path, p.key_path("outline_file"));
  const SvgShape& shape = pick_outline(p, f.drawing);
  const std::string key = p.has("outline_id") ? "outline_id" : "outline_file";
  if (!encloses(shape) || shape.subpaths != 1)
    p.fail(key,
           "the outline, " + shape.describe() + " of " + svg_path + ", must be one closed curve: " +
               (shape.subpaths != 1 ? "it has " + std::to_string(shape.subpaths) +
                                          " subpaths (Inkscape: Path > Break Apart, and keep the outline's)"
                                    : "it is open (close it: a path ending with Z, or a polygon)"));
  if (shape.points.size() < 3)
    p.fail(key, "the outline, " + shape.describe() + " of " + svg_path + ", has " +
                    std::to_string(shape.points.size()) +
                    " distinct points: a closed outline needs at least 3");
  out.line = shape.line;

  static constexpr std::array<std::string_view, 4> kDirections{"right", "left", "up", "down"};
  f.tip = screen_direction(p.get_choice("drawing_tip", kDirections, "right"));
  f.leading_edge = p.has("drawing_leading_edge")
                       ? screen_direction(p.get_choice("drawing_leading_edge", kDirections))
                       : Vec(f.tip.y(), -f.tip.x());  // 90° counterclockwise as seen
  if (f.leading_edge.dot(f.tip) != 0.0)
    p.fail("drawing_leading_edge", "must be at right angles to drawing_tip (\"" +
                                       DrawingFrame::direction_name(f.tip) +
                                       "\"): the leading edge runs along the span");

  const auto pivots = find_svg_shapes(f.drawing, "pivot");
  if (pivots.size() > 1)
    p.fail("outline_file", "several shapes of " + svg_path + " are 'pivot': " + list_shapes(pivots));
  if (pivots.size() == 1 && pivots.front()->points.empty())
    p.fail("outline_file",
           "the pivot, " + pivots.front()->describe() + " of " + svg_path + ", has no points");
  if (pivots.size() == 1) {
    // The centre of its bounding box: a circle's centre, to the last bit where the centre
    // and radius are (the mean of its points differs by round-off).
    Vec lo = pivots.front()->points.front(), hi = lo;
    for (const Vec& q : pivots.front()->points) {
      lo = lo.cwiseMin(q);
      hi = hi.cwiseMax(q);
    }
    f.pivot = 0.5 * (lo + hi);
  } else {  // the root-most point; of a straight root, its leading-edge end
    double extent = 0.0;
    for (const Vec& q : shape.points)
      extent = std::max(extent, (q - shape.points.front()).cwiseAbs().maxCoeff());
    f.pivot = shape.points.front();
    for (const Vec& q : shape.points) {
      const double dy = (q - f.pivot).dot(f.tip), dx = (q - f.pivot).dot(f.leading_edge);
      if (dy < -1e-9 * extent || (dy <= 1e-9 * extent && dx > 0.0)) f.pivot = q;
    }
  }
  for (const Vec& q : shape.points) out.outline.push_back(f.to_wing(q));
  f.outline_source =
      "outline " + shape.describe() + " of " + std::filesystem::path(svg_path).filename().string();
  f.pivot_source = pivots.size() == 1 ? pivots.front()->describe() : std::string("its root-most point");
  return out;
}

std::vector<Vec> drawing_vein_points(const TomlTable& v, const DrawingFrame& frame) {
  const std::string name = v.get_string("drawing_id");
  const auto found = find_svg_shapes(frame.drawing, name);
  if (found.empty())
    v.fail("drawing_id", "no shape with the id or label '" + name + "' in " + frame.drawing.file +
                             missing_shape_note(frame.drawing, name));
  if (found.size() > 1)
    v.fail("drawing_id",
           "several shapes of " + frame.drawing.file + " are '" + name + "': " + list_shapes(found));
  const SvgShape& s = *found.front();
  if (s.closed || s.subpaths != 1)
    v.fail(
        "drawing_id",
        "the vein, " + s.describe() + " of " + frame.drawing.file + ", must be one open line: " +
            (s.subpaths != 1 ? "it has " + std::to_string(s.subpaths) +
                                   " subpaths (a branching vein is one [[veins]] entry a branch: Path > "
                                   "Break Apart, and name each piece)"
                             : "it is closed (a vein traced as an area, as Trace Bitmap gives it, is drawn "
                               "as a line along its middle instead: its thickness is outer_diameter)"));
  if (s.points.size() < 2)
    v.fail("drawing_id", "the vein, " + s.describe() + ", has fewer than 2 distinct points");
  if (s.points.size() > kMaxOutlinePoints)  // as an outline: gmsh makes an edge of each piece
    v.fail("drawing_id", "the vein, " + s.describe() + ", is flattened into " +
                             std::to_string(s.points.size()) + " points, more than " +
                             std::to_string(kMaxOutlinePoints) + ": simplify it in the drawing program");
  std::vector<Vec> pts;
  for (const Vec& q : s.points) pts.push_back(frame.to_wing(q));
  if (pts.back().y() < pts.front().y()) std::reverse(pts.begin(), pts.end());
  return pts;
}

}  // namespace flapsim::wings
