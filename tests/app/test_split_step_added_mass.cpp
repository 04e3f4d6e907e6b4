// The air's added mass in the chain's step (numerics.added_mass, docs/fsi.md "Added mass in
// the coupling") when the chain solves a step in pieces (its Newton halves a step that does
// not converge whole; structure_substeps). The linearisation holds for the step's end rate:
// it acts in a step solved whole only (mbd::LoadDamping). Before, it acted in every piece
// against the end rate: a flat-plate chain released from 1° bends at its 8 joints, whose steps
// the chain halves, needed 26 lattice solves at step 2 and stopped at step 3 (exit 3).
// The reference without the added mass takes IQN-ILS with 3 earlier steps' pairs: with
// Aitken's relaxation this light plate's coupling is on the edge, and whether that run got
// through hung on the last bits of the C library's math functions (it stopped at step 31
// with their builds without FMA, docs/performance.md "The C library's math functions";
// IQN-ILS alone stopped with the FMA builds). IQN-ILS with reuse completed with both builds
// and at coupling tolerances 0.9–1.1e-6; the coupling method does not move the fixed point.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace {

const std::string kSplitSource = FLAPSIM_SOURCE_DIR;

struct SplitRun {
  int status = -1;
  double mean_lift = 0.0;  // [N]
  double split_steps = 0.0;
};

SplitRun split_step_run(const flapsim::test::ScratchDir& dir, const std::string& chain, bool added_mass) {
  const std::string name = added_mass ? "with" : "without";
  const auto file = dir / (name + ".toml");
  std::ofstream(file) << "wing = \"" << kSplitSource << "/wings/flat_plate.toml\"\n"
                      << "[kinematics]\nfrequency_hz = 10\nsweep = { mean_deg = 10.0, cos_deg = [50.0] }\n"
                         "deviation = 0.0\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
                         "[structure]\nkind = \"flexible\"\nbodies = 8\n"
                         "initial_angles_deg = [1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, "
                         "0.0, 1.0, 0.0]\n"
                         "[numerics]\nsteps_per_cycle = 40\ncycles = 1\nchordwise_panels = 6\nspanwise_panels = 10\n"
                         "core_radius = 0.2\nfar_wake_cycles = 0.5\nadded_mass = "
                      << (added_mass ? "true" : "false\ncoupling = \"iqn_ils\"\ncoupling_reuse_steps = 3")
                      << "\n[output]\nvtk_every = 0\n";
  const auto out = dir / name;
  SplitRun r;
  r.status = flapsim::test::run_flapsim("run " + file.string() + " --chain " + chain + " -q -o " + out.string());
  const std::string summary = flapsim::test::read_text(out / "summary.json");
  r.mean_lift = flapsim::test::json_number(summary, "mean_lift_N");
  r.split_steps = flapsim::test::json_number(summary, "split_structural_steps");
  return r;
}

}  // namespace

TEST(SplitStepAddedMass, AChainThatHalvesItsStepsConvergesToTheSameLiftWithTheAddedMass) {
  flapsim::test::ScratchDir dir("split_step_added_mass");
  const auto chain_dir = dir / "chain";
  ASSERT_EQ(flapsim::test::run_flapsim("reduce " + kSplitSource + "/wings/flat_plate.toml --bodies 8 -o " +
                                       chain_dir.string()),
            0);
  const std::string chain = (chain_dir / "chain.toml").string();
  const SplitRun with = split_step_run(dir, chain, true), without = split_step_run(dir, chain, false);
  ASSERT_EQ(without.status, 0);
  ASSERT_EQ(with.status, 0);
  // The premise: the chain halved steps (measured 96–98 with the added mass, 118–125 without).
  EXPECT_GT(with.split_steps, 0.0);
  // The same fixed point: the mean lift within 1e-5 (measured 3e-7, the coupling tolerance's
  // 1e-6 rad in the joint angles).
  std::printf("[ value ] flat plate released from 1 deg bends: mean lift %.9g N with the added mass, %.9g N "
              "without (%.2g); %.0f halved steps\n",
              with.mean_lift, without.mean_lift, with.mean_lift / without.mean_lift - 1.0, with.split_steps);
  EXPECT_NEAR(with.mean_lift / without.mean_lift, 1.0, 1e-5);
}
