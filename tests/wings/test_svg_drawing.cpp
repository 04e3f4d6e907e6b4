// The SVG reader of wing drawings (wings/loader/svg_drawing.hpp): path data by SVG 1.1's grammar,
// Bézier and arc flattening against the exact curves, transforms of groups, the elements
// skipped, and every error located by file and line.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "expect_input_error.hpp"
#include "wings/loader/svg_drawing.hpp"

namespace w = flapsim::wings;
using Eigen::Vector2d;

namespace {

w::SvgDrawing drawing(const std::string& body) {
  return w::parse_svg_drawing("<svg xmlns=\"http://www.w3.org/2000/svg\">\n" + body + "\n</svg>\n", "d.svg",
                              "planform.outline_file");
}

// The drawing's one shape (a copy: the drawing is often a temporary).
w::SvgShape only(const w::SvgDrawing& d) {
  EXPECT_EQ(d.shapes.size(), 1u);
  return d.shapes.empty() ? w::SvgShape{} : d.shapes.front();
}

void expect_points(const std::vector<Vector2d>& got, const std::vector<Vector2d>& want, double tol = 1e-12) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i)
    EXPECT_LT((got[i] - want[i]).norm(), tol)
        << "point " << i << ": " << got[i].transpose() << " vs " << want[i].transpose();
}

}  // namespace

// Lines, absolute and relative, H and V, the implicit lineto after a moveto, closepath.
TEST(SvgDrawing, StraightPathCommandsAbsoluteAndRelative) {
  const w::SvgShape a = only(drawing("<path id=\"a\" d=\"M 0,0 L 10 0 10,5 Z\"/>"));
  EXPECT_TRUE(a.closed);
  EXPECT_EQ(a.id, "a");
  expect_points(a.points, {{0, 0}, {10, 0}, {10, 5}});
  const w::SvgShape b = only(drawing("<path d=\"m 1 1 h 4 v 2 h -4 z\"/>"));
  expect_points(b.points, {{1, 1}, {5, 1}, {5, 3}, {1, 3}});
  // After m, pairs are relative linetos; after M absolute ones.
  const w::SvgShape c = only(drawing("<path d=\"m 1 1 2 0 0 2\"/>"));
  EXPECT_FALSE(c.closed);
  expect_points(c.points, {{1, 1}, {3, 1}, {3, 3}});
}

// SVG 1.1, 8.3.9: "10-5.5.5" is 10, −5.5, 0.5; exponents; no separators after commands.
TEST(SvgDrawing, NumbersWithoutSeparatorsFollowSvgsGrammar) {
  const w::SvgShape s = only(drawing("<path d=\"M0,0L10-5.5.5,2l1e1-2E-1\"/>"));
  expect_points(s.points, {{0, 0}, {10, -5.5}, {0.5, 2}, {10.5, 1.8}});
}

