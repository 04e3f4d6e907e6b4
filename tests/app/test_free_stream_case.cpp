// A wing that does not flap, held at 5° in a free stream: the coefficients are based on
// the free stream (docs/fsi.md, "Coefficients, forces and power"), and after the start-up
// transient the lift and drag are those of the steady solution of the same lattice.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "flat_plate_glide.hpp"
#include "uvlm/planform_grid.hpp"
#include "uvlm/vortex_lattice.hpp"
#include <Eigen/Geometry>

namespace {

using flapsim::test::read_text;
using flapsim::test::run_flapsim;

double number_in(const std::string& json, const std::string& key) {
  const double x = flapsim::test::json_number(json, key);
  if (std::isnan(x)) ADD_FAILURE() << key << " not in summary.json:\n" << json;
  return x;
}

}  // namespace

TEST(FreeStreamCase, CoefficientsUseTheFreeStreamWhenTheWingDoesNotFlap) {
  // wings/flat_plate.toml (AR 4, chord 10 mm) at α = 5° (rotation 5°, no sweep) in
  // U∞ = 5 m/s along −x, 4 × 8 panels, flat wake, two periods of 25 chords (UΔt = c).
  // Reference: the steady solution of the same lattice (uvlm::solve_steady, attached
  // leading edge): CL within 1.5 %, CD within 3 % (what is left of the start-up transient
  // over the second period); and the lattice value for this wing, CL = 0.316 at 8 × 64
  // (docs/validation.md U4), within 10 % at this coarse lattice.
  flapsim::test::ScratchDir dir("free_stream_case");
  std::ofstream(dir / "case.toml") << flapsim::test::flat_plate_glide_case("glide", 20.0, 5.0, 25, 2,
                                                                            "leading_edge = \"attached\"\n");
  ASSERT_EQ(run_flapsim("run " + (dir / "case.toml").string() + " -o " + (dir / "out").string()), 0);
  const std::string summary = read_text(dir / "out" / "summary.json");
  EXPECT_NE(summary.find("\"reference_kind\": \"free_stream\""), std::string::npos) << summary;
  EXPECT_DOUBLE_EQ(number_in(summary, "reference_speed_m_s"), 5.0);
  EXPECT_DOUBLE_EQ(number_in(summary, "flapping_speed_m_s"), 0.0);
  // A wing that does not flap has no coefficients on a flapping speed.
  EXPECT_EQ(summary.find("on_flapping_speed"), std::string::npos) << summary;
  const double cl = number_in(summary, "mean_CL"), cd = number_in(summary, "mean_CD");

  // The same lattice, steady: the plate's outline in the wing frame, turned nose up by 5°.
  namespace uvlm = flapsim::uvlm;
  uvlm::PlanformGridOptions g;
  g.chordwise = 4;
  g.spanwise = 8;
  const std::vector<Eigen::Vector2d> outline = {{2.5e-3, 0.0}, {2.5e-3, 40e-3}, {-7.5e-3, 40e-3}, {-7.5e-3, 0.0}};
  const Eigen::Matrix3Xd nodes =
      Eigen::AngleAxisd(-5.0 * std::numbers::pi / 180.0, Eigen::Vector3d::UnitY()).toRotationMatrix() *
      uvlm::make_planform_grid(outline, g).nodes;
  uvlm::VortexLatticeModel m;
  m.chordwise = 4;
  m.spanwise = 8;
  m.wake_capacity = 2;
  m.leading_edge = uvlm::LeadingEdge::Attached;
  m.core = {uvlm::CoreModel::LambOseen, 1e-8};
  uvlm::VortexLatticeData d(m);
  uvlm::solve_steady(m, d, nodes, Eigen::Vector3d(-5.0, 0.0, 0.0), 1.225, 100.0);
  const double qs = 0.5 * 1.225 * 25.0 * 400e-6;  // ½ ρ U∞² S, S = 400 mm²
  const double cl_steady = d.loads.total_force.z() / qs, cd_steady = -d.loads.total_force.x() / qs;
  std::printf("[ value ] glide at 5 deg: CL %.4f (steady lattice %.4f, U4 0.316), CD %.5f (steady %.5f)\n", cl,
              cl_steady, cd, cd_steady);
  EXPECT_NEAR(cl / cl_steady, 1.0, 0.015);
  EXPECT_NEAR(cd / cd_steady, 1.0, 0.03);
  EXPECT_NEAR(cl / 0.316, 1.0, 0.10);
  EXPECT_NEAR(number_in(summary, "mean_lift_N") / qs, cl, 1e-3 * cl);
}

