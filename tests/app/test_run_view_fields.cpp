// The fields a run's ParaView files carry for colouring and plotting (docs/output_files.md),
// read back with VTK and checked against their definitions and history.csv: the wing's
// pressure-jump coefficient Cp = Δp / (½ ρ U_ref²) and displacement from the rigid wing,
// the wake's age, the frames' loads, the chain's joint angles and spring moments, and the
// tip's and markers' paths. Short runs of the 40 mm × 10 mm plate (wings/flat_plate.toml).
#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/stiff_plate_wing.hpp"
#include "app/history_csv.hpp"
#include "app/one_joint_chain.hpp"
#include "app/robustness_helpers.hpp"
#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace run_view_fields {

namespace fs = std::filesystem;
using flapsim::test::ScratchDir;

constexpr int kChordwise = 4, kSpanwise = 4, kStepsPerCycle = 12;
constexpr double kDensity = 1.225;  // [kg/m³], the case's [air] density

// The plate (wings/flat_plate.toml unless `wing` says otherwise) flapping with eq. 8 (50°
// sweep amplitude) for one cycle of 12 steps, frames every 4 steps. Uniform chordwise
// spacing over the chord x = 2.5 … −7.5 mm puts the lattice nodes i = 1 on x = 0, the
// chain's axis. `top`: top-level keys; `numerics`: more [numerics] keys; `tables`: the
// [structure] table and more.
std::string plate_case(const std::string& top, const std::string& tables, const std::string& numerics = "",
                       const std::string& wing = FLAPSIM_SOURCE_DIR "/wings/flat_plate.toml") {
  std::ostringstream s;
  s << "name = \"plate\"\nwing = \"" << wing << "\"\n" << top
    << "[kinematics]\nfrequency_hz = 26.1\nsweep = { mean_deg = 10.0, cos_deg = [50.0] }\n"
    << "rotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n[air]\ndensity = " << kDensity << "\n"
    << "[numerics]\nsteps_per_cycle = " << kStepsPerCycle << "\ncycles = 1\nchordwise_panels = " << kChordwise
    << "\nspanwise_panels = " << kSpanwise << "\nspacing = \"uniform\"\ncore_radius = 0.2\n" << numerics
    << "[output]\nvtk_every = 4\n"
    << tables;
  return s.str();
}

// Runs a case text in DIR/NAME.toml into DIR/NAME.
fs::path run_case(const ScratchDir& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / (name + ".toml")) << text;
  EXPECT_EQ(flapsim::test::run_flapsim("run " + (dir / (name + ".toml")).string() + " -q -o " +
                                       (dir / name).string()),
            0)
      << name;
  return dir / name;
}

vtkSmartPointer<vtkPolyData> read_frame(const fs::path& file) {
  EXPECT_TRUE(fs::exists(file)) << file;
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  return reader->GetOutput();
}

double cell_value(vtkPolyData* d, const char* name, vtkIdType cell, int component = 0) {
  vtkDataArray* a = d->GetCellData()->GetArray(name);
  EXPECT_NE(a, nullptr) << name;
  return a ? a->GetComponent(cell, component) : NAN;
}

Eigen::Vector3d point_vector(vtkPolyData* d, const char* name, vtkIdType point) {
  vtkDataArray* a = d->GetPointData()->GetArray(name);
  EXPECT_NE(a, nullptr) << name;
  if (!a) return Eigen::Vector3d::Constant(NAN);
  return {a->GetComponent(point, 0), a->GetComponent(point, 1), a->GetComponent(point, 2)};
}

double field_value(vtkPolyData* d, const char* name) {
  vtkDataArray* a = vtkDataArray::SafeDownCast(d->GetFieldData()->GetAbstractArray(name));
  EXPECT_NE(a, nullptr) << name;
  return a ? a->GetComponent(0, 0) : NAN;
}

Eigen::Vector3d point(vtkPolyData* d, vtkIdType k) {
  double p[3];
  d->GetPoint(k, p);
  return {p[0], p[1], p[2]};
}

