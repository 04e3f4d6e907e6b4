// `[structure] kind = "fem"` through `flapsim run`: a very stiff plate (its FEM's first
// bending frequency about 6 times the wingbeat) flies and is driven as the same plate run
// as a rigid wing (one body welded to the base, whose drive moment the multibody library
// computes from the body's inertia: an independent route to the same answer), and its
// outputs are those of the chain's runs column by column, plus the FEM's frames (fem.pvd).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "app/history_csv.hpp"
#include "app/stiff_plate_wing.hpp"
#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace {

using namespace flapsim;


// Eq. 8 with a 20° sweep amplitude, 80 steps per cycle, one cycle. ρ∞ = 0: the start from
// rest relative to an accelerating base excites the FEM's stiff modes, which generalized-α
// with ρ∞ = 0 damps within a few steps (the rigid body has none).
std::string plate_case(const std::string& kind) {
  return "name = \"stiff_" + kind + "\"\nwing = \"wing.toml\"\n"
         "[kinematics]\nfrequency_hz = 26.1\nrotation_phase = -0.1\n"
         "sweep = { mean_deg = 10.0, cos_deg = [20.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
         "[structure]\nkind = \"" + kind + "\"\n"
         "[numerics]\nsteps_per_cycle = 80\ncycles = 1\nchordwise_panels = 3\nspanwise_panels = 4\n"
         "core_radius = 0.2\nrho_infinity = 0.0\n[output]\nvtk_every = 40\n";
}

TEST(FemStructureCase, AStiffFemPlateFliesAndIsDrivenAsTheRigidPlate) {
  test::ScratchDir dir("fem_structure_case");
  std::ofstream(dir / "wing.toml") << test::kStiffPlateWing;
  for (const std::string kind : {"rigid", "fem"}) {
    std::ofstream(dir / (kind + ".toml")) << plate_case(kind);
    ASSERT_EQ(test::run_flapsim("run " + (dir / (kind + ".toml")).string() + " -q -o " + (dir / kind).string()), 0)
        << kind;
  }
  const std::string rigid = test::read_text(dir / "rigid" / "summary.json");
  const std::string fem = test::read_text(dir / "fem" / "summary.json");
  EXPECT_NE(fem.find("\"structure_kind\": \"fem\""), std::string::npos) << fem;
  EXPECT_GT(test::json_number(fem, "fem_nodes"), 50.0) << fem;

  // The same columns, in the same order: chain and FEM runs compare column by column.
  const test::HistoryCsv hr = test::read_history_csv(dir / "rigid" / "history.csv");
  const test::HistoryCsv hf = test::read_history_csv(dir / "fem" / "history.csv");
  ASSERT_EQ(hr.names, hf.names);
  ASSERT_EQ(hr.rows.size(), 80u);
  ASSERT_EQ(hf.rows.size(), 80u);

  // Lift: a deflection of (f/f₁)² ≈ 2.6 % of the quasi-static one under the inertial and
  // aerodynamic loads tilts the plate by hundredths of a degree (peak tip bend below): the
  // mean lift within 0.5 % of the rigid plate's (measured +0.17 %).
  const double lift_rigid = test::json_number(rigid, "mean_lift_N"), lift_fem = test::json_number(fem, "mean_lift_N");
  EXPECT_NEAR(lift_fem, lift_rigid, 5e-3 * std::abs(lift_rigid));
  const double bend = test::json_number(fem, "peak_tip_bend_deg");
  EXPECT_GT(bend, 0.0);
  EXPECT_LT(bend, 0.1);

  // The drive moment, second half of the cycle (the start's transient gone): the FEM's from
  // M v̇ − f_ext over its nodes, the rigid body's from its momentum; they differ by the
  // plate's dynamic amplification 1/(1 − (f/f₁)²) − 1 = 2.7 % of the inertial part and the
  // shell's rotary inertia ρt³/12 (1 % of the plate's about its span axis, t²/c²): within
  // 4 % of the peak moment of each component (measured 0.8, 1.1 and 2.4 %).
  for (const std::string axis : {"Mx", "My", "Mz"}) {
    const std::vector<double> mr = hr.column(axis + "_drive_Nm"), mf = hf.column(axis + "_drive_Nm");
    double peak = 0.0, worst = 0.0;
    for (std::size_t i = 40; i < mr.size(); ++i) {
      peak = std::max(peak, std::abs(mr[i]));
      worst = std::max(worst, std::abs(mf[i] - mr[i]));
    }
    EXPECT_LT(worst, 0.04 * peak) << axis << ": peak " << peak << " N m";
  }

  // The FEM's frames: the deformed mesh with its displacement and membrane strain.
  const std::string frame = test::read_text(dir / "fem" / "vtk" / "fem_000080.vtp");
  EXPECT_NE(frame.find("displacement_m"), std::string::npos);
  EXPECT_NE(frame.find("membrane_strain"), std::string::npos);
  EXPECT_NE(test::read_text(dir / "fem" / "fem.pvd").find("fem_000080.vtp"), std::string::npos);
  EXPECT_NE(test::read_text(dir / "fem" / "run.pvsm").find("fem.pvd"), std::string::npos);
}

