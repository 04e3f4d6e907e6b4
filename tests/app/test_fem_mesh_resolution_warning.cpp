// A `kind = "fem"` case whose membrane mesh has fewer than four elements across the wing's
// mean chord is warned about by check and run (pipeline/app/fem_mesh_resolution_warning.hpp):
// a 37.5 mm mesh on the 75 mm film wing's 15 mm chord (20 nodes) was accepted silently.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "shipped_case_text.hpp"

namespace {

const std::string kResolutionWarning = "elements across the wing's mean chord";

// `flapsim check` of cases/film_wing_fem.toml (wing path absolute) with `structure_lines`
// added to [structure]; its stderr.
std::string check_film_case(const flapsim::test::ScratchDir& dir, const std::string& name,
                            const std::string& structure_lines) {
  std::string text = flapsim::test::shipped_case_text("film_wing_fem");
  text.replace(text.find("[structure]\n"), 12, "[structure]\n" + structure_lines);
  const auto file = dir / (name + ".toml");
  std::ofstream(file) << text;
  const auto out = flapsim::test::run_flapsim_capturing_stderr(dir.path(), "check " + file.string());
  EXPECT_EQ(out.status, 0) << out.err;
  return out.err;
}

}  // namespace

TEST(FemMeshResolutionWarning, AMeshCoarserThanAQuarterOfTheChordIsWarnedAbout) {
  flapsim::test::ScratchDir dir("fem_mesh_resolution_warning");
  // The shipped case: 2.17 mm elements, about 7 across the 15 mm mean chord.
  EXPECT_EQ(check_film_case(dir, "shipped", "").find(kResolutionWarning), std::string::npos);
  // 37.5 mm (the veins too): the median element 11.8 mm, 1.3 across the chord.
  const std::string coarse =
      check_film_case(dir, "coarse", "element_size_mm = 37.5\nvein_element_size_mm = 37.5\n");
  EXPECT_NE(coarse.find(kResolutionWarning), std::string::npos) << coarse;
  EXPECT_NE(coarse.find("1.3 elements across"), std::string::npos) << coarse;
  // Sizes of 7.5 mm: median element 5.06 mm, 3.0 across, still too coarse; of 5 mm: 3.66 mm,
  // 4.1 across, not warned (gmsh grades the mesh finer near the outline and the rod).
  const std::string three = check_film_case(dir, "three_across", "element_size_mm = 7.5\nvein_element_size_mm = 7.5\n");
  EXPECT_NE(three.find("3.0 elements across"), std::string::npos) << three;
  EXPECT_EQ(check_film_case(dir, "four_across", "element_size_mm = 5.0\nvein_element_size_mm = 5.0\n")
                .find(kResolutionWarning),
            std::string::npos);
}