TEST(RunViewFields, TheRigidPlatesCpDisplacementWakeAgeAndFrameLoads) {
  ScratchDir dir("run_view_fields_rigid");
  const fs::path out = run_case(dir, "rigid", plate_case("", "[structure]\nkind = \"rigid\"\n"));
  const std::string summary = flapsim::test::read_text(out / "summary.json");
  const double u_ref = flapsim::test::json_number(summary, "reference_speed_m_s");
  const double area = flapsim::test::json_number(summary, "reference_area_m2");
  const double dt = flapsim::test::json_number(summary, "dt_s");
  const flapsim::test::HistoryCsv h = flapsim::test::read_history_csv(out / "history.csv");
  const long step = 8;

  // Cp = Δp / q_ref with q_ref = ½ ρ U_ref², the dynamic pressure of CL = L / (q_ref S)
  // (docs/fsi.md, "Coefficients"): every panel, and the frame's CL by the same q_ref.
  const auto wing = read_frame(out / "vtk" / "wing_000008.vtp");
  const double q_ref = 0.5 * kDensity * u_ref * u_ref;
  ASSERT_EQ(wing->GetNumberOfCells(), kChordwise * kSpanwise);
  for (vtkIdType k = 0; k < wing->GetNumberOfCells(); ++k)
    EXPECT_NEAR(cell_value(wing, "Cp", k), cell_value(wing, "pressure_jump_Pa", k) / q_ref,
                1e-12 * std::abs(cell_value(wing, "pressure_jump_Pa", k) / q_ref))
        << "panel " << k;
  EXPECT_GT(std::abs(cell_value(wing, "Cp", 3)), 0.1);  // a loaded panel (the leading edge's)
  EXPECT_NEAR(field_value(wing, "CL"), field_value(wing, "lift_N") / (q_ref * area),
              1e-12 * std::abs(field_value(wing, "CL")));

  // force_N is each panel's whole force, the leading-edge row's suction included
  // (docs/fsi.md, "The fields to colour by"): the cells' forces sum to the frame's lift (+z_G
  // in a hover), and pressure_jump_Pa is their normal part per area.
  double lift_of_cells = 0.0;
  for (vtkIdType k = 0; k < wing->GetNumberOfCells(); ++k) lift_of_cells += cell_value(wing, "force_N", k, 2);
  EXPECT_NEAR(lift_of_cells, field_value(wing, "lift_N"), 1e-9 * std::abs(field_value(wing, "lift_N")));

  // The frame's loads are history.csv's of the same step (the same doubles, written in
  // shortest round-trip form there).
  for (const auto& [field, column] : {std::pair{"lift_N", "lift_N"}, {"CL", "CL"}, {"drag_N", "drag_N"},
                                      {"CD", "CD"}, {"power_W", "power_W"}, {"drive_power_W", "drive_power_W"}})
    EXPECT_EQ(field_value(wing, field), h.at(step, column)) << field;

  // A rigid wing is where the rigid wing is: displacement 0 (to round-off) in every frame.
  for (const char* f : {"wing_000000.vtp", "wing_000004.vtp", "wing_000008.vtp", "wing_000012.vtp"}) {
    const auto w = read_frame(out / "vtk" / f);
    for (vtkIdType p = 0; p < w->GetNumberOfPoints(); ++p)
      EXPECT_LT(point_vector(w, "displacement_m", p).norm(), 1e-15) << f << " point " << p;
  }

  // Wake age: one node row leaves the trailing edge per step (uvlm::advance) and the frame is
  // written before the step's row is shed, so after step n the rows' ages are (n − 1) dt …
  // dt, 0 (the row on the edge), and a ring's is the mean of its two rows': the newest ring
  // dt/2, the oldest (n − 3/2) dt.
  const auto wake = read_frame(out / "vtk" / "wake_000008.vtp");
  const vtkIdType rings = wake->GetNumberOfCells();
  ASSERT_EQ(rings, (step - 1) * kSpanwise);
  vtkDataArray* point_age = wake->GetPointData()->GetArray("age_s");
  ASSERT_NE(point_age, nullptr);
  EXPECT_NEAR(point_age->GetRange()[1], (step - 1) * dt, 1e-12 * dt);
  EXPECT_NEAR(point_age->GetTuple1(wake->GetNumberOfPoints() - 1), 0.0, 1e-15);
  EXPECT_NEAR(cell_value(wake, "age_s", rings - 1), 0.5 * dt, 1e-12 * dt);
  EXPECT_NEAR(cell_value(wake, "age_s", 0), (step - 1.5) * dt, 1e-12 * dt);

  // The tip path: t = 0 and every step; the tip of the rigid wing (its chain's end, 40 mm
  // out along the span) stays 40 mm from the pivot and, with neither deviation nor a tilted
  // stroke plane, in the plane z = 0.
  const auto path = read_frame(out / "tip_path.vtp");
  ASSERT_EQ(path->GetNumberOfPoints(), kStepsPerCycle + 1);
  EXPECT_EQ(path->GetNumberOfLines(), 1);
  vtkDataArray* t = path->GetPointData()->GetArray("t_s");
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->GetTuple1(kStepsPerCycle), h.at(kStepsPerCycle, "t_s"));
  for (vtkIdType k = 0; k < path->GetNumberOfPoints(); ++k) {
    EXPECT_NEAR(point(path, k).norm(), 0.040, 1e-12) << k;
    EXPECT_NEAR(point(path, k).z(), 0.0, 1e-15) << k;
  }
  EXPECT_NE(flapsim::test::read_text(out / "flapsim_outputs.toml").find("tip_path.vtp"), std::string::npos);
}

