// A `kind = "fem"` case whose FEM has a natural mode near the wingbeat frequency or twice
// it is warned about by check, run and sweep as a chain is (pipeline/app/
// fem_resonance_warning.hpp; docs/case_file.md, "Warnings about the built case"). Before, a
// user's 13 mm bumblebee-size wing of a 4 µm membrane (tests/data/bumblebee_forewing_4um.toml;
// first mode 186.5 Hz) flapped at 150 Hz on its FEM bent its tip past 75° within a fifth of
// a wingbeat with no word from check, while the chain of the same wing was warned.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/fem_resonance_warning.hpp"
#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/io/case_file.hpp"

namespace {

const std::string kBeeWing = std::string(FLAPSIM_SOURCE_DIR) + "/tests/data/bumblebee_forewing_4um.toml";
const std::string kFemResonance = "the FEM's mode ";

// The bumblebee-size wing on its FEM, set up as cases/film_wing_fem.toml (a thin film:
// newton_geometric_terms = "current", rho_infinity = 0), sweep ±55°, rotation 90 ± 40°, one
// wingbeat at `frequency_hz`; `structure_lines` added to [structure]. Returns the case file.
std::filesystem::path bee_fem_case(const flapsim::test::ScratchDir& dir, const std::string& name, double frequency_hz,
                                   const std::string& structure_lines = "") {
  const auto file = dir / (name + ".toml");
  std::ofstream(file) << "name = \"" << name << "\"\nwing = \"" << kBeeWing
                      << "\"\n[kinematics]\nfrequency_hz = " << frequency_hz
                      << "\nsweep = { cos_deg = [55.0] }\nrotation = { mean_deg = 90.0, sin_deg = [40.0] }\n"
                         "[structure]\nkind = \"fem\"\nnewton_geometric_terms = \"current\"\n"
                      << structure_lines
                      << "[numerics]\nsteps_per_cycle = 80\nrho_infinity = 0.0\ncycles = 1\nchordwise_panels = 6\n"
                         "spanwise_panels = 10\ncore_radius = 0.2\nfar_wake_cycles = 0.5\n[output]\nvtk_every = 4\n";
  return file;
}

// `flapsim check FILE`'s stderr (exit status 0 expected).
std::string check_bee_case(const flapsim::test::ScratchDir& dir, const std::filesystem::path& file) {
  const flapsim::test::FlapsimOutcome out = flapsim::test::run_flapsim_capturing_stderr(dir.path(), "check " + file.string());
  EXPECT_EQ(out.status, 0) << out.err;
  return out.err;
}

// The frequencies of DIR/modes.csv (`flapsim modes`: mode,frequency_hz,kind,...), lowest first.
std::vector<double> modes_csv_frequencies(const std::filesystem::path& csv) {
  std::istringstream in(flapsim::test::read_text(csv));
  std::string line;
  std::getline(in, line);  // header
  std::vector<double> out;
  while (std::getline(in, line))
    if (const auto comma = line.find(','); comma != std::string::npos)
      out.push_back(std::strtod(line.c_str() + comma + 1, nullptr));
  return out;
}

}  // namespace

TEST(FemResonanceWarning, CheckWarnsTheBumblebeeWingFlappedAt150HzNamingItsModes) {
  flapsim::test::ScratchDir dir("fem_resonance_bee_150");
  const std::string err = check_bee_case(dir, bee_fem_case(dir, "bee150", 150.0));
  // `flapsim modes` of the wing (its own mesh, the case's): 186.515 Hz (bending), 305.513 Hz
  // (bending), 388.45 Hz (torsion), 437.5 Hz. The strongest first, as the chain's warning
  // names it: mode 2 against 2 f = 300 Hz, r = 300 / 305.513 = 0.982, 1 / (1 − r²) = 27.7.
  EXPECT_NE(err.find("warning: the FEM's mode 2 (bending shape), 305.5 Hz, lies near twice the wingbeat frequency "
                     "300 Hz (mode / drive = 1.02): an undamped oscillator driven there moves 28 times"),
            std::string::npos)
      << err;
  // The user's mode 1, 186.515 Hz = 1.24 f: r = 150 / 186.515, 1 / (1 − r²) = 2.83 ≥ 2 (the
  // band 0.82…1.41 f); and mode 3, 388.45 / 300 = 1.29 (1.63…2.83 f: 1 / (1 − 0.596) = 2.5).
  EXPECT_NE(err.find("mode 1 (bending shape), 186.5 Hz, near the wingbeat frequency (mode / drive = 1.24, 2.8 times)"),
            std::string::npos)
      << err;
  EXPECT_NE(err.find("mode 3 (torsion shape), 388.5 Hz, near twice the wingbeat frequency (mode / drive = 1.29, "
                     "2.5 times)"),
            std::string::npos)
      << err;
  // And that the run will take longer than check estimates (a swept 50 um wing driven near its
  // mode 1 took 194 s for 20 steps against 1.4 s estimated, 4 Dec; docs/case_file.md).
  EXPECT_NE(err.find("driven near a mode the FEM halves its steps, beyond the time estimated here"),
            std::string::npos)
      << err;
  // Mode 4, 437.5 Hz = 1.46 × 2 f (1 / (1.458² − 1) = 0.89 < 2), is outside the band.
  EXPECT_EQ(err.find("mode 4 ("), std::string::npos) << err;
  // Only the FEM's warning: the chain's is for kind = "flexible".
  EXPECT_EQ(err.find("the chain's mode"), std::string::npos) << err;
}

