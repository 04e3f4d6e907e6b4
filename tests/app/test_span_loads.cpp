// span_loads.csv: the lift of each spanwise strip of the lattice over the last cycle
// (pipeline/app/span_loads.hpp; docs/fsi.md, "Outputs"). Until 4 Dec a run gave the lift
// along the span only through wing.pvd's panel forces, and that with `leading_edge = "shed"`
// the revolving Robofly's tip strip carries 41 % of its lift went unseen behind a total
// within 10 % of the measurement (docs/uvlm.md, "Where shed's lift lies along the span").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/span_loads.hpp"
#include "sweep_test_helpers.hpp"

namespace span_loads_test {

namespace fs = std::filesystem;
using flapsim::test::ScratchDir;

struct Strip {
  double y_inner, y_outer, chord, lift, per_span, share;
};

std::vector<Strip> read_span_loads(const fs::path& file, std::string* header) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  *header = line;
  std::vector<Strip> strips;
  while (std::getline(in, line)) {
    const auto cells = flapsim::io::split_csv_line(line);
    if (cells.size() != 7) break;
    strips.push_back({std::stod(cells[1]), std::stod(cells[2]), std::stod(cells[3]), std::stod(cells[4]),
                      std::stod(cells[5]), std::stod(cells[6])});
  }
  return strips;
}

// Prandtl's lifting line for a flat rectangular wing of span b and chord c at angle α
// (Glauert's series, odd and even terms, collocation at θ_k = (k + ½) π / N; a0 = 2π):
// Γ(y) = 2 b U Σ A_n sin nθ with y = b/2 (1 − cos θ) from the root. The lift of the band
// [y0, y1] per unit ρU, by the trapezoidal rule on 400 intervals.
double lifting_line_band(double b, double c, double alpha, double y0, double y1) {
  constexpr int kTerms = 41;
  const double mu = 2.0 * std::numbers::pi * c / (4.0 * b);
  Eigen::MatrixXd a(kTerms, kTerms);
  Eigen::VectorXd rhs(kTerms);
  for (int k = 0; k < kTerms; ++k) {
    const double th = (k + 0.5) * std::numbers::pi / kTerms;
    for (int n = 1; n <= kTerms; ++n) a(k, n - 1) = std::sin(n * th) * (std::sin(th) + n * mu);
    rhs(k) = mu * alpha * std::sin(th);
  }
  const Eigen::VectorXd coefficients = a.partialPivLu().solve(rhs);
  const auto gamma = [&](double y) {  // per unit U
    const double th = std::acos(std::clamp(1.0 - 2.0 * y / b, -1.0, 1.0));
    double g = 0.0;
    for (int n = 1; n <= kTerms; ++n) g += coefficients(n - 1) * std::sin(n * th);
    return 2.0 * b * g;
  };
  constexpr int kIntervals = 400;
  const double h = (y1 - y0) / kIntervals;
  double sum = 0.5 * (gamma(y0) + gamma(y1));
  for (int i = 1; i < kIntervals; ++i) sum += gamma(y0 + i * h);
  return sum * h;
}

// wings/flat_plate.toml (chord 10 mm, span 40 mm from y = 0, both ends free) with its span
// stretched to `span_mm`, at 5° in a 10 m/s stream, the steady lattice (no start-up), the
// leading edge's suction kept (`attached`: the flow lifting-line theory describes; the
// default `separated` adds Polhamus' vortex lift, +5.8 % on the aspect ratio 4 plate). Runs
// it and returns span_loads.csv's strips and summary.json's mean lift.
std::vector<Strip> run_plate_in_a_stream(const ScratchDir& dir, int span_mm, int strips, double* mean_lift,
                                         std::string* header) {
  const std::string name = "plate_ar" + std::to_string(span_mm / 10);
  std::string wing = flapsim::test::read_text(FLAPSIM_SOURCE_DIR "/wings/flat_plate.toml");
  const std::string outline = "outline = [[2.5, 0.0], [2.5, 40.0], [-7.5, 40.0], [-7.5, 0.0]]";
  const auto at = wing.find(outline);
  EXPECT_NE(at, std::string::npos);  // else the plate flies at its own span and the checks fail
  if (at != std::string::npos)
    wing.replace(at, outline.size(),
                 "outline = [[2.5, 0.0], [2.5, " + std::to_string(span_mm) + ".0], [-7.5, " +
                     std::to_string(span_mm) + ".0], [-7.5, 0.0]]");
  std::ofstream(dir / (name + "_wing.toml")) << wing;
  std::ofstream(dir / (name + ".toml"))
      << "name = \"" << name << "\"\nwing = \"" << name
      << "_wing.toml\"\n"
         "[kinematics]\nfrequency_hz = 10.0\nsweep = 0.0\nrotation = 5.0\n"
         "[air]\ndensity = 1.225\nfreestream = [-10.0, 0.0, 0.0]\n[structure]\nkind = \"rigid\"\n"
         "[numerics]\nsteps_per_cycle = 4\ncycles = 1\nchordwise_panels = 4\nspanwise_panels = "
      << strips << "\nsteady = true\nleading_edge = \"attached\"\n[output]\nvtk_every = 0\n";
  const fs::path out = dir / name;
  EXPECT_EQ(flapsim::test::run_flapsim("run " + (dir / (name + ".toml")).string() + " -o " + out.string()),
            0);
  *mean_lift = flapsim::test::json_number(flapsim::test::read_text(out / "summary.json"), "mean_lift_N");
  return read_span_loads(out / "span_loads.csv", header);
}

