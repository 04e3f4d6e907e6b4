// A wing from an SVG drawing (wings/loader/drawing_frame.hpp; docs/wing_file.md, "A wing from a
// drawing"): the same wing as its inline outline and `points` veins worked out by hand, in
// every orientation of the drawing, the pivot, the shipped test drawing's Bézier outline
// against its exact area, and each mistake a user can make named.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "common/scratch_dir.hpp"
#include "expect_input_error.hpp"
#include "wings/loader/planform_geometry.hpp"
#include "wings/loader/toml_reader.hpp"
#include "wings/loader/wing_file.hpp"

namespace w = flapsim::wings;
using Eigen::Vector2d;
using flapsim::test::ScratchDir;

namespace {

const std::string kMaterial =
    "[materials.film]\nyoungs_modulus = 4.0e9\npoisson_ratio = 0.3\ndensity = 1400.0\n"
    "[membrane]\nthickness = 0.01\nmaterial = \"film\"\n";

// A trapezoid drawn with its tip to the right and its leading edge up, page units (y down):
// root from (10, 20) (leading edge) to (10, 50), tip from (110, 10) to (110, 40); a vein
// from (12, 30) to (100, 25). Pivot: the root's leading-edge end, (10, 20). In the wing's
// frame (y = x_page − 10, x = 20 − y_page, then scaled by 50 mm / 100): outline (0, 0),
// (5, 50), (−10, 50), (−15, 0) mm, the vein from (−5, 1) to (−2.5, 45) mm.
const std::string kShapes =
    "<polygon id=\"outline\" points=\"10,20 110,10 110,40 10,50\"/>\n"
    "<polyline id=\"R1\" points=\"12,30 100,25\"/>\n";

std::string svg(const std::string& body) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\">\n" + body + "</svg>\n";
}

std::string wing_toml(const std::string& planform_extra, const std::string& vein = "drawing_id = \"R1\"") {
  return "length_unit = \"mm\"\n[planform]\noutline_file = \"w.svg\"\nspan = 50.0\nclamp_y = 0.5\n" +
         planform_extra + kMaterial + "[[veins]]\nmaterial = \"film\"\nouter_diameter = 0.2\nwall = 0.05\n" +
         vein + "\n";
}

w::Wing read(const ScratchDir& dir, const std::string& drawing, const std::string& toml) {
  std::ofstream(dir / "w.svg") << drawing;
  return w::read_wing(w::parse_toml_string(toml, (dir / "w.toml").string()));
}

// The wing by hand, as an inline outline and a `points` vein.
w::Wing by_hand() {
  return w::read_wing(w::parse_toml_string(
      "length_unit = \"mm\"\n[planform]\noutline = [[0, 0], [5, 50], [-10, 50], [-15, 0]]\nclamp_y = 0.5\n" +
          kMaterial +
          "[[veins]]\nmaterial = \"film\"\nouter_diameter = 0.2\nwall = 0.05\npoints = [[-5, 1], [-2.5, "
          "45]]\n",
      "hand.toml"));
}

void expect_same_wing(const w::Wing& a, const w::Wing& b) {
  ASSERT_EQ(a.outline.size(), b.outline.size());
  // The outline may start at another point: match each by its nearest.
  for (const Vector2d& p : a.outline) {
    double nearest = 1e300;
    for (const Vector2d& q : b.outline) nearest = std::min(nearest, (p - q).norm());
    EXPECT_LT(nearest, 1e-15) << p.transpose();
  }
  ASSERT_EQ(a.veins.size(), b.veins.size());
  for (std::size_t v = 0; v < a.veins.size(); ++v) {
    ASSERT_EQ(a.veins[v].points.size(), b.veins[v].points.size());
    for (std::size_t i = 0; i < a.veins[v].points.size(); ++i)
      EXPECT_LT((a.veins[v].points[i] - b.veins[v].points[i]).norm(), 1e-15);
  }
  EXPECT_NEAR(w::planform_properties(a.outline).area, w::planform_properties(b.outline).area, 1e-18);
}

}  // namespace

