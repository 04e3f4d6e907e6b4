// Wing files: the shipped wings, chord-coordinate veins, section masses, and each
// kind of bad input located by file, line and key.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "wings/loader/input_error.hpp"
#include "wings/loader/planform_geometry.hpp"
#include "wings/loader/toml_reader.hpp"
#include "wings/loader/wing_file.hpp"
#include "wings/loader/wing_mass_properties.hpp"

namespace w = flapsim::wings;
using flapsim::InputError;

namespace {

const std::string kSource = FLAPSIM_SOURCE_DIR;

w::Wing wing_from_text(const std::string& text) {
  return w::read_wing(w::parse_toml_string(text, kSource + "/tests/data/inline.toml"));
}

InputError error_of(const std::string& text) {
  try {
    wing_from_text(text);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return InputError("", 0, "", "");
}

// A 10 mm x 5 mm plate (x from -3 to 2 mm), lines numbered for the tests below.
std::string plate(const std::string& membrane_extra = "", const std::string& veins = "") {
  return "length_unit = \"mm\"\n"                                          // 1
         "[planform]\n"                                                    // 2
         "outline = [[2.0, 0.0], [2.0, 10.0], [-3.0, 10.0], [-3.0, 0.0]]\n"  // 3
         "clamp_y = 0.0\n"                                                 // 4
         "[materials.film]\n"                                              // 5
         "youngs_modulus = 4.0e9\n"                                        // 6
         "poisson_ratio = 0.3\n"                                           // 7
         "density = 1400.0\n"                                              // 8
         "[membrane]\n"                                                    // 9
         "material = \"film\"\n" +                                         // 10
         membrane_extra + veins;
}

}  // namespace

TEST(WingFile, HawkmothMatchesRotationPhasePaperTable2) {
  const w::Wing wing = w::load_wing_file(kSource + "/wings/hawkmoth.toml");
  const auto p = w::planform_properties(wing.outline);
  // RP Table 2: span 48.3 mm, area 815.3 mm² (the file scales and stretches to them).
  EXPECT_NEAR(p.span, 48.3e-3, 48.3e-3 * 1e-9);
  EXPECT_NEAR(p.area, 815.3e-6, 815.3e-6 * 1e-9);
  EXPECT_EQ(wing.veins.size(), 14u);  // docs/hawkmoth_reference_data.md venation table: 14 veins
  // Chordwise stretch needed: 815.3 / (0.3092 · 48.3²) = 1.130
  // (docs/hawkmoth_reference_data.md: "by 1.131").
  // The outline's x extent grows by the same factor: 0.43145 R unscaled.
  double xmin = 1e9, xmax = -1e9;
  for (const auto& q : wing.outline) xmin = std::min(xmin, q.x()), xmax = std::max(xmax, q.x());
  EXPECT_NEAR((xmax - xmin) / (0.43145 * 48.3e-3), 815.3 / (0.30916 * 48.3 * 48.3), 2e-4);
  // Structural mass 33.8 mg (RP Table 1: 13.27 + 13.01 + 7.48 = 33.76 mg; MB §3.1: 0.033 g).
  EXPECT_NEAR(w::estimate_wing_mass(wing).total(), 33.8e-6, 0.05e-6);
  // Calibrated effective membrane (wings/hawkmoth.toml header): 120 µm thick, with the
  // areal mass of the 12 µm, 1200 kg/m³ cuticle membrane of docs/hawkmoth_reference_data.md.
  EXPECT_NEAR(wing.membrane.thickness, 120e-6, 1e-12);
  EXPECT_NEAR(wing.membrane.thickness * wing.membrane.material.density, 12e-6 * 1200.0, 1e-12);
  EXPECT_NEAR(wing.clamp_y, 2e-3, 1e-12);
}

TEST(WingFile, ThinMembraneHawkmothHasTheReferenceStartingValues) {
  const w::Wing wing = w::load_wing_file(kSource + "/wings/hawkmoth_thin_membrane.toml");
  // docs/hawkmoth_reference_data.md, "Materials" and the venation table: 12 µm membrane,
  // costa 0.40 -> 0.12 mm.
  EXPECT_NEAR(wing.membrane.thickness, 12e-6, 1e-12);
  EXPECT_NEAR(wing.veins.front().root_section.outer_diameter, 0.40e-3, 1e-15);
  EXPECT_NEAR(wing.veins.front().tip_section.wall, 0.02e-3, 1e-15);
  EXPECT_NEAR(w::estimate_wing_mass(wing).total(), 33.8e-6, 0.05e-6);
}

TEST(WingFile, HawkmothCostaFollowsTheLeadingEdge) {
  const w::Wing wing = w::load_wing_file(kSource + "/wings/hawkmoth.toml");
  const w::Vein& costa = wing.veins.front();
  ASSERT_EQ(costa.points.size(), 25u);  // 1 + subdivide 24
  for (const auto& q : costa.points) {
    const auto c = w::chord_at(wing.outline, q.y());
    ASSERT_TRUE(c);
    // ξ = 0.01 of the local chord behind the leading edge (docs/hawkmoth_reference_data.md).
    EXPECT_NEAR((c->leading_x - q.x()) / c->length(), 0.01, 1e-12);
  }
  // Calibrated sections (wings/hawkmoth.toml header): 1.7 x the reference data's costa
  // 0.40 mm (root) and wall 0.02 mm (end), docs/hawkmoth_reference_data.md.
  EXPECT_NEAR(costa.root_section.outer_diameter, 1.7 * 0.40e-3, 1e-15);
  EXPECT_NEAR(costa.tip_section.wall, 1.7 * 0.02e-3, 1e-15);
}

TEST(WingFile, FlatPlateAndRobofly) {
  const w::Wing plate = w::load_wing_file(kSource + "/wings/flat_plate.toml");
  const auto p = w::planform_properties(plate.outline);
  EXPECT_NEAR(p.aspect_ratio, 4.0, 1e-12);  // 40 mm x 10 mm from the pivot
  // Mass ρ h S = 1390 · 0.2e-3 · 400e-6 = 1.112e-4 kg.
  EXPECT_NEAR(w::estimate_wing_mass(plate).total(), 1.112e-4, 1e-12);
  const w::Wing robofly = w::load_wing_file(kSource + "/wings/robofly.toml");
  const auto r = w::planform_properties(robofly.outline);
  EXPECT_NEAR(r.span, 0.25, 1e-12);
  EXPECT_NEAR(r.area, 0.2531 * 0.25 * 0.25, 0.0001 * 0.0625);  // CSV header: 0.2531 R²
  EXPECT_NEAR(r.root_y / r.span, 0.25, 0.01);                   // root edge at 0.25 R
}

TEST(WingFile, ChordPointsMapToTheLocalChord) {
  // Plate leading edge x = 2 mm, trailing edge x = −3 mm, R = 10 mm:
  // (y/R, ξ) = (0.5, 0.2) → x = 2 − 0.2 · 5 = 1 mm, y = 5 mm.
  const w::Wing wing = wing_from_text(plate("thickness = 0.05\n",
                                            "[[veins]]\n"
                                            "material = \"film\"\n"
                                            "chord_points = [[0.0, 0.0], [0.5, 0.2]]\n"
                                            "outer_diameter = 0.3\nwall = 0.15\n"));
  ASSERT_EQ(wing.veins.size(), 1u);
  EXPECT_NEAR(wing.veins[0].points[1].x(), 1e-3, 1e-15);
  EXPECT_NEAR(wing.veins[0].points[1].y(), 5e-3, 1e-15);
  EXPECT_EQ(wing.veins[0].name, "vein 1");
}

TEST(WingFile, SectionAreasAndVeinMass) {
  w::Vein v;
  v.points = {{0, 0}, {0, 0.01}};  // 10 mm
  v.material.density = 1000.0;
  v.root_section.outer_diameter = 1e-3;
  v.root_section.wall = 0.1e-3;
  v.tip_section = v.root_section;
  // Hollow tube: A = π t (D − t) = π · 0.1 · 0.9 mm².
  const double a = std::numbers::pi * 0.1e-3 * 0.9e-3;
  EXPECT_NEAR(w::section_area(v.root_section), a, 1e-18);
  EXPECT_NEAR(w::vein_mass(v), 1000.0 * a * 0.01, 1e-15);
  // Taper D, t → half at the end: A(u) = a (1 − u/2)², ∫_0^1 = 7/12 a.
  v.tip_section.outer_diameter = 0.5e-3;
  v.tip_section.wall = 0.05e-3;
  EXPECT_NEAR(w::vein_mass(v), 1000.0 * a * 7.0 / 12.0 * 0.01, 1e-15);
  // Rectangle 2 x 0.5 mm.
  w::Section r;
  r.shape = w::Section::Shape::Rectangle;
  r.width = 2e-3;
  r.height = 0.5e-3;
  EXPECT_NEAR(w::section_area(r), 1e-6, 1e-20);
}

TEST(WingFile, RectangularRodSections) {
  const w::Wing wing = wing_from_text(plate("thickness = 0.05\n",
                                            "[[veins]]\n"
                                            "name = \"carbon rod\"\n"
                                            "material = \"film\"\n"
                                            "shape = \"rectangle\"\n"
                                            "points = [[1.5, 0.0], [1.5, 9.0]]\n"
                                            "width = [1.0, 0.5]\nheight = 0.3\n"));
  EXPECT_EQ(wing.veins[0].root_section.shape, w::Section::Shape::Rectangle);
  EXPECT_NEAR(wing.veins[0].tip_section.width, 0.5e-3, 1e-15);
  EXPECT_NEAR(wing.veins[0].tip_section.height, 0.3e-3, 1e-15);
}

// --- bad input: each gives file, line and key ---------------------------------------------

TEST(WingFileErrors, MissingThickness) {
  const auto e = error_of(plate());
  EXPECT_EQ(e.line(), 9);  // the [membrane] header
  EXPECT_EQ(e.key(), "membrane.thickness");
}

TEST(WingFileErrors, NegativeThickness) {
  const auto e = error_of(plate("thickness = -0.05\n"));
  EXPECT_EQ(e.line(), 11);
  EXPECT_EQ(e.key(), "membrane.thickness");
}

TEST(WingFileErrors, SelfIntersectingOutline) {
  std::string t = plate("thickness = 0.05\n");
  t.replace(t.find("[[2.0, 0.0], [2.0, 10.0]"), 24, "[[2.0, 0.0], [-3.0, 10.0]");
  t.replace(t.find("[-3.0, 10.0], [-3.0, 0.0]]"), 26, "[2.0, 10.0], [-3.0, 0.0]]");
  const auto e = error_of(t);
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.key(), "planform.outline");
  EXPECT_NE(e.message().find("not a simple polygon"), std::string::npos);
}

