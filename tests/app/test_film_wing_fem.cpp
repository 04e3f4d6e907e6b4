// The shipped 25 µm film wing (cases/film_wing_fem.toml: a 1 mm carbon rod and a 25 µm Mylar
// film, 20 Hz, held vertical at its root) flown with its own FEM as the structure, for one
// wingbeat. Before the FEM's step halving and with ρ∞ = 0.9 this run stopped at step 4 (exit
// status 3: docs/fsi.md, "Film wings"); the bar chain cannot represent a film pitching
// about its rod (docs/reduction.md, "Film wings").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "app/history_csv.hpp"
#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace {

using namespace flapsim;

// The shipped case for one wingbeat (the wing file by its path in the source tree), as
// `kind` ("fem" or "rigid").
std::string one_wingbeat_of_the_film_case(const std::string& kind) {
  std::string text = test::read_text(std::filesystem::path(FLAPSIM_SOURCE_DIR) / "cases" / "film_wing_fem.toml");
  auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  };
  replace("wing = \"../wings/", std::string("wing = \"") + FLAPSIM_SOURCE_DIR + "/wings/");
  replace("cycles = 5", "cycles = 1");
  replace("kind = \"fem\"", "kind = \"" + kind + "\"");
  if (kind != "fem") replace("newton_geometric_terms = \"current\"\n", "");  // a key of the FEM's only
  replace("vtk_every = 4", "vtk_every = 0");
  return text;
}

TEST(FilmWingFem, TheShippedFilmWingFliesAWingbeatOnItsFem) {
  test::ScratchDir dir("film_wing_fem");
  for (const std::string kind : {"rigid", "fem"}) {
    std::ofstream(dir / (kind + ".toml")) << one_wingbeat_of_the_film_case(kind);
    ASSERT_EQ(test::run_flapsim("run " + (dir / (kind + ".toml")).string() + " -q -o " + (dir / kind).string()), 0)
        << kind;
  }
  const std::string summary = test::read_text(dir / "fem" / "summary.json");
  // The step halving carried it: measured 50 of 80 steps split, up to 8 pieces.
  EXPECT_GT(test::json_number(summary, "split_structural_steps"), 0.0) << summary;
  EXPECT_LE(test::json_number(summary, "max_structural_pieces"), 256.0) << summary;

  const test::HistoryCsv fem = test::read_history_csv(dir / "fem" / "history.csv");
  const test::HistoryCsv rigid = test::read_history_csv(dir / "rigid" / "history.csv");
  ASSERT_EQ(fem.rows.size(), 80u);
  ASSERT_EQ(rigid.rows.size(), 80u);
  double lift_fem = 0.0, lift_rigid = 0.0, aero = 0.0, drive = 0.0, twist = 0.0;
  for (long s = 1; s <= 80; ++s) {
    lift_fem += fem.at(s, "lift_N") / 80.0;
    lift_rigid += rigid.at(s, "lift_N") / 80.0;
    aero += fem.at(s, "power_W") / 80.0;
    drive += fem.at(s, "drive_power_W") / 80.0;
    twist = std::max(twist, std::abs(fem.at(s, "tip_twist_deg")));
  }
  std::printf("  mean lift FEM %.4f mN, rigid %.2e mN; power aerodynamic %.3f mW, drive %.3f mW; peak tip twist "
              "%.1f deg\n",
              1e3 * lift_fem, 1e3 * lift_rigid, 1e3 * aero, 1e3 * drive, twist);
  // The wing held vertical gives no lift when rigid (the strokes mirror each other); the
  // film's pitch about the rod is all the lift (measured 1.99 mN in this wingbeat, 2.06 mN
  // in the 5th: docs/fsi.md, "Film wings").
  EXPECT_LT(std::abs(lift_rigid), 1e-9);
  EXPECT_GT(lift_fem, 1e-3);
  // The film pitches by tens of degrees (measured 17.4° in this wingbeat, ±15.8° in the 5th).
  EXPECT_GT(twist, 10.0);
  EXPECT_LT(twist, 25.0);
  // Two routes to the wingbeat's power: the FEM's clamp reactions times the base's motion
  // (drive) and the lattice's forces on the moving surface (aerodynamic). The film's own
  // kinetic and elastic energy are small against a wingbeat's work, so they agree within 2 %
  // (measured +0.33 %; the 5-cycle run's cycles +0.34 … −0.12 %).
  EXPECT_NEAR(drive, aero, 0.02 * aero);
}

}  // namespace
