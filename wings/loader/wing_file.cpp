#include "wings/loader/wing_file.hpp"

#include "wings/loader/surface_shape.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>
#include <utility>

#include "wings/loader/drawing_frame.hpp"
#include "wings/loader/drawn_vein_ends.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/mesh_budget.hpp"
#include "wings/loader/outline_csv.hpp"
#include "wings/loader/outline_shapes.hpp"
#include "wings/loader/path_from_file_hint.hpp"
#include "wings/loader/planform_geometry.hpp"

namespace flapsim::wings {

namespace {

std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// A dimension given either as one number (constant) or as [root, end] (linear taper).
std::pair<double, double> read_taper(const TomlTable& t, std::string_view key) {
  if (!t.has(key)) t.fail(key, "missing required key (a length or [root, end] lengths)");
  if (t.is_number(key)) {
    const double v = t.get_length(key, Bounds::positive());
    return {v, v};
  }
  if (!t.is_array(key)) t.fail(key, "expected a length or an array [root, end] of two lengths");
  const auto v = t.get_lengths(key, Bounds::positive());
  if (v.size() != 2) t.fail(key, "expected [root, end]: 2 numbers, found " + std::to_string(v.size()));
  return {v[0], v[1]};
}

void warn(std::vector<InputWarning>& warnings, const TomlTable& t, std::string_view key,
          const std::string& message) {
  warnings.push_back({t.file(), t.line_of(key), t.key_path(key), message});
}

// Plausibility (docs/wing_file.md, "Plausibility warnings"): values outside what any
// wing material has, with the unit mistake that would explain them.
void check_modulus(const TomlTable& t, double e, std::vector<InputWarning>& warnings) {
  if (e < 1e6) {
    std::string guess;
    for (const auto& [unit, factor] : {std::pair{"GPa", 1e9}, std::pair{"MPa", 1e6}, std::pair{"kPa", 1e3}})
      if (e * factor >= 1e6 && e * factor <= 1e12)
        guess += std::string(guess.empty() ? "" : " or ") + unit + " (" + fmt(e) + " " + unit + " = " +
                 fmt(e * factor) + ")";
    warn(warnings, t, "youngs_modulus",
         fmt(e) + " Pa is below 1 MPa, softer than any wing material; youngs_modulus is in Pa" +
             (guess.empty() ? std::string(".") : ": was it meant in " + guess + "?"));
  } else if (e > 1e12) {
    warn(warnings, t, "youngs_modulus",
         fmt(e) + " Pa is above 1 TPa, stiffer than diamond; youngs_modulus is in Pa: was it given in "
                  "a smaller unit (e.g. kPa: " + fmt(e) + " kPa = " + fmt(e * 1e3) + " Pa), or is the exponent off?");
  }
}

void check_density(const TomlTable& t, double rho, std::vector<InputWarning>& warnings) {
  if (rho < 10.0)
    warn(warnings, t, "density",
         fmt(rho) + " kg/m³ is below 10 kg/m³, lighter than any wing material; density is in kg/m³: was it "
                    "meant in g/cm³ (" + fmt(rho) + " g/cm³ = " + fmt(rho * 1e3) + " kg/m³)?");
  else if (rho > 20000.0)
    warn(warnings, t, "density",
         fmt(rho) + " kg/m³ is above 20000 kg/m³, denser than any wing material; density is in kg/m³: was it "
                    "meant in g/m³ (" + fmt(rho) + " g/m³ = " + fmt(rho * 1e-3) + " kg/m³)?");
}

// A membrane below 1 µm is a small insect's (a fruit fly's 0.5 µm on a 2.5 mm wing, thinner still on
// a fairyfly's 0.15 mm one) or a unit mistake (25 µm written in metres in a mm file: 25 nm on a
// hawkmoth's 48 mm, 5e-7 of the span). Warned below 1 µm only where it is also under 1e-4 of the
// span: the thinnest films on wings measured here lie at 1.8e-4 (80 µm on a 0.45 m ornithopter
// wing), 2e-4 (a fruit fly), 3e-4 (the hawkmoth's).
void check_film(const TomlTable& t, double thickness_m, double span_m, std::vector<InputWarning>& warnings) {
  if (thickness_m >= 1e-6 || thickness_m >= 1e-4 * span_m) return;
  const double written = thickness_m / t.length_scale();
  std::string message = "the membrane would be " + fmt(thickness_m * 1e6) +
                        " µm thick, thinner than 1 µm and " + fmt(thickness_m / span_m) +
                        " of the span; thickness is in length_unit = \"" + t.length_unit() + "\"";
  if (t.length_unit() != "m" && written >= 1e-6 && written <= 1e-3)
    message += ": was it written in metres? " + fmt(written) + " m is " + fmt(written / t.length_scale()) +
               " " + t.length_unit();
  else
    message += ": is the value in that unit?";
  warn(warnings, t, "thickness", message);
}

// A length a wing cannot have, and the length_unit that would make it one it can
// (a wing drawn in mm in a file that declares metres is 1000 times too long).
std::string unit_guess(const TomlTable& t, double metres, double lo, double hi) {
  const double written = metres / t.length_scale();
  for (const auto& [unit, scale] : {std::pair{"mm", 1e-3}, std::pair{"cm", 1e-2}, std::pair{"um", 1e-6},
                                    std::pair{"m", 1.0}})
    if (unit != t.length_unit() && written * scale >= lo && written * scale <= hi)
      return ": was it written in " + std::string(unit) + " (length_unit = \"" + unit + "\")?";
  return ": is the value in that unit?";
}

void check_span(const TomlTable& p, double span_m, std::vector<InputWarning>& warnings) {
  constexpr double kLongest = 2.0, kShortest = 1e-4;  // [m]: a 1 m ornithopter wing; a 0.15 mm fairyfly wing
  if (span_m >= kShortest && span_m <= kLongest) return;
  std::string key = "span";
  for (const char* k : {"span", "outline", "spline", "outline_file", "shape"})
    if (p.has(k)) {
      key = k;
      break;
    }
  warn(warnings, p, key,
       "the wing would be " + fmt(span_m) + " m from pivot to tip, " +
           (span_m > kLongest ? "longer than any flapping wing (2 m)" : "shorter than any flapping wing (0.1 mm)") +
           "; lengths are in length_unit = \"" + p.length_unit() + "\"" + unit_guess(p, span_m, 1e-3, 1.0));
}

// A drawing read with its tip in the wrong direction: the outline reaches further across the
// span than along it (the drawn test wing read with drawing_tip = "up": R²/S 0.075, a mean
// chord 13 times its span).
void check_drawing_direction(const TomlTable& p, const DrawingFrame& frame, const Polygon& outline,
                             std::vector<InputWarning>& warnings) {
  Eigen::Vector2d lo = outline.front(), hi = lo;
  for (const auto& q : outline) {
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  const Eigen::Vector2d extent = hi - lo;  // (chordwise, spanwise) [m]
  if (extent.x() <= extent.y()) return;
  const std::string tip = DrawingFrame::direction_name(frame.tip);
  const bool across = frame.tip.y() == 0.0;  // right or left
  warn(warnings, p, p.has("drawing_tip") ? "drawing_tip" : "outline_file",
       "the drawn outline reaches " + fmt(extent.x() / p.length_scale()) + " " + p.length_unit() +
           " chordwise but " + fmt(extent.y() / p.length_scale()) + " " + p.length_unit() +
           " from root to tip, its span along the drawing's " + tip + " direction: does the tip point " +
           (across ? "up or down" : "right or left") + " in the drawing? Set drawing_tip (docs/wing_file.md, "
           "\"A wing from a drawing\")");
}

void check_plate(const TomlTable& t, double thickness_m, std::vector<InputWarning>& warnings) {
  if (thickness_m <= 5e-3) return;
  warn(warnings, t, "thickness",
       "the membrane would be " + fmt(thickness_m * 1e3) + " mm thick, thicker than any wing film or plate (5 mm); "
       "thickness is in length_unit = \"" + t.length_unit() + "\"" + unit_guess(t, thickness_m, 1e-6, 5e-3));
}

// Non-structural mass (scales, glue, a film's coating) is grams per m² on any wing: the
// hawkmoth of the rotation-phase paper carries 12 g/m² (wings/hawkmoth_rp.toml). Above 1 kg/m²,
// the areal mass of a 0.7 mm cuticle sheet, it was written in g/m² (20 g/m² made a 48 mm wing
// weigh 16 g unwarned until 3 Dec).
void check_nonstructural_mass(const TomlTable& t, double kg_per_m2, std::vector<InputWarning>& warnings) {
  if (kg_per_m2 <= 1.0) return;
  warn(warnings, t, "nonstructural_mass_per_area",
       fmt(kg_per_m2) +
           " kg/m^2 is heavier than a 0.7 mm sheet of cuticle (1 kg/m^2); "
           "nonstructural_mass_per_area is in kg/m^2: was it written in g/m^2? " +
           fmt(kg_per_m2) + " g/m^2 is " + fmt(kg_per_m2 * 1e-3) + " kg/m^2");
}

// A vein as thick as a quarter of the span is no vein (an insect's costa is 1-2 % of its span,
// a MAV's carbon spar 1-5 %): its section was written in another unit than the file's lengths
// (0.4 mm as 0.4 in a file in metres made a 34 mg hawkmoth wing weigh 5.2 kg unwarned until 3 Dec).
void check_vein_section(const TomlTable& v, const Vein& vein, double span_m,
                        std::vector<InputWarning>& warnings) {
  double largest = 0.0;
  std::string key;
  for (const Section& s : {vein.root_section, vein.tip_section}) {
    const bool rect = s.shape == Section::Shape::Rectangle;
    const std::pair<double, const char*> sides[] = {
        {rect ? s.width : s.outer_diameter,
         rect ? "width" : (v.has("diameter") ? "diameter" : "outer_diameter")},
        {rect ? s.height : 0.0, "height"}};
    for (const auto& [size, name] : sides)
      if (size > largest) {
        largest = size;
        key = name;
      }
  }
  if (!(largest > 0.25 * span_m)) return;
  warn(warnings, v, key,
       "the vein's section would be " + fmt(largest / v.length_scale()) + " " + v.length_unit() +
           " across, " + fmt(100.0 * largest / span_m) +
           " % of the span (veins are 1-5 %); section sizes are in length_unit = \"" + v.length_unit() +
           "\"" + unit_guess(v, largest, 1e-6, 0.05 * span_m));
}

// The vortex lattice spans each section y = const from its leading to its trailing edge
// (uvlm/planform_grid.hpp). An outline that a chordwise line crosses more than twice (a
// slot from the tip, a hooked edge) leaves a gap the lattice covers: say where, when the
// gap is more than kLatticeGapShare of the wing (a digitised edge's wiggles are not).
// The FEM stages warn; a run in air refuses the wing (pipeline/app/fsi_setup.cpp).
constexpr double kLatticeGapShare = 0.01;
LatticeGap lattice_gap(const TomlTable& p, const std::vector<Eigen::Vector2d>& outline) {
  std::vector<double> ys;
  for (const auto& q : outline) ys.push_back(q.y());
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  // Between two vertex heights the crossings move linearly in y, so the gap area of the
  // band is its height times the gap at mid-height (exact).
  double lo = 1e300, hi = -1e300, gap_area = 0.0;
  int most = 0;
  std::vector<double> xs;
  for (std::size_t k = 0; k + 1 < ys.size(); ++k) {
    const double y = 0.5 * (ys[k] + ys[k + 1]);
    xs.clear();
    for (std::size_t i = 0; i < outline.size(); ++i) {
      const Eigen::Vector2d& a = outline[i];
      const Eigen::Vector2d& b = outline[(i + 1) % outline.size()];
      if ((a.y() < y) != (b.y() < y)) xs.push_back(a.x() + (y - a.y()) / (b.y() - a.y()) * (b.x() - a.x()));
    }
    if (xs.size() <= 2) continue;
    std::sort(xs.begin(), xs.end());
    double gap = 0.0;
    for (std::size_t i = 1; i + 1 < xs.size(); i += 2) gap += xs[i + 1] - xs[i];
    gap_area += gap * (ys[k + 1] - ys[k]);
    lo = std::min(lo, ys[k]);
    hi = std::max(hi, ys[k + 1]);
    most = std::max(most, static_cast<int>(xs.size()));
  }
  const double area = polygon_area(outline);
  LatticeGap g;
  if (most == 0 || !(gap_area > kLatticeGapShare * area)) return g;
  g.area_share = gap_area / area;
  g.y_from = lo;
  g.y_to = hi;
  g.crossings = most;
  g.key = "outline";
  for (const char* k : {"outline", "spline", "outline_file", "shape"})
    if (p.has(k)) {
      g.key = k;
      break;
    }
  g.description = "from y = " + fmt(lo / p.length_scale()) + " to " + fmt(hi / p.length_scale()) + " " +
                  p.length_unit() + " a line along the chord crosses the outline " + std::to_string(most) +
                  " times (a slot or a hooked edge): the vortex lattice of a run in air spans each section from "
                  "its leading to its trailing edge and would cover the gap, " + fmt(100.0 * g.area_share) +
                  " % of the wing's area";
  g.file = p.file();
  g.line = p.line_of(g.key);
  g.key = p.key_path(g.key);
  return g;
}

// A root clamp holds a strip of a few per cent of the span (the shipped wings: 0-5 %, the
// Robofly's root edge). Holding most of the wing leaves a stub: its FEM modes are tens of kHz,
// a FEM run is a rigid wing, and a reduction finds no beam to measure (it stopped as a
// "numerical failure"; a 40 mm wing clamped to 39.9 mm passed check without a word).
void check_clamp_share(const TomlTable& p, double clamp_y, const PlanformProperties& props,
                       std::vector<InputWarning>& warnings) {
  const double held = clamp_span_share(props, clamp_y);
  if (held <= kClampHoldsMost) return;
  warn(warnings, p, "clamp_y",
       "the clamp holds " + fmt(100.0 * held) + " % of the wing's span range (" +
           fmt(props.root_y / p.length_scale()) + " to " + fmt(props.span / p.length_scale()) + " " +
           p.length_unit() + "): only the outer " + fmt((props.span - clamp_y) / p.length_scale()) + " " +
           p.length_unit() +
           " bends (a FEM run is close to a rigid wing, and a reduction may find no beam to measure); a root "
           "clamp holds the strip the mechanism grips, a few per cent of the span (docs/wing_file.md)");
}

// Fewer than two elements across the mean chord: the FEM cannot bend along the chord at all,
// `modes` names its modes from a handful of nodes (beam shares NaN on a 10 mm chord meshed at
// 20 mm: 8 nodes) and `reduce` refuses it; the wing file's check said nothing.
void check_elements_across_chord(const TomlTable& m, double element_size, const PlanformProperties& props,
                                 std::vector<InputWarning>& warnings) {
  if (!(props.mean_chord > 0.0) || element_size <= 0.5 * props.mean_chord) return;
  warn(warnings, m, "element_size",
       "fewer than two elements across the wing's mean chord (" + fmt(props.mean_chord / m.length_scale()) +
           " " + m.length_unit() +
           "): the FEM cannot bend along the chord, its modes and a reduction are coarse or "
           "refused; at most a quarter of the mean chord (the default is a fiftieth of the span, "
           "docs/wing_file.md)");
}

void warn_lattice_gap(const LatticeGap& g, std::vector<InputWarning>& warnings) {
  if (!(g.area_share > 0.0)) return;
  warnings.push_back({g.file, g.line, g.key, g.description + "; the FEM follows the outline, a run in air refuses it"});
}

Material read_material(const TomlTable& t, std::vector<InputWarning>& warnings) {
  t.expect_only({"youngs_modulus", "poisson_ratio", "density"});
  Material m;
  m.youngs_modulus = t.get_double("youngs_modulus", Bounds::positive());
  // Isotropic stability: −1 < ν < 1/2.
  m.poisson_ratio = t.get_double("poisson_ratio", Bounds::open(-1.0, 0.5));
  m.density = t.get_double("density", Bounds::positive());
  check_modulus(t, m.youngs_modulus, warnings);
  check_density(t, m.density, warnings);
  return m;
}

const Material& find_material(const TomlTable& t, std::string_view key,
                              const std::map<std::string, Material>& materials) {
  const std::string name = t.get_string(key);
  const auto it = materials.find(name);
  if (it == materials.end()) {
    std::string list;
    for (const auto& [k, v] : materials) list += (list.empty() ? "" : ", ") + k;
    t.fail(key, "unknown material \"" + name + "\"; [materials] defines: " +
                    (list.empty() ? "(none)" : list));
  }
  return it->second;
}

// --- planform ---------------------------------------------------------------------------

struct Planform {
  Polygon outline;
  double clamp_y = 0.0;
  bool from_spline = false;  ///< the outline is `spline`'s curve, not the points as written
  std::optional<DrawingFrame> drawing;  ///< an SVG outline_file: its map, for veins with drawing_id
  double span_scale = 1.0;              ///< `span`'s uniform scale of the outline as written [-]
  double chord_stretch = 1.0;           ///< `area`'s chordwise stretch of the outline [-]
  /// Whether `span` (`area`) moved the outline from where its points were written (by more
  /// than 0.1 %): veins given by absolute `points` then no longer lie where they were drawn.
  bool span_rescaled() const { return std::abs(span_scale - 1.0) > 1e-3; }
  bool chord_rescaled() const { return std::abs(chord_stretch - 1.0) > 1e-3; }
  bool rescaled() const { return span_rescaled() || chord_rescaled(); }
};

// The outline of `shape = "..."` (ellipse, half_ellipse, rounded_rectangle) from its size keys.
Polygon read_shape_outline(const TomlTable& p, int samples) {
  constexpr std::array<std::pair<std::string_view, OutlineShape>, 3> kShapes{
      {{"ellipse", OutlineShape::ellipse},
       {"half_ellipse", OutlineShape::half_ellipse},
       {"rounded_rectangle", OutlineShape::rounded_rectangle}}};
  const OutlineShape shape = p.get_choice("shape", kShapes);
  if (!p.has("span")) p.fail("span", "missing required key: a shape reaches from root_y to the tip at 'span'");
  ShapeSize size;
  size.tip_y = p.get_length("span", Bounds::positive());
  size.chord = p.get_length("chord", Bounds::positive());
  size.root_y = p.get_length("root_y", 0.0, Bounds::at_least(0.0));
  if (!(size.root_y < size.tip_y)) p.fail("root_y", "must be smaller than the span");
  size.leading_edge_x = p.get_length("leading_edge_x", 0.25 * size.chord, Bounds::any());
  if (shape == OutlineShape::rounded_rectangle) {
    const double limit = std::min(0.5 * size.chord, size.tip_y - size.root_y);
    size.tip_radius = p.get_length("tip_radius", 0.5 * size.chord, Bounds::positive());
    if (size.tip_radius > limit * (1 + 1e-12))
      p.fail("tip_radius", "must not exceed half the chord nor the length span - root_y (" +
                               fmt(limit / p.length_scale()) + " " + p.length_unit() + ")");
  } else if (p.has("tip_radius")) {
    p.fail("tip_radius", "only applies to shape = \"rounded_rectangle\"");
  }
  return shape_outline(shape, size, samples);
}

Planform read_planform(const TomlTable& p, std::vector<InputWarning>& warnings) {
  p.expect_only({"outline", "outline_file", "spline", "shape", "outline_points", "chord", "root_y",
                 "leading_edge_x", "tip_radius", "span", "area", "clamp_y", "outline_id", "drawing_tip",
                 "drawing_leading_edge"});
  const std::array<std::string_view, 4> sources{"outline", "outline_file", "spline", "shape"};
  std::string outline_key;
  for (const auto key : sources)
    if (p.has(key)) {
      if (!outline_key.empty())
        p.fail(key, "give exactly one of 'outline' (inline [[x, y], ...]), 'outline_file' (CSV or SVG), "
                    "'spline' (control points of a closed spline) or 'shape' (ellipse, half_ellipse, "
                    "rounded_rectangle); '" + outline_key + "' is given too");
      outline_key = key;
    }
  if (outline_key.empty())
    p.fail("outline", "missing: give one of 'outline', 'outline_file', 'spline' or 'shape'");
  const bool from_file = outline_key == "outline_file";
  if (outline_key != "shape")
    for (const char* k : {"chord", "root_y", "leading_edge_x", "tip_radius"})
      if (p.has(k)) p.fail(k, "only applies to 'shape'");
  const int samples =
      p.get_int("outline_points", 96, Bounds::closed(16, static_cast<double>(kMaxOutlinePoints)));
  if (p.has("outline_points") && outline_key != "spline" && outline_key != "shape")
    p.fail("outline_points", "only applies to 'spline' and 'shape'");

  Planform out;
  OutlineCsv csv;  // with the CSV line of each point, for messages
  int drawing_line = 0;  // an SVG outline's element's line in the drawing
  const bool from_drawing = from_file && is_svg_path(p.get_string("outline_file"));
  if (!from_drawing)
    for (const char* k : {"outline_id", "drawing_tip", "drawing_leading_edge"})
      if (p.has(k)) p.fail(k, "only applies to an SVG drawing as outline_file");
  if (from_file) {
    // The CSV is in units of the wing length, a drawing in its own; 'span' scales either.
    if (!p.has("span"))
      p.fail("span", std::string("missing required key: ") + (from_drawing ? "a drawing" : "a CSV outline") +
                         " is scaled to 'span'");
    const std::string file_path = p.get_path("outline_file");
    // A missing file is the wing file's error, at the line that names it.
    if (std::error_code ec; !std::filesystem::exists(file_path, ec))
      p.fail("outline_file", "file not found: " + file_path +
                                 " (paths are relative to the wing file's folder" +
                                 path_from_file_hint(p.get_string("outline_file"), p.file(), "wing") + ")");
    // So is a path that is no file (a folder, /dev/zero): before, named against itself alone.
    if (std::error_code ec; !std::filesystem::is_regular_file(file_path, ec))
      p.fail("outline_file", file_path +
                                 " is not a regular file (a device, FIFO or folder): give the outline's CSV "
                                 "or SVG file");
    if (const std::string unread = unread_outline_format(file_path); !unread.empty())
      p.fail("outline_file", file_path + " is " + unread);
    if (from_drawing) {
      DrawingOutline drawn = read_drawing_outline(p, file_path);
      out.outline = std::move(drawn.outline);
      out.drawing = std::move(drawn.frame);
      drawing_line = drawn.line;
      if (out.outline.size() > kMaxOutlinePoints)
        throw InputError(file_path, drawing_line, p.key_path("outline_file"),
                         "the outline is flattened into " + std::to_string(out.outline.size()) +
                             " points, more than " + std::to_string(kMaxOutlinePoints) +
                             " (meshing costs about n^2): simplify it in the drawing program");
    } else {
      csv = read_outline_csv_lines(file_path, p.key_path("outline_file"));
      out.outline = csv.points;
    }
  } else if (outline_key == "shape") {
    out.outline = read_shape_outline(p, samples);
  } else {
    const auto rows = p.get_number_rows(outline_key, 2);
    if (rows.size() > kMaxOutlinePoints)
      p.fail_at(p.line_of_element(outline_key, kMaxOutlinePoints), outline_key,
                "more than " + std::to_string(kMaxOutlinePoints) +
                    " points (meshing costs about n^2: simplify the outline to the mesh size, "
                    "docs/wing_file.md)");
    for (const auto& r : rows) out.outline.emplace_back(r[0] * p.length_scale(), r[1] * p.length_scale());
  }
  // A closing point repeating the first (as drawing programs write it) is accepted.
  if (outline_key != "shape") {
    double extent = 0.0;
    for (const auto& q : out.outline) extent = std::max(extent, q.cwiseAbs().maxCoeff());
    // Within kNearRepeat of the first, as the near-repeat check below reads a repeat: a drawing
    // program's closing point rounded apart from the first is closing, not an error.
    drop_closing_point(out.outline, kNearRepeat * extent);
    if (out.outline.size() < 3)
      p.fail(outline_key, "an outline needs at least 3 points, found " + std::to_string(out.outline.size()));
  }
  if (outline_key == "spline") {
    for (std::size_t i = 0; i < out.outline.size(); ++i)
      if (out.outline[i] == out.outline[(i + 1) % out.outline.size()])
        p.fail_at(p.line_of_element("spline", (i + 1) % out.outline.size()), "spline",
                  "control points " + std::to_string(i + 1) + " and " +
                      std::to_string((i + 1) % out.outline.size() + 1) + " coincide");
    out.outline = closed_spline(out.outline, samples);
    out.from_spline = true;
    if (out.outline.size() > kMaxOutlinePoints)
      p.fail("spline", "the spline is sampled with " + std::to_string(out.outline.size()) + " points, more than " +
                           std::to_string(kMaxOutlinePoints) + ": lower 'outline_points' or give fewer control points");
  }

  // 1. Scale uniformly so the largest y equals the span (pivot to tip).
  double max_y = -1e300;
  for (const auto& q : out.outline) max_y = std::max(max_y, q.y());
  if (p.has("span")) {
    const double span = p.get_length("span", Bounds::positive());
    if (!(max_y > 0.0))
      p.fail(outline_key, "the outline must reach y > 0 (the tip) to be scaled to the span");
    const double k = span / max_y;
    for (auto& q : out.outline) q *= k;
    out.span_scale = k;
    // A CSV's numbers carry no unit. With its tip at y = 1 it is in units of the span (the
    // shipped outlines), and a vein's points can only have been written for the scaled wing;
    // otherwise it is taken in the wing's length unit, and `span` rescales it when it differs
    // from the CSV's own tip (a 60 mm outline with span = 60 mm is not rescaled).
    if (from_file && !from_drawing)
      out.span_scale = std::abs(max_y - 1.0) <= 1e-3 ? 1.0 : k / p.length_scale();
    if (out.drawing) out.drawing->scale = k;
    max_y = span;
  }
  // A span no flapping wing has, warned before the outline's checks: an error they find (a
  // "sliver" of a span in mm written as 40000) then carries the warning with its unit guess.
  check_span(p, max_y, warnings);

  // 2. The polygon must be simple (checked before stretching, which keeps simplicity).
  // An error at point `at` of the outline, at its line in whichever file gave it.
  auto fail_at_point = [&](std::size_t at, const std::string& what) {
    if (from_drawing)  // the drawing's file and the outline element's line
      throw InputError(p.get_path("outline_file"), drawing_line, p.key_path("outline_file"), what);
    if (from_file)  // the CSV's file and line of the point
      throw InputError(p.get_path("outline_file"), csv.lines[at], p.key_path("outline_file"), what);
    const int line = outline_key == "outline" ? p.line_of_element(outline_key, at) : p.line_of(outline_key);
    p.fail_at(line, outline_key, what);
  };
  {  // A point a hair from the next one (below kNearRepeat of the outline's size: a typo or a
     // drawing's double click) is a repeat: gmsh merges such points and fails with "Could not
     // create line", naming neither (a point 1.4e-7 mm from the next on a 40 mm wing).
    double extent = 0.0;
    for (const auto& q : out.outline) extent = std::max(extent, q.cwiseAbs().maxCoeff());
    const std::size_t n = out.outline.size();
    for (std::size_t i = 0; i < n && outline_key != "shape" && outline_key != "spline"; ++i) {
      const std::size_t next = (i + 1) % n;
      const double d = (out.outline[i] - out.outline[next]).norm();
      if (d == 0.0 || d >= kNearRepeat * extent) continue;
      const std::size_t at = std::max(i, next);
      fail_at_point(at, "point " + std::to_string(at) + " nearly repeats point " +
                            std::to_string(std::min(i, next)) + " (" + fmt(d / p.length_scale()) + " " +
                            p.length_unit() +
                            " apart, below 1e-6 of the outline's size): remove one (points counted from 0)");
    }
  }
  if (const auto hit = find_self_intersection(out.outline)) {
    const std::size_t n = out.outline.size();
    const auto i = static_cast<std::size_t>(hit->first), next = (i + 1) % n;
    // A point equal to the next (a zero-length edge) is named as the repeat it is, at the
    // later of the two in the file.
    const bool repeat = out.outline[i] == out.outline[next];
    const std::size_t at = repeat ? std::max(i, next) : i;
    const std::string what =
        repeat ? "point " + std::to_string(at) + " repeats point " + std::to_string(std::min(i, next)) +
                     " (points counted from 0; a closing point equal to the first is accepted once)"
               : "the outline is not a simple polygon: edge " + std::to_string(i) + " (points " +
                     std::to_string(i) + "-" + std::to_string(next) + ") touches or crosses edge " +
                     std::to_string(hit->second);
    fail_at_point(at, what);
  }
  const double signed_area = polygon_signed_area(out.outline);
  if (signed_area == 0.0) p.fail(outline_key, "the outline has zero area");
  {  // A sliver is not a wing, and gmsh cannot mesh it (mesh_budget.hpp).
    double y_max = -1e300;
    for (const auto& q : out.outline) y_max = std::max(y_max, q.y());
    if (y_max > 0.0 && y_max * y_max / std::abs(signed_area) > kMaxAspectRatio)
      p.fail(outline_key, "the outline is a sliver: aspect ratio R^2/S = " + fmt(y_max * y_max / std::abs(signed_area)) +
                              " exceeds " + fmt(kMaxAspectRatio));
  }
  if (signed_area < 0.0) std::reverse(out.outline.begin(), out.outline.end());
  max_y = -1e300;
  double min_y = 1e300;
  for (const auto& q : out.outline) {
    max_y = std::max(max_y, q.y());
    min_y = std::min(min_y, q.y());
  }
  if (!(max_y > 0.0)) p.fail(outline_key, "the outline must reach y > 0 (the wing extends along +y)");

  // 3. Optional chordwise stretch about x = 0 (the span axis) to a given area.
  if (p.has("area")) {
    const double area = p.get_double("area", Bounds::positive()) * p.length_scale() * p.length_scale();
    const double k = area / polygon_area(out.outline);
    for (auto& q : out.outline) q.x() *= k;
    out.chord_stretch = k;
    if (out.drawing) out.drawing->x_stretch = k;
  }

  // Every coordinate usable in metres after scaling and stretching: 0 or a normal number
  // (a point written as 2.2e-308 mm is a denormal in metres).
  for (std::size_t i = 0; i < out.outline.size(); ++i)
    for (double c : {out.outline[i].x(), out.outline[i].y()})
      if (c != 0.0 && std::fpclassify(c) != FP_NORMAL)
        p.fail_at(outline_key == "outline" ? p.line_of_element(outline_key, i) : p.line_of(outline_key), outline_key,
                  "point " + std::to_string(i) + " has a coordinate too small to compute with in metres (" +
                      fmt(c) + " m)");

  out.clamp_y = p.get_length("clamp_y");
  if (!(out.clamp_y >= min_y && out.clamp_y < max_y))
    p.fail("clamp_y", "must lie within the outline's span range [" + fmt(min_y / p.length_scale()) +
                          ", " + fmt(max_y / p.length_scale()) + ") " + p.length_unit());
  return out;
}

// `span` scales the outline and `area` stretches it along the chord; a vein's `points` are
// absolute positions and stay as written (chord_points and drawn veins follow the outline).
// A wing rescaled from 40 to 80 mm kept its spar from 0 to 40 mm, half the wing, without a word.
void check_absolute_veins_of_a_rescaled_outline(const Planform& planform, const TomlTable& p,
                                                const std::vector<TomlTable>& veins,
                                                std::vector<InputWarning>& warnings) {
  if (!planform.rescaled()) return;
  const bool scaled = planform.span_rescaled();
  for (const TomlTable& v : veins) {
    if (!v.has("points")) continue;
    std::string how;
    if (scaled)
      how = "scaled by " + fmt(planform.span_scale) +
            " to 'span' = " + fmt(p.get_length("span") / p.length_scale()) + " " + p.length_unit();
    if (planform.chord_rescaled())
      how += std::string(scaled ? " and " : "") + "stretched along the chord by " +
             fmt(planform.chord_stretch) + " to 'area'";
    warn(warnings, v, "points",
         "the outline is " + how +
             ", but a vein's points are absolute positions and stay as written (the veins with 'points' no "
             "longer lie where they were drawn on the outline): write them for the rescaled wing, or give "
             "them "
             "as chord_points (fractions of the span and the chord, which follow the outline; "
             "docs/wing_file.md)");
    return;  // once for the wing
  }
}

// --- veins --------------------------------------------------------------------------------

Section read_section_end(const std::string& shape, const std::pair<double, double>& a,
                         const std::pair<double, double>& b, bool root) {
  Section s;
  if (shape == "rectangle") {
    s.shape = Section::Shape::Rectangle;
    s.width = root ? a.first : a.second;
    s.height = root ? b.first : b.second;
  } else {
    s.shape = Section::Shape::HollowCircle;
    s.outer_diameter = root ? a.first : a.second;
    s.wall = root ? b.first : b.second;
  }
  return s;
}

// A vein drawn along a straight run of `spline` control points: the C² curve passes through
// them but rounds the corners next to the run and swings beside it (a leading edge at x = 0
// through (0, 2), (0, 20), (0, 40) after a square root corner lay 0.41 mm outside at y = 22 mm).
constexpr const char* kSplineVeinHint =
    "; the outline is the spline's curve, through its control points but bending between them "
    "(beside a straight run of them next to a corner it swings inside): move the vein inside, or "
    "draw straight edges with 'outline'";

// A drawn vein's end a little short of another vein, or past it, joined to it
// (drawn_vein_ends.hpp), with a warning for each.
void join_drawn_veins(Wing& wing, const std::vector<TomlTable>& tables) {
  std::vector<std::vector<Eigen::Vector2d>> lines;
  std::vector<bool> drawn;
  for (std::size_t i = 0; i < wing.veins.size(); ++i) {
    lines.push_back(wing.veins[i].points);
    drawn.push_back(tables[i].has("drawing_id"));
  }
  const auto joins =
      join_drawn_vein_ends(lines, drawn, wing.outline, 1e-3 * wing.span, kDrawnVeinOvershoot * wing.span);
  for (const DrawnVeinJoin& j : joins) {
    const TomlTable& t = tables[j.vein];
    wing.veins[j.vein].points = lines[j.vein];
    const std::string other = "vein " + std::to_string(j.other + 1) + " ('" + wing.veins[j.other].name + "')";
    const std::string amount = fmt(j.distance / t.length_scale()) + " " + t.length_unit();
    warn(wing.warnings, t, "drawing_id",
         "the drawn vein's " + std::string(j.end == 0 ? "root" : "outer") + " end " +
             (j.crossed ? "crosses " + other + " and goes on " + amount + ": cut where it crosses"
                        : "stops " + amount + " short of " + other + ": joined to it"));
  }
}

Vein read_vein(const TomlTable& v, std::size_t index, const Planform& planform,
               const std::map<std::string, Material>& materials, std::vector<InputWarning>& warnings) {
  const Polygon& outline = planform.outline;
  v.expect_only({"name", "material", "points", "chord_points", "drawing_id", "subdivide", "shape",
                 "outer_diameter", "wall", "diameter", "width", "height"});
  Vein vein;
  vein.name = v.get_string("name", "vein " + std::to_string(index + 1));
  vein.material = find_material(v, "material", materials);

  const bool abs_pts = v.has("points"), chord_pts = v.has("chord_points"), drawn = v.has("drawing_id");
  if (int(abs_pts) + int(chord_pts) + int(drawn) != 1)
    v.fail(abs_pts ? (chord_pts ? "chord_points" : "drawing_id") : chord_pts ? "drawing_id" : "points",
           "give exactly one of 'points' ([[x, y], ...] lengths), 'chord_points' ([[y/R, xi], ...]) or "
           "'drawing_id' (a line of the planform's SVG drawing)");
  if (drawn && !planform.drawing)
    v.fail("drawing_id", "the planform's outline_file is no SVG drawing: a vein is drawn in the outline's drawing");
  const std::string pts_key = abs_pts ? "points" : chord_pts ? "chord_points" : "drawing_id";
  const auto rows = drawn ? std::vector<std::vector<double>>{} : v.get_number_rows(pts_key, 2);
  if (!drawn && rows.size() < 2)
    v.fail(pts_key, "a vein needs at least 2 points, found " + std::to_string(rows.size()));
  // The line of a point's row ('drawing_id''s own line for a drawn vein).
  const auto line_of_row = [&](std::size_t row) {
    return drawn ? v.line_of(pts_key) : v.line_of_element(pts_key, row);
  };

  const PlanformProperties outline_properties = planform_properties(outline);
  const double span = outline_properties.span;
  std::vector<std::size_t> source_row;  // which row of the file each point came from
  if (drawn) {
    if (v.has("subdivide")) v.fail("subdivide", "only applies to 'chord_points'");
    vein.points = drawing_vein_points(v, *planform.drawing);
    const auto reach = cut_overshooting_ends(vein.points, outline, 1e-3 * span, kDrawnVeinOvershoot * span);
    for (int end = 0; end < 2; ++end)
      if (reach[end] > 0.0)
        warn(warnings, v, "drawing_id",
             "the drawn vein's " + std::string(end == 0 ? "root" : "outer") +
                 " end passes the outline's edge by " + fmt(reach[end] / v.length_scale()) + " " +
                 v.length_unit() + " (" + fmt(100.0 * reach[end] / span) +
                 " % of the span): cut at the edge");
    source_row.assign(vein.points.size(), 0);
  } else if (abs_pts) {
    if (v.has("subdivide")) v.fail("subdivide", "only applies to 'chord_points'");
    for (std::size_t i = 0; i < rows.size(); ++i) {
      vein.points.emplace_back(rows[i][0] * v.length_scale(), rows[i][1] * v.length_scale());
      for (double c : {vein.points.back().x(), vein.points.back().y()})
        if (c != 0.0 && std::fpclassify(c) != FP_NORMAL)
          v.fail_at(v.line_of_element("points", i), "points",
                    "point " + std::to_string(i) + " has a coordinate too small to compute with in metres");
      source_row.push_back(i);
    }
  } else {
    const int sub = v.get_int("subdivide", 1, Bounds::closed(1, 1000));
    auto to_xy = [&](double eta, double xi, std::size_t row) {
      const auto c = chord_at(outline, eta * span);
      if (!c)
        v.fail_at(v.line_of_element(pts_key, row), pts_key,
                  "y/R = " + fmt(eta) + " lies outside the outline's span range (y/R from " +
                      fmt(outline_properties.root_y / span) + " at its root to 1 at its tip)");
      return Eigen::Vector2d(c->leading_x - xi * c->length(), eta * span);
    };
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const int line = v.line_of_element(pts_key, i);
      if (!(rows[i][0] >= 0.0 && rows[i][0] <= 1.0))
        v.fail_at(line, pts_key, "y/R = " + fmt(rows[i][0]) + " must be in [0, 1]");
      if (!(rows[i][1] >= 0.0 && rows[i][1] <= 1.0))
        v.fail_at(line, pts_key, "chord fraction xi = " + fmt(rows[i][1]) +
                                     " must be in [0, 1] (0 leading edge, 1 trailing edge)");
    }
    // Subdivide in (y/R, ξ) so a vein at constant ξ follows the curved edges. A piece
    // with both ends on the leading edge (ξ = 0) or both on the trailing edge (ξ = 1) runs
    // along that edge: through the outline's own vertices between them, whatever
    // `subdivide` (the chords between points on a curved edge leave it, outward where it
    // is concave, and gmsh then left the vein outside the membrane or meshed the sliver
    // between them: a costa at ξ = 0 along a half-ellipse, 0.056°).
    vein.points.push_back(to_xy(rows[0][0], rows[0][1], 0));
    source_row.push_back(0);
    for (std::size_t i = 1; i < rows.size(); ++i) {
      const double xi = rows[i][1];
      if (xi == rows[i - 1][1] && (xi == 0.0 || xi == 1.0)) {
        for (const Eigen::Vector2d& q :
             edge_vertices_between(outline, rows[i - 1][0] * span, rows[i][0] * span, xi == 0.0)) {
          vein.points.push_back(q);
          source_row.push_back(i);
        }
        vein.points.push_back(to_xy(rows[i][0], xi, i));
        source_row.push_back(i);
        continue;
      }
      for (int k = 1; k <= sub; ++k) {
        const double u = double(k) / sub;
        vein.points.push_back(to_xy((1 - u) * rows[i - 1][0] + u * rows[i][0],
                                    (1 - u) * rows[i - 1][1] + u * rows[i][1], i));
        source_row.push_back(i);
      }
    }
  }
  for (std::size_t i = 1; i < vein.points.size(); ++i)
    if ((vein.points[i] - vein.points[i - 1]).norm() == 0.0)
      v.fail_at(line_of_row(source_row[i]), pts_key, "two consecutive points coincide");

  // Inside the outline, or on its edge within 0.1 % of the span; segments are sampled
  // so a vein cannot cut across a notch between two inside points.
  const double tol = 1e-3 * span;
  // A point off the outline's edge by no more than the tolerance, outside or inside, is
  // moved onto the edge (its nearest point). Left outside, gmsh does not embed it in the
  // membrane and the vein floats unsupported (a spar 0.03 mm outside a 40 mm wing's edge made
  // the FEM singular); left inside, gmsh meshes the gap into sliver triangles (a root spar
  // written to start on a swept leading edge, 1.1 µm inside it on a 95 mm wing: its end
  // node held by a triangle of 3 mm sides and 1 µm height, on which the FEM's Newton
  // stalled at step 263 of a film wing's run; tests/data/swept_film_50um_wing.toml).
  // A point off the edge by round-off only (a chord point at xi = 1 lies 1.7e-18 m outside
  // wings/hawkmoth.toml's trailing edge) is left as it is: gmsh merges it, and moving it
  // would change the shipped wings' meshes in the last digits.
  const double round_off = 1e-12 * span;
  for (auto& q : vein.points)
    if (const double d = distance_to_boundary(outline, q); d > round_off && d <= tol)
      q = nearest_boundary_point(outline, q);
  for (std::size_t i = 0; i < vein.points.size(); ++i) {
    const int nsamp = i == 0 ? 1 : 8;
    for (int k = 0; k < nsamp; ++k) {
      const double u = i == 0 ? 0.0 : double(k + 1) / nsamp;
      const Eigen::Vector2d q = i == 0 ? vein.points[0]
                                       : ((1 - u) * vein.points[i - 1] + u * vein.points[i]).eval();
      if (!contains_point(outline, q, tol)) {
        v.fail_at(
            line_of_row(source_row[i]), pts_key,
            "the vein leaves the outline near (x, y) = (" + fmt(q.x() / v.length_scale()) + ", " +
                fmt(q.y() / v.length_scale()) + ") " + v.length_unit() + ", " +
                fmt(distance_to_boundary(outline, q) / v.length_scale()) + " " + v.length_unit() +
                " outside it (tolerance " + fmt(tol / v.length_scale()) + " " + v.length_unit() + ")" +
                (planform.from_spline ? kSplineVeinHint : "") +
                (abs_pts && planform.rescaled()
                     ? "; the outline was rescaled by 'span' or 'area', and a vein's points are absolute "
                       "positions that stay as written: write them for the rescaled wing, or as chord_points"
                     : "") +
                (drawn
                     ? "; a drawn vein's end may pass the edge by up to " + fmt(100.0 * kDrawnVeinOvershoot) +
                           " % of the span (" + fmt(kDrawnVeinOvershoot * span / v.length_scale()) + " " +
                           v.length_unit() + ") and is cut there"
                     : ""));
      }
    }
  }

  vein.line = v.line_of(pts_key);
  vein.key = v.key_path(pts_key);
  const std::string shape =
      v.get_choice("shape", {"hollow_circle", "solid_circle", "rectangle"}, "hollow_circle");
  if (shape != "solid_circle" && v.has("diameter"))
    v.fail("diameter", "only applies to shape = \"solid_circle\" (a hollow circle has 'outer_diameter' and 'wall')");
  if (shape == "solid_circle") {
    // A solid round rod: the hollow circle whose wall is half its diameter (A = π D²/4).
    for (const char* k : {"outer_diameter", "wall", "width", "height"})
      if (v.has(k)) v.fail(k, "does not apply to shape = \"solid_circle\" (give 'diameter')");
    const auto d = read_taper(v, "diameter");
    vein.root_section = read_section_end("hollow_circle", d, {d.first / 2, d.second / 2}, true);
    vein.tip_section = read_section_end("hollow_circle", d, {d.first / 2, d.second / 2}, false);
  } else if (shape == "hollow_circle") {
    for (const char* k : {"width", "height"})
      if (v.has(k)) v.fail(k, "only applies to shape = \"rectangle\"");
    const auto d = read_taper(v, "outer_diameter");
    const auto w = read_taper(v, "wall");
    if (w.first > d.first / 2 * (1 + 1e-12) || w.second > d.second / 2 * (1 + 1e-12))
      v.fail("wall", "the wall must not exceed half the outer diameter (wall = D/2 is a solid rod)");
    vein.root_section = read_section_end(shape, d, w, true);
    vein.tip_section = read_section_end(shape, d, w, false);
  } else {
    for (const char* k : {"outer_diameter", "wall"})
      if (v.has(k)) v.fail(k, "only applies to shape = \"hollow_circle\"");
    const auto w = read_taper(v, "width");
    const auto h = read_taper(v, "height");
    vein.root_section = read_section_end(shape, w, h, true);
    vein.tip_section = read_section_end(shape, w, h, false);
  }
  return vein;
}

}  // namespace

bool is_wing_document(const TomlTable& root) { return root.has("planform"); }

namespace {
void read_wing_keys(const TomlTable& root, Wing& wing);
}  // namespace

Wing read_wing(TomlTable root) {
  // A case or chain file where a wing file belongs: say what it is rather than list its
  // tables as unknown keys.
  if (!root.has("planform")) {
    if (root.has("kinematics"))
      root.fail("kinematics", "this is a case file (it has [kinematics]), not a wing file (no [planform])" +
                                  std::string(root.is_string("wing") ? ": its wing is " + root.get_string("wing") +
                                                                           " (relative to the case file)"
                                                                     : "") +
                                  "; mesh, modes and reduce take a wing file, run and sweep a case file");
    if (root.has("bodies"))
      root.fail("bodies", "this is a chain file (it has [[bodies]], as 'flapsim reduce' writes it), not a wing "
                          "file (no [planform]): run takes it with --chain");
  }
  root.expect_only({"name", "description", "length_unit", "planform", "materials", "membrane",
                    "veins", "mesh", "surface"});
  root.read_length_unit();
  Wing wing;
  try {
    read_wing_keys(root, wing);
  } catch (const OverrideInputError&) {
    throw;  // a sweep's value: located by the sweep (sweep_case.cpp)
  } catch (const InputError& e) {
    // A warning before the error often names its cause (an outline in m under length_unit
    // = "mm" warned "shorter than any flapping wing", then failed on the mesh size): the
    // warnings are printed only for a wing that reads, so the error carries them.
    if (wing.warnings.empty()) throw;
    std::string note;
    for (const InputWarning& w : wing.warnings) note += "; perhaps the cause, a warning before it: " + w.text();
    throw InputError(e.file(), e.line(), e.key(), e.message() + note);
  }
  return wing;
}

namespace {

// The keys of a wing file, in the order they depend on one another; warnings go to wing.warnings.
void read_wing_keys(const TomlTable& root, Wing& wing) {
  wing.source_file = root.file();
  wing.name = root.get_string("name", std::filesystem::path(root.file()).stem().string());
  if (root.has("description")) root.get_string("description");

  // Materials first: membrane and veins refer to them by name.
  std::map<std::string, Material> materials;
  const TomlTable mats = root.get_table("materials");
  for (const auto& name : mats.keys()) materials[name] = read_material(mats.get_table(name), wing.warnings);

  const TomlTable planform_table = root.get_table("planform");
  const Planform planform = read_planform(planform_table, wing.warnings);
  wing.outline = planform.outline;
  wing.clamp_y = planform.clamp_y;
  if (planform.drawing)
    wing.drawing = planform.drawing->describe(planform_table.length_unit(), planform_table.length_scale());
  const PlanformProperties props = planform_properties(wing.outline);
  wing.span = props.span;
  if (planform.drawing)
    check_drawing_direction(planform_table, *planform.drawing, wing.outline, wing.warnings);
  wing.lattice_gap = lattice_gap(planform_table, wing.outline);
  warn_lattice_gap(wing.lattice_gap, wing.warnings);

  const TomlTable mem = root.get_table("membrane");
  mem.expect_only({"thickness", "material", "nonstructural_mass_per_area"});
  wing.membrane.thickness = mem.get_length("thickness", Bounds::positive());
  check_film(mem, wing.membrane.thickness, wing.span, wing.warnings);
  check_plate(mem, wing.membrane.thickness, wing.warnings);
  wing.membrane.material = find_material(mem, "material", materials);
  wing.membrane.nonstructural_mass_per_area =
      mem.get_double("nonstructural_mass_per_area", 0.0, Bounds::non_negative());
  check_nonstructural_mass(mem, wing.membrane.nonstructural_mass_per_area, wing.warnings);

  const auto veins = root.get_tables("veins");
  for (std::size_t i = 0; i < veins.size(); ++i) {
    wing.veins.push_back(read_vein(veins[i], i, planform, materials, wing.warnings));
    check_vein_section(veins[i], wing.veins.back(), wing.span, wing.warnings);
  }
  if (planform.drawing) join_drawn_veins(wing, veins);
  check_absolute_veins_of_a_rescaled_outline(planform, planform_table, veins, wing.warnings);

  // Mesh sizes default to R/50 (about 2500 membrane nodes on a hawkmoth-like planform).
  wing.mesh.element_size = wing.span / 50.0;
  wing.mesh.vein_element_size = wing.mesh.element_size;
  const auto mesh = root.find_table("mesh");
  if (mesh) {
    mesh->expect_only({"element_size", "vein_element_size"});
    wing.mesh.element_size = mesh->get_length("element_size", wing.mesh.element_size, Bounds::positive());
    wing.mesh.vein_element_size =
        mesh->get_length("vein_element_size", wing.mesh.element_size, Bounds::positive());
  }
  wing.clamp_y_line = planform_table.line_of("clamp_y");
  check_clamp_share(planform_table, wing.clamp_y, props, wing.warnings);
  if (mesh && mesh->has("element_size")) {
    wing.element_size_line = mesh->line_of("element_size");
    check_elements_across_chord(*mesh, wing.mesh.element_size, props, wing.warnings);
  }
  if (const auto surface = root.find_table("surface")) wing.surface = read_surface_shape(*surface);
  // The mesh-size rules (mesh_budget.hpp): refused here, before gmsh runs out of memory.
  MeshSizeKeys keys;
  keys.element_given = mesh && mesh->has("element_size");
  keys.vein_given = mesh && mesh->has("vein_element_size");
  keys.length_scale = root.length_scale();
  keys.unit = root.length_unit();
  if (const auto problem = mesh_size_problem(wing, keys)) {
    if (mesh) mesh->fail(problem->key, problem->what);
    root.fail("mesh", problem->what);
  }
}

}  // namespace

Wing load_wing_file(const std::string& path) { return read_wing(parse_toml_file(path)); }

}  // namespace flapsim::wings