TEST(WingFileErrors, VeinOutsideOutline) {
  const auto e = error_of(plate("thickness = 0.05\n",
                                "[[veins]]\n"                                 // 12
                                "material = \"film\"\n"                       // 13
                                "points = [[1.5, 0.0], [2.5, 9.0]]\n"         // 14
                                "outer_diameter = 0.3\nwall = 0.05\n"));
  EXPECT_EQ(e.line(), 14);
  EXPECT_EQ(e.key(), "veins[0].points");
}

// A wing whose root is off the pivot (y from 2 to 10 mm: y/R from 0.2) and a vein written from
// y/R = 0.1: the message gives the outline's range, which a user would otherwise work out.
TEST(WingFileErrors, ChordPointsBelowTheRootNameTheOutlinesRange) {
  std::string t = plate("thickness = 0.05\n",
                        "[[veins]]\n"                                      // 12
                        "material = \"film\"\n"                            // 13
                        "chord_points = [[0.1, 0.5], [0.9, 0.5]]\n"         // 14
                        "outer_diameter = 0.3\nwall = 0.05\n");
  t.replace(t.find("[[2.0, 0.0]"), 11, "[[2.0, 2.0]");
  t.replace(t.find("[-3.0, 0.0]]"), 12, "[-3.0, 2.0]]");
  t.replace(t.find("clamp_y = 0.0"), 13, "clamp_y = 2.0");
  const auto e = error_of(t);
  EXPECT_EQ(e.line(), 14);
  EXPECT_EQ(e.key(), "veins[0].chord_points");
  EXPECT_NE(e.message().find("y/R = 0.1 lies outside the outline's span range (y/R from 0.2 at its root to 1 at its tip)"),
            std::string::npos)
      << e.message();
}

