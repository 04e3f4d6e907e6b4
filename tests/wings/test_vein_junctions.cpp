// A vein's end written next to another vein is moved onto it when the gap would be meshed
// into slivers (wings/vein_junctions.hpp): the ends only, within tan(0.5°) of the vein
// element size and at most 0.1 % of the span.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "wings/toml_reader.hpp"
#include "wings/vein_junctions.hpp"
#include "wings/wing_file.hpp"

namespace w = flapsim::wings;

namespace {

// A 40 mm rectangle (x from −5 to 5 mm) with a spar along x = 1 mm and a second vein
// written as `cross`; `mesh` the [mesh] table (default R/50 = 0.8 mm elements).
w::Wing wing_with(const std::string& cross, const std::string& mesh = "") {
  const std::string text =
      "name = \"t\"\nlength_unit = \"mm\"\n[planform]\n"
      "outline = [[5.0, 0.0], [5.0, 40.0], [-5.0, 40.0], [-5.0, 0.0]]\nclamp_y = 0.0\n"
      "[materials.film]\nyoungs_modulus = 4.0e9\npoisson_ratio = 0.3\ndensity = 1400.0\n"
      "[membrane]\nthickness = 0.05\nmaterial = \"film\"\n"
      "[[veins]]\nname = \"spar\"\npoints = [[1.0, 0.0], [1.0, 30.0]]\nouter_diameter = 0.3\nwall = 0.1\n"
      "material = \"film\"\n"
      "[[veins]]\nname = \"cross\"\npoints = " +
      cross + "\nouter_diameter = 0.3\nwall = 0.1\nmaterial = \"film\"\n" + mesh;
  return w::read_wing(w::parse_toml_string(text, "j.toml"));
}

}  // namespace

TEST(VeinJunctions, TheToleranceIsTheSliverAngleTimesTheVeinElementSizeAtMostATenthOfAPercentOfTheSpan) {
  // tan(0.5°) = 8.7269e-3 (by hand: 0.5° = 8.7266e-3 rad, tan x ≈ x + x³/3).
  EXPECT_NEAR(w::vein_junction_tolerance(0.04, 0.8e-3), 0.8e-3 * 8.72686779e-3, 1e-15);
  EXPECT_EQ(w::vein_junction_tolerance(0.04, 10e-3), 0.04e-3);  // capped: 87 µm > 40 µm
}

TEST(VeinJunctions, AnEndAMicrometreOffAnotherVeinIsMovedOntoIt) {
  // 0.8 mm elements: tolerance 6.98 µm. The cross vein's first point 1 µm right of the spar
  // (x = 1.001 mm) lands on it, x = 1 mm exactly; its other end, far from any vein, stays.
  const w::Wing wing = wing_with("[[1.001, 10.0], [-4.0, 20.0]]");
  const auto& p = wing.veins[1].points;
  EXPECT_EQ(p.front().x(), 1e-3);
  EXPECT_NEAR(p.front().y(), 10e-3, 1e-15);
  EXPECT_NEAR(p.back().x(), -4e-3, 1e-15);
  EXPECT_NEAR(p.back().y(), 20e-3, 1e-15);
  EXPECT_EQ(wing.veins[0].points.back().y(), 30.0 * 1e-3);  // the spar unchanged
  // Its last point 1 µm past the spar's end (30 mm): onto that end, exactly (the spar's end
  // lies 0.2 µm from the cross vein's line as written: moved onto its line, as a T, the two
  // ends would each have landed beside the other's).
  const w::Wing past = wing_with("[[-4.0, 20.0], [1.0, 30.001]]");
  EXPECT_EQ(past.veins[1].points.back(), past.veins[0].points.back());
  EXPECT_EQ(past.veins[0].points.back().y(), 30.0 * 1e-3);
}

TEST(VeinJunctions, AGapWiderThanTheToleranceAndAnInnerPointStayAsWritten) {
  // 20 µm off at 0.8 mm elements (tolerance 6.98 µm): meshed as written (about 1.4°, no sliver).
  const w::Wing wide = wing_with("[[1.02, 10.0], [-4.0, 20.0]]");
  EXPECT_NEAR(wide.veins[1].points.front().x(), 1.02e-3, 1e-15);
  // The same 20 µm with 10 mm elements (tolerance min(87 µm, 40 µm)): moved; 50 µm: not.
  const std::string coarse = "[mesh]\nelement_size = 10.0\n";
  EXPECT_EQ(wing_with("[[1.02, 10.0], [-4.0, 20.0]]", coarse).veins[1].points.front().x(), 1e-3);
  EXPECT_NEAR(wing_with("[[1.05, 10.0], [-4.0, 20.0]]", coarse).veins[1].points.front().x(), 1.05e-3, 1e-15);
  // An inner point 1 µm off the spar is where a vein runs past another: left alone.
  const w::Wing inner = wing_with("[[-4.0, 5.0], [0.999, 10.0], [-4.0, 15.0]]");
  EXPECT_NEAR(inner.veins[1].points[1].x(), 0.999e-3, 1e-15);
}

TEST(VeinJunctions, EndsMeetEndsFirstThenLinesAndAnEndOnAVeinIsNotMoved) {
  std::vector<w::Vein> veins(3);
  veins[0].points = {{0.0, 0.0}, {0.0, 1.0}};    // x = 0
  veins[1].points = {{3e-6, 0.0}, {3e-6, 1.0}};  // x = 3 µm
  veins[2].points = {{2e-6, 0.5}, {-1.0, 0.5}};  // starts 2 µm from the first, 1 µm from the second
  EXPECT_EQ(w::snap_vein_ends_onto_other_veins(veins, 5e-6, 1e-12), 3);
  // The second vein's ends are 3 µm from the first's: onto them (ends first, onto the
  // earlier vein); then the third's start is 2 µm from both lines, now one: onto x = 0.
  EXPECT_EQ(veins[1].points[0], Eigen::Vector2d(0.0, 0.0));
  EXPECT_EQ(veins[1].points[1], Eigen::Vector2d(0.0, 1.0));
  EXPECT_EQ(veins[2].points[0], Eigen::Vector2d(0.0, 0.5));
  // Nothing is moved a second time: every end now lies on another vein.
  EXPECT_EQ(w::snap_vein_ends_onto_other_veins(veins, 5e-6, 1e-12), 0);
}
