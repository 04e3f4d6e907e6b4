// `flapsim check`'s wing summary shows a small wing's mass and membrane. Before: a 0.8 mm
// half-ellipse of a 1.5 um cuticle film (0.28 ug) printed "estimated mass 0.000 mg (membrane
// 0.000, ...)".
#include <gtest/gtest.h>

#include <string>

#include "wings/loader/toml_reader.hpp"
#include "wings/loader/wing_file.hpp"
#include "wings/loader/wing_summary.hpp"

namespace {

namespace w = flapsim::wings;

std::string mass_line(const std::string& summary) {
  const auto at = summary.find("estimated mass");
  return at == std::string::npos ? "" : summary.substr(at, summary.find('\n', at) - at);
}

w::Wing plate(const std::string& unit, double length, double chord, double thickness) {
  const std::string l = std::to_string(length), c = std::to_string(chord);
  return w::read_wing(w::parse_toml_string(
      "length_unit = \"" + unit + "\"\n[planform]\noutline = [[0, 0], [0, " + l + "], [-" + c + ", " + l +
          "], [-" + c + ", 0]]\nclamp_y = 0\n[materials.film]\nyoungs_modulus = 4e9\npoisson_ratio = 0.3\n"
          "density = 1200\n[membrane]\nthickness = " + std::to_string(thickness) + "\nmaterial = \"film\"\n",
      "plate.toml"));
}

TEST(WingSummaryUnits, AWingBelowATenthOfAMilligramIsShownInMicrograms) {
  // rho h S = 1200 kg/m^3 * 2e-6 m * (1e-3 m * 0.25e-3 m) = 6.0e-10 kg = 0.600 ug.
  EXPECT_EQ(mass_line(w::describe_wing(plate("um", 1000, 250, 2))).rfind("estimated mass              0.600 ug "
                                                                           "(membrane 0.600, non-structural 0.000, "
                                                                           "veins 0.000)", 0), 0u)
      << w::describe_wing(plate("um", 1000, 250, 2));
  // 1200 * 0.2e-3 * (40e-3 * 10e-3) = 9.6e-5 kg = 96.000 mg (the flat plate): still in mg.
  EXPECT_NE(mass_line(w::describe_wing(plate("mm", 40, 10, 0.2))).find(" 96.000 mg (membrane 96.000,"),
            std::string::npos)
      << w::describe_wing(plate("mm", 40, 10, 0.2));
}

TEST(WingSummaryUnits, AHeavyWingIsShownInGramsOrKilograms) {
  // 1200 * 1e-3 * (0.4 * 0.1) = 0.048 kg = 48.000 g (a 400 mm MAV plate of 1 mm; "48000.000 mg").
  EXPECT_NE(mass_line(w::describe_wing(plate("mm", 400, 100, 1.0))).find(" 48.000 g (membrane 48.000,"),
            std::string::npos)
      << w::describe_wing(plate("mm", 400, 100, 1.0));
  // The flat plate written in metres in a mm file: 1200 * 0.2 * (40 * 10) = 96000 kg ("9.6e10 mg").
  EXPECT_NE(mass_line(w::describe_wing(plate("m", 40, 10, 0.2))).find(" 96000.000 kg (membrane 96000.000,"),
            std::string::npos)
      << w::describe_wing(plate("m", 40, 10, 0.2));
}

TEST(WingSummaryUnits, AMembraneBelowATenthOfAMillimetreIsShownInMicrometres) {
  // A fruit fly's 0.5 um membrane read "0.0005 mm" (one digit); 0.2 mm stays in mm.
  EXPECT_NE(w::describe_wing(plate("um", 2500, 800, 0.5)).find("membrane thickness         0.5000 um"),
            std::string::npos)
      << w::describe_wing(plate("um", 2500, 800, 0.5));
  EXPECT_NE(w::describe_wing(plate("mm", 40, 10, 0.2)).find("membrane thickness         0.2000 mm"),
            std::string::npos)
      << w::describe_wing(plate("mm", 40, 10, 0.2));
}

}  // namespace
