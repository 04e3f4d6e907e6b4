// A `kind = "fem"` case whose membrane is a thin film against its mesh is warned about by
// check and run (pipeline/app/film_wrinkle_warning.hpp; docs/fsi.md, "Film wings"): its
// FEM splits the steps where the film wrinkles, and the shipped film cases took 8× and 16×
// the time `check` estimates.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "fem/wing_fem.hpp"
#include "pipeline/app/film_wrinkle_warning.hpp"
#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/io/case_file.hpp"
#include "wings/loader/wing_file.hpp"

namespace {

const std::string kWrinkleSource = FLAPSIM_SOURCE_DIR;
const std::string kWrinkleWarning = "wrinkles of the mesh's own wavelength";

// `flapsim check` of a shipped case with its wing path made absolute; its stderr.
std::string check_case(const flapsim::test::ScratchDir& dir, const std::string& case_name, const std::string& wing) {
  std::string text = flapsim::test::read_text(kWrinkleSource + "/cases/" + case_name + ".toml");
  const std::string relative = "\"../wings/" + wing + ".toml\"";
  text.replace(text.find(relative), relative.size(), "\"" + kWrinkleSource + "/wings/" + wing + ".toml\"");
  const auto file = dir / (case_name + ".toml");
  std::ofstream(file) << text;
  const flapsim::test::FlapsimOutcome out =
      flapsim::test::run_flapsim_capturing_stderr(dir.path(), "check " + file.string());
  EXPECT_EQ(out.status, 0) << out.err;
  return out.err;
}

}  // namespace

TEST(FilmWrinkleWarning, TheWrinkleStrainIsWhereTheMembraneForceMeetsTheBendingStiffness) {
  // 25 µm Mylar (ν = 0.38) at a wavelength of 2.5 mm, by hand: (2π · 0.01)² = 3.9478e-3,
  // / 12 / (1 − 0.1444) = 3.845e-4 (docs/fsi.md: a film in compression wrinkles at the
  // mesh's wavelength, N k² against D k⁴).
  EXPECT_NEAR(flapsim::app::mesh_wrinkle_strain(25e-6, 0.38, 2.5e-3), 3.845e-4, 1e-7);
  // t² scaling: twice as thick wrinkles at four times the strain.
  EXPECT_NEAR(flapsim::app::mesh_wrinkle_strain(50e-6, 0.38, 2.5e-3) / flapsim::app::mesh_wrinkle_strain(25e-6, 0.38, 2.5e-3),
              4.0, 1e-12);
}

TEST(FilmWrinkleWarning, TheFilmWingsAreBelowTheThresholdAndTheHawkmothFarAbove) {
  using flapsim::app::typical_membrane_wrinkle;
  const auto film = typical_membrane_wrinkle(
      flapsim::fem::build_wing_fem(flapsim::wings::load_wing_file(kWrinkleSource + "/wings/film_wing_75mm_25um.toml")).model);
  const auto mav = typical_membrane_wrinkle(
      flapsim::fem::build_wing_fem(flapsim::wings::load_wing_file(kWrinkleSource + "/wings/mav_film_wing_25um.toml")).model);
  const auto hawkmoth = typical_membrane_wrinkle(
      flapsim::fem::build_wing_fem(flapsim::wings::load_wing_file(kWrinkleSource + "/wings/hawkmoth.toml")).model);
  ASSERT_TRUE(film && mav && hawkmoth);
  std::printf("  typical wrinkle strain: 75 mm film wing %.3g (%.3g mm), MAV film wing %.3g (%.3g mm), hawkmoth %.3g "
              "(%.3g mm)\n",
              film->strain, 1e3 * film->size, mav->strain, 1e3 * mav->size, hawkmoth->strain, 1e3 * hawkmoth->size);
  // Measured: 5.13e-4 (2.17 mm), 3.85e-4 (2.5 mm), 0.221 (0.485 mm).
  EXPECT_NEAR(film->strain, 5.1e-4, 0.3e-4);
  EXPECT_NEAR(mav->strain, 3.8e-4, 0.3e-4);
  EXPECT_LT(film->strain, flapsim::app::kFilmWrinkleStrain);
  EXPECT_LT(mav->strain, flapsim::app::kFilmWrinkleStrain);
  EXPECT_GT(hawkmoth->strain, 100.0 * flapsim::app::kFilmWrinkleStrain);
}

TEST(FilmWrinkleWarning, TheBumblebeeSizeMembraneIsBelowTheThreshold) {
  // A user's 13 mm forewing of a 4 µm membrane (tests/data/bumblebee_forewing_4um.toml): its
  // FEM split every step at 150 Hz into up to 64 pieces, 10 steps in 565 s against 17 s
  // estimated for 160, with no warning while the threshold was 1e-3 (docs/fsi.md).
  const auto bee = flapsim::app::typical_membrane_wrinkle(
      flapsim::fem::build_wing_fem(flapsim::wings::load_wing_file(kWrinkleSource + "/tests/data/bumblebee_forewing_4um.toml"))
          .model);
  ASSERT_TRUE(bee);
  EXPECT_NEAR(bee->strain, 1.06e-3, 0.05e-3);  // measured: 0.233 mm elements, 4 µm
  EXPECT_LT(bee->strain, flapsim::app::kFilmWrinkleStrain);
}

