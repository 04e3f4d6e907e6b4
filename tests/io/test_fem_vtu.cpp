// fem.vtu as ParaView reads it: written by pipeline::write_fem_vtu, read back
// with VTK's own XML reader; also the `flapsim modes` and `flapsim mesh`
// commands end to end (outputs and exit status on bad input).

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
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
#include "pipeline/fem_output/fem_vtk.hpp"

namespace flapsim {
namespace {

namespace fs = std::filesystem;

fs::path scratch_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("flapsim_fem_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

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
  std::vector<pipeline::StaticResult> st;
  for (auto& lc : fem::tip_load_cases(model.mesh, fem::tip_station(model.mesh)))
    st.push_back({lc, statics.solve(lc.loads)});
  const fs::path dir = scratch_dir("vtu");
  pipeline::write_fem_vtu(dir / "fem.vtu", model.mesh, 0.0, modes, st);

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
  fs::remove_all(dir);
}

int run(const std::string& cmd) {
  const int status = std::system((cmd + " > /dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(FemCommands, MeshAndModesWriteTheirFiles) {
  const fs::path dir = scratch_dir("cli");
  const std::string wing = std::string(FLAPSIM_SOURCE_DIR) + "/wings/flat_plate.toml";
  ASSERT_EQ(run(std::string(FLAPSIM_BINARY) + " mesh " + wing + " -o " + dir.string()), 0);
  EXPECT_TRUE(fs::exists(dir / "mesh.msh"));
  EXPECT_TRUE(fs::exists(dir / "mesh.vtu"));
  ASSERT_EQ(run(std::string(FLAPSIM_BINARY) + " modes " + wing + " -o " + dir.string() + " --modes 4"), 0);
  std::ifstream csv(dir / "modes.csv");
  std::string header, first;
  std::getline(csv, header);
  std::getline(csv, first);
  EXPECT_EQ(header, "mode,frequency_hz,kind");
  EXPECT_EQ(first.substr(0, 2), "1,");
  EXPECT_TRUE(fs::exists(dir / "fem.vtu"));
  // Bad input: exit status 2 and nothing written.
  const fs::path bad = dir / "bad";
  EXPECT_EQ(run(std::string(FLAPSIM_BINARY) + " modes " + wing + " -o " + bad.string() + " --modes 0"), 2);
  EXPECT_EQ(run(std::string(FLAPSIM_BINARY) + " mesh " + (dir / "missing.toml").string() + " -o " + bad.string()), 2);
  EXPECT_FALSE(fs::exists(bad / "modes.csv"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace flapsim
