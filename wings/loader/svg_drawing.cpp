#include "wings/loader/svg_drawing.hpp"

#include <algorithm>
#include <fstream>
#include <optional>
#include <sstream>

#include "wings/loader/bounded_input_file.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/svg_clones.hpp"
#include "wings/loader/svg_numbers.hpp"
#include "wings/loader/svg_path_data.hpp"
#include "wings/loader/svg_transform.hpp"
#include "wings/loader/svg_xml_tags.hpp"
#include "wings/loader/text_trim.hpp"

namespace flapsim::wings {

namespace {

using Vec = Eigen::Vector2d;

// The error of one element (or of the file, line 0).
struct Where {
  const std::string& file;
  const std::string& key;
  [[noreturn]] void fail(int line, const std::string& what) const { throw InputError(file, line, key, what); }
};

// The elements whose content is not drawn (definitions, metadata).
bool skipped_subtree(const std::string& name) {
  for (const char* n : {"defs", "clipPath", "mask", "marker", "pattern", "symbol", "metadata", "title",
                        "desc", "style", "script", "namedview", "sodipodi:namedview", "foreignObject"})
    if (name == n) return true;
  return false;
}

// The elements whose shapes are drawn only where a clone refers to them (SVG 1.1, 5.3, 5.5).
bool definitions(const std::string& name) { return name == "defs" || name == "symbol"; }

// `display:none` on the tag, in its style or as an attribute (SVG 1.1, 11.5: the element
// and everything inside it is not rendered). Inkscape hides layers and objects so.
bool display_none(const SvgTag& tag) {
  if (const std::string* d = tag.attribute("display"); d && trim(*d) == "none") return true;
  const std::string* style = tag.attribute("style");
  if (!style) return false;
  std::istringstream declarations(*style);
  for (std::string declaration; std::getline(declarations, declaration, ';');)
    if (const auto colon = declaration.find(':'); colon != std::string::npos &&
                                                  trim(declaration.substr(0, colon)) == "display" &&
                                                  trim(declaration.substr(colon + 1)) == "none")
      return true;
  return false;
}

double length_attribute(const SvgTag& tag, std::string_view key, const Where& where, bool required) {
  const std::string* v = tag.attribute(key);
  if (!v) {
    if (required) where.fail(tag.line, "<" + tag.name + "> has no " + std::string(key));
    return 0.0;
  }
  const auto x = parse_svg_length(*v);
  if (!x) where.fail(tag.line, "<" + tag.name + "> " + std::string(key) + "=\"" + *v + "\" is not a length");
  return *x;
}

std::vector<Vec> point_list(const SvgTag& tag, const Where& where) {
  const std::string* v = tag.attribute("points");
  if (!v) where.fail(tag.line, "<" + tag.name + "> has no points");
  NumberScanner s(*v);
  std::vector<Vec> pts;
  while (!s.at_end()) {
    const auto x = s.number(), y = x ? s.number() : std::nullopt;
    if (!x || !y)
      where.fail(tag.line, "<" + tag.name + "> points=\"...\" holds something other than x,y pairs");
    append_svg_point(pts, Vec(*x, *y));
  }
  return pts;
}

// One shape of a tag, in the tag's own coordinates; nullopt for a tag that is no shape.
std::optional<SvgShape> shape_of(const SvgTag& tag, const Where& where, std::size_t points_before) {
  SvgShape s;
  s.element = tag.name;
  s.line = tag.line;
  if (const auto* id = tag.attribute("id")) s.id = *id;
  if (const auto* label = tag.attribute("inkscape:label")) s.label = *label;
  s.subpaths = 1;
  if (tag.name == "path") {
    const std::string* d = tag.attribute("d");
    if (!d) where.fail(tag.line, s.describe() + " has no path data (d)");
    std::vector<SvgSubpath> subs;
    try {
      subs = parse_svg_path_data(*d, points_before);
    } catch (const SvgSyntaxError& e) {
      where.fail(tag.line, s.describe() + ": " + e.what());
    }
    if (subs.empty()) return std::nullopt;
    s.subpaths = static_cast<int>(subs.size());
    s.points = subs.front().points;
    s.closed = subs.front().closed;
  } else if (tag.name == "polygon" || tag.name == "polyline") {
    s.points = point_list(tag, where);
    s.closed = tag.name == "polygon";
  } else if (tag.name == "line") {
    append_svg_point(
        s.points, Vec(length_attribute(tag, "x1", where, false), length_attribute(tag, "y1", where, false)));
    append_svg_point(
        s.points, Vec(length_attribute(tag, "x2", where, false), length_attribute(tag, "y2", where, false)));
  } else if (tag.name == "rect") {
    if (length_attribute(tag, "rx", where, false) != 0.0 || length_attribute(tag, "ry", where, false) != 0.0)
      where.fail(tag.line, s.describe() +
                               " has rounded corners (rx, ry), not read: convert it to a path "
                               "(Inkscape: Path > Object to Path)");
    const double x = length_attribute(tag, "x", where, false), y = length_attribute(tag, "y", where, false);
    const double w = length_attribute(tag, "width", where, true),
                 h = length_attribute(tag, "height", where, true);
    s.points = {Vec(x, y), Vec(x + w, y), Vec(x + w, y + h), Vec(x, y + h)};
    s.closed = true;
  } else if (tag.name == "circle" || tag.name == "ellipse") {
    const Vec c(length_attribute(tag, "cx", where, false), length_attribute(tag, "cy", where, false));
    const double rx = length_attribute(tag, tag.name == "circle" ? "r" : "rx", where, true);
    const double ry = tag.name == "circle" ? rx : length_attribute(tag, "ry", where, true);
    s.points = svg_ellipse_points(c, rx, ry);
    s.closed = true;
  } else {
    return std::nullopt;
  }
  if (s.closed && s.points.size() > 1 && s.points.back() == s.points.front()) s.points.pop_back();
  return s;
}

// A <use> tag's clone: its names, what it refers to and its frame (the transforms around it
// and its own, then translate(x, y); SVG 1.1, 5.6).
SvgCloneSource::Clone clone_of(const SvgTag& tag, const SvgAffine& transform, const Where& where) {
  SvgCloneSource::Clone c;
  c.use.element = "use";
  c.use.line = tag.line;
  if (const auto* id = tag.attribute("id")) c.use.id = *id;
  if (const auto* label = tag.attribute("inkscape:label")) c.use.label = *label;
  if (const std::string* h = tag.attribute("href")) c.href = trim(*h);
  if (const std::string* h = tag.attribute("xlink:href"); h && c.href.empty()) c.href = trim(*h);
  c.frame = svg_compose(transform, svg_translation(length_attribute(tag, "x", where, false),
                                                   length_attribute(tag, "y", where, false)));
  return c;
}

}  // namespace

std::string SvgShape::describe() const {
  std::string s = clone_of.empty() ? "the " + element : std::string("the clone");
  if (!id.empty()) s += " '" + id + "'";
  if (!label.empty() && label != id) s += " (label '" + label + "')";
  s += " (line " + std::to_string(line) + ")";
  return clone_of.empty() ? s : s + " of " + clone_of;
}

SvgDrawing parse_svg_drawing(std::string_view text, const std::string& file, const std::string& key) {
  const Where where{file, key};
  if (text.size() >= 2 && text[0] == '\x1f' && text[1] == '\x8b')  // gzip's magic number (RFC 1952)
    where.fail(0, "the drawing is compressed (gzip, an .svgz saved as .svg): save it as plain SVG");
  SvgDrawing drawing;
  drawing.file = file;
  struct Open {
    std::string name;
    SvgAffine transform;
    bool skipped;
    bool defined;  // in <defs> or a <symbol>: its shapes drawn only by clones
    bool hidden;
    int line;
    std::vector<std::string> names;  // the ids and labels of it and the groups around it
    std::string target;              // its id, if it is a clone's target (SvgCloneSource::targets)
  };
  SvgCloneSource clones;
  // The items of an element with an id end where it closes.
  auto end_target = [&](const std::string& id) {
    if (const auto t = clones.targets.find(id); t != clones.targets.end() && t->second.last == 0)
      t->second.last = clones.items.size();
  };
  std::vector<Open> stack;
  SvgTagReader reader(text, file, key);
  SvgTag tag;
  std::size_t points = 0;  // of the shapes so far
  bool seen_svg = false;
  while (reader.next(tag)) {
    if (tag.closing) {
      if (stack.empty() || stack.back().name != tag.name)
        where.fail(tag.line, "malformed SVG: </" + tag.name + "> closes " +
                                 (stack.empty() ? std::string("nothing")
                                                : "<" + stack.back().name + "> of line " +
                                                      std::to_string(stack.back().line)));
      if (!stack.back().target.empty()) end_target(stack.back().target);
      stack.pop_back();
      continue;
    }
    if (!seen_svg && tag.name != "svg")
      where.fail(tag.line, "not an SVG drawing: its first element is <" + tag.name + ">, not <svg>");
    seen_svg = true;
    const bool parent_skipped = !stack.empty() && stack.back().skipped;
    const bool skipped = parent_skipped || skipped_subtree(tag.name);
    // Shapes read: drawn ones, and in <defs> and <symbol> those a clone may draw.
    const bool defined =
        skipped && ((!stack.empty() && stack.back().defined) || (!parent_skipped && definitions(tag.name)));
    const bool read = !skipped || defined;
    const bool hidden = (!stack.empty() && stack.back().hidden) || display_none(tag);
    const SvgAffine parent = stack.empty() ? svg_identity() : stack.back().transform;
    SvgAffine transform = parent;
    if (read)
      if (const std::string* t = tag.attribute("transform")) try {
          transform = svg_compose(transform, parse_svg_transform(*t));
        } catch (const SvgSyntaxError& e) {
          if (!skipped) where.fail(tag.line, e.what());
          transform = parent;  // a definition's error: read where a clone draws it (not at all)
        }
    std::vector<std::string> names = stack.empty() ? std::vector<std::string>{} : stack.back().names;
    std::string target;
    if (const std::string* id = tag.attribute("id"); read && id && !clones.targets.contains(*id)) {
      target = *id;
      const std::size_t own = (tag.attribute("inkscape:label") ? 1u : 0u) + 1u;  // its id and label
      clones.targets[target] = {clones.items.size(), 0, parent, names.size() + own,
                                tag.name == "symbol" && tag.attribute("viewBox") != nullptr};
    }
    std::optional<SvgShape> shape;
    if (!skipped) {
      shape = shape_of(tag, where, points);
    } else if (defined) {
      try {
        shape = shape_of(tag, where, points);
      } catch (const InputError&) {  // a definition that cannot be read: no shape for a clone
      }
    }
    if (shape) {
      for (Vec& p : shape->points) p = svg_apply(transform, p);
      if (!skipped) {  // a definition's points count where a clone copies them (svg_clones.cpp)
        points += shape->points.size();
        if (points > kMaxDrawingPoints) where.fail(tag.line, too_many_drawing_points());
      }
      shape->group_names = names;
      clones.items.push_back({static_cast<int>(clones.shapes.size()), -1});
      clones.shapes.push_back(*shape);
      if (!skipped) (hidden ? drawing.hidden : drawing.shapes).push_back(std::move(*shape));
    } else if (read && tag.name == "use") {
      SvgCloneSource::Clone c = clone_of(tag, transform, where);
      c.use.group_names = names;
      c.hidden = hidden;
      c.drawn = !skipped;
      c.position = (hidden ? drawing.hidden : drawing.shapes).size();
      clones.items.push_back({-1, static_cast<int>(clones.clones.size())});
      clones.clones.push_back(std::move(c));
    }
    if (tag.self_closing) {
      if (!target.empty()) end_target(target);
    } else {
      for (const char* attribute : {"id", "inkscape:label"})
        if (const std::string* n = tag.attribute(attribute)) names.push_back(*n);
      stack.push_back({tag.name, transform, skipped, defined, hidden, tag.line, std::move(names), target});
    }
  }
  if (!seen_svg) where.fail(0, "not an SVG drawing: no <svg> element");
  if (!stack.empty())
    where.fail(stack.back().line, "malformed SVG: <" + stack.back().name + "> is never closed");
  add_svg_clones(clones, drawing, points, key);
  return drawing;
}

SvgDrawing read_svg_drawing(const std::string& path, const std::string& key) {
  check_bounded_input_file(path, key, "the drawing", kMaxDrawingFileBytes);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, key, "cannot open the drawing");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_svg_drawing(text.str(), path, key);
}