TEST(RunViewFields, TheFlexiblePlatesJointsTipPathAndDisplacementAgreeWithItsHistory) {
  // Two 20 mm bodies with a bend and a twist spring of 1e-3 N m/rad at y = 20 mm
  // (app/one_joint_chain.hpp); the marker "tip" on the chain's end, body 2's outboard joint.
  ScratchDir dir("run_view_fields_flexible");
  std::ofstream(dir / "chain.toml") << flapsim::test::kOneJointChain;
  const fs::path rigid = run_case(dir, "rigid", plate_case("", "[structure]\nkind = \"rigid\"\n"));
  const fs::path out = run_case(dir, "flexible",
                                plate_case("chain = \"chain.toml\"\n", "[structure]\nkind = \"flexible\"\nbodies = 2\n"
                                           "[[markers]]\nname = \"tip\"\nbody = 2\npoint = [0.0, 0.02, 0.0]\n"));
  const flapsim::test::HistoryCsv h = flapsim::test::read_history_csv(out / "history.csv");
  const long step = 8;

  // chain.vtp: body 2's joint angles are history.csv's bend_2_rad, twist_2_rad, on its
  // joint line (cell 1) and its centre-of-mass line (cell 3); its spring moments k Φ with
  // the chain file's k = 1e-3 N m/rad (rest angles 0); body 1 is welded: zeros.
  const auto chain = read_frame(out / "vtk" / "chain_000008.vtp");
  ASSERT_EQ(chain->GetNumberOfCells(), 4);
  const double bend = h.at(step, "bend_2_rad"), twist = h.at(step, "twist_2_rad");
  EXPECT_GT(std::abs(bend), 1e-4);  // the air bends the plate
  for (vtkIdType cell : {1, 3}) {
    EXPECT_EQ(cell_value(chain, "bend_rad", cell), bend);
    EXPECT_EQ(cell_value(chain, "twist_rad", cell), twist);
    EXPECT_NEAR(cell_value(chain, "bend_moment_Nm", cell), 1e-3 * bend, 1e-15);
    EXPECT_NEAR(cell_value(chain, "twist_moment_Nm", cell), 1e-3 * twist, 1e-15);
  }
  for (const char* f : {"bend_rad", "twist_rad", "bend_moment_Nm", "twist_moment_Nm"})
    EXPECT_EQ(cell_value(chain, f, 0), 0.0) << f;

  // The tip path ends where history.csv's tip marker ends (the same point of the same body);
  // the marker's own path likewise.
  const auto path = read_frame(out / "tip_path.vtp");
  ASSERT_EQ(path->GetNumberOfPoints(), kStepsPerCycle + 1);
  const Eigen::Vector3d marker_end(h.at(kStepsPerCycle, "tip_x_m"), h.at(kStepsPerCycle, "tip_y_m"),
                                   h.at(kStepsPerCycle, "tip_z_m"));
  EXPECT_LT((point(path, kStepsPerCycle) - marker_end).norm(), 1e-15);
  const auto marker_path = read_frame(out / "marker_1_path.vtp");
  ASSERT_EQ(marker_path->GetNumberOfPoints(), kStepsPerCycle + 1);
  EXPECT_LT((point(marker_path, kStepsPerCycle) - marker_end).norm(), 1e-15);
  auto* name = vtkStringArray::SafeDownCast(marker_path->GetFieldData()->GetAbstractArray("point"));
  ASSERT_NE(name, nullptr);
  EXPECT_EQ(name->GetValue(0), "tip");

  // displacement_m of the lattice node on the chain's end (i = 1 at x = 0, the tip row):
  // the marker's position (history.csv) minus where the rigid wing's chain end is at that
  // time (the rigid run's tip path, the same base motion). The lattice is solved on the
  // coupling's last iterate, the history on the accepted state: they differ by the coupling
  // tolerance (1e-6 rad × 20 mm).
  const auto wing = read_frame(out / "vtk" / "wing_000008.vtp");
  const vtkIdType tip_node = 1 + (kChordwise + 1) * kSpanwise;
  const Eigen::Vector3d marker(h.at(step, "tip_x_m"), h.at(step, "tip_y_m"), h.at(step, "tip_z_m"));
  const Eigen::Vector3d expected = marker - point(read_frame(rigid / "tip_path.vtp"), step);
  const Eigen::Vector3d displacement = point_vector(wing, "displacement_m", tip_node);
  EXPECT_GT(expected.norm(), 1e-5);
  EXPECT_LT((displacement - expected).norm(), 1e-7) << displacement.transpose() << " / " << expected.transpose();
  // At t = 0 the chain is at its rest angles: the wing is the rigid wing.
  const auto start = read_frame(out / "vtk" / "wing_000000.vtp");
  for (vtkIdType p = 0; p < start->GetNumberOfPoints(); ++p)
    EXPECT_LT(point_vector(start, "displacement_m", p).norm(), 1e-15) << p;
}


