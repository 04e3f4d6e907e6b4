// The FEM of whole wings: gmsh meshing with veins fragmented into the
// membrane, the free–free rigid-body count, the hawkmoth's mass against the
// papers' target and its lowest modes.

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <set>

#include <Eigen/Dense>

#include "fem/load_cases.hpp"
#include "fem/static_solver.hpp"
#include "fem/wing_fem.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/wing_file.hpp"

namespace flapsim::fem {
namespace {

// A small rectangular test wing (20 mm × 8 mm, 20 μm film) with a leading-edge
// vein and an oblique vein crossing the membrane, built in code.
wings::Wing small_wing() {
  wings::Wing w;
  w.name = "small";
  w.outline = {{2.0e-3, 0.0}, {2.0e-3, 20e-3}, {-6e-3, 20e-3}, {-6e-3, 0.0}};
  w.span = 20e-3;
  w.membrane.thickness = 20e-6;
  w.membrane.material = {3e9, 0.3, 1200.0};
  w.membrane.nonstructural_mass_per_area = 0.01;
  wings::Vein le;
  le.name = "leading edge";
  le.points = {{1.5e-3, 0.5e-3}, {1.5e-3, 19.5e-3}};
  le.root_section.outer_diameter = 0.3e-3;
  le.root_section.wall = 0.05e-3;
  le.tip_section.outer_diameter = 0.1e-3;
  le.tip_section.wall = 0.02e-3;
  le.material = {6e9, 0.3, 1200.0};
  wings::Vein ob = le;
  ob.name = "oblique";
  ob.points = {{1.5e-3, 2e-3}, {-2e-3, 10e-3}, {-6e-3, 16e-3}};  // ends on the trailing edge
  w.veins = {le, ob};
  w.mesh.element_size = 1.0e-3;
  w.mesh.vein_element_size = 0.5e-3;
  w.clamp_y = 0.0;
  return w;
}

TEST(WingMesh, VeinsShareNodesWithTheMembrane) {
  const wings::Wing w = small_wing();
  const Mesh mesh = mesh_wing(w);
  ASSERT_GT(mesh.triangles.size(), 100u);
  ASSERT_GT(mesh.beams.size(), 20u);
  std::set<int> shell_nodes;
  for (const auto& t : mesh.triangles) shell_nodes.insert(t.begin(), t.end());
  for (const auto& b : mesh.beams) {
    // Every vein node is a membrane node: fragment made them conformal.
    EXPECT_TRUE(shell_nodes.count(b.nodes[0]) && shell_nodes.count(b.nodes[1]));
    const double len = (mesh.nodes[b.nodes[1]] - mesh.nodes[b.nodes[0]]).norm();
    EXPECT_LT(len, 0.75e-3);  // vein_element_size 0.5 mm (gmsh keeps within ~1.5×)
  }
  // Both veins are meshed over their whole length (polyline length, to 1e-9 m).
  double len[2] = {0.0, 0.0};
  for (const auto& b : mesh.beams) len[b.vein] += (mesh.nodes[b.nodes[1]] - mesh.nodes[b.nodes[0]]).norm();
  EXPECT_NEAR(len[0], 19e-3, 1e-9);
  const double ob = std::hypot(3.5e-3, 8e-3) + std::hypot(4e-3, 6e-3);
  EXPECT_NEAR(len[1], ob, 1e-9);
  // The membrane area is the outline's (20 × 8 mm²).
  double area = 0.0;
  for (const auto& t : mesh.triangles)
    area += 0.5 * (mesh.nodes[t[1]] - mesh.nodes[t[0]]).cross(mesh.nodes[t[2]] - mesh.nodes[t[0]]).z();
  EXPECT_NEAR(area, 160e-6, 1e-12);
}

TEST(WingFem, FreeFreeWingHasExactlySixRigidBodyModes) {
  const WingFem fem = build_wing_fem(small_wing());
  // K annihilates the six rigid motions u = t + r × p (rotations r).
  const Mesh& mesh = fem.model.mesh;
  const double knorm = fem.system.stiffness.norm();
  for (int mode = 0; mode < 6; ++mode) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(mesh.num_dofs());
    Eigen::Vector3d t = Eigen::Vector3d::Zero(), r = Eigen::Vector3d::Zero();
    (mode < 3 ? t : r)(mode % 3) = 1.0;
    for (int i = 0; i < mesh.num_nodes(); ++i) {
      u.segment<3>(dof_index(i, UX)) = t + r.cross(mesh.nodes[i]);
      u.segment<3>(dof_index(i, RX)) = r;
    }
    EXPECT_LT((fem.system.stiffness * u).norm() / (knorm * u.norm()), 1e-13) << "rigid motion " << mode;
  }
  const WingModes m = wing_modes(fem, 10, /*clamped=*/false);
  // Six rigid-body modes (three translations, three rotations): their
  // frequencies are round-off compared with the first elastic one.
  const double f7 = m.modes.frequencies_hz(6);
  ASSERT_GT(f7, 1.0);
  for (int k = 0; k < 6; ++k) EXPECT_LT(std::abs(m.modes.frequencies_hz(k)), 1e-4 * f7) << "mode " << k + 1;
  for (int k = 0; k < 6; ++k) EXPECT_EQ(m.kinds[k], ModeKind::Rigid);
  EXPECT_NE(m.kinds[6], ModeKind::Rigid);  // the seventh is elastic: exactly six
}

TEST(WingFem, ElementMassesAddUpToTheWingMass) {
  const wings::Wing w = small_wing();
  const WingFem fem = build_wing_fem(w);
  // Membrane (ρh + μ)·S plus veins ∫ρA ds. The vein areas taper linearly in D
  // and t, so A(s) is quadratic and the FEM's midpoint sections miss ∫A by
  // O(Δs²): compare with the exact integral to 1e-4.
  const double membrane = (1200.0 * 20e-6 + 0.01) * 160e-6;
  double veins = 0.0;
  for (const auto& v : w.veins) {
    double L = 0.0;
    for (size_t i = 0; i + 1 < v.points.size(); ++i) L += (v.points[i + 1] - v.points[i]).norm();
    const int n = 2000;  // fine midpoint sum of the exact quadratic area
    for (int i = 0; i < n; ++i) {
      const double s = (i + 0.5) / n;
      const double D = v.root_section.outer_diameter + s * (v.tip_section.outer_diameter - v.root_section.outer_diameter);
      const double t = v.root_section.wall + s * (v.tip_section.wall - v.root_section.wall);
      veins += 1200.0 * M_PI * t * (D - t) * L / n;
    }
  }
  EXPECT_NEAR(fem.system.total_mass / (membrane + veins), 1.0, 1e-4);
  // The mass matrix carries the same mass: rigid translation uᵀ M u = m.
  Eigen::VectorXd ux = Eigen::VectorXd::Zero(fem.model.mesh.num_dofs());
  for (int i = 0; i < fem.model.mesh.num_nodes(); ++i) ux(dof_index(i, UX)) = 1.0;
  EXPECT_NEAR(ux.dot(fem.system.mass * ux) / fem.system.total_mass, 1.0, 1e-12);
}

TEST(WingFem, AssemblyOnTwoThreadsGivesTheSameBitsAsOnOne) {
  // The threaded assembly (flapsim modes --threads 2) keeps the serial order of the
  // triplets, so K, M and the element masses must be equal bit for bit, not just close:
  // a difference in the last bit would move the modes of `flapsim modes` and the chain
  // file of `flapsim reduce` (docs/performance.md, "FEM stage").
  const wings::Wing w = small_wing();
  const StructuralModel model = wing_structural_model(w, mesh_wing(w));
  const AssembledSystem one = assemble(model, 1), two = assemble(model, 2);
  auto same = [](const SparseMatrix& a, const SparseMatrix& b) {
    if (a.rows() != b.rows() || a.nonZeros() != b.nonZeros()) return false;
    for (int c = 0; c < a.outerSize(); ++c) {
      SparseMatrix::InnerIterator ia(a, c), ib(b, c);
      for (; ia && ib; ++ia, ++ib)
        if (ia.row() != ib.row() || ia.value() != ib.value()) return false;
      if (ia || ib) return false;
    }
    return true;
  };
  EXPECT_TRUE(same(one.stiffness, two.stiffness));
  EXPECT_TRUE(same(one.mass, two.mass));
  EXPECT_EQ(one.total_mass, two.total_mass);
  ASSERT_EQ(one.element_masses.size(), two.element_masses.size());
  for (std::size_t e = 0; e < one.element_masses.size(); ++e) {
    EXPECT_EQ(one.element_masses[e].index, two.element_masses[e].index);
    EXPECT_EQ(one.element_masses[e].mass, two.element_masses[e].mass);
    EXPECT_TRUE(one.element_masses[e].second_moment == two.element_masses[e].second_moment);
  }
}

TEST(WingMesh, AVeinOutsideTheMembraneIsRefusedNamingIt) {
  // A vein beside the outline (x = 2.03 mm, the edge at x = 2 mm), as a wing built in code
  // (the file reader moves such a vein onto the outline): gmsh leaves it outside the
  // surface, sharing no node with the membrane, and the FEM would be singular.
  wings::Wing w = small_wing();
  w.source_file = "small.toml";
  w.veins[0].points = {{2.03e-3, 0.5e-3}, {2.03e-3, 19.5e-3}};
  w.veins[0].key = "veins[0].points";
  w.veins[0].line = 12;
  try {
    mesh_wing(w);
    ADD_FAILURE() << "a vein outside the membrane was meshed";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "small.toml");
    EXPECT_EQ(e.line(), 12);
    EXPECT_EQ(e.key(), "veins[0].points");
    EXPECT_NE(e.message().find("'leading edge' is not embedded"), std::string::npos) << e.what();
  }
  // On the edge itself it is embedded: every beam node a membrane node.
  w.veins[0].points = {{2.0e-3, 0.5e-3}, {2.0e-3, 19.5e-3}};
  const Mesh mesh = mesh_wing(w);
  std::set<int> shell_nodes;
  for (const auto& t : mesh.triangles) shell_nodes.insert(t.begin(), t.end());
  int vein0 = 0;
  for (const auto& b : mesh.beams) {
    EXPECT_TRUE(shell_nodes.count(b.nodes[0]) && shell_nodes.count(b.nodes[1]));
    vein0 += b.vein == 0;
  }
  EXPECT_GE(vein0, 19);  // 19 mm at vein_element_size 0.5 mm: at least 19 elements
}