namespace {

std::vector<const SvgShape*> shapes_named(const std::vector<SvgShape>& shapes, std::string_view name) {
  std::vector<const SvgShape*> found;
  for (const SvgShape& s : shapes)
    if (s.id == name || s.label == name) found.push_back(&s);
  if (found.empty())  // the shapes of a group of that name
    for (const SvgShape& s : shapes)
      if (std::find(s.group_names.begin(), s.group_names.end(), name) != s.group_names.end())
        found.push_back(&s);
  return found;
}

}  // namespace

std::vector<const SvgShape*> find_svg_shapes(const SvgDrawing& drawing, std::string_view name) {
  return shapes_named(drawing.shapes, name);
}

std::string missing_shape_note(const SvgDrawing& drawing, std::string_view name) {
  if (const auto found = shapes_named(drawing.hidden, name); !found.empty())
    return " (" + found.front()->describe() +
           " of it is hidden, display:none: show it in the drawing, "
           "as Inkscape's eye in Layers and Objects does)";
  for (const SvgDrawing::UnreadClone& c : drawing.unread_clones)
    if (c.use.id == name || c.use.label == name ||
        std::find(c.use.group_names.begin(), c.use.group_names.end(), name) != c.use.group_names.end())
      return " (" + c.use.describe() + " is a clone that draws nothing: " + c.why + ")";
  return "";
}

}  // namespace flapsim::wings
