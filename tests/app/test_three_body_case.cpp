// `flapsim run cases/three_body.toml`: the rotation-phase paper's 3-body system in
// vacuum, read from its case file (chain file, eq. 5 kinematics, eq. 6 loads, marker A)
// and run through the coupled-run path, reproduces the same system built directly in
// code and integrated by the multibody library (tests/mbd/three_body_trajectory.hpp),
// which tests/mbd checks against Simbody (within 0.5 % of the amplitude).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "mbd/three_body_trajectory.hpp"

namespace {

using namespace flapsim;

TEST(ThreeBodyCase, FlapsimRunReproducesTheMultibodyIntegration) {
  test::ScratchDir dir("three_body_case");
  ASSERT_EQ(test::run_flapsim("run " + std::string(FLAPSIM_SOURCE_DIR) + "/cases/three_body.toml -o " +
                              (dir / "out").string() + " --vtk-every 0"),
            0);
  std::ifstream in(dir / "out" / "history.csv");
  ASSERT_TRUE(in.good());
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::stringstream hs(line); std::getline(hs, line, ',');) names.push_back(line);
  const auto col = [&](const std::string& n) {
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), n) - names.begin());
  };
  const std::size_t ct = col("t_s"), cx = col("A_x_m"), cy = col("A_y_m"), cz = col("A_z_m");
  ASSERT_LT(cz, names.size()) << "no marker A in history.csv";

  // The case: 3 cycles of 1000 steps at 26 Hz; the reference samples every step.
  const mbd::ChainModel chain = mbd::test::three_body_chain();
  const double t_end = 3.0 / mbd::test::kThreeBodyFrequency;
  const mbd::test::Trajectory ref = mbd::test::integrate_three_body(chain, t_end, 3000, 1);
  double amplitude = 0.0;
  for (int c = 0; c < 3; ++c) {
    const auto [lo, hi] = std::minmax_element(ref.a.begin(), ref.a.end(), [c](const auto& a, const auto& b) {
      return a(c) < b(c);
    });
    amplitude = std::max(amplitude, 0.5 * ((*hi)(c) - (*lo)(c)));
  }
  double worst = 0.0;
  std::size_t rows = 0;
  for (std::string row; std::getline(in, row);) {
    std::vector<double> v;
    for (std::stringstream rs(row); std::getline(rs, line, ',');) v.push_back(std::stod(line));
    ++rows;
    ASSERT_LT(rows, ref.t.size());
    ASSERT_NEAR(v[ct], ref.t[rows], 1e-12);
    worst = std::max(worst, (Eigen::Vector3d(v[cx], v[cy], v[cz]) - ref.a[rows]).norm());
  }
  EXPECT_EQ(rows, 3000u);
  std::printf("[three-body case] max |A_run - A_mbd| = %.3e of the amplitude %.4f mm\n",
              worst / amplitude, amplitude * 1e3);
  // The two routes evaluate the same model with the same steps; they differ only in how
  // the eq. 6 loads are evaluated (a periodic signal of the phase f·t against sin ωt),
  // round-off that the implicit integration carries along.
  EXPECT_LT(worst, 1e-9 * amplitude);
}

}  // namespace
