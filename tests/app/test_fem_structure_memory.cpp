// The memory of a run whose structure is the wing's FEM (kind = "fem"), against the process's
// measured peak. The estimate took the linear FEM's count (fem_memory_bytes) and said 102 MB for
// a swept film wing of 7518 DOFs that peaked at 138-148 MB (the hawkmoth FEM hover: 220 MB for
// 367 MB); the nonlinear FEM holds its tangent matrix and more factorisations
// (kFemStructureMemoryFactor, resource_estimate.hpp).
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cmath>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/resource_estimate.hpp"
#include "pipeline/io/case_file.hpp"

namespace {

using namespace flapsim;

TEST(FemStructureMemory, TheEstimateIsThePeakOfARunOfTheWingsFem) {
#if defined(__SANITIZE_ADDRESS__)
  // Under `make test-asan` the program's peak is ASan's (shadow memory, quarantine), not the
  // one the estimate is for.
  GTEST_SKIP() << "a peak measured on the ASan build is not the program's";
#endif
  const test::ScratchDir dir("fem_structure_memory");
  // In vacuum (the FEM alone), 60 steps of a wingbeat at 12 Hz: no step split in pieces (a
  // split step keeps its matrices, up to nonlinear_dynamics.hpp's kKeptMatricesBytes more).
  std::ofstream(dir / "case.toml") << "name = \"memory\"\nair = \"none\"\nwing = \"" << FLAPSIM_SOURCE_DIR
                                   << "/tests/data/swept_film_wing.toml\"\n"
                                      "[kinematics]\nfrequency_hz = 12.0\nsweep = { cos_deg = [50.0] }\n"
                                      "rotation = { mean_deg = 90.0, sin_deg = [-35.0] }\n"
                                      "[structure]\nkind = \"fem\"\n"
                                      "[numerics]\nsteps_per_cycle = 60\ncycles = 1\n";
  ASSERT_EQ(test::run_flapsim("run '" + (dir / "case.toml").string() + "' --vtk-every 0 -o '" +
                              (dir / "out").string() + "'"),
            0);
  struct rusage usage {};
  ASSERT_EQ(::getrusage(RUSAGE_CHILDREN, &usage), 0);
  const double peak = 1024.0 * static_cast<double>(usage.ru_maxrss);  // [B] (ru_maxrss in kB)
  const std::string summary = test::read_text(dir / "out" / "summary.json");
  const double nodes = test::json_number(summary, "fem_nodes");
  ASSERT_EQ(nodes, 1253.0) << summary;  // 7518 DOFs, 6 a node
  EXPECT_TRUE(std::isnan(test::json_number(summary, "split_structural_steps")))
      << summary;  // set only when some were
  const app::RunEstimate e =
      app::estimate_run(io::load_case_file((dir / "case.toml").string()), 1, static_cast<int>(6 * nodes));
  // Source: the process's own peak (getrusage). 15 %: the fit's spread on its four runs was 4 %.
  EXPECT_NEAR(e.memory_bytes / peak, 1.0, 0.15) << e.memory_bytes << " B estimated, " << peak << " B peak";
}

}  // namespace