TEST(WingFromDrawing, IsTheWingItsPointsWorkedOutByHandGive) {
  ScratchDir dir("drawing_by_hand");
  expect_same_wing(read(dir, svg(kShapes), wing_toml("")), by_hand());
  // A vein drawn from its tip to its root: its root-most end first, as written by hand.
  expect_same_wing(read(dir,
                        svg("<polygon id=\"outline\" points=\"10,20 110,10 110,40 10,50\"/>\n"
                            "<polyline id=\"R1\" points=\"100,25 12,30\"/>\n"),
                        wing_toml("")),
                   by_hand());
}

// The same drawing turned on the page (tip up: rotate(−90) turns it counterclockwise as
// seen) or mirrored (leading edge down) is the same wing with drawing_tip and
// drawing_leading_edge saying so; the default leading edge lies 90° counterclockwise of the tip.
// An outline drawn back to its first point without a closepath (Z) is closed as drawn.
TEST(WingFromDrawing, AnOutlineEndingWhereItStartsIsClosed) {
  ScratchDir dir("drawing_open_closed");
  expect_same_wing(read(dir,
                        svg("<path id=\"outline\" d=\"M 10,20 L 110,10 110,40 10,50 10,20\"/>\n"
                            "<polyline id=\"R1\" points=\"12,30 100,25\"/>\n"),
                        wing_toml("")),
                   by_hand());
}

TEST(WingFromDrawing, EveryOrientationOfTheDrawingGivesTheSameWing) {
  ScratchDir dir("drawing_orientations");
  const w::Wing hand = by_hand();
  expect_same_wing(
      read(dir, svg("<g transform=\"rotate(-90)\">" + kShapes + "</g>"), wing_toml("drawing_tip = \"up\"\n")),
      hand);
  expect_same_wing(read(dir, svg("<g transform=\"rotate(90)\">" + kShapes + "</g>"),
                        wing_toml("drawing_tip = \"down\"\n")),
                   hand);
  expect_same_wing(read(dir, svg("<g transform=\"rotate(180)\">" + kShapes + "</g>"),
                        wing_toml("drawing_tip = \"left\"\n")),
                   hand);
  expect_same_wing(read(dir, svg("<g transform=\"scale(1,-1)\">" + kShapes + "</g>"),
                        wing_toml("drawing_leading_edge = \"down\"\n")),
                   hand);
  // Without the key, the turned drawing is another wing (its span along the page's x), 3 times
  // wider than long: warned, asking where the tip points. The hand-made wing is not.
  const w::Wing unturned = read(dir, svg("<g transform=\"rotate(-90)\">" + kShapes + "</g>"), wing_toml(""));
  EXPECT_GT(
      std::abs(w::planform_properties(unturned.outline).area - w::planform_properties(hand.outline).area),
      1e-6);
  ASSERT_EQ(unturned.warnings.size(), 1u);
  EXPECT_EQ(unturned.warnings.front().key, "planform.outline_file");
  EXPECT_NE(unturned.warnings.front().message.find("from root to tip, its span along the drawing's right direction: "
                                                   "does the tip point up or down in the drawing?"),
            std::string::npos)
      << unturned.warnings.front().message;
  EXPECT_TRUE(read(dir, svg(kShapes), wing_toml("")).warnings.empty());
}

// A circle named "pivot" at the root's middle, (10, 35): the wing is the hand-made one moved
// by 15 page units (7.5 mm) in x.
TEST(WingFromDrawing, APivotCircleSetsTheOrigin) {
  ScratchDir dir("drawing_pivot");
  const w::Wing wing =
      read(dir, svg(kShapes + "<circle id=\"pivot\" cx=\"10\" cy=\"35\" r=\"1\"/>\n"), wing_toml(""));
  const w::Wing hand = by_hand();
  for (const Vector2d& p : hand.outline) {
    double nearest = 1e300;
    for (const Vector2d& q : wing.outline) nearest = std::min(nearest, (p + Vector2d(7.5e-3, 0) - q).norm());
    EXPECT_LT(nearest, 1e-15);
  }
}