TEST(FreeStreamCase, AFlappingWingsCoefficientsAreGivenOnItsFlappingSpeedToo) {
  // The flat plate flapping (20 Hz, sweep ±30°) in a 5 m/s stream: the coefficients are on
  // U∞ (docs/fsi.md), and also on the flapping speed at r2·R, by hand 4 Φ₀ f r2 R =
  // 4 (π/6) 20 (1/√3) 0.04 m = 0.967 m/s (the cycle-mean |dφ/dt| of a cosine is 4 Φ₀ f; the
  // rectangle's r2 is 1/√3): CL and CD times (U∞ / U_f)².
  flapsim::test::ScratchDir dir("free_stream_flapping");
  std::string text = flapsim::test::flat_plate_glide_case("flap", 20.0, 80.0, 20, 1);
  text.replace(text.find("sweep = 0.0"), 11, "sweep = { cos_deg = [30.0] }");
  std::ofstream(dir / "case.toml") << text;
  ASSERT_EQ(run_flapsim("run " + (dir / "case.toml").string() + " -o " + (dir / "out").string(), dir / "report.txt"),
            0);
  const std::string summary = read_text(dir / "out" / "summary.json");
  const double uf = number_in(summary, "flapping_speed_m_s");
  EXPECT_NEAR(uf, 4.0 * (std::numbers::pi / 6.0) * 20.0 / std::sqrt(3.0) * 0.04, 1e-3);
  const double scale = (5.0 / uf) * (5.0 / uf);
  EXPECT_NEAR(number_in(summary, "mean_CL_on_flapping_speed"), number_in(summary, "mean_CL") * scale,
              1e-12 * std::abs(number_in(summary, "mean_CL") * scale));
  EXPECT_NEAR(number_in(summary, "mean_CD_on_flapping_speed"), number_in(summary, "mean_CD") * scale,
              1e-12 * std::abs(number_in(summary, "mean_CD") * scale) + 1e-15);
  EXPECT_NE(read_text(dir / "report.txt").find("on the flapping speed at r2, 0.96"), std::string::npos)
      << read_text(dir / "report.txt");
}

TEST(FreeStreamCase, SteadyLatticeDoesNotDependOnTheTimeStep) {
  // numerics.steady = true (docs/case_file.md; docs/uvlm.md, "Steady lattice"): the same
  // glide as above gives the same mean lift and drag at 10 and 40 steps per period (the
  // steady lattice does not see Δt: 1e-12 relative), the lattice value of the wing within
  // 10 % (U4, CL 0.316 at 8 × 64), and without the key, at 40 steps per period, the
  // impulsive start comes within 1.5 % of it over the second period (as above).
  flapsim::test::ScratchDir dir("free_stream_steady");
  auto run = [&](int steps, bool steady) {
    const std::string name = "glide_" + std::to_string(steps) + (steady ? "_steady" : "");
    std::ofstream(dir / (name + ".toml")) << flapsim::test::flat_plate_glide_case(
        name, 20.0, 5.0, steps, 2, std::string("leading_edge = \"attached\"\nsteady = ") + (steady ? "true" : "false") + "\n");
    EXPECT_EQ(run_flapsim("run " + (dir / (name + ".toml")).string() + " -o " + (dir / name).string()), 0);
    const std::string summary = read_text(dir / name / "summary.json");
    return std::pair{number_in(summary, "mean_CL"), number_in(summary, "mean_CD")};
  };
  const auto [cl10, cd10] = run(10, true);
  const auto [cl40, cd40] = run(40, true);
  const auto [cl_u, cd_u] = run(40, false);
  std::printf("[ value ] steady lattice CL %.6f, %.6f (10, 40 steps), CD %.6f, %.6f; unsteady at 40 steps CL %.6f, CD %.6f\n",
              cl10, cl40, cd10, cd40, cl_u, cd_u);
  EXPECT_NEAR(cl10 / cl40, 1.0, 1e-12);
  EXPECT_NEAR(cd10 / cd40, 1.0, 1e-12);
  EXPECT_NEAR(cl40 / 0.316, 1.0, 0.10);
  EXPECT_NEAR(cl_u / cl40, 1.0, 0.015);
}