TEST(WingFileErrors, VeinOnTheEdgeIsAccepted) {
  EXPECT_NO_THROW(wing_from_text(plate("thickness = 0.05\n",
                                       "[[veins]]\nmaterial = \"film\"\n"
                                       "points = [[2.0, 0.0], [2.0, 10.0]]\n"
                                       "outer_diameter = 0.3\nwall = 0.05\n")));
}

TEST(WingFileErrors, UnknownUnit) {
  std::string t = plate("thickness = 0.05\n");
  t.replace(t.find("\"mm\""), 4, "\"inch\"");
  const auto e = error_of(t);
  EXPECT_EQ(e.line(), 1);
  EXPECT_EQ(e.key(), "length_unit");
}

TEST(WingFileErrors, StringWhereNumberBelongs) {
  const auto e = error_of(plate("thickness = \"0.05\"\n"));
  EXPECT_EQ(e.line(), 11);
  EXPECT_NE(e.message().find("expected a number"), std::string::npos);
}

TEST(WingFileErrors, TruncatedFile) {
  const std::string t = plate("thickness = 0.05\n", "[[veins]]\npoints = [[1.5, 0.0], [1.");
  const auto e = error_of(t);
  EXPECT_EQ(e.line(), 13);
  EXPECT_NE(e.message().find("syntax"), std::string::npos);
}

TEST(WingFileErrors, WallThickerThanHalfTheDiameter) {
  const auto e = error_of(plate("thickness = 0.05\n",
                                "[[veins]]\nmaterial = \"film\"\n"
                                "points = [[1.5, 0.0], [1.5, 9.0]]\n"
                                "outer_diameter = 0.3\n"
                                "wall = [0.1, 0.2]\n"));  // line 16
  EXPECT_EQ(e.line(), 16);
  EXPECT_EQ(e.key(), "veins[0].wall");
}

TEST(WingFileErrors, PoissonRatioOutsideStableRange) {
  std::string t = plate("thickness = 0.05\n");
  t.replace(t.find("poisson_ratio = 0.3"), 19, "poisson_ratio = 0.5");
  const auto e = error_of(t);
  EXPECT_EQ(e.line(), 7);
  EXPECT_EQ(e.key(), "materials.film.poisson_ratio");
}

TEST(WingFileErrors, UnknownMaterialAndTypo) {
  EXPECT_EQ(error_of(plate("thickness = 0.05\n", "[[veins]]\nmaterial = \"steel\"\n")).line(), 13);
  const auto e = error_of(plate("thicknes = 0.05\n"));
  EXPECT_EQ(e.line(), 11);
  EXPECT_EQ(e.key(), "membrane.thicknes");
}
