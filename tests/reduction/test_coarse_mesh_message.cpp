// A wing meshed too coarsely to be reduced says what to change. Before: `flapsim reduce`
// of a 30 × 10 mm film with element_size = 8 mm stopped with "reduction:
// extract_beam_properties: every cell lies in the tip zone" (exit 3), which names neither
// the cause nor the key. Now a ReductionFailure (exit 3) says the mesh is too coarse along
// the span and names [mesh] element_size; a finer mesh of the same wing reduces. Likewise a
// root clamp that reaches the loaded tip zone names clamp_y.

#include <gtest/gtest.h>

#include <string>

#include "fem/wing_fem.hpp"
#include "reduction/beam_properties.hpp"
#include "reduction/reduction_failure.hpp"
#include "wings/loader/wing_model.hpp"

namespace flapsim::reduction {
namespace {

wings::Wing film_plate(double element_size) {
  wings::Wing w;
  w.name = "film";
  w.outline = {{3e-3, 0.0}, {3e-3, 30e-3}, {-7e-3, 30e-3}, {-7e-3, 0.0}};
  w.span = 30e-3;
  w.clamp_y = 0.5e-3;
  w.membrane.thickness = 50e-6;
  w.membrane.material.youngs_modulus = 4e9;
  w.membrane.material.poisson_ratio = 0.38;
  w.membrane.material.density = 1390.0;
  w.mesh.element_size = element_size;
  w.mesh.vein_element_size = element_size;
  return w;
}

TEST(CoarseMesh, TooCoarseAMeshIsNamedWithTheKeyToChange) {
  const fem::WingFem fem = fem::build_wing_fem(film_plate(8e-3));
  try {
    const ClampedWingAnalysis analysis(fem.model.mesh, fem.system, fem.root_clamp);
    (void)extract_beam_properties(analysis, 40);
    FAIL() << "a 30 mm wing meshed at 8 mm was reduced";
  } catch (const ReductionFailure& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("too coarse"), std::string::npos) << what;
    EXPECT_NE(what.find("element_size"), std::string::npos) << what;
  }
}

TEST(CoarseMesh, AClampReachingTheTipZoneNamesClampY) {
  // clamp_y 29 mm of a 30 mm wing. Before: "reduction: reduction: the tip zone reaches the
  // clamped root; the wing is too short" (the wing is not short; the clamp is long).
  wings::Wing w = film_plate(1.5e-3);
  w.clamp_y = 29e-3;
  const fem::WingFem fem = fem::build_wing_fem(w);
  try {
    const ClampedWingAnalysis analysis(fem.model.mesh, fem.system, fem.root_clamp);
    FAIL() << "a wing clamped up to 1 mm from its tip was analysed";
  } catch (const ReductionFailure& e) {
    EXPECT_NE(std::string(e.what()).find("clamp_y"), std::string::npos) << e.what();
  }
}

TEST(CoarseMesh, AFinerMeshOfTheSameWingReduces) {
  const fem::WingFem fem = fem::build_wing_fem(film_plate(2e-3));
  const ClampedWingAnalysis analysis(fem.model.mesh, fem.system, fem.root_clamp);
  EXPECT_EQ(extract_beam_properties(analysis, 40).stations.size(), 40u);
}

}  // namespace
}  // namespace flapsim::reduction