TEST(SpanLoads, AFlatPlateInAStreamsStripsTileTheSpanSymmetricallyAndAddUpToTheRunsLift) {
  ScratchDir dir("span_loads_plate");
  double mean_lift = 0.0;
  std::string header;
  const std::vector<Strip> strips = run_plate_in_a_stream(dir, 40, 10, &mean_lift, &header);
  EXPECT_EQ(header, "strip,y_inner_m,y_outer_m,chord_m,mean_lift_N,lift_per_span_N_m,lift_share");
  ASSERT_EQ(strips.size(), 10u);
  // The strips tile the span, root to tip, at the chord of the rectangle.
  double sum = 0.0, shares = 0.0;
  for (std::size_t j = 0; j < strips.size(); ++j) {
    EXPECT_NEAR(strips[j].y_inner, 0.004 * j, 1e-12) << j;
    EXPECT_NEAR(strips[j].y_outer, 0.004 * (j + 1), 1e-12) << j;
    EXPECT_NEAR(strips[j].chord, 0.010, 1e-12) << j;
    EXPECT_NEAR(strips[j].per_span, strips[j].lift / 0.004, 1e-9 * std::abs(strips[j].per_span)) << j;
    sum += strips[j].lift;
    shares += strips[j].share;
  }
  // They add up to summary.json's mean lift (the same panels' forces, the same window).
  EXPECT_NEAR(sum, mean_lift, 1e-12 * std::abs(mean_lift));
  EXPECT_NEAR(shares, 1.0, 1e-12);
  // The wing and its stream are symmetric about mid-span, so is its load: strip j as
  // strip 9 − j (round-off).
  for (std::size_t j = 0; j < 5; ++j)
    EXPECT_NEAR(strips[j].lift, strips[9 - j].lift, 1e-8 * strips[j].lift) << j;
}

TEST(SpanLoads, RectangularPlatesApproachPrandtlsLiftingLineAsTheirAspectRatioGrows) {
  // Prandtl's lifting line is the large-aspect-ratio limit of a lifting surface such as the
  // lattice ([Katz & Plotkin 2001], ch. 8 and 12): for a rectangular plate the lattice's
  // lift lies below it by an amount that shrinks as the aspect ratio grows. Measured (4 Dec),
  // the total against lifting line at AR 4, 8, 16: −4.54, −1.94, −1.06 % (AR × difference
  // 18, 16, 17 %); asserted: below it, shrinking from one aspect ratio to the next, and AR ×
  // difference within 12–24 % (about the measurement). The load's shape: each strip's share
  // within 4 % of lifting line's (measured at most 3.3 %), the end strips within 12 %
  // (measured +8.8 … +10.2 %: the lattice holds the tip vortex at the strip's outer side,
  // where lifting line's circulation falls to zero as a square root).
  // Until 4 Dec this test flew the AR 4 plate with the default `separated` and found the
  // total +0.9 % from lifting line: Polhamus' vortex lift, which lifting line does not have,
  // made up for the lifting surface's deficit.
  ScratchDir dir("span_loads_lifting_line");
  const double alpha = 5.0 * std::numbers::pi / 180.0, u = 10.0, rho = 1.225;
  double previous = -1.0;  // the last aspect ratio's difference
  for (const auto& [span_mm, count] : {std::pair{40, 10}, std::pair{80, 16}, std::pair{160, 32}}) {
    double mean_lift = 0.0;
    std::string header;
    const std::vector<Strip> strips = run_plate_in_a_stream(dir, span_mm, count, &mean_lift, &header);
    ASSERT_EQ(strips.size(), static_cast<std::size_t>(count));
    const double span = 1e-3 * span_mm, aspect_ratio = span / 0.010;
    std::vector<double> reference;
    double sum = 0.0, reference_sum = 0.0;
    for (const Strip& s : strips) {
      reference.push_back(rho * u * u * lifting_line_band(span, 0.010, alpha, s.y_inner, s.y_outer));
      reference_sum += reference.back();
      sum += s.lift;
    }
    const double difference = sum / reference_sum - 1.0;
    EXPECT_LT(difference, 0.0) << "AR " << aspect_ratio;
    EXPECT_GT(difference, previous) << "AR " << aspect_ratio;
    previous = difference;
    EXPECT_GT(-difference * aspect_ratio, 0.12) << "AR " << aspect_ratio << ": " << difference;
    EXPECT_LT(-difference * aspect_ratio, 0.24) << "AR " << aspect_ratio << ": " << difference;
    for (std::size_t j = 0; j < strips.size(); ++j) {
      const double tolerance = (j == 0 || j + 1 == strips.size()) ? 0.12 : 0.04;
      EXPECT_NEAR(strips[j].share / (reference[j] / reference_sum), 1.0, tolerance)
          << "AR " << aspect_ratio << ", strip " << j + 1;
    }
  }
}