TEST(WingMesh, AVeinLyingAlongAnotherIsRefusedNamingBoth) {
  // A second vein written on top of a stretch of the leading edge (a "doubler"; or one whose
  // two ends the file reader moved onto it, wings/loader/vein_junctions.hpp): gmsh meshes the shared
  // stretch as one line and gives it to one vein; here the leading edge took it and the
  // doubler, without elements, was refused as "shorter than the mesh tolerance, or outside
  // the membrane", neither of which it was; had the doubler taken it, the leading edge's
  // section there would have been lost without a word. Refused before meshing, either way.
  wings::Wing w = small_wing();
  w.source_file = "small.toml";
  wings::Vein doubler = w.veins[0];
  doubler.name = "doubler";
  doubler.points = {{1.5e-3, 5e-3}, {1.5e-3, 8e-3}};
  doubler.key = "veins[2].points";
  doubler.line = 30;
  w.veins.push_back(doubler);
  try {
    mesh_wing(w);
    ADD_FAILURE() << "a vein without elements was meshed";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 30);
    EXPECT_EQ(e.key(), "veins[2].points");
    EXPECT_NE(e.message().find("vein 'doubler' lies along vein 'leading edge'"), std::string::npos) << e.what();
  }
  // 0.1 mm beside it, it is a vein of its own.
  w.veins[2].points = {{1.4e-3, 5e-3}, {1.4e-3, 8e-3}};
  const Mesh mesh = mesh_wing(w);
  EXPECT_GE(std::count_if(mesh.beams.begin(), mesh.beams.end(), [](const BeamElement& b) { return b.vein == 2; }), 6);
}

}  // namespace
}  // namespace flapsim::fem
