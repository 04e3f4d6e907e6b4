// How run.pvsm draws the structure's series (pipeline/io/pvsm_state.hpp, RunState): the
// chain's bars as thick black lines; a FEM's surface mesh (fem.pvd) in air as thin
// translucent lines, so that the wing's colours show through its thousands of edges (drawn
// as the chain's, a 3280-triangle wing's Cp was hidden under black), in vacuum as a grey
// surface with its edges.
#include <gtest/gtest.h>

#include <string>

#include "pipeline/io/pvsm_state.hpp"

namespace io = flapsim::io;

namespace {

// The value of property `name` of the proxy with id `id` in the state's XML ("" if none).
std::string structure_property(const std::string& xml, int id, const std::string& name) {
  const std::string key = "id=\"" + std::to_string(id) + "." + name + "\"";
  const auto at = xml.find(key);
  if (at == std::string::npos) return "";
  const auto value = xml.find("value=\"", at);
  return xml.substr(value + 7, xml.find('"', value + 7) - value - 7);
}

TEST(RunStateStructure, TheChainIsThickBlackLinesAndAFemMeshThinLinesOverTheWingOrASurface) {
  // The front view's representations are ids 2101 …; the structure's is 2103 (pvsm_state.cpp).
  io::RunState chain;
  const std::string bars = io::run_state_xml(chain);
  EXPECT_EQ(structure_property(bars, 2103, "Representation"), "Wireframe");
  EXPECT_EQ(structure_property(bars, 2103, "LineWidth"), "4");
  EXPECT_EQ(structure_property(bars, 2103, "Opacity"), "");  // opaque
  io::RunState fem_in_air;
  fem_in_air.chain_pvd = "fem.pvd";
  fem_in_air.structure_mesh = true;
  const std::string over_wing = io::run_state_xml(fem_in_air);
  EXPECT_EQ(structure_property(over_wing, 2103, "Representation"), "Wireframe");
  EXPECT_EQ(structure_property(over_wing, 2103, "LineWidth"), "1");
  EXPECT_EQ(structure_property(over_wing, 2103, "Opacity"), "0.25");
  EXPECT_EQ(structure_property(over_wing, 2101, "Representation"),
            "Surface With Edges");  // the wing, coloured
  EXPECT_NE(over_wing.find("fem.pvd"), std::string::npos);
  io::RunState fem_in_vacuum = fem_in_air;
  fem_in_vacuum.air = false;
  EXPECT_EQ(structure_property(io::run_state_xml(fem_in_vacuum), 2103, "Representation"), "Surface");
}

// A FEM run in vacuum (cases/vacuum_flapping_fem.toml) showed a grey surface under the
// edges of its 8873 triangles: its 10 mm tip deflection was invisible. Its surface is
// coloured by |displacement_m| (point data, magnitude), white at rest to blue at the
// displacement_range the run measured, with a scalar bar.
TEST(RunStateStructure, AFemInVacuumIsColouredByItsDisplacement) {
  io::RunState fem_in_vacuum;
  fem_in_vacuum.air = false;
  fem_in_vacuum.chain_pvd = "fem.pvd";
  fem_in_vacuum.structure_mesh = true;
  fem_in_vacuum.displacement_range = 0.0125;
  const std::string xml = io::run_state_xml(fem_in_vacuum);
  const auto colour = xml.find("id=\"2103.ColorArrayName\"");
  ASSERT_NE(colour, std::string::npos);
  EXPECT_NE(xml.substr(colour, xml.find("</Property>", colour) - colour).find("value=\"displacement_m\""),
            std::string::npos);
  EXPECT_EQ(structure_property(xml, 3003, "VectorMode"), "0");  // magnitude
  const auto points = xml.find("id=\"3003.RGBPoints\"");
  ASSERT_NE(points, std::string::npos);
  EXPECT_NE(xml.substr(points, xml.find("</Property>", points) - points).find("value=\"0.0125\""),
            std::string::npos);
  EXPECT_NE(xml.find("|displacement| [m]"), std::string::npos);  // its scalar bar
  // A chain in vacuum and anything in air have no such map.
  io::RunState chain_in_vacuum;
  chain_in_vacuum.air = false;
  EXPECT_EQ(io::run_state_xml(chain_in_vacuum).find("displacement_m.PVLookupTable"), std::string::npos);
}

}  // namespace