TEST(RunViewFields, TheFemPlatesDisplacementAndTipAreItsFramesNodes) {
  ScratchDir dir("run_view_fields_fem");
  std::ofstream(dir / "wing.toml") << flapsim::test::kStiffPlateWing;
  const fs::path rigid = run_case(dir, "rigid", plate_case("", "[structure]\nkind = \"rigid\"\n", "", "wing.toml"));
  const fs::path out =
      run_case(dir, "fem", plate_case("", "[structure]\nkind = \"fem\"\n", "rho_infinity = 0.0\n", "wing.toml"));

  // displacement_m of the lattice nodes on the tip edge (i = 0, 1, 4: x = 2.5, 0, −7.5 mm,
  // each on a mesh node) against fem.vtp's displacement_m of that mesh node, found by its
  // rigid position x − d (io::fem_frame_mesh: x − (p + Q X), another route to the rigid wing).
  // The lattice rides on the coupling's last iterate, fem.vtp shows the FEM's answer: apart by
  // at most the coupling tolerance τ L = 1e-6 × 40 mm.
  for (const char* frame : {"000000", "000008"}) {
    const auto wing = read_frame(out / "vtk" / ("wing_" + std::string(frame) + ".vtp"));
    const auto fem = read_frame(out / "vtk" / ("fem_" + std::string(frame) + ".vtp"));
    for (const vtkIdType i : {0, 1, 4}) {
      const vtkIdType node = i + (kChordwise + 1) * kSpanwise;
      const Eigen::Vector3d d = point_vector(wing, "displacement_m", node);
      const Eigen::Vector3d rigid_position = point(wing, node) - d;
      vtkIdType nearest = -1;
      double distance = 1.0;
      for (vtkIdType k = 0; k < fem->GetNumberOfPoints(); ++k) {
        const double r = (point(fem, k) - point_vector(fem, "displacement_m", k) - rigid_position).norm();
        if (r < distance) {
          distance = r;
          nearest = k;
        }
      }
      ASSERT_LT(distance, 1e-12) << frame << " node " << node;  // the lattice node is that mesh node
      EXPECT_LT((d - point_vector(fem, "displacement_m", nearest)).norm(), 4e-8) << frame << " node " << node;
      if (std::string(frame) == "000000") EXPECT_LT(d.norm(), 1e-15);  // at rest relative to the base at t = 0
      else EXPECT_GT(d.norm(), 1e-6);                                   // the air and the inertia bend it
    }
  }

  // The FEM's tip: the mesh node at (0, 40 mm, 0), where the rigid run's chain ends: its
  // rigid position (x − d in the last fem.vtp) is the rigid run's last tip point.
  const auto path = read_frame(out / "tip_path.vtp");
  ASSERT_EQ(path->GetNumberOfPoints(), kStepsPerCycle + 1);
  const Eigen::Vector3d tip = point(path, kStepsPerCycle);
  const auto fem = read_frame(out / "vtk" / "fem_000012.vtp");
  vtkIdType at = -1;
  for (vtkIdType k = 0; k < fem->GetNumberOfPoints(); ++k)
    if ((point(fem, k) - tip).norm() < 1e-15) at = k;
  ASSERT_GE(at, 0) << "the tip is a node of the last fem.vtp";
  const Eigen::Vector3d rigid_tip = point(read_frame(rigid / "tip_path.vtp"), kStepsPerCycle);
  EXPECT_LT((point(fem, at) - point_vector(fem, "displacement_m", at) - rigid_tip).norm(), 1e-12);
}