// A wing whose span axis does not move in still air (it only pitches about it, docs/fsi.md
// "Coefficients, forces and power": a case with neither speed is refused). Until 2 Dec its
// span point's speed of round-off, 2e-17 m/s, was taken as the reference speed: exit 0,
// status "ok" and mean CL 8e32 with a warning of a Reynolds number 1.5e-14.
TEST(FreeStreamCase, AWingThatOnlyPitchesInStillAirIsRefused) {
  flapsim::test::ScratchDir dir("pitch_only_case");
  std::ofstream(dir / "case.toml") << "name = \"pitch\"\nwing = \"" FLAPSIM_SOURCE_DIR
                                      "/wings/flat_plate.toml\"\n"
                                      "[kinematics]\nfrequency_hz = 20.0\nsweep = 10.0\n"
                                      "rotation = { mean_deg = 90.0, sin_deg = [-40.0] }\n"
                                      "[structure]\nkind = \"rigid\"\n"
                                      "[numerics]\nsteps_per_cycle = 20\ncycles = 1\n";
  const auto outcome = flapsim::test::run_flapsim_capturing_stderr(
      dir.path(), "run " + (dir / "case.toml").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(outcome.status, 2) << outcome.err;
  EXPECT_NE(outcome.err.find("neither a free stream nor a moving span"), std::string::npos) << outcome.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "summary.json"));
}

// Kinematics whose speed overflows: a sweep of cos_deg = [1e300]. `check` passed it (exit 0,
// a Mach warning of an infinite tip speed) and `run` stopped at its first step with exit 3 as
// a diverged lattice; both now refuse it as bad input naming the kinematics (exit 2).
TEST(FreeStreamCase, KinematicsWhoseSpeedOverflowsAreBadInput) {
  flapsim::test::ScratchDir dir("overflowing_sweep_case");
  std::ofstream(dir / "case.toml") << "name = \"overflow\"\nwing = \"" FLAPSIM_SOURCE_DIR
                                      "/wings/flat_plate.toml\"\n"
                                      "[kinematics]\nfrequency_hz = 20.0\nsweep = { cos_deg = [1e300] }\n"
                                      "rotation = { mean_deg = 90.0, sin_deg = [-40.0] }\n"
                                      "[structure]\nkind = \"rigid\"\n"
                                      "[numerics]\nsteps_per_cycle = 20\ncycles = 1\n";
  for (const std::string command : {"check ", "run "}) {
    const auto outcome = flapsim::test::run_flapsim_capturing_stderr(
        dir.path(),
        command + (dir / "case.toml").string() + (command == "run " ? " -o " + (dir / "out").string() : ""));
    EXPECT_EQ(outcome.status, 2) << command << outcome.err;
    EXPECT_NE(outcome.err.find("case.toml:5: key 'kinematics'"), std::string::npos) << outcome.err;
    EXPECT_NE(outcome.err.find("speed at r2 R is not finite"), std::string::npos) << outcome.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "summary.json"));
}