// A cubic's points lie on the exact curve B(k/n), its ends exactly; the chords keep within
// the documented flatness (2.5e-4 of the control polygon) of the curve.
TEST(SvgDrawing, CubicBezierPointsLieOnTheCurveWithinTheFlatness) {
  const Vector2d p0(0, 0), p1(30, -40), p2(80, -40), p3(100, 0);
  const w::SvgShape s = only(drawing("<path d=\"M 0 0 C 30 -40 80 -40 100 0\"/>"));
  const int n = static_cast<int>(s.points.size()) - 1;
  ASSERT_GE(n, 2);
  const auto bezier = [&](double t) {
    const double u = 1 - t;
    return Vector2d(u * u * u * p0 + 3 * u * u * t * p1 + 3 * u * t * t * p2 + t * t * t * p3);
  };
  for (int k = 0; k <= n; ++k) EXPECT_LT((s.points[k] - bezier(double(k) / n)).norm(), 1e-12);
  EXPECT_EQ(s.points.back(), p3);
  const double polygon = (p1 - p0).norm() + (p2 - p1).norm() + (p3 - p2).norm();
  double worst = 0.0;  // the curve's largest distance from its chords, densely sampled
  for (int k = 0; k < n; ++k)
    for (int j = 1; j < 50; ++j) {
      const double t = (k + j / 50.0) / n;
      const Vector2d a = s.points[k], b = s.points[k + 1], q = bezier(t);
      const double u = std::clamp((q - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      worst = std::max(worst, (a + u * (b - a) - q).norm());
    }
  EXPECT_LE(worst, 2.5e-4 * polygon);
  EXPECT_GT(worst, 2.5e-6 * polygon);  // not flattened far finer than asked
}

// An arc's points lie on its circle (SVG 1.1, F.6.5: the centre from the end points and
// flags); 96 pieces a turn: a quarter circle in 24. The four flag choices by hand.
TEST(SvgDrawing, ArcsFollowTheirCircleWithTheFlagsChoosingTheCentre) {
  // From (10, 0) to (0, 10), radius 10: centre (0, 0) or (10, 10).
  struct Case {
    const char* flags;
    Vector2d centre;
    int pieces;
  };
  for (const Case& c : {Case{"0 1", {0, 0}, 24}, Case{"0 0", {10, 10}, 24}, Case{"1 0", {0, 0}, 72},
                        Case{"1 1", {10, 10}, 72}}) {
    const w::SvgShape s = only(drawing(std::string("<path d=\"M 10 0 A 10 10 0 ") + c.flags + " 0 10\"/>"));
    EXPECT_EQ(static_cast<int>(s.points.size()) - 1, c.pieces) << c.flags;
    for (const Vector2d& q : s.points) EXPECT_NEAR((q - c.centre).norm(), 10.0, 1e-12) << c.flags;
    EXPECT_EQ(s.points.back(), Vector2d(0, 10));
  }
  // Radii too small for the ends are scaled up (F.6.6): a half circle of radius 5.
  const w::SvgShape h = only(drawing("<path d=\"M 0 0 A 1 1 0 0 1 10 0\"/>"));
  for (const Vector2d& q : h.points) EXPECT_NEAR((q - Vector2d(5, 0)).norm(), 5.0, 1e-12);
}

// Smooth cubics reflect the last control point; quadratics and their smooth form likewise.
TEST(SvgDrawing, SmoothCurvesReflectTheLastControlPoint) {
  const w::SvgShape s = only(drawing("<path d=\"M 0 0 C 0 10 10 10 10 0 S 20 -10 20 0\"/>"));
  const w::SvgShape t = only(drawing("<path d=\"M 0 0 C 0 10 10 10 10 0 C 10 -10 20 -10 20 0\"/>"));
  expect_points(s.points, t.points);
  const w::SvgShape q = only(drawing("<path d=\"M 0 0 Q 5 10 10 0 T 20 0\"/>"));
  const w::SvgShape r = only(drawing("<path d=\"M 0 0 Q 5 10 10 0 Q 15 -10 20 0\"/>"));
  expect_points(q.points, r.points);
  // After another command the first control point is the current point (SVG 1.1, 8.3.6).
  expect_points(only(drawing("<path d=\"M 0 0 L 1 1 S 5 10 10 0\"/>")).points,
                only(drawing("<path d=\"M 0 0 L 1 1 C 1 1 5 10 10 0\"/>")).points);
  expect_points(only(drawing("<path d=\"M 0 0 L 1 1 T 10 0\"/>")).points,
                only(drawing("<path d=\"M 0 0 L 1 1 Q 1 1 10 0\"/>")).points);
}

// Group and element transforms compose outside in: translate(100, 0) of the group, then
// the element's scale(2) rotate(90): (1, 0) → (0, 1) → (0, 2) → (100, 2).
TEST(SvgDrawing, TransformsOfGroupsAndElementsCompose) {
  const w::SvgShape s =
      only(drawing("<g transform=\"translate(100,0)\"><g><polyline transform=\"scale(2) rotate(90)\" "
                   "points=\"0,0 1,0 1,1\"/></g></g>"));
  expect_points(s.points, {{100, 0}, {100, 2}, {98, 2}});
  const w::SvgShape m =
      only(drawing("<line transform=\"matrix(1 0 0 -1 5 5)\" x1=\"1\" y1=\"1\" x2=\"2\" y2=\"3\"/>"));
  expect_points(m.points, {{6, 4}, {7, 2}});
  const w::SvgShape r =
      only(drawing("<line transform=\"rotate(180 5 5)\" x1=\"0\" y1=\"0\" x2=\"10\" y2=\"0\"/>"));
  expect_points(r.points, {{10, 10}, {0, 10}});
}

// What a drawing program writes around the shapes: the XML declaration, comments, a
// DOCTYPE, Inkscape's named view and metadata, and <defs> whose paths are no shapes.
TEST(SvgDrawing, DefinitionsCommentsAndMetadataAreNotShapes) {
  const w::SvgDrawing d = w::parse_svg_drawing(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!DOCTYPE svg [ <!ENTITY x \"y\"> ]>\n"
      "<!-- a <path d=\"M 0 0\"/> in a comment -->\n"
      "<svg:svg xmlns:svg=\"http://www.w3.org/2000/svg\" width=\"210mm\">\n"
      "  <sodipodi:namedview id=\"base\"/>\n  <defs><path id=\"lpe\" d=\"M 0 0 L 1 1\"/></defs>\n"
      "  <metadata><rdf:RDF><cc:Work/></rdf:RDF></metadata>\n"
      "  <svg:g inkscape:label=\"Layer 1\">\n    <svg:rect id=\"r&amp;1\" inkscape:label=\"wing\" x=\"1\" "
      "y=\"2\"\n"
      "      width=\"3\" height=\"4\"/>\n  </svg:g>\n</svg:svg>\n",
      "d.svg", "k");
  const w::SvgShape r = only(d);
  EXPECT_EQ(r.element, "rect");
  EXPECT_EQ(r.id, "r&1");
  EXPECT_EQ(r.label, "wing");
  EXPECT_EQ(r.line, 9);
  EXPECT_TRUE(r.closed);
  expect_points(r.points, {{1, 2}, {4, 2}, {4, 6}, {1, 6}});
  EXPECT_EQ(w::find_svg_shapes(d, "wing").size(), 1u);
  EXPECT_EQ(w::find_svg_shapes(d, "r&1").size(), 1u);
  EXPECT_TRUE(w::find_svg_shapes(d, "lpe").empty());
}

// A name may be a group's: matplotlib writes a patch's gid on the <g> around its path.
// The shape's own id or label comes first; a group of two shapes names both.
TEST(SvgDrawing, AGroupsNameFindsTheShapesInsideIt) {
  const w::SvgDrawing d = drawing(
      "<g id=\"outline\"><g><path d=\"M 0 0 L 1 0 L 1 1 Z\"/></g></g>\n"
      "<g id=\"veins\"><path id=\"outline_copy\" d=\"M 0 0 L 1 1\"/><path d=\"M 0 1 L 1 0\"/></g>\n"
      "<g id=\"R1\"><path id=\"inner\" inkscape:label=\"R1\" d=\"M 2 2 L 3 3\"/><path d=\"M 5 5 L 6 6\"/></g>\n");
  const auto outline = w::find_svg_shapes(d, "outline");
  ASSERT_EQ(outline.size(), 1u);
  EXPECT_TRUE(outline.front()->closed);
  EXPECT_EQ(outline.front()->group_names, (std::vector<std::string>{"outline"}));
  EXPECT_EQ(w::find_svg_shapes(d, "veins").size(), 2u);
  const auto r1 = w::find_svg_shapes(d, "R1");  // its own label, not the group's two
  ASSERT_EQ(r1.size(), 1u);
  EXPECT_EQ(r1.front()->id, "inner");
}

// A <use> (Inkscape's clone) draws its original in the use's frame: the use's transform, then
// translate(x, y), then the original's own transform, not the transforms of the groups around
// the original (SVG 1.1, 5.6). Worked by hand: the path's (0,0)-(10,0) moved by its own
// translate(1,0) is (1,0)-(11,0); y = 5 gives (1,5)-(11,5); rotate(90), (x,y) -> (-y,x), gives
// (-5,1)-(-5,11). The original, inside translate(100,0): (101,0)-(111,0).
TEST(SvgDrawing, AClonesShapeIsItsOriginalInTheClonesFrame) {
  const w::SvgDrawing d = drawing(
      "<g transform=\"translate(100,0)\"><path id=\"p\" transform=\"translate(1,0)\" d=\"M 0 0 L 10 "
      "0\"/></g>\n"
      "<use xlink:href=\"#p\" id=\"u\" inkscape:label=\"vein2\" x=\"0\" y=\"5\" transform=\"rotate(90)\"/>\n"
      "<path id=\"last\" d=\"M 0 0 L 0 1\"/>");
  ASSERT_EQ(d.shapes.size(), 3u);  // in document order: the clone where its <use> is
  EXPECT_EQ(d.shapes[0].id, "p");
  expect_points(d.shapes[0].points, {{101, 0}, {111, 0}});
  const auto clone = w::find_svg_shapes(d, "vein2");
  ASSERT_EQ(clone.size(), 1u);
  EXPECT_EQ(clone.front(), &d.shapes[1]);
  expect_points(clone.front()->points, {{-5, 1}, {-5, 11}});
  EXPECT_EQ(clone.front()->id, "u");
  EXPECT_EQ(clone.front()->line, 3);
  EXPECT_EQ(clone.front()->describe(), "the clone 'u' (label 'vein2') (line 3) of the path 'p' (line 2)");
  EXPECT_EQ(w::find_svg_shapes(d, "p").size(), 1u);  // the original alone has its id
  EXPECT_EQ(d.shapes[2].id, "last");
}

// A clone of a group defined in <defs> draws the group's shapes, found by the clone's name as
// a group's; the definitions themselves are not drawn. A clone of the clone follows it; a
// hidden <use> is a hidden shape.
TEST(SvgDrawing, ClonesOfAGroupAndOfAClone) {
  const w::SvgDrawing d = drawing(
      "<defs><g id=\"pair\" transform=\"scale(2)\"><path id=\"a\" d=\"M 0 0 L 1 0\"/>"
      "<path id=\"b\" d=\"M 0 1 L 1 1\"/></g></defs>\n"
      "<use href=\"#pair\" id=\"twins\" x=\"10\"/>\n"
      "<use href=\"#twins\" id=\"again\" y=\"100\"/>\n"
      "<use href=\"#pair\" id=\"ghost\" style=\"display:none\"/>");
  EXPECT_EQ(d.shapes.size(), 4u);
  EXPECT_TRUE(w::find_svg_shapes(d, "a").empty());
  const auto twins = w::find_svg_shapes(d, "twins");  // with the group's scale(2), then x = 10
  ASSERT_EQ(twins.size(), 2u);
  expect_points(twins[0]->points, {{10, 0}, {12, 0}});
  expect_points(twins[1]->points, {{10, 2}, {12, 2}});
  const auto again = w::find_svg_shapes(d, "again");
  ASSERT_EQ(again.size(), 2u);
  expect_points(again[1]->points, {{10, 102}, {12, 102}});
  EXPECT_EQ(again[1]->describe(), "the clone (line 4) of the path 'b' (line 2)");
  EXPECT_EQ(d.hidden.size(), 2u);
  EXPECT_TRUE(d.unread_clones.empty());
}

// A clone that cannot be drawn is no shape; a name only it has says why.
TEST(SvgDrawing, ClonesThatDrawNothingAreNamedWithWhy) {
  const w::SvgDrawing d = drawing(
      "<use id=\"lost\" href=\"#nothing\"/>\n"
      "<g id=\"loop\"><use id=\"self\" href=\"#loop\"/></g>\n"
      "<use id=\"other\" href=\"other.svg#p\"/>\n"
      "<defs><symbol id=\"sym\" viewBox=\"0 0 1 1\"><path d=\"M 0 0 L 1 1\"/></symbol></defs>\n"
      "<use id=\"scaled\" href=\"#sym\" width=\"10\" height=\"10\"/>");
  EXPECT_TRUE(d.shapes.empty());
  ASSERT_EQ(d.unread_clones.size(), 4u);
  const auto note = [&](const char* name) { return w::missing_shape_note(d, name); };
  EXPECT_NE(
      note("lost").find("the use 'lost' (line 2) is a clone that draws nothing: the drawing has no element "
                        "with the id 'nothing'"),
      std::string::npos)
      << note("lost");
  EXPECT_NE(note("self").find("deep"), std::string::npos) << note("self");
  EXPECT_NE(note("other").find("not an element of this drawing"), std::string::npos) << note("other");
  EXPECT_NE(note("scaled").find("viewBox"), std::string::npos) << note("scaled");
  EXPECT_EQ(note("nobody"), "");
}

// Clones of groups of clones multiply: 9 levels of 10 clones each of a 2-point line ask for
// 2·10^9 points, refused at the drawing's budget (kMaxDrawingPoints, 10^6) as they are made.
TEST(SvgDrawing, ClonesMultiplyingPastTheDrawingsBudgetAreRefused) {
  std::string body = "<defs><g id=\"g0\"><path d=\"M 0 0 L 1 0\"/></g>\n";
  for (int level = 1; level <= 9; ++level) {
    body += "<g id=\"g" + std::to_string(level) + "\">";
    for (int k = 0; k < 10; ++k) body += "<use href=\"#g" + std::to_string(level - 1) + "\"/>";
    body += "</g>\n";
  }
  body += "</defs>\n<use href=\"#g9\"/>";
  const std::string e = expect_input_error([&] { (void)drawing(body); }).what();
  EXPECT_NE(e.find("more than 1000000 points (with its clones)"), std::string::npos) << e;
}

// A circle is 96 points on it; a path's subpaths are counted, the first kept.
TEST(SvgDrawing, CirclesAndSubpaths) {
  const w::SvgShape c = only(drawing("<circle cx=\"3\" cy=\"4\" r=\"2\"/>"));
  EXPECT_EQ(c.points.size(), 96u);
  Vector2d mean = Vector2d::Zero();
  for (const Vector2d& q : c.points) {
    EXPECT_NEAR((q - Vector2d(3, 4)).norm(), 2.0, 1e-12);
    mean += q / 96.0;
  }
  EXPECT_LT((mean - Vector2d(3, 4)).norm(), 1e-12);
  const w::SvgShape p = only(drawing("<path d=\"M 0 0 L 1 0 L 1 1 Z M 5 5 L 6 5 L 6 6 Z\"/>"));
  EXPECT_EQ(p.subpaths, 2);
  expect_points(p.points, {{0, 0}, {1, 0}, {1, 1}});
}

// Each error names the file and the line of the element.
TEST(SvgDrawing, ErrorsNameTheFileAndTheElementsLine) {
  const auto bad_path = expect_input_error([] { drawing("\n<path id=\"v\" d=\"M 0 0 L 1\"/>"); });
  EXPECT_EQ(bad_path.file(), "d.svg");
  EXPECT_EQ(bad_path.line(), 3);
  EXPECT_EQ(bad_path.key(), "planform.outline_file");
  EXPECT_NE(
      bad_path.message().find("the path 'v' (line 3): path data (d) at character 10: expected a number"),
      std::string::npos)
      << bad_path.message();
  const auto bad_transform = expect_input_error([] { drawing("<g transform=\"perspective(2)\"></g>"); });
  EXPECT_EQ(bad_transform.line(), 2);
  EXPECT_NE(bad_transform.message().find("unknown transform 'perspective'"), std::string::npos);
  const auto unclosed = expect_input_error([] { drawing("<g>\n<path d=\"M 0 0 L 1 1\"/>"); });
  EXPECT_NE(unclosed.message().find("</svg> closes <g> of line 2"), std::string::npos) << unclosed.message();
  const auto rounded =
      expect_input_error([] { drawing("<rect x=\"0\" y=\"0\" width=\"1\" height=\"1\" rx=\"0.1\"/>"); });
  EXPECT_NE(rounded.message().find("Object to Path"), std::string::npos);
  const auto not_svg = expect_input_error([] { w::parse_svg_drawing("<html></html>", "d.svg", "k"); });
  EXPECT_NE(not_svg.message().find("not an SVG drawing"), std::string::npos);
  const auto arc_flag = expect_input_error([] { drawing("<path d=\"M 0 0 A 1 1 0 2 0 1 1\"/>"); });
  EXPECT_NE(arc_flag.message().find("large-arc flag must be 0 or 1"), std::string::npos);
  const auto missing = expect_input_error([] { w::read_svg_drawing("/nonexistent/wing.svg", "k"); });
  EXPECT_EQ(missing.file(), "/nonexistent/wing.svg");
  // A compressed drawing saved with the .svg extension: gzip's first two bytes (RFC 1952).
  const auto gzipped =
      expect_input_error([] { w::parse_svg_drawing(std::string("\x1f\x8b\x08\0\0\0", 6), "d.svg", "k"); });
  EXPECT_NE(gzipped.message().find("compressed (gzip"), std::string::npos) << gzipped.message();
}