TEST(SpanLoads, AFlappingWingsStripsAddUpToItsMeanLiftAndARunInVacuumWritesNone) {
  // The tiny hover of the sweep tests (3 × 4 panels, one cycle of 24 steps): the strips'
  // means over the cycle add up to summary.json's mean lift.
  ScratchDir dir("span_loads_hover");
  std::ofstream(dir / "case.toml") << flapsim::test::tiny_plate_case(24);
  const fs::path out = dir / "out";
  ASSERT_EQ(flapsim::test::run_flapsim("run " + (dir / "case.toml").string() + " -o " + out.string()), 0);
  std::string header;
  const std::vector<Strip> strips = read_span_loads(out / "span_loads.csv", &header);
  ASSERT_EQ(strips.size(), 4u);
  double sum = 0.0;
  for (const Strip& s : strips) sum += s.lift;
  const double mean_lift =
      flapsim::test::json_number(flapsim::test::read_text(out / "summary.json"), "mean_lift_N");
  EXPECT_NEAR(sum, mean_lift, 1e-12 * std::abs(mean_lift));
  // The same folder run again in vacuum: no lattice, no strips, and the earlier run's file
  // does not stay behind as if this run had written it.
  std::string vacuum = flapsim::test::tiny_plate_case(24);
  vacuum.replace(vacuum.find("[kinematics]"), 0, "air = \"none\"\n");
  std::ofstream(dir / "vacuum.toml") << vacuum;
  ASSERT_EQ(flapsim::test::run_flapsim("run " + (dir / "vacuum.toml").string() + " -o " + out.string() +
                                       " --force"),
            0);
  EXPECT_FALSE(fs::exists(out / "span_loads.csv"));
}

// A strip's share has its lift's sign whatever the net lift: strips of −1, +3, −4 mN (net
// −2 mN, a wing pushed down) share −0.5, +1.5, −2 (adding up to −1). Before: of the signed sum,
// +0.5, −1.5, +2, the strip that lifts read as pushing down (a user's failed run, 6 Dec).
TEST(SpanLoads, ShareHasTheStripsSignWhereTheNetLiftIsDown) {
  ScratchDir dir("span_loads_down");
  const std::vector<flapsim::app::SpanStrip> strips = {
      {0.0, 0.01, 0.01}, {0.01, 0.02, 0.01}, {0.02, 0.03, 0.01}};
  flapsim::app::write_span_loads(dir / "span_loads.csv", strips, {-1e-3, 3e-3, -4e-3});
  std::string header;
  const auto rows = read_span_loads(dir / "span_loads.csv", &header);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_NEAR(rows[0].share, -0.5, 1e-12);
  EXPECT_NEAR(rows[1].share, 1.5, 1e-12);
  EXPECT_NEAR(rows[2].share, -2.0, 1e-12);
  // A net lift up: the shares of the sum, adding up to 1 (+1, −3, +4 mN over 2 mN: 0.5, −1.5, 2).
  flapsim::app::write_span_loads(dir / "up.csv", strips, {1e-3, -3e-3, 4e-3});
  const auto up = read_span_loads(dir / "up.csv", &header);
  EXPECT_NEAR(up[0].share + up[1].share + up[2].share, 1.0, 1e-12);
  EXPECT_NEAR(up[1].share, -1.5, 1e-12);
}

}  // namespace span_loads_test