// The film warning names the element size the mesh-resolution warning names, on a membrane of
// one thickness: check gave "elements of 10.8 mm" and "elements of 14.1 mm" for one coarse
// mesh (the two medians of an even count taken from either end).
TEST(FilmWrinkleWarning, ItsElementSizeIsTheMeshResolutionWarningsMedian) {
  flapsim::test::ScratchDir dir("wrinkle_median");
  std::ifstream in(kWrinkleSource + "/tests/data/valid_tiny_wing.toml");
  std::string wing((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(dir / "w.toml") << wing << "\n[mesh]\nelement_size = 1.5\n";
  const auto fem = flapsim::fem::build_wing_fem(flapsim::wings::load_wing_file((dir / "w.toml").string()));
  const flapsim::fem::Mesh& mesh = fem.model.mesh;
  ASSERT_EQ(mesh.triangles.size() % 2, 0u)
      << mesh.triangles.size() << " triangles: the case needs an even count";
  // fem_mesh_resolution_warning.cpp: the shell triangles' mean edges, ascending, at n / 2.
  std::vector<double> sizes;
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e) sizes.push_back(mesh.triangle_mean_edge(e));
  std::sort(sizes.begin(), sizes.end());
  ASSERT_NE(sizes[sizes.size() / 2 - 1], sizes[sizes.size() / 2]);  // the two medians differ here
  const auto wrinkle = flapsim::app::typical_membrane_wrinkle(fem.model);
  ASSERT_TRUE(wrinkle);
  EXPECT_EQ(wrinkle->size, sizes[sizes.size() / 2]);
}

TEST(FilmWrinkleWarning, CheckWarnsForTheFilmWingsFemAndNotForTheHawkmoths) {
  flapsim::test::ScratchDir dir("film_wrinkle_warning");
  EXPECT_NE(check_case(dir, "film_wing_fem", "film_wing_75mm_25um").find(kWrinkleWarning), std::string::npos);
  EXPECT_EQ(check_case(dir, "hover_flexible_fem", "hawkmoth").find(kWrinkleWarning), std::string::npos);
}

TEST(FilmWrinkleWarning, AThinFilmsFemGoesWithoutTheAddedMass) {
  // The lumped added mass (pipeline/fsi/fem_added_mass.hpp) slowed a split film step's coupling,
  // and on the MAV film wing it changed the coupling's path until the run stopped at step 285
  // (docs/fsi.md, "Added mass in the coupling"): the setup leaves it out for a membrane below
  // kFilmWrinkleStrain and keeps it for the hawkmoth's (here on 2 mm elements, about 0.01).
  const flapsim::io::Case film = flapsim::io::load_case_file(kWrinkleSource + "/cases/film_wing_fem.toml");
  EXPECT_FALSE(flapsim::app::build_fsi_setup(film, {}).fem_structure->lumped_added_mass);
  flapsim::io::Case hawkmoth = flapsim::io::load_case_file(kWrinkleSource + "/cases/hover_flexible_fem.toml");
  hawkmoth.structure.fem_element_size = hawkmoth.structure.fem_vein_element_size = 2e-3;
  EXPECT_TRUE(flapsim::app::build_fsi_setup(hawkmoth, {}).fem_structure->lumped_added_mass);
}

TEST(FilmWrinkleWarning, AThinFilmsFemStopsNewtonByTheIncrementAlone) {
  // DynamicsOptions::contraction_stop (fem/nonlinear_dynamics.hpp) took 13 % of the hawkmoth
  // FEM hover's Newton iterations, but the MAV film wing's five wingbeats took 12 % longer with
  // it (their split steps move chaotically; docs/fem.md, "Newton's stop from the measured
  // contraction"): the setup leaves it out below kFilmWrinkleStrain, as the added mass above.
  const flapsim::io::Case film = flapsim::io::load_case_file(kWrinkleSource + "/cases/mav_film_wing_25um_fem.toml");
  EXPECT_FALSE(flapsim::app::build_fsi_setup(film, {}).fem_structure->dynamics.options.contraction_stop);
  flapsim::io::Case hawkmoth = flapsim::io::load_case_file(kWrinkleSource + "/cases/hover_flexible_fem.toml");
  hawkmoth.structure.fem_element_size = hawkmoth.structure.fem_vein_element_size = 2e-3;
  EXPECT_TRUE(flapsim::app::build_fsi_setup(hawkmoth, {}).fem_structure->dynamics.options.contraction_stop);
}
