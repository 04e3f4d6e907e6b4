// `flapsim modes` leaves fem_modes.pvsm next to fem.vtu: a ParaView state that animates
// the --state-mode mode (Warp By Vector on mode_NN, its scale factor swung by a sinusoid
// key frame), names its frequency and kinds in a text (the values fem.vtu's field data
// holds, read back with VTK) and shows a scalar bar for its colours; a mode beyond
// --modes is bad input (exit 2, nothing written).
#include <gtest/gtest.h>

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace {

namespace fs = std::filesystem;

// The state's proxies by id: type and each property's element values or proxy ids.
struct Proxy {
  std::string type;
  std::map<std::string, std::vector<std::string>> properties;
};
std::map<int, Proxy> read_proxies(const fs::path& state) {
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(state.c_str());
  EXPECT_EQ(parser->Parse(), 1);
  std::map<int, Proxy> out;
  std::function<void(vtkXMLDataElement*)> visit = [&](vtkXMLDataElement* e) {
    if (std::string(e->GetName()) == "Proxy" && e->GetAttribute("group")) {
      int id = 0;
      e->GetScalarAttribute("id", id);
      Proxy& p = out[id];
      p.type = e->GetAttribute("type");
      for (int k = 0; k < e->GetNumberOfNestedElements(); ++k) {
        vtkXMLDataElement* prop = e->GetNestedElement(k);
        if (!prop->GetAttribute("name")) continue;  // the layout's <Layout>
        auto& values = p.properties[prop->GetAttribute("name")];
        for (int j = 0; j < prop->GetNumberOfNestedElements(); ++j) {
          const char* v = prop->GetNestedElement(j)->GetAttribute("value");
          values.emplace_back(v ? v : "");  // VTK's parser gives no attribute for value=""
        }
      }
      return;
    }
    for (int k = 0; k < e->GetNumberOfNestedElements(); ++k) visit(e->GetNestedElement(k));
  };
  visit(parser->GetRootElement());
  return out;
}

const Proxy* of_type(const std::map<int, Proxy>& proxies, const std::string& type, int* id = nullptr) {
  for (const auto& [i, p] : proxies)
    if (p.type == type) {
      if (id) *id = i;
      return &p;
    }
  ADD_FAILURE() << "no " << type << " in the state";
  return nullptr;
}

TEST(FemModesState, AnimatesTheChosenModeAndNamesIt) {
  const flapsim::test::ScratchDir scratch("fem_modes_state");
  const fs::path dir = scratch / "out";
  const std::string wing = std::string(FLAPSIM_SOURCE_DIR) + "/wings/flat_plate.toml";
  ASSERT_EQ(flapsim::test::run_flapsim("modes " + wing + " -o " + dir.string() + " --modes 3 --state-mode 2"), 0);
  const auto proxies = read_proxies(dir / "fem_modes.pvsm");

  int reader_id = 0, warp_id = 0;
  const Proxy* reader = of_type(proxies, "XMLUnstructuredGridReader", &reader_id);
  const Proxy* warp = of_type(proxies, "WarpByVector", &warp_id);
  ASSERT_TRUE(reader && warp);
  ASSERT_EQ(reader->properties.at("FileName").at(0), "fem.vtu");  // relative to the state
  EXPECT_EQ(warp->properties.at("Input").at(0), std::to_string(reader_id));
  EXPECT_EQ(warp->properties.at("Vectors").at(4), "mode_02");

  // fem.vtu has the vector and the values the text names.
  vtkNew<vtkXMLUnstructuredGridReader> vtu;
  vtu->SetFileName((dir / "fem.vtu").c_str());
  vtu->Update();
  vtkUnstructuredGrid* grid = vtu->GetOutput();
  ASSERT_NE(grid->GetPointData()->GetArray("mode_02"), nullptr);
  const double f = grid->GetFieldData()->GetArray("mode_02_frequency_Hz")->GetTuple1(0);
  const auto text_field = [&](const char* name) {
    auto* a = vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray(name));
    return a ? a->GetValue(0) : std::string("?");
  };
  char expected[128];
  std::snprintf(expected, sizeof expected, "mode 2: %.2f Hz, %s (shape: %s)", f, text_field("mode_02_kind").c_str(),
                text_field("mode_02_shape_kind").c_str());
  const Proxy* text = of_type(proxies, "TextSource");
  ASSERT_TRUE(text);
  EXPECT_EQ(text->properties.at("Text").at(0).rfind(expected, 0), 0u) << text->properties.at("Text").at(0);

  // The swing: a key-frame cue on the warp's ScaleFactor, sinusoid key frames, played by the scene.
  int cue_id = 0;
  const Proxy* cue = of_type(proxies, "KeyFrameAnimationCue", &cue_id);
  ASSERT_TRUE(cue);
  EXPECT_EQ(cue->properties.at("AnimatedProxy").at(0), std::to_string(warp_id));
  EXPECT_EQ(cue->properties.at("AnimatedPropertyName").at(0), "ScaleFactor");
  for (const std::string& k : cue->properties.at("KeyFrames")) EXPECT_EQ(proxies.at(std::stoi(k)).type, "SinusoidKeyFrame");
  const auto& cues = of_type(proxies, "AnimationScene")->properties.at("Cues");
  EXPECT_NE(std::find(cues.begin(), cues.end(), std::to_string(cue_id)), cues.end());

  // The coloured representation (the warped wing) has a scalar bar of its colour map in the view.
  const auto& shown = of_type(proxies, "RenderView")->properties.at("Representations");
  std::vector<std::string> coloured, bars;
  for (const std::string& id : shown) {
    const Proxy& p = proxies.at(std::stoi(id));
    if (p.type == "GeometryRepresentation" && !p.properties.at("ColorArrayName").at(4).empty())
      coloured.push_back(p.properties.at("LookupTable").at(0));
    if (p.type == "ScalarBarWidgetRepresentation") bars.push_back(p.properties.at("LookupTable").at(0));
  }
  ASSERT_EQ(coloured.size(), 1u);
  EXPECT_EQ(bars, coloured);

  // A mode beyond --modes: a usage error (exit status 1, README), nothing written.
  EXPECT_EQ(flapsim::test::run_flapsim("modes " + wing + " -o " + (scratch / "bad").string() +
                                       " --modes 3 --state-mode 4"),
            1);
  EXPECT_FALSE(fs::exists(scratch / "bad" / "fem_modes.pvsm"));
}