// The case's element sizes meet the wing file's rules (wings/loader/mesh_budget.hpp, wing_file.cpp):
// a typo of 0.001 for 1 mm asked gmsh for ~10⁹ triangles (minutes and 14 GB before this
// check) and is refused at the case's line and key, exit status 2, before any meshing.
TEST(FemStructureCase, AMeshSizeTheWingFileWouldRefuseIsRefusedAtTheCasesLineAndKey) {
  test::ScratchDir dir("fem_structure_mesh_sizes");
  // The stiff plate with a vein along its leading edge (the veins' size counts along veins).
  std::ofstream(dir / "wing.toml") << test::kStiffPlateWing
                                   << "[[veins]]\nname = \"edge\"\nshape = \"solid_circle\"\n"
                                      "points = [[2.0, 0.0], [2.0, 40.0]]\ndiameter = 0.5\nmaterial = \"stiff\"\n";
  struct Bad {
    std::string keys;  // after kind = "fem" (line 9 of plate_case)
    int line;
    std::string key, says;
  };
  const Bad cases[] = {
      {"element_size_mm = 0.001\n", 10, "structure.element_size_mm", "more than the budget"},
      {"element_size_mm = 2.0\nvein_element_size_mm = 0.001\n", 11, "structure.vein_element_size_mm",
       "more than the budget"},
      {"element_size_mm = 1.0\nvein_element_size_mm = 2.0\n", 11, "structure.vein_element_size_mm",
       "must not exceed structure.element_size_mm (2 mm against 1 mm)"},
      // Without element_size_mm the membrane's size is the wing file's, and the message says
      // so (it named structure.element_size_mm, a key the case does not have).
      {"vein_element_size_mm = 3.0\n", 10, "structure.vein_element_size_mm",
       "wing.toml, [mesh] element_size) (3 mm against 2.5 mm)"},
      {"element_size_mm = 30.0\n", 10, "structure.element_size_mm", "half the span"},
  };
  for (const Bad& b : cases) {
    std::string text = plate_case("fem");
    text.insert(text.find("kind = \"fem\"\n") + 13, b.keys);
    std::ofstream(dir / "case.toml") << text;
    const test::FlapsimOutcome out = test::run_flapsim_capturing_stderr(dir.path(), "check " + (dir / "case.toml").string());
    EXPECT_EQ(out.status, 2) << b.keys << out.err;
    const std::string where = "case.toml:" + std::to_string(b.line) + ": key '" + b.key + "'";
    EXPECT_NE(out.err.find(where), std::string::npos) << b.keys << out.err;
    EXPECT_NE(out.err.find(b.says), std::string::npos) << b.keys << out.err;
  }
  // A size within the rules runs (the plate's 2.5 mm halved).
  std::string fine = plate_case("fem");
  fine.insert(fine.find("kind = \"fem\"\n") + 13, "element_size_mm = 1.25\n");
  std::ofstream(dir / "case.toml") << fine;
  EXPECT_EQ(test::run_flapsim_capturing_stderr(dir.path(), "check " + (dir / "case.toml").string()).status, 0);
}


}  // namespace

// A coupling that stalls within numerics.max_coupling_iterations is tried again with the
// structure finer (docs/fsi.md, "A stalled coupling, tried again"); the message counted the
// sub-iterations of all tries ("did not converge in 3 sub-iterations" at a limit of 1) and
// did not name the limit. The stiff FEM plate at 8 steps a wingbeat needs 2 a step.
TEST(FemStructureCase, ACouplingStalledAtItsLimitNamesTheLimitAndTheTries) {
  test::ScratchDir dir("fem_structure_coupling_limit");
  std::ofstream(dir / "wing.toml") << test::kStiffPlateWing;
  std::string text = plate_case("fem");
  text.replace(text.find("steps_per_cycle = 80"), 20, "steps_per_cycle = 8\nmax_coupling_iterations = 1");
  std::ofstream(dir / "case.toml") << text;
  const auto out = test::run_flapsim_capturing_stderr(dir.path(), "run " + (dir / "case.toml").string() + " -q -o " +
                                                                      (dir / "out").string());
  EXPECT_EQ(out.status, 3) << out.err;
  EXPECT_NE(out.err.find("strong coupling did not converge in 3 sub-iterations"), std::string::npos) << out.err;
  EXPECT_NE(out.err.find("tried 3 times, the structure finer each time, at most 1 a try "
                         "(numerics.max_coupling_iterations)"),
            std::string::npos)
      << out.err;
}