// The shipped test drawing (tests/data/drawn_wing.svg, Inkscape's layout): its outline is
// three cubic Bézier curves and the root's straight closing edge. Green's theorem over the
// exact curves gives its area, A = Σ ∮ x dy, closed form for a cubic (the integral of
// x(t) y'(t) over t in [0, 1], a polynomial); the flattened outline's area lies within the
// flattening's bound of it (each chord within 2.5e-4 of its curve's control polygon: a
// relative area error of that order). Scaled to span 40 mm: the drawing's tip, the largest
// x of the curves, found by sampling them.
TEST(WingFromDrawing, TheTestDrawingsBezierOutlineHasItsExactArea) {
  const std::string file = std::string(FLAPSIM_SOURCE_DIR) + "/tests/data/drawn_wing.toml";
  const w::Wing wing = w::read_wing(w::parse_toml_file(file));
  // The outline's curves in the layer's coordinates (relative commands resolved by hand):
  // start (20, 90); c 60,-20 140,-30 195,-20 → (80,70) (160,60) (215,70); c 13,5 13,25 -3,30
  // from (215, 70) → (228,75) (228,95) (212,100); C 150,125 70,130 20,115; Z back to (20, 90).
  using P = Vector2d;
  const P c[3][4] = {{P(20, 90), P(80, 70), P(160, 60), P(215, 70)},
                     {P(215, 70), P(228, 75), P(228, 95), P(212, 100)},
                     {P(212, 100), P(150, 125), P(70, 130), P(20, 115)}};
  // ∫ x dy over a cubic by Gauss–Legendre with 4 points: exact for the degree-5 integrand.
  const double gx[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  const double gw[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  double area = 0.0, tip_x = -1e300;
  for (const auto& b : c) {
    for (int k = 0; k < 4; ++k) {
      const double t = 0.5 * (gx[k] + 1), u = 1 - t;
      const P q = u * u * u * b[0] + 3 * u * u * t * b[1] + 3 * u * t * t * b[2] + t * t * t * b[3];
      const P d = 3 * u * u * (b[1] - b[0]) + 6 * u * t * (b[2] - b[1]) + 3 * t * t * (b[3] - b[2]);
      area += 0.5 * gw[k] * q.x() * d.y();
    }
    for (int k = 0; k <= 100000; ++k) {  // the tip: the largest x of the curves
      const double t = k / 100000.0, u = 1 - t;
      tip_x = std::max(tip_x, u * u * u * b[0].x() + 3 * u * u * t * b[1].x() + 3 * u * t * t * b[2].x() +
                                  t * t * t * b[3].x());
    }
  }
  area += 20.0 * (90.0 - 115.0);                // the root's edge x = 20 from y = 115 to 90: ∫ x dy
  area = std::abs(area);                        // page y points down: the sign is the drawing's direction
  const double scale = 40e-3 / (tip_x - 20.0);  // the pivot's x is the root's, 20: y_wing = x − 20
  const double exact = area * scale * scale;
  const double flattened = w::planform_properties(wing.outline).area;
  // The chords cut off at most (2/3) δ ℓ each (δ their distance from the curve, within 2.5e-4
  // of the curve's control polygon, 226, 50 and 205 page units): (2/3) Σ δ ℓ over a perimeter
  // of about 450 units against an area of about 5300: under 1e-3 of it.
  EXPECT_LT(flattened / exact, 1.0);
  EXPECT_GT(flattened / exact, 1.0 - 1e-3) << flattened << " vs " << exact;
  EXPECT_NEAR(w::planform_properties(wing.outline).span, 40e-3, 1e-6 * 40e-3);  // tip sampled within 1e-6 R
  EXPECT_EQ(wing.veins.size(), 2u);
  // What `check` prints of it (the scale: 40 mm over the tip's x from the pivot, 0.1957 mm).
  EXPECT_NE(wing.drawing.find("outline the path 'path1' (label 'outline') (line 33) of drawn_wing.svg, tip right, "
                              "leading edge up, pivot the circle 'pivot' (line 38); 1 drawing unit = 0.1957 mm"),
            std::string::npos)
      << wing.drawing;
  EXPECT_NEAR(scale, 0.1957e-3, 0.00005e-3);
  // R1 is drawn from the tip inward; its first point is the root-most: page (22, 95), the
  // pivot at (20, 92): y = 2, x = −3 page units.
  // (scale from the exact tip: the flattened outline's tip lies within 1e-6 R of it)
  EXPECT_LT((wing.veins[0].points.front() - scale * Vector2d(-3, 2)).norm(), 1e-6 * 40e-3);
}

// What a user gets wrong, each named with the key and line.
TEST(WingFromDrawing, MistakesAreNamed) {
  ScratchDir dir("drawing_mistakes");
  // A copy of the message: what() of the returned error dies with that temporary
  // (AddressSanitizer found the pointer read after the error was freed).
  const auto message = [&](const std::string& drawing, const std::string& toml) -> std::string {
    return expect_input_error([&] { read(dir, drawing, toml); }).what();
  };
  const std::string two =
      "<rect id=\"a\" x=\"0\" y=\"0\" width=\"100\" height=\"20\"/>\n"
      "<rect id=\"b\" x=\"0\" y=\"30\" width=\"100\" height=\"20\"/>\n";
  EXPECT_NE(std::string(message(svg(two), wing_toml("", "points = [[0, 1], [0, 2]]")))
                .find("has 2 closed shapes: name the outline's with outline_id"),
            std::string::npos);
  EXPECT_NE(std::string(message(svg(two), wing_toml("outline_id = \"c\"\n", "points = [[0, 1], [0, 2]]")))
                .find("no shape with the id or label 'c' in"),
            std::string::npos);
  EXPECT_NE(std::string(message(svg("<path id=\"outline\" d=\"M 0 0 L 100 0 L 100 20\"/>\n"),
                                wing_toml("", "points = [[0, 1], [0, 2]]")))
                .find("must be one closed curve: it is open"),
            std::string::npos);
  EXPECT_NE(std::string(message(svg(kShapes), wing_toml("", "drawing_id = \"R2\"")))
                .find("no shape with the id or label 'R2'"),
            std::string::npos);
  // An outline or a pivot without points (found by fuzzing the wing's drawing: `points=""`
  // read the first point of an empty outline).
  EXPECT_NE(std::string(message(svg("<polygon id=\"outline\" points=\"\"/>\n"),
                                wing_toml("", "points = [[0, 1], [0, 2]]")))
                .find("has 0 distinct points: a closed outline needs at least 3"),
            std::string::npos);
  EXPECT_NE(std::string(message(svg(kShapes + "<polygon id=\"pivot\" points=\"\"/>\n"), wing_toml("")))
                .find("the pivot, the polygon 'pivot' (line 4) of"),
            std::string::npos);
  // A branching vein drawn as one path, and a vein traced as an area: what to draw instead.
  const std::string outline = "<polygon id=\"outline\" points=\"10,20 110,10 110,40 10,50\"/>\n";
  EXPECT_NE(
      std::string(
          message(svg(outline + "<path id=\"R1\" d=\"M 12 30 L 100 25 M 50 28 L 90 15\"/>\n"), wing_toml("")))
          .find("must be one open line: it has 2 subpaths (a branching vein is one [[veins]] entry a branch"),
      std::string::npos);
  EXPECT_NE(
      std::string(message(svg(outline + "<path id=\"R1\" d=\"M 12 30 L 100 25 L 100 26 L 12 31 Z\"/>\n"),
                          wing_toml("")))
          .find("it is closed (a vein traced as an area"),
      std::string::npos);
  EXPECT_NE(std::string(message(svg(kShapes),
                                wing_toml("drawing_tip = \"right\"\ndrawing_leading_edge = \"left\"\n")))
                .find("must be at right angles to drawing_tip"),
            std::string::npos);
  // A vein drawn past the outline: the wing file's line of drawing_id.
  const auto outside = expect_input_error([&] {
    read(dir,
         svg("<polygon id=\"outline\" points=\"10,20 110,10 110,40 10,50\"/>\n<polyline id=\"R1\" "
             "points=\"12,30 130,25\"/>\n"),
         wing_toml(""));
  });
  EXPECT_EQ(outside.key(), "veins[0].drawing_id");
  EXPECT_EQ(outside.line(), 17);  // wing_toml's line of drawing_id
  EXPECT_NE(outside.message().find("the vein leaves the outline"), std::string::npos);
  // The drawing's keys without a drawing, and a drawn vein without one.
  const auto inline_outline = [](const std::string& extra, const std::string& vein) {
    return "length_unit = \"mm\"\n[planform]\noutline = [[0, 0], [5, 50], [-10, 50], [-15, 0]]\nclamp_y = "
           "0.5\n" +
           extra + kMaterial + "[[veins]]\nmaterial = \"film\"\nouter_diameter = 0.2\nwall = 0.05\n" + vein +
           "\n";
  };
  EXPECT_NE(
      std::string(expect_input_error([&] {
                    w::read_wing(w::parse_toml_string(
                        inline_outline("drawing_tip = \"up\"\n", "points = [[0, 1], [0, 2]]"), "x.toml"));
                  }).what())
          .find("only applies to an SVG drawing"),
      std::string::npos);
  EXPECT_NE(
      std::string(expect_input_error([&] {
                    w::read_wing(w::parse_toml_string(inline_outline("", "drawing_id = \"R1\""), "x.toml"));
                  }).what())
          .find("no SVG drawing"),
      std::string::npos);
}

// A hidden layer (Inkscape: style="display:none" on the layer's group) or a hidden object is
// not part of the drawing (SVG 1.1, 11.5): a closed reference shape in a hidden layer is not
// a second outline, a hidden vein is not read, and a name found only among the hidden shapes
// says so. Before: hidden shapes were read like the others ("has 2 closed shapes").
TEST(WingFromDrawing, HiddenLayersAndObjectsAreNotRead) {
  ScratchDir dir("drawing_hidden");
  const std::string hidden_layer =
      "<g inkscape:groupmode=\"layer\" inkscape:label=\"trace\" style=\"fill:none; display : none\">\n"
      "  <rect x=\"0\" y=\"0\" width=\"300\" height=\"90\"/>\n"
      "  <polyline id=\"R2\" points=\"12,30 100,25\"/>\n</g>\n";
  const std::string unnamed_outline =
      "<polygon points=\"10,20 110,10 110,40 10,50\"/>\n<polyline id=\"R1\" points=\"12,30 100,25\"/>\n";
  // The visible shapes alone are the wing worked out by hand; check's line counts the hidden ones.
  const w::Wing visible = read(dir, svg(hidden_layer + unnamed_outline), wing_toml(""));
  expect_same_wing(visible, by_hand());
  EXPECT_NE(visible.drawing.find("; 2 hidden shapes (display:none) not read"), std::string::npos)
      << visible.drawing;
  // The same layer shown: two closed shapes.
  std::string shown = hidden_layer;
  shown.replace(shown.find("display : none"), 14, "display:inline");
  EXPECT_NE(
      std::string(expect_input_error([&] { read(dir, svg(shown + unnamed_outline), wing_toml("")); }).what())
          .find("has 2 closed shapes"),
      std::string::npos);
  // A vein named only in the hidden layer; an outline hidden by its own attribute.
  const std::string hidden_vein =
      expect_input_error([&] {
        read(dir, svg(hidden_layer + unnamed_outline), wing_toml("", "drawing_id = \"R2\""));
      }).what();
  EXPECT_NE(hidden_vein.find("no shape with the id or label 'R2'"), std::string::npos) << hidden_vein;
  EXPECT_NE(hidden_vein.find("the polyline 'R2' (line 4) of it is hidden, display:none"), std::string::npos)
      << hidden_vein;
  const std::string hidden_outline =
      expect_input_error([&] {
        read(dir, svg("<polygon display=\"none\" points=\"10,20 110,10 110,40 10,50\"/>\n"), wing_toml(""));
      }).what();
  EXPECT_NE(hidden_outline.find("has no closed shape for the outline"), std::string::npos) << hidden_outline;
  EXPECT_NE(hidden_outline.find("its 1 hidden shape, display:none, is not read"), std::string::npos)
      << hidden_outline;
}

// Inkscape's clones (Edit > Clone): a vein drawn once and cloned into place, and an outline
// cloned from a template in <defs> moved by the clone's transform, give the wing worked out
// by hand; a vein named by a clone that draws nothing is refused saying why.
TEST(WingFromDrawing, ClonedShapesAreTheWingsOutlineAndVeins) {
  ScratchDir dir("drawing_clones");
  const std::string cloned =
      "<defs><polygon id=\"template\" points=\"0,10 100,0 100,30 0,40\"/></defs>\n"
      "<use href=\"#template\" id=\"outline\" transform=\"translate(10,10)\"/>\n"
      "<g transform=\"translate(500,500)\"><polyline id=\"vein\" points=\"2,5 90,0\"/></g>\n"
      "<g style=\"display:none\">\n<use xlink:href=\"#vein\" id=\"draft\"/></g>\n"
      "<use xlink:href=\"#vein\" id=\"use7\" inkscape:label=\"R1\" x=\"10\" y=\"25\"/>\n";
  // The original vein inside translate(500,500) is a second, unnamed open shape: not read.
  expect_same_wing(read(dir, svg(cloned), wing_toml("")), by_hand());
  // An outline cloned from a template that is not there.
  const std::string no_outline =
      expect_input_error([&] {
        read(dir,
             svg("<use href=\"#templet\" id=\"use3\"/>\n<polyline id=\"R1\" points=\"12,30 100,25\"/>\n"),
             wing_toml(""));
      }).what();
  EXPECT_NE(no_outline.find("has no closed shape for the outline"), std::string::npos) << no_outline;
  EXPECT_NE(
      no_outline.find("(the use 'use3' (line 2) is a clone that draws nothing: the drawing has no element "
                      "with the id 'templet')"),
      std::string::npos)
      << no_outline;
  // check's line says which clone draws nothing.
  const w::Wing broken = read(dir, svg(cloned + "<use href=\"#gone\" id=\"R2\"/>\n"), wing_toml(""));
  EXPECT_NE(
      broken.drawing.find("; 1 clone draws nothing (the use 'R2' (line 8): the drawing has no element with "
                          "the id 'gone')"),
      std::string::npos)
      << broken.drawing;
  const std::string lost =
      expect_input_error([&] {
        read(dir, svg(cloned + "<use href=\"#gone\" id=\"R2\"/>\n"), wing_toml("", "drawing_id = \"R2\""));
      }).what();
  EXPECT_NE(lost.find("no shape with the id or label 'R2'"), std::string::npos) << lost;
  EXPECT_NE(
      lost.find("the use 'R2' (line 8) is a clone that draws nothing: the drawing has no element with the "
                "id 'gone'"),
      std::string::npos)
      << lost;
}

// An outline_file in a format flapsim does not read is named with what to do, before its
// bytes are read as CSV (before: "expected a line "x,y" ..., found "%PDF-1.4"").
TEST(WingFromDrawing, ADrawingInAnotherFormatIsNamedWithWhatToDo) {
  ScratchDir dir("drawing_formats");
  for (const char* name : {"w.pdf", "w.DXF", "w.svgz", "w.png", "w.ai"}) {
    std::ofstream(dir / name) << "%PDF-1.4\n";
    std::string toml = wing_toml("", "points = [[0, 1], [0, 2]]");
    toml.replace(toml.find("w.svg"), 5, name);
    const auto e =
        expect_input_error([&] { w::read_wing(w::parse_toml_string(toml, (dir / "w.toml").string())); });
    EXPECT_EQ(e.key(), "planform.outline_file") << name;
    EXPECT_EQ(e.line(), 3) << name;  // wing_toml's line of outline_file
    EXPECT_NE(e.message().find("which is not read"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find(std::string(name) == "w.png" ? "trace the wing's outline" : "SVG"),
              std::string::npos)
        << e.message();
  }
  // The drawing or an outline CSV given where the wing file belongs (`flapsim mesh w.svg`).
  std::ofstream(dir / "d.svg") << svg(kShapes);
  std::ofstream(dir / "o.csv") << "x,y\n0,0\n";
  for (const char* name : {"d.svg", "o.csv"}) {
    const auto e = expect_input_error([&] { w::load_wing_file((dir / name).string()); });
    EXPECT_NE(e.message().find("TOML syntax error"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("is not a wing file: a wing file (TOML, docs/wing_file.md) names it"),
              std::string::npos)
        << e.message();
  }
  // A CSV under another extension is read as before (here .txt).
  std::ofstream(dir / "o.txt") << "x,y\n0,0\n0.1,1\n-0.2,1\n-0.3,0\n";
  EXPECT_EQ(
      w::read_wing(w::parse_toml_string(
                       "length_unit = \"mm\"\n[planform]\noutline_file = \"o.txt\"\nspan = 50.0\nclamp_y = "
                       "0.5\n" +
                           kMaterial,
                       (dir / "w.toml").string()))
          .outline.size(),
      4u);
}

// A traced vein passing the outline's edge a little at either end (here 1 drawing unit,
// 0.5 mm, 1 % of the 50 mm span) is cut at the edge, with a warning for each end; by hand
// (the trapezoid's map above): the vein (9, 30)–(111, 25) crosses the root x = 10 at
// t = 1/102 and the tip x = 110 at t = 101/102, so it runs from (x, y) = ((20 − (30 − 5/102))/2,
// 0) to ((20 − (30 − 505/102))/2, 50) mm. Passing by 8 % of the span it is refused.
TEST(WingFromDrawing, AVeinPassingTheEdgeALittleIsCutAtTheEdge) {
  ScratchDir dir("drawing_vein_overshoot");
  const std::string outline = "<polygon id=\"outline\" points=\"10,20 110,10 110,40 10,50\"/>\n";
  const w::Wing wing =
      read(dir, svg(outline + "<polyline id=\"R1\" points=\"9,30 111,25\"/>\n"), wing_toml(""));
  ASSERT_EQ(wing.veins.size(), 1u);
  const auto& p = wing.veins[0].points;
  ASSERT_EQ(p.size(), 2u);
  EXPECT_NEAR(p[0].x(), (20.0 - (30.0 - 5.0 / 102.0)) / 2.0 * 1e-3, 1e-12);
  EXPECT_NEAR(p[0].y(), 0.0, 1e-12);
  EXPECT_NEAR(p[1].x(), (20.0 - (30.0 - 505.0 / 102.0)) / 2.0 * 1e-3, 1e-12);
  EXPECT_NEAR(p[1].y(), 50e-3, 1e-12);
  ASSERT_EQ(wing.warnings.size(), 2u);
  EXPECT_NE(
      wing.warnings[0].message.find("root end passes the outline's edge by 0.5 mm (1 % of the span): cut"),
      std::string::npos)
      << wing.warnings[0].message;
  EXPECT_EQ(wing.warnings[1].key, "veins[0].drawing_id");
  const auto far = expect_input_error(
      [&] { read(dir, svg(outline + "<polyline id=\"R1\" points=\"12,30 118,25\"/>\n"), wing_toml("")); });
  EXPECT_NE(far.message().find("4 mm outside it"), std::string::npos) << far.message();
  EXPECT_NE(far.message().find("a drawn vein's end may pass the edge by up to 2 % of the span (1 mm)"),
            std::string::npos)
      << far.message();
}

// A traced branch that stops a little short of the vein it starts from, or passes it, is
// joined to it (else the branch's end floats in the membrane, held by the film alone). On the
// trapezoid (wing frame by hand: x = (20 − y_page)/2, y = (x_page − 10)/2 mm), R1 runs from
// (10, 30) to (110, 25): at x_page = 50 through y_page = 28, the wing's (−4, 20) mm. A branch
// R2 from (50, 28.6) (0.3 mm short of R1) to (90, 38) starts on R1's nearest point; from
// (50, 27.4) (0.3 mm past R1) it is cut where it crosses R1. Each joins within 1e-12 m
// of R1's line, a warning says how far it was; a branch 2 mm off (4 % of the span) stays free.
TEST(WingFromDrawing, ABranchStoppingShortOfAVeinOrPassingItIsJoinedToIt) {
  ScratchDir dir("drawing_vein_junction");
  const std::string shapes =
      "<polygon id=\"outline\" points=\"10,20 110,10 110,40 10,50\"/>\n"
      "<polyline id=\"R1\" points=\"10,30 110,25\"/>\n";
  const std::string two_veins = wing_toml("") +
                                "[[veins]]\nmaterial = \"film\"\nouter_diameter = 0.2\nwall = "
                                "0.05\ndrawing_id = \"R2\"\n";
  // R1 in the wing's frame: from (−5, 0) to (−2.5, 50) mm.
  const auto off_r1 = [](const Vector2d& q) {
    const Vector2d a(-5e-3, 0.0), b(-2.5e-3, 50e-3);
    const Vector2d n = Vector2d(-(b - a).y(), (b - a).x()).normalized();
    return std::abs((q - a).dot(n));
  };
  for (const char* start : {"50,28.6", "50,27.4", "50,32"}) {
    SCOPED_TRACE(start);
    const w::Wing wing = read(
        dir, svg(shapes + "<polyline id=\"R2\" points=\"" + std::string(start) + " 90,38\"/>\n"), two_veins);
    ASSERT_EQ(wing.veins.size(), 2u);
    const Vector2d root = wing.veins[1].points.front();
    if (std::string(start) == "50,32") {  // 2 mm off: a free end, as drawn
      EXPECT_NEAR(root.x(), -6e-3, 1e-12);
      EXPECT_TRUE(wing.warnings.empty());
      continue;
    }
    EXPECT_LT(off_r1(root), 1e-12);
    EXPECT_EQ(wing.veins[1].points.size(), 2u);
    ASSERT_EQ(wing.warnings.size(), 1u);
    EXPECT_EQ(wing.warnings[0].key, "veins[1].drawing_id");
    const std::string expected = std::string(start) == "50,28.6"
                                     ? "root end stops 0.29"  // 0.3 mm along y_page, 0.2996 mm across R1
                                     // R2 meets R1 at 17.8°: 0.3 mm past it across is 0.985 mm along R2.
                                     : "root end crosses vein 1 ('vein 1') and goes on 0.98";
    EXPECT_NE(wing.warnings[0].message.find(expected), std::string::npos) << wing.warnings[0].message;
  }
}