TEST(RunViewFields, ARunThatStopsWithExitStatusThreeLeavesTheTipPathSoFar) {
  // The diverging two-body chain of app.ExitStatus.ThreeForANumericalFailureOfTheRun: the
  // path is written at the failure, atomically, through the last completed step.
  ScratchDir dir("run_view_fields_failed");
  std::ofstream(dir / "chain.toml") << flapsim::test::kDivergingTwoBodyChain;
  std::ofstream(dir / "case.toml") << flapsim::test::replace_once(
      flapsim::test::small_plate_case("flexible", 40, 1), "steps_per_cycle = 24", "steps_per_cycle = 4");
  ASSERT_EQ(flapsim::test::run_flapsim("run " + (dir / "case.toml").string() + " --chain " +
                                       (dir / "chain.toml").string() + " -o " + (dir / "out").string()),
            3);
  const flapsim::test::HistoryCsv h = flapsim::test::read_history_csv(dir / "out" / "history.csv");
  ASSERT_GE(h.rows.size(), 1u);
  const auto path = read_frame(dir / "out" / "tip_path.vtp");
  const long steps = static_cast<long>(h.rows.size());
  ASSERT_EQ(path->GetNumberOfPoints(), steps + 1);  // t = 0 and every recorded step
  EXPECT_EQ(path->GetPointData()->GetArray("t_s")->GetTuple1(steps), h.at(steps, "t_s"));
  EXPECT_TRUE(dir.temporaries().empty());
}

}  // namespace run_view_fields
