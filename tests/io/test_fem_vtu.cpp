// fem.vtu as ParaView reads it: written by io::write_fem_vtu, read back
// with VTK's own XML reader.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "fem/load_cases.hpp"
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
  io::write_fem_vtu(dir / "fem.vtu", model.mesh, 0.0, modes, st);

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
  // Values survive the round trip: uz of mode 1 at the last node.
  const int last = model.mesh.num_nodes() - 1;
  EXPECT_NEAR(m1->GetComponent(last, 2), modes.shapes(fem::dof_index(last, fem::UZ), 0),
              1e-12 * modes.shapes.col(0).cwiseAbs().maxCoeff());
  for (const char* name : {"mode_03", "static_tip_force_le", "static_tip_force_te", "static_tip_moment",
                           "static_tip_torque", "static_tip_torque_rotation", "clamped"})
    EXPECT_NE(g->GetPointData()->GetArray(name), nullptr) << name;
}

}  // namespace
}  // namespace flapsim