TEST(FemResonanceWarning, TheSameWingFlappedFarFromEveryBandIsNotWarned) {
  flapsim::test::ScratchDir dir("fem_resonance_bee_50");
  // At 50 Hz the lowest mode, 186.515 Hz, is 3.73 f, above the band's top 2.83 f (at 2 f:
  // r = 100 / 186.515, 1 / (1 − r²) = 1.40 < 2), and every other mode higher still; any
  // f below 186.515 / 2.83 = 65.9 Hz is clear of the bands, and none above (the modes
  // are too dense for a gap).
  const std::string err = check_bee_case(dir, bee_fem_case(dir, "bee50", 50.0));
  EXPECT_EQ(err.find(kFemResonance), std::string::npos) << err;
  // The check ran its setup warnings: the film's (4 µm on 0.233 mm elements) is there.
  EXPECT_NE(err.find("wrinkles of the mesh's own wavelength"), std::string::npos) << err;
}

TEST(FemResonanceWarning, TheSameWingFlappedAboveItsFirstModeIsWarnedSo) {
  // At 300 Hz the lowest mode, 186.515 Hz, lies below the fundamental's band (0.82 f =
  // 245 Hz: lowest_resonant_mode_hz): the wing is driven above it, r = 300 / 186.515 =
  // 1.608, and moves against its base by r² / (r² − 1) = 1.63 times the base's motion. That
  // is warned in place of the resonance of modes 2 and 3 (305.5, 388.5 Hz) with 300 Hz.
  flapsim::test::ScratchDir dir("fem_resonance_bee_300");
  const std::string err = check_bee_case(dir, bee_fem_case(dir, "bee300", 300.0));
  EXPECT_NE(
      err.find(
          "warning: the FEM's mode 1 (bending shape), 186.5 Hz, lies below the wingbeat frequency 300 Hz "
          "(drive / mode = 1.61): a wing driven above its first mode deforms against its base by about as "
          "much as the base moves (1.63 times it"),
      std::string::npos)
      << err;
  EXPECT_EQ(err.find("lies near"), std::string::npos) << err;
  // Just inside the band (mode 1 at 0.82 f: f = 186.515 / 0.8165 = 228.4 Hz; 225 Hz): the
  // resonance, not the drive above the mode (mode 1 at r = 1.206, 1 / (r² − 1) = 2.19, listed
  // beside the strongest, mode 3 against 2 f).
  const std::string near = check_bee_case(dir, bee_fem_case(dir, "bee225", 225.0));
  EXPECT_NE(
      near.find("mode 1 (bending shape), 186.5 Hz, near the wingbeat frequency (mode / drive = 0.829, 2.2 "
                "times)"),
      std::string::npos)
      << near;
  EXPECT_EQ(near.find("lies below the wingbeat frequency"), std::string::npos) << near;
}

TEST(FemResonanceWarning, TheWarnedFrequencyIsFlapsimModesOnTheMeshTheCaseChooses) {
  flapsim::test::ScratchDir dir("fem_resonance_bee_modes");
  // The case's mesh, coarser than the wing file's (span / 50 = 0.26 mm): 0.4 mm, the veins
  // at min(0.4, 0.26) mm (fem_structure_setup.cpp); the same sizes in a copy of the wing
  // file's [mesh] give `flapsim modes` the same mesh.
  const auto file = bee_fem_case(dir, "bee150_coarse", 150.0, "element_size_mm = 0.4\n");
  std::ofstream(dir / "bee_coarse.toml") << flapsim::test::read_text(kBeeWing)
                                         << "\n[mesh]\nelement_size = 0.4\nvein_element_size = 0.26\n";
  ASSERT_EQ(flapsim::test::run_flapsim("modes " + (dir / "bee_coarse.toml").string() + " -o " +
                                       (dir / "modes").string() + " --threads 1"),
            0);
  const std::vector<double> listed = modes_csv_frequencies(dir / "modes" / "modes.csv");
  ASSERT_GE(listed.size(), 4u);
  const flapsim::io::Case c = flapsim::io::load_case_file(file.string());
  const flapsim::app::FemNaturalModes fem = flapsim::app::fem_resonance_modes(c, flapsim::app::build_fsi_setup(c, {}));
  // 4 modes: the 4th lies above 2.83 f = 424 Hz.
  ASSERT_EQ(fem.frequencies_hz.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    std::printf("  mode %zu: flapsim modes %.9f Hz, the warning's %.9f Hz (relative %.1e)\n", i + 1, listed[i],
                fem.frequencies_hz[i], fem.frequencies_hz[i] / listed[i] - 1.0);
    // The same mesh, the same K and M (fem::assemble, the same bits) and solver, but 4
    // modes asked against `flapsim modes`' 20 (another Krylov space): equal to rounding,
    // not always to the bit (measured: 0, 0, 6.7e-16 and 2.0e-15 relative).
    EXPECT_NEAR(fem.frequencies_hz[i] / listed[i], 1.0, 1e-12) << "mode " << i + 1;
  }
  // The warning names `flapsim modes`' number for this mesh (not the wing file's mesh's
  // 186.515 Hz: printed to 4 digits, 186.5).
  char mode1[80];
  std::snprintf(mode1, sizeof mode1, "mode 1 (bending shape), %.4g Hz, near the wingbeat frequency", listed[0]);
  std::printf("  %s\n", mode1);
  const std::string err = check_bee_case(dir, file);
  EXPECT_NE(err.find(mode1), std::string::npos) << err;
  // The coarser mesh moves mode 1 (measured: 186.254 Hz against 186.515, 1.4e-3), so the
  // agreement above is with this mesh's modes.
  EXPECT_GT(std::abs(listed[0] / 186.515 - 1.0), 1e-3);
}
