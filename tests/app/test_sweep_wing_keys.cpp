// A sweep of a wing key that cannot reach the run is refused. Before: `flapsim sweep CASE
// --chain chain.toml --vary wing.materials.pet.youngs_modulus=1e9,4e9` ran both cases and
// gave identical rows (mean lift 0.45311 mN both): with a chain file the structure comes
// from the chain, and the user believed they had swept the stiffness. Now: exit 2 before
// anything runs, naming the key and what to do. A rigid wing likewise ignores stiffness and
// mesh keys; keys that do reach the run (the outline with a chain file, the mass of a
// rigid wing) are accepted.
#include <gtest/gtest.h>

#include <string>

#include "pipeline/app/sweep/sweep_case.hpp"
#include "wings/loader/input_error.hpp"

using namespace flapsim;

namespace {

const std::string kSource = FLAPSIM_SOURCE_DIR;

std::string refusal(const sweep::SweepInputs& inputs, const std::string& key, double value) {
  try {
    sweep::resolve_case(inputs, {{key, value}});
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SweepWingKeys, AStiffnessKeyWithAChainFileIsRefused) {
  const sweep::SweepInputs inputs{kSource + "/cases/hover_flexible.toml",
                                  kSource + "/cases/chains/hawkmoth_10_bodies.toml", 1.0, ""};
  const std::string e = refusal(inputs, "wing.materials.vein.youngs_modulus", 3e9);
  EXPECT_NE(e.find("key 'wing.materials.vein.youngs_modulus'"), std::string::npos) << e;
  EXPECT_NE(e.find("changes nothing"), std::string::npos) << e;
  EXPECT_NE(refusal(inputs, "wing.membrane.nonstructural_mass_per_area", 0.01).find("changes nothing"),
            std::string::npos);
  EXPECT_EQ(refusal(inputs, "wing.planform.area", 800.0), "");  // the lattice's outline
  // Without the chain file the wing is reduced in process for each value: accepted.
  EXPECT_EQ(refusal({inputs.case_file, "", 1.0, ""}, "wing.materials.vein.youngs_modulus", 3e9), "");
}

TEST(SweepWingKeys, AStiffnessKeyOfARigidWingIsRefusedItsMassIsNot) {
  const sweep::SweepInputs inputs{kSource + "/cases/lua_rigid.toml", "", 1.0, ""};
  EXPECT_NE(refusal(inputs, "wing.materials.vein.youngs_modulus", 3e9).find("rigid wing"), std::string::npos);
  EXPECT_NE(refusal(inputs, "wing.mesh.element_size", 0.8).find("rigid wing"), std::string::npos);
  EXPECT_EQ(refusal(inputs, "wing.membrane.nonstructural_mass_per_area", 0.01), "");
  // spring_scale of a rigid wing is only warned about (flapsim sweep): grids of a rigid
  // case over spring_scale are how the sweep's own tests exercise a grid.
  EXPECT_EQ(refusal(inputs, "spring_scale", 2.0), "");
}

}  // namespace
