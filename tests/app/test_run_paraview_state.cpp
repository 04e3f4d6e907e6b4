// What a run leaves for ParaView beyond the series: run.pvsm, a state file whose every
// file name exists relative to it (parsed with VTK's XML parser), and on every frame the
// field data t_over_T, lift_N and CL, starting with a t = 0 frame; lift_N equals
// history.csv's lift at the same step.
#include <gtest/gtest.h>

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPolyDataReader.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace fs = std::filesystem;

namespace {

// Every <Element value> of every <Property name="FileName"> in the state (the readers' files).
std::vector<std::string> state_file_names(vtkXMLDataElement* e) {
  std::vector<std::string> names;
  std::function<void(vtkXMLDataElement*)> visit = [&](vtkXMLDataElement* x) {
    if (std::string(x->GetName()) == "Property" && x->GetAttribute("name") &&
        std::string(x->GetAttribute("name")) == "FileName")
      for (int k = 0; k < x->GetNumberOfNestedElements(); ++k)
        if (const char* v = x->GetNestedElement(k)->GetAttribute("value")) names.emplace_back(v);
    for (int k = 0; k < x->GetNumberOfNestedElements(); ++k) visit(x->GetNestedElement(k));
  };
  visit(e);
  return names;
}

std::vector<std::pair<double, std::string>> pvd_entries(const fs::path& pvd) {
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(pvd.c_str());
  EXPECT_EQ(parser->Parse(), 1) << pvd;
  std::vector<std::pair<double, std::string>> out;
  vtkXMLDataElement* c = parser->GetRootElement()->FindNestedElementWithName("Collection");
  for (int k = 0; c && k < c->GetNumberOfNestedElements(); ++k) {
    double t = -1;
    c->GetNestedElement(k)->GetScalarAttribute("timestep", t);
    out.emplace_back(t, c->GetNestedElement(k)->GetAttribute("file"));
  }
  return out;
}

double field(vtkPolyData* data, const char* name) {
  vtkDataArray* a = data->GetFieldData()->GetArray(name);
  EXPECT_NE(a, nullptr) << name;
  return a ? a->GetTuple1(0) : std::nan("");
}

// history.csv as rows of numbers under its header.
std::vector<std::vector<double>> read_history(const fs::path& csv, std::vector<std::string>& header) {
  std::ifstream in(csv);
  std::string line, cell;
  std::getline(in, line);
  std::stringstream h(line);
  while (std::getline(h, cell, ',')) header.push_back(cell);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::stringstream r(line);
    rows.emplace_back();
    while (std::getline(r, cell, ',')) rows.back().push_back(std::stod(cell));
  }
  return rows;
}

TEST(RunParaViewState, StateNamesExistingFilesAndFramesCarryLiftAndPhase) {
  flapsim::test::ScratchDir dir("run_pvsm");
  const double f = 26.1;
  std::ofstream(dir / "case.toml")
      << "name = \"plate\"\nwing = \"" << FLAPSIM_SOURCE_DIR << "/wings/flat_plate.toml\"\n"
      << "[kinematics]\nfrequency_hz = " << f << "\n"
      << "sweep = { mean_deg = 10.0, cos_deg = [50.0] }\n"
      << "rotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
      << "[structure]\nkind = \"rigid\"\n"
      << "[numerics]\nsteps_per_cycle = 12\ncycles = 1\nchordwise_panels = 3\nspanwise_panels = 4\n"
      << "core_radius = 0.2\n[output]\nvtk_every = 4\n";
  ASSERT_EQ(flapsim::test::run_flapsim("run " + (dir / "case.toml").string() + " -o " + (dir / "out").string()), 0);

  // The state: well-formed XML whose reader files all exist relative to it.
  const fs::path state = dir / "out" / "run.pvsm";
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(state.c_str());
  ASSERT_EQ(parser->Parse(), 1);
  ASSERT_STREQ(parser->GetRootElement()->GetName(), "ParaView");
  const auto names = state_file_names(parser->GetRootElement());
  ASSERT_EQ(names.size(), 3u);  // wing, wake, chain
  for (const std::string& n : names) {
    EXPECT_TRUE(fs::path(n).is_relative()) << n;
    EXPECT_TRUE(fs::is_regular_file(state.parent_path() / n)) << n;
    for (const auto& [t, file] : pvd_entries(state.parent_path() / n))
      EXPECT_TRUE(fs::is_regular_file(state.parent_path() / fs::path(n).parent_path() / file)) << file;
  }

  // Frames at t = 0 (before the first step) and every 4 steps: t/T = f t, lift and CL
  // as field data, lift equal to history.csv's at the same step.
  std::vector<std::string> header;
  const auto rows = read_history(dir / "out" / "history.csv", header);
  const auto column = [&](const std::string& name) {
    for (std::size_t k = 0; k < header.size(); ++k)
      if (header[k] == name) return k;
    ADD_FAILURE() << "no column " << name;
    return std::size_t{0};
  };
  const auto wing = pvd_entries(dir / "out" / "wing.pvd");
  ASSERT_EQ(wing.size(), 4u);  // steps 0, 4, 8, 12
  // The state opens at the frame nearest phase 0.25 (step 4, t/T 0.33), not at t = 0
  // (a wing without loads, no wake: the first thing ParaView showed).
  const std::string xml = flapsim::test::read_text(state);
  const auto keeper = xml.find("id=\"256.Time\"");
  ASSERT_NE(keeper, std::string::npos);
  const auto value = xml.find("value=\"", keeper) + 7;
  EXPECT_EQ(std::stod(xml.substr(value, xml.find('"', value) - value)), wing[1].first);
  EXPECT_EQ(wing[0].first, 0.0);
  for (std::size_t k = 0; k < wing.size(); ++k) {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName((dir / "out" / wing[k].second).c_str());
    reader->Update();
    vtkPolyData* data = reader->GetOutput();
    ASSERT_EQ(data->GetNumberOfCells(), 12) << wing[k].second;  // the lattice, also at t = 0
    const double step = field(data, "step");
    EXPECT_EQ(step, 4.0 * k);
    EXPECT_NEAR(field(data, "t_over_T"), f * wing[k].first, 1e-12);
    EXPECT_EQ(field(data, "TimeValue"), wing[k].first);
    if (k == 0) {
      EXPECT_EQ(field(data, "lift_N"), 0.0);  // no loads before the first solve
      continue;
    }
    const auto& row = rows.at(static_cast<std::size_t>(step) - 1);  // history starts at step 1
    EXPECT_DOUBLE_EQ(row[column("t_s")], wing[k].first);
    EXPECT_DOUBLE_EQ(field(data, "lift_N"), row[column("lift_N")]);
    EXPECT_DOUBLE_EQ(field(data, "CL"), row[column("CL")]);
  }
}

}  // namespace