// A mesh too coarse for the modes asked for: the flat plate at 8 mm elements has 19 nodes and
// fewer modes than 500. Before, --state-mode past the modes computed read beyond the results
// (a state animating a mode_96 that fem.vtu lacks, "0.00 Hz", or exit 4 with a garbled
// message). Now a warning says how many there are, and the state animates the last of them.
TEST(FemModesState, AModePastThoseACoarseMeshGivesIsWarnedAndTheLastOneAnimated) {
  const flapsim::test::ScratchDir scratch("fem_modes_state_coarse");
  std::ofstream(scratch / "coarse.toml")
      << "name = \"coarse\"\nlength_unit = \"mm\"\n[planform]\n"
         "outline = [[2.5, 0.0], [2.5, 40.0], [-7.5, 40.0], [-7.5, 0.0]]\nclamp_y = 0.0\n"
         "[materials.pet]\nyoungs_modulus = 4.0e9\npoisson_ratio = 0.38\ndensity = 1390.0\n"
         "[membrane]\nthickness = 0.2\nmaterial = \"pet\"\n[mesh]\nelement_size = 8.0\nvein_element_size = "
         "8.0\n";
  const fs::path dir = scratch / "out";
  const flapsim::test::FlapsimOutcome r = flapsim::test::run_flapsim_capturing_stderr(
      scratch.path(), "modes " + (scratch / "coarse.toml").string() + " -o " + dir.string() +
                          " --modes 500 --state-mode 300");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("not the 500 asked for (--modes)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--state-mode 300 is beyond the"), std::string::npos) << r.err;
  vtkNew<vtkXMLUnstructuredGridReader> vtu;
  vtu->SetFileName((dir / "fem.vtu").c_str());
  vtu->Update();
  int last = 0;
  char name[16];
  for (int k = 1; k <= 500; ++k) {
    std::snprintf(name, sizeof name, "mode_%02d", k);
    if (vtu->GetOutput()->GetPointData()->GetArray(name)) last = k;
  }
  ASSERT_GT(last, 1);
  ASSERT_LT(last, 300);
  std::snprintf(name, sizeof name, "mode_%02d", last);
  const auto proxies = read_proxies(dir / "fem_modes.pvsm");
  const Proxy* warp = of_type(proxies, "WarpByVector");
  ASSERT_TRUE(warp);
  EXPECT_EQ(warp->properties.at("Vectors").at(4), name);
  const Proxy* text = of_type(proxies, "TextSource");
  ASSERT_TRUE(text);
  EXPECT_EQ(text->properties.at("Text").at(0).find("0.00 Hz"), std::string::npos)
      << text->properties.at("Text").at(0);
}

}  // namespace
