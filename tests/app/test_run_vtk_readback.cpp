// The ParaView series a `flapsim run` writes (wing.pvd, wake.pvd) read back with VTK's own
// XML parser and readers: every listed file opens, the wing has one cell per lattice panel
// carrying circulation and pressure, and the wake grows by one row of panels per step.
#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPolyDataReader.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace fs = std::filesystem;

namespace {

struct SeriesEntry {
  double time;
  fs::path file;  // as ParaView resolves it: relative to the .pvd's folder
};

// The DataSet entries of a .pvd collection, parsed by VTK.
std::vector<SeriesEntry> read_pvd(const fs::path& pvd) {
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(pvd.c_str());
  EXPECT_EQ(parser->Parse(), 1) << pvd;
  std::vector<SeriesEntry> entries;
  vtkXMLDataElement* collection = parser->GetRootElement()->FindNestedElementWithName("Collection");
  if (!collection) return entries;
  for (int k = 0; k < collection->GetNumberOfNestedElements(); ++k) {
    vtkXMLDataElement* ds = collection->GetNestedElement(k);
    double t = -1;
    ds->GetScalarAttribute("timestep", t);
    entries.push_back({t, pvd.parent_path() / ds->GetAttribute("file")});
  }
  return entries;
}

vtkSmartPointer<vtkPolyData> read_vtp(const fs::path& file) {
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  return reader->GetOutput();
}

TEST(RunVtkOutput, WingAndWakeSeriesReadBackWithVtkReaders) {
  flapsim::test::ScratchDir dir("run_vtk_readback");
  const int nc = 3, ns = 4, steps = 12, every = 4;
  std::ofstream(dir / "case.toml")
      << "name = \"plate\"\nwing = \"" << FLAPSIM_SOURCE_DIR << "/wings/flat_plate.toml\"\n"
      << "[kinematics]\nfrequency_hz = 26.1\n"
      << "sweep = { mean_deg = 10.0, cos_deg = [50.0] }\n"
      << "rotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
      << "[structure]\nkind = \"rigid\"\n"
      << "[numerics]\nsteps_per_cycle = " << steps << "\ncycles = 1\nchordwise_panels = " << nc
      << "\nspanwise_panels = " << ns << "\ncore_radius = 0.2\n[output]\nvtk_every = " << every << "\n";
  ASSERT_EQ(flapsim::test::run_flapsim("run " + (dir / "case.toml").string() + " -o " + (dir / "out").string()), 0);

  const auto wing = read_pvd(dir / "out" / "wing.pvd");
  ASSERT_GE(wing.size(), 2u);
  for (const SeriesEntry& e : wing) {
    auto data = read_vtp(e.file);
    ASSERT_EQ(data->GetNumberOfCells(), nc * ns) << e.file;  // one quad per panel
    EXPECT_NE(data->GetCellData()->GetArray("circulation_m2_s"), nullptr);
    EXPECT_NE(data->GetCellData()->GetArray("pressure_jump_Pa"), nullptr);
  }
  const auto wake = read_pvd(dir / "out" / "wake.pvd");
  ASSERT_EQ(wake.size(), wing.size());
  vtkIdType previous = -1;
  for (const SeriesEntry& e : wake) {
    auto data = read_vtp(e.file);
    EXPECT_NE(data->GetCellData()->GetArray("circulation_m2_s"), nullptr);
    // One row of ns wake panels shed per step: the wake only grows.
    EXPECT_EQ(data->GetNumberOfCells() % ns, 0) << e.file;
    EXPECT_GT(data->GetNumberOfCells(), previous) << e.file;
    previous = data->GetNumberOfCells();
  }
  EXPECT_TRUE(dir.temporaries().empty());
}

}  // namespace
