// Plausibility warnings of wing files (docs/wing_file.md, "Plausibility warnings"):
// each implausible value is accepted, located by file, line and key, and the message
// names the likely unit mistake; plausible wings (the shipped ones) give none.
// Also the solid round rod section.
#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>
#include <string>

#include "wings/loader/input_error.hpp"
#include "wings/loader/toml_reader.hpp"
#include "wings/loader/wing_file.hpp"
#include "wings/loader/wing_mass_properties.hpp"

namespace w = flapsim::wings;

namespace {

const std::string kSource = FLAPSIM_SOURCE_DIR;

// A 10 x 5 mm plate; the material and membrane lines are numbered for the tests.
w::Wing plate(const std::string& modulus, const std::string& density, const std::string& thickness,
              const std::string& veins = "") {
  const std::string text =
      "length_unit = \"mm\"\n"                                            // 1
      "[planform]\n"                                                      // 2
      "outline = [[2.0, 0.0], [2.0, 10.0], [-3.0, 10.0], [-3.0, 0.0]]\n"  // 3
      "clamp_y = 0.0\n"                                                   // 4
      "[materials.film]\n"                                                // 5
      "youngs_modulus = " + modulus + "\n"                                // 6
      "poisson_ratio = 0.3\n"                                             // 7
      "density = " + density + "\n"                                       // 8
      "[membrane]\n"                                                      // 9
      "material = \"film\"\n"                                             // 10
      "thickness = " + thickness + "\n" +                                 // 11
      veins;
  return w::read_wing(w::parse_toml_string(text, kSource + "/tests/data/inline.toml"));
}

void expect_one_warning(const w::Wing& wing, const std::string& key, int line, const std::string& hint) {
  ASSERT_EQ(wing.warnings.size(), 1u);
  const flapsim::InputWarning& warning = wing.warnings[0];
  EXPECT_EQ(warning.key, key);
  EXPECT_EQ(warning.line, line);
  EXPECT_NE(warning.text().find("inline.toml:" + std::to_string(line)), std::string::npos) << warning.text();
  EXPECT_NE(warning.message.find(hint), std::string::npos) << warning.message;
}

TEST(WingPlausibility, PlausibleWingsGiveNoWarning) {
  EXPECT_TRUE(plate("4.0e9", "1400.0", "0.02").warnings.empty());
  for (const char* f : {"hawkmoth.toml", "hawkmoth_thin_membrane.toml", "flat_plate.toml", "robofly.toml",
                        "mav_film_wing.toml", "mav_film_wing_25um.toml"})
    EXPECT_TRUE(w::load_wing_file(kSource + "/wings/" + f).warnings.empty()) << f;
}

// Every wing file shipped in wings/ (the list above names the older ones; this one also the
// later ones: the paper's hawkmoth, the 75 mm film wing).
TEST(WingPlausibility, EveryShippedWingGivesNoWarning) {
  int read = 0;
  for (const auto& e : std::filesystem::directory_iterator(kSource + "/wings")) {
    if (e.path().extension() != ".toml") continue;
    EXPECT_TRUE(w::load_wing_file(e.path().string()).warnings.empty()) << e.path();
    ++read;
  }
  EXPECT_GE(read, 8);
}

// A vein's section in another unit than the file's lengths: 3 (meant in µm) in a file in mm
// is a 3 mm tube on a 10 mm wing, 30 % of the span. Unwarned until 3 Dec (0.4 as mm in a file
// in metres made a hawkmoth wing weigh 5.2 kg). A 0.5 mm tube (5 %) is not warned.
TEST(WingPlausibility, AVeinAQuarterOfTheSpanAcross) {
  const std::string vein =
      "[[veins]]\n"                            // 12
      "material = \"film\"\n"                  // 13
      "points = [[0.0, 0.0], [0.0, 10.0]]\n";  // 14
  const w::Wing wing = plate("4.0e9", "1400.0", "0.02", vein + "outer_diameter = 3.0\nwall = 1.0\n");
  expect_one_warning(
      wing, "veins[0].outer_diameter", 15,
      "the vein's section would be 3 mm across, 30 % of the span (veins are 1-5 %); section sizes "
      "are in length_unit = \"mm\": was it written in um (length_unit = \"um\")?");
  EXPECT_TRUE(plate("4.0e9", "1400.0", "0.02", vein + "outer_diameter = 0.5\nwall = 0.1\n").warnings.empty());
  const w::Wing rod =
      plate("4.0e9", "1400.0", "0.02", vein + "shape = \"rectangle\"\nwidth = 0.5\nheight = 4.0\n");
  expect_one_warning(rod, "veins[0].height", 17, "40 % of the span");
}

// Non-structural mass in g/m² where kg/m² is asked: 20 (meant 20 g/m²) is a 20 kg/m² load,
// the areal mass of a 14 mm cuticle sheet. 0.012 (the paper hawkmoth's) is not warned.
TEST(WingPlausibility, NonStructuralMassAboveOneKilogramPerSquareMetre) {
  const w::Wing wing = plate("4.0e9", "1400.0", "0.02", "nonstructural_mass_per_area = 20.0\n");
  expect_one_warning(
      wing, "membrane.nonstructural_mass_per_area", 12,
      "20 kg/m^2 is heavier than a 0.7 mm sheet of cuticle (1 kg/m^2); nonstructural_mass_per_area "
      "is in kg/m^2: was it written in g/m^2? 20 g/m^2 is 0.02 kg/m^2");
  EXPECT_TRUE(plate("4.0e9", "1400.0", "0.02", "nonstructural_mass_per_area = 0.012\n").warnings.empty());
}

TEST(WingPlausibility, FilmThinnerThanOneMicrometre) {
  // 25e-6 with length_unit = "mm" is 25 nm: the value was written in metres; in mm
  // the 25 µm film is 0.025.
  const w::Wing wing = plate("4.0e9", "1400.0", "25e-6");
  EXPECT_DOUBLE_EQ(wing.membrane.thickness, 25e-9);  // accepted as written
  expect_one_warning(wing, "membrane.thickness", 11, "was it written in metres? 2.5e-05 m is 0.025 mm");
}

TEST(WingPlausibility, ASmallInsectsSubmicrometreMembraneIsNotWarned) {
  // A fruit fly's 0.5 µm membrane on a 2.5 mm wing (2e-4 of the span) is an insect's, not a
  // unit mistake; the same membrane on this 10 mm plate (5e-5) is warned, as 25 nm is above.
  const std::string fruit_fly =
      "length_unit = \"um\"\n[planform]\nshape = \"half_ellipse\"\nspan = 2500.0\nchord = 900.0\nclamp_y = "
      "100.0\n"
      "[materials.cuticle]\nyoungs_modulus = 6.0e9\npoisson_ratio = 0.49\ndensity = 1200.0\n"
      "[membrane]\nmaterial = \"cuticle\"\nthickness = 0.5\n";
  EXPECT_TRUE(
      w::read_wing(w::parse_toml_string(fruit_fly, kSource + "/tests/data/inline.toml")).warnings.empty());
  expect_one_warning(plate("4.0e9", "1400.0", "0.0005"), "membrane.thickness", 11,
                     "thinner than 1 µm and 5e-05 of the span");
}

TEST(WingPlausibility, ModulusBelowOneMegapascal) {
  // 4.0 read as Pa; 4 GPa (4e9 Pa) is a typical insect cuticle or polyester film.
  expect_one_warning(plate("4.0", "1400.0", "0.02"), "materials.film.youngs_modulus", 6,
                     "GPa (4 GPa = 4e+09)");
}

TEST(WingPlausibility, ModulusAboveOneTerapascal) {
  expect_one_warning(plate("6.0e12", "1400.0", "0.02"), "materials.film.youngs_modulus", 6, "above 1 TPa");
}

TEST(WingPlausibility, DensityOutsideTenToTwentyThousand) {
  // 1.4 read as kg/m³ is g/cm³: 1.4 g/cm³ = 1400 kg/m³.
  expect_one_warning(plate("4.0e9", "1.4", "0.02"), "materials.film.density", 8, "g/cm³ (1.4 g/cm³ = 1400 kg/m³)");
  expect_one_warning(plate("4.0e9", "1.4e6", "0.02"), "materials.film.density", 8, "above 20000 kg/m³");
  // The limits themselves are plausible.
  EXPECT_TRUE(plate("1.0e6", "10.0", "0.002").warnings.empty());
  EXPECT_TRUE(plate("1.0e12", "20000.0", "0.002").warnings.empty());
}

TEST(WingPlausibility, AWingDrawnInMillimetresInAFileInMetres) {
  // A user's film wing in mm, but length_unit left at its default "m": the wing is 10 m long
  // and its film 20 mm thick. Before: accepted without a word (check printed a 10000 mm span).
  const std::string text =
      "[planform]\n"                                                      // 1
      "outline = [[2.0, 0.0], [2.0, 10.0], [-3.0, 10.0], [-3.0, 0.0]]\n"  // 2
      "clamp_y = 0.0\n"                                                   // 3
      "[materials.film]\nyoungs_modulus = 4e9\npoisson_ratio = 0.3\ndensity = 1400.0\n"  // 4-7
      "[membrane]\nmaterial = \"film\"\nthickness = 0.02\n";              // 8-10
  const w::Wing wing = w::read_wing(w::parse_toml_string(text, kSource + "/tests/data/inline.toml"));
  ASSERT_EQ(wing.warnings.size(), 2u);
  EXPECT_EQ(wing.warnings[0].key, "planform.outline");
  EXPECT_EQ(wing.warnings[0].line, 2);
  EXPECT_NE(wing.warnings[0].message.find("10 m from pivot to tip"), std::string::npos) << wing.warnings[0].message;
  EXPECT_NE(wing.warnings[0].message.find("was it written in mm"), std::string::npos) << wing.warnings[0].message;
  EXPECT_EQ(wing.warnings[1].key, "membrane.thickness");
  EXPECT_EQ(wing.warnings[1].line, 10);
  EXPECT_NE(wing.warnings[1].message.find("was it written in mm"), std::string::npos) << wing.warnings[1].message;
  // A 5 mm plate is plausible.
  EXPECT_TRUE(plate("4.0e9", "1400.0", "5.0").warnings.empty());
}

w::Wing outline_wing(const std::string& outline) {
  const std::string text =
      "length_unit = \"mm\"\n[planform]\noutline = " + outline + "\nclamp_y = 0.5\n"  // outline on line 3
      "[materials.film]\nyoungs_modulus = 4e9\npoisson_ratio = 0.3\ndensity = 1400.0\n"
      "[membrane]\nmaterial = \"film\"\nthickness = 0.05\n";
  return w::read_wing(w::parse_toml_string(text, kSource + "/tests/data/inline.toml"));
}

TEST(WingPlausibility, ASlotThatTheVortexLatticeWouldCoverIsWarned) {
  // A 10 x 40 mm plate with a 4 mm slot from y = 15 mm to the tip: the lattice spans each
  // section from x = 2 to x = -8 and covers the slot (100 mm², a third of the wing). Before:
  // no word; the run's lattice silently had 400 mm² of panels on a 300 mm² wing.
  const w::Wing forked = outline_wing(
      "[[2.0, 0.0], [2.0, 40.0], [-1.0, 40.0], [-1.0, 15.0], [-5.0, 15.0], [-5.0, 40.0], [-8.0, 40.0], [-8.0, 0.0]]");
  ASSERT_EQ(forked.warnings.size(), 1u);
  EXPECT_EQ(forked.warnings[0].key, "planform.outline");
  EXPECT_EQ(forked.warnings[0].line, 3);
  EXPECT_NE(forked.warnings[0].message.find("from y = 15 to 40 mm a line along the chord crosses the outline 4 times"),
            std::string::npos)
      << forked.warnings[0].message;
  // A notch in the trailing edge (a bay) is crossed twice by every chordwise line: the
  // lattice follows it, no warning.
  EXPECT_TRUE(outline_wing("[[2.0, 0.0], [2.0, 40.0], [-8.0, 40.0], [-8.0, 22.0], [-2.0, 20.0], [-8.0, 18.0], "
                           "[-8.0, 0.0]]")
                  .warnings.empty());
}

TEST(WingSolidRod, SolidCircleIsTheFullDisc) {
  // shape = "solid_circle", diameter D: area π D²/4 along the whole rod, mass ρ A L.
  const w::Wing wing = plate("4.0e9", "1400.0", "0.02",
                             "[[veins]]\nmaterial = \"film\"\nshape = \"solid_circle\"\n"
                             "points = [[1.0, 0.0], [1.0, 9.0]]\ndiameter = [0.4, 0.2]\n");
  ASSERT_EQ(wing.veins.size(), 1u);
  const w::Vein& v = wing.veins[0];
  const double d0 = 0.4e-3, d1 = 0.2e-3;
  EXPECT_NEAR(w::section_area(v.root_section), std::numbers::pi * d0 * d0 / 4, 1e-18);
  EXPECT_NEAR(w::section_area(v.tip_section), std::numbers::pi * d1 * d1 / 4, 1e-18);
  // Linear taper of D: ∫_0^1 (D0 + u (D1 − D0))² du = (D0² + D0 D1 + D1²) / 3.
  const double mean_d2 = (d0 * d0 + d0 * d1 + d1 * d1) / 3;
  EXPECT_NEAR(w::vein_mass(v), 1400.0 * std::numbers::pi / 4 * mean_d2 * 9e-3, 1e-15);
  // 'wall' belongs to the hollow circle only.
  EXPECT_THROW(plate("4.0e9", "1400.0", "0.02",
                     "[[veins]]\nmaterial = \"film\"\nshape = \"solid_circle\"\n"
                     "points = [[1.0, 0.0], [1.0, 9.0]]\ndiameter = 0.4\nwall = 0.1\n"),
               flapsim::InputError);
}

}  // namespace
