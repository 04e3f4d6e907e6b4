// fem.vtu as ParaView reads it: written by io::write_fem_vtu, read back
// with VTK's own XML reader.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkStringArray.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "fem/load_cases.hpp"
#include "fem/mode_classification.hpp"
#include "fem/static_solver.hpp"
#include "fem/structured_mesh.hpp"
#include "fem/structural_model.hpp"
#include "fem/wing_fem.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/io/fem_vtk.hpp"

namespace flapsim {
namespace {

TEST(FemVtu, ModeShapesAndStaticCasesReadBackWithVtk) {
  // A cantilever plate 10 × 40 mm (clamped at y = 0).
  fem::StructuralModel model;
  model.mesh = fem::rectangle_mesh(-5e-3, 0.0, 10e-3, 40e-3, 4, 16);
  fem::ShellProperties s;
  s.thickness = 0.2e-3;
  s.youngs_modulus = 4e9;
  s.density = 1390.0;
  model.shell.assign(model.mesh.triangles.size(), s);
  const auto sys = fem::assemble(model);
  const fem::Constraints c = fem::root_clamp(model.mesh, 0.0);
  fem::ModalOptions opt;
  opt.num_modes = 3;
  const fem::ModalResult modes = fem::solve_modes(sys.stiffness, sys.mass, c, opt);
  const fem::StaticSolver statics(sys.stiffness, c);
  std::vector<io::StaticResult> st;
  for (auto& lc : fem::tip_load_cases(model.mesh, fem::tip_station(model.mesh)))
    st.push_back({lc, statics.solve(lc.loads)});
  const test::ScratchDir dir("fem_vtu");
  const auto kinds = fem::classify_modes(model.mesh, sys, modes.shapes, modes.frequencies_hz);
  std::vector<io::ModeLabel> labels;
  for (const auto k : kinds) labels.push_back({fem::to_string(k), 1.0, fem::to_string(k)});
  io::write_fem_vtu(dir / "fem.vtu", model.mesh, 0.0, modes, labels, st);

  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName((dir / "fem.vtu").c_str());
  reader->Update();
  vtkUnstructuredGrid* g = reader->GetOutput();
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->GetNumberOfPoints(), model.mesh.num_nodes());
  EXPECT_EQ(g->GetNumberOfCells(), static_cast<vtkIdType>(model.mesh.triangles.size()));
  vtkDataArray* m1 = g->GetPointData()->GetArray("mode_01");
  ASSERT_NE(m1, nullptr);
  ASSERT_EQ(m1->GetNumberOfComponents(), 3);
  vtkFieldData* fd = g->GetFieldData();
  const double span = 40e-3;  // the plate reaches y = 40 mm
  ASSERT_NE(fd->GetArray("span_m"), nullptr);
  EXPECT_DOUBLE_EQ(fd->GetArray("span_m")->GetTuple1(0), span);
  // Each mode: its frequency and kind as field data, and a shape scaled so that
  // ParaView's Warp By Vector at scale 1 moves no node more than 20 % of the span
  // (the writer aims at io::kModeViewFraction = 10 %).
  for (int k = 0; k < 3; ++k) {
    const std::string name = "mode_0" + std::to_string(k + 1);
    vtkDataArray* m = g->GetPointData()->GetArray(name.c_str());
    ASSERT_NE(m, nullptr) << name;
    double largest = 0.0;
    for (vtkIdType i = 0; i < m->GetNumberOfTuples(); ++i) {
      double v[3];
      m->GetTuple(i, v);
      largest = std::max(largest, std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
    }
    EXPECT_LE(largest, 0.2 * span) << name;
    EXPECT_NEAR(largest, io::kModeViewFraction * span, 1e-12 * span) << name;
    vtkDataArray* f = fd->GetArray((name + "_frequency_Hz").c_str());
    ASSERT_NE(f, nullptr) << name;
    EXPECT_DOUBLE_EQ(f->GetTuple1(0), modes.frequencies_hz(k));
    auto* kind = vtkStringArray::SafeDownCast(fd->GetAbstractArray((name + "_kind").c_str()));
    ASSERT_NE(kind, nullptr) << name;
    EXPECT_EQ(kind->GetValue(0), fem::to_string(kinds[static_cast<std::size_t>(k)]));
    // The stored shape is the mass-normalised one times the stored scale.
    vtkDataArray* scale = fd->GetArray((name + "_scale").c_str());
    ASSERT_NE(scale, nullptr) << name;
    const int last = model.mesh.num_nodes() - 1;
    EXPECT_NEAR(m->GetComponent(last, 2), scale->GetTuple1(0) * modes.shapes(fem::dof_index(last, fem::UZ), k),
                1e-12 * span)
        << name;
  }
  // The first mode of a clamped plate strip is its first bending mode (Leissa).
  EXPECT_EQ(vtkStringArray::SafeDownCast(fd->GetAbstractArray("mode_01_kind"))->GetValue(0), "bending");
  // Static cases carry the unit of their unit load in their names.
  for (const char* name : {"static_tip_force_le_m_per_N", "static_tip_force_te_m_per_N",
                           "static_tip_moment_m_per_N_m", "static_tip_torque_m_per_N_m",
                           "static_tip_torque_rotation_rad_per_N_m", "clamped"})
    EXPECT_NE(g->GetPointData()->GetArray(name), nullptr) << name;
  EXPECT_NE(fd->GetArray("static_tip_force_le_view_scale"), nullptr);
}

}  // namespace
}  // namespace flapsim
