// Outlines without a list of points (wings/loader/outline_shapes.hpp): the closed spline
// through control points and the parametric planforms, against their exact areas;
// and the same through the wing file's [planform] keys.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "wings/loader/input_error.hpp"
#include "wings/loader/outline_shapes.hpp"
#include "wings/loader/planform_geometry.hpp"
#include "wings/loader/toml_reader.hpp"
#include "wings/loader/wing_file.hpp"

namespace w = flapsim::wings;
using flapsim::InputError;

namespace {

constexpr double kPi = std::numbers::pi;
const std::string kSource = FLAPSIM_SOURCE_DIR;

w::Wing wing_from_planform(const std::string& planform) {
  const std::string text = "length_unit = \"mm\"\n[planform]\n" + planform +
                           "\n[materials.film]\nyoungs_modulus = 4.0e9\npoisson_ratio = 0.3\ndensity = 1400.0\n"
                           "[membrane]\nmaterial = \"film\"\nthickness = 0.02\n";
  return w::read_wing(w::parse_toml_string(text, kSource + "/tests/data/inline.toml"));
}

TEST(OutlineShapes, EllipseIsTheInscribedPolygonOfTheEllipse) {
  // n points on an ellipse of semi-axes a, b enclose (n/2) sin(2π/n) a b exactly.
  const w::ShapeSize size{.root_y = 0.002, .tip_y = 0.042, .chord = 0.010, .leading_edge_x = 0.004};
  const int n = 64;
  const w::Polygon p = w::shape_outline(w::OutlineShape::ellipse, size, n);
  ASSERT_EQ(p.size(), static_cast<std::size_t>(n));
  const double a = 0.005, b = 0.020;
  EXPECT_NEAR(w::polygon_signed_area(p), 0.5 * n * std::sin(2 * kPi / n) * a * b, 1e-15);
  const w::PlanformProperties props = w::planform_properties(p);
  EXPECT_NEAR(props.span, 0.042, 1e-15);
  double max_x = -1, min_y = 1;
  for (const auto& q : p) {
    max_x = std::max(max_x, q.x());
    min_y = std::min(min_y, q.y());
  }
  EXPECT_NEAR(max_x, 0.004, 1e-15);
  EXPECT_NEAR(min_y, 0.002, 1e-15);
  EXPECT_FALSE(w::find_self_intersection(p));
}

TEST(OutlineShapes, HalfEllipseHasTheFullChordAtTheRoot) {
  // n + 1 points on a half ellipse closed by its axis: (n/2) sin(π/n) a b; here the
  // root chord is the full chord and the tip lies at the span.
  const w::ShapeSize size{.root_y = 0.0, .tip_y = 0.05, .chord = 0.02, .leading_edge_x = 0.005};
  const w::Polygon p = w::shape_outline(w::OutlineShape::half_ellipse, size, 97);
  const int n = static_cast<int>(p.size()) - 1;
  EXPECT_NEAR(w::polygon_signed_area(p), 0.5 * n * std::sin(kPi / n) * 0.01 * 0.05, 1e-15);
  // Within 0.1 % of the exact half-ellipse area π c R / 4.
  EXPECT_NEAR(w::polygon_area(p), kPi * 0.02 * 0.05 / 4, 1e-3 * kPi * 0.02 * 0.05 / 4);
  const auto root = w::chord_at(p, 1e-9);
  ASSERT_TRUE(root);
  EXPECT_NEAR(root->length(), 0.02, 1e-9);
  EXPECT_NEAR(root->leading_x, 0.005, 1e-9);
}

TEST(OutlineShapes, EllipsesKeepTheirRootTipAndChordAtAnyPointCount) {
  // An even count of a half ellipse (the default 96) missed its tip, and the scaling to the
  // span stretched the outline: root edge at 1.000134 mm (written 1), chord 16.0021 mm, the
  // area above the exact ellipse's (552.967 against 552.920 mm²), and a vein starting at
  // y = root_y refused as outside the outline. An ellipse of 18 points had its foremost point
  // 0.12 mm behind leading_edge_x and a chord of 15.76 mm.
  for (const int n : {16, 17, 18, 19, 96, 97}) {
    const std::string count = "\noutline_points = " + std::to_string(n);
    const w::Wing h = wing_from_planform(
        "shape = \"half_ellipse\"\nspan = 45.0\nchord = 16.0\nroot_y = 1.0\n"
        "leading_edge_x = 4.0\nclamp_y = 1.5" +
        count);
    double min_y = 1, max_y = -1;
    for (const auto& q : h.outline) {
      min_y = std::min(min_y, q.y());
      max_y = std::max(max_y, q.y());
    }
    EXPECT_NEAR(min_y, 0.001, 1e-15) << n;
    EXPECT_NEAR(max_y, 0.045, 1e-15) << n;
    const auto root = w::chord_at(h.outline, 0.001 + 1e-12);
    ASSERT_TRUE(root) << n;
    EXPECT_NEAR(root->length(), 0.016, 1e-12) << n;
    EXPECT_NEAR(root->leading_x, 0.004, 1e-12) << n;
    EXPECT_LT(w::polygon_area(h.outline), kPi * 0.016 * 0.044 / 4) << n;  // inscribed
    EXPECT_EQ(h.outline.size() % 2, 1u) << n;

    const w::Wing e = wing_from_planform(
        "shape = \"ellipse\"\nspan = 45.0\nchord = 16.0\nroot_y = 1.0\n"
        "leading_edge_x = 4.0\nclamp_y = 2.0" +
        count);
    double max_x = -1, min_x = 1;
    min_y = 1;
    max_y = -1;
    for (const auto& q : e.outline) {
      max_x = std::max(max_x, q.x());
      min_x = std::min(min_x, q.x());
      min_y = std::min(min_y, q.y());
      max_y = std::max(max_y, q.y());
    }
    EXPECT_NEAR(max_x, 0.004, 1e-15) << n;
    EXPECT_NEAR(max_x - min_x, 0.016, 1e-15) << n;
    EXPECT_NEAR(min_y, 0.001, 1e-15) << n;
    EXPECT_NEAR(max_y, 0.045, 1e-15) << n;
    EXPECT_EQ(e.outline.size() % 4, 0u) << n;
    EXPECT_GE(e.outline.size(), static_cast<std::size_t>(n)) << n;
  }
}

TEST(OutlineShapes, RoundedRectangleLosesTheCornersOfItsTip) {
  // Exact area c L − 2 (1 − π/4) r² (two quarter-circle corners); the polygon's arcs
  // are inscribed, m segments of a quarter circle enclose (m/2) sin(π/2m) r² instead of π r²/4.
  const double c = 0.01, len = 0.04, r = 0.003;
  const w::ShapeSize size{.root_y = 0.0, .tip_y = len, .chord = c, .leading_edge_x = 0.0025, .tip_radius = r};
  const int samples = 96;
  const w::Polygon p = w::shape_outline(w::OutlineShape::rounded_rectangle, size, samples);
  // outline_points is the number of points (docs/wing_file.md): the 2 root corners and two
  // arcs of m segments (m + 1 points each). Before, m was samples / 4: 52 points for 96.
  EXPECT_EQ(p.size(), static_cast<std::size_t>(samples));
  const int m = (samples - 4) / 2;
  const double exact = c * len - 2 * (1 - kPi / 4) * r * r;
  const double inscribed = exact - 2 * (kPi / 4 - 0.5 * m * std::sin(kPi / (2 * m))) * r * r;
  EXPECT_NEAR(w::polygon_signed_area(p), inscribed, 1e-15);
  EXPECT_NEAR(w::polygon_area(p), exact, 1e-4 * exact);
  // A tip radius of half the chord gives a semicircular tip with no straight part.
  const w::ShapeSize round{.root_y = 0.0, .tip_y = len, .chord = c, .leading_edge_x = 0.0, .tip_radius = c / 2};
  const w::Polygon q = w::shape_outline(w::OutlineShape::rounded_rectangle, round, samples);
  EXPECT_FALSE(w::find_self_intersection(q));
  EXPECT_EQ(q.size(), static_cast<std::size_t>(samples));  // the arcs share their top point
  EXPECT_NEAR(w::polygon_area(q), c * (len - c / 2) + kPi * c * c / 8, 1e-3 * c * len);
  EXPECT_THROW(w::shape_outline(w::OutlineShape::rounded_rectangle,
                                {.root_y = 0.0, .tip_y = len, .chord = c, .tip_radius = 0.6 * c}, samples),
               std::invalid_argument);
}

TEST(OutlineShapes, ClosedSplinePassesThroughItsControlPointsAndApproachesTheCurve) {
  // 12 control points on an ellipse (a = 5, b = 20 mm): the spline contains them, is
  // counter-clockwise, and its area is within 0.5 % of π a b.
  const double a = 5e-3, b = 20e-3;
  w::Polygon control;
  for (int k = 0; k < 12; ++k) {
    const double t = 2 * kPi * k / 12;
    control.emplace_back(a * std::cos(t), b + b * std::sin(t));
  }
  const w::Polygon p = w::closed_spline(control, 120);
  for (const auto& c : control) {
    double nearest = 1;
    for (const auto& q : p) nearest = std::min(nearest, (q - c).norm());
    EXPECT_LT(nearest, 1e-15);
  }
  EXPECT_GT(w::polygon_signed_area(p), 0.0);
  EXPECT_NEAR(w::polygon_area(p), kPi * a * b, 5e-3 * kPi * a * b);
  EXPECT_FALSE(w::find_self_intersection(p));
  // Clockwise control points give the same curve, counter-clockwise.
  w::Polygon reversed(control.rbegin(), control.rend());
  EXPECT_NEAR(w::polygon_signed_area(w::closed_spline(reversed, 120)), w::polygon_signed_area(p),
              1e-3 * w::polygon_area(p));
  EXPECT_THROW(w::closed_spline({{0, 0}, {1, 0}}, 10), std::invalid_argument);
}

TEST(OutlineShapes, WingFileShapeKeys) {
  const w::Wing e = wing_from_planform(
      "shape = \"half_ellipse\"\nspan = 40.0\nchord = 12.0\nclamp_y = 1.0\noutline_points = 65");
  EXPECT_NEAR(e.span, 0.040, 1e-15);
  EXPECT_NEAR(w::polygon_area(e.outline), kPi * 0.012 * 0.040 / 4, 2e-3 * kPi * 0.012 * 0.040 / 4);
  // Default leading edge at a quarter of the chord in front of the span axis.
  EXPECT_NEAR(w::chord_at(e.outline, 1e-9)->leading_x, 0.003, 1e-9);
  // 'area' stretches a shape like any outline.
  const w::Wing r = wing_from_planform(
      "shape = \"rounded_rectangle\"\nspan = 40.0\nchord = 10.0\ntip_radius = 5.0\nroot_y = 0.0\n"
      "area = 500.0\nclamp_y = 0.0");
  EXPECT_NEAR(w::polygon_area(r.outline), 500e-6, 1e-12);
  const w::Wing s = wing_from_planform(
      "spline = [[3, 0], [4, 20], [2, 38], [-4, 36], [-7, 15], [-6, 0]]\nclamp_y = 0.0");
  EXPECT_GT(s.outline.size(), 90u);
  EXPECT_FALSE(w::find_self_intersection(s.outline));
}

TEST(OutlineShapes, WingFileShapeErrorsNameTheKey) {
  try {
    wing_from_planform("shape = \"circle\"\nspan = 40.0\nchord = 12.0\nclamp_y = 0.0");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "planform.shape");
    EXPECT_EQ(e.line(), 3);
  }
  try {
    wing_from_planform("shape = \"ellipse\"\nspan = 40.0\nchord = 12.0\ntip_radius = 2.0\nclamp_y = 0.0");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "planform.tip_radius");
  }
  try {
    wing_from_planform("outline = [[0, 0], [1, 10], [-1, 10]]\nchord = 3.0\nclamp_y = 0.0");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "planform.chord");
  }
  try {
    wing_from_planform("shape = \"ellipse\"\nspline = [[0, 0], [1, 10], [-1, 10]]\nspan = 4.0\nchord = 1.0\nclamp_y = 0.0");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("exactly one of"), std::string::npos) << e.what();
  }
}

TEST(OutlineShapes, RepeatedClosingPointIsAccepted) {
  // The outline written with its first point repeated at the end (as many drawing
  // programs export it) is the same polygon as without it.
  const w::Wing open = wing_from_planform("outline = [[2, 0], [2, 10], [-3, 10], [-3, 0]]\nclamp_y = 0.0");
  const w::Wing closed =
      wing_from_planform("outline = [[2, 0], [2, 10], [-3, 10], [-3, 0], [2, 0]]\nclamp_y = 0.0");
  ASSERT_EQ(closed.outline.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(closed.outline[i], open.outline[i]);
  EXPECT_DOUBLE_EQ(w::polygon_area(closed.outline), 50e-6);
}

}  // namespace
