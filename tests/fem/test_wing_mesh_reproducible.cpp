// The same wing meshes to the same mesh, whatever the threads do. Before: gmsh meshed the
// surfaces that the veins cut the membrane into on several threads (its own OpenMP
// threads), and the mesh changed from run to run: the free-free wing of test_wing_fem.cpp
// gave a first elastic mode of 177.72032, 177.72088 or 177.73458 Hz in repeated runs of
// one binary (always 177.72032 with OMP_NUM_THREADS=1). fem/gmsh_module.cpp now meshes
// on one thread; the FEM's own loops keep theirs.
#include <gtest/gtest.h>
#include <omp.h>

#include "fem/wing_mesher.hpp"

namespace flapsim::fem {
namespace {

// A 20 mm × 8 mm wing whose three veins cut the membrane into four surfaces.
wings::Wing four_surface_wing() {
  wings::Wing w;
  w.name = "four surfaces";
  w.outline = {{2.0e-3, 0.0}, {2.0e-3, 20e-3}, {-6e-3, 20e-3}, {-6e-3, 0.0}};
  w.span = 20e-3;
  w.membrane.thickness = 20e-6;
  w.membrane.material = {3e9, 0.3, 1200.0};
  wings::Vein v;
  v.root_section.outer_diameter = 0.3e-3;
  v.root_section.wall = 0.05e-3;
  v.tip_section = v.root_section;
  v.material = {6e9, 0.3, 1200.0};
  v.name = "oblique 1";
  v.points = {{2.0e-3, 2e-3}, {-2e-3, 10e-3}, {-6e-3, 16e-3}};  // leading to trailing edge
  w.veins.push_back(v);
  v.name = "oblique 2";
  v.points = {{2.0e-3, 8e-3}, {-6e-3, 12e-3}};
  w.veins.push_back(v);
  v.name = "chordwise";
  v.points = {{2.0e-3, 17e-3}, {-6e-3, 17e-3}};
  w.veins.push_back(v);
  w.mesh.element_size = 0.5e-3;
  w.mesh.vein_element_size = 0.25e-3;
  return w;
}

TEST(WingMeshReproducible, MeshingAgainWithTwoThreadsGivesTheSameMeshBitForBit) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(2);
  const wings::Wing w = four_surface_wing();
  const Mesh first = mesh_wing(w);
  ASSERT_GT(first.num_nodes(), 500);
  for (int run = 1; run < 8; ++run) {
    const Mesh m = mesh_wing(w);
    ASSERT_EQ(m.num_nodes(), first.num_nodes()) << "run " << run;
    ASSERT_EQ(m.triangles, first.triangles) << "run " << run;
    for (int i = 0; i < m.num_nodes(); ++i) ASSERT_EQ(m.nodes[i], first.nodes[i]) << "run " << run << ", node " << i;
  }
  omp_set_num_threads(threads);
}

}  // namespace
}  // namespace flapsim::fem
