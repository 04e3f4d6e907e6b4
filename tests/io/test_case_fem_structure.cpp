// `[structure] kind = "fem"` in a case file (docs/case_file.md, "[structure]"): its keys
// are read in SI units (gravity as for any structure), and what belongs to the chain
// (bodies, joint angles, point loads, markers, a chain file, the chain integrator's
// substeps) is refused at its file, line and key.
#include <gtest/gtest.h>

#include <string>

#include "inline_case.hpp"
#include "pipeline/io/case_model.hpp"
#include "pipeline/io/case_summary.hpp"
#include "wings/loader/input_error.hpp"

namespace p = flapsim::io;

namespace {

const std::string kFemHead =
    "wing = \"valid_tiny_wing.toml\"\n"                                   // 1
    "[kinematics]\n"                                                      // 2
    "frequency_hz = 20.0\n"                                               // 3
    "sweep = { mean_deg = 0.0, cos_deg = [60.0] }\n"                      // 4
    "rotation = { mean_deg = 90.0, sin_deg = [-60.0] }\n"                 // 5
    "[structure]\n"                                                       // 6
    "kind = \"fem\"\n";                                                   // 7

}  // namespace

TEST(CaseFemStructure, KeysAreReadInSiUnits) {
  const p::Case c = case_from_text(kFemHead + "element_size_mm = 1.5\nvein_element_size_mm = 0.5\n"
                                              "stiffness_damping_s = 2e-5\ngravity = [0.0, 0.0, -9.81]\n"
                                              "newton_geometric_terms = \"current\"\nnewton_matrix_per_piece = true\n");
  EXPECT_EQ(c.structure.kind, p::Case::Structure::Kind::Fem);
  EXPECT_EQ(c.structure.bodies, 1);
  EXPECT_DOUBLE_EQ(c.structure.fem_element_size, 1.5e-3);       // mm → m
  EXPECT_DOUBLE_EQ(c.structure.fem_vein_element_size, 0.5e-3);
  EXPECT_DOUBLE_EQ(c.structure.fem_stiffness_damping, 2e-5);    // s
  EXPECT_DOUBLE_EQ(c.structure.gravity.z(), -9.81);              // m/s², ground frame
  EXPECT_FALSE(c.structure.fem_linearised_geometric_terms);      // "current"
  EXPECT_TRUE(c.structure.fem_matrix_per_piece);
  // Defaults: the wing file's mesh, no damping.
  const p::Case d = case_from_text(kFemHead);
  EXPECT_EQ(d.structure.fem_element_size, 0.0);
  EXPECT_EQ(d.structure.fem_vein_element_size, 0.0);
  EXPECT_EQ(d.structure.fem_stiffness_damping, 0.0);
  EXPECT_TRUE(d.structure.fem_linearised_geometric_terms);  // "linearised"
  EXPECT_TRUE(d.structure.fem_matrix_per_piece);            // a kept matrix for each piece
}

TEST(CaseFemStructure, WhatBelongsToTheChainIsRefusedAtItsLineAndKey) {
  struct Bad {
    std::string text;
    int line;
    std::string key;
  };
  const Bad cases[] = {
      {kFemHead + "bodies = 10\n", 8, "structure.bodies"},
      {kFemHead + "initial_angles_deg = [1.0, 2.0]\n", 8, "structure.initial_angles_deg"},
      {kFemHead + "element_size_mm = 0.0\n", 8, "structure.element_size_mm"},
      {kFemHead + "stiffness_damping_s = -1e-5\n", 8, "structure.stiffness_damping_s"},
      {kFemHead + "newton_geometric_terms = \"mixed\"\n", 8, "structure.newton_geometric_terms"},
      {kFemHead + "newton_matrix_per_piece = 1\n", 8, "structure.newton_matrix_per_piece"},
      {kFemHead + "[[loads]]\nbody = 1\npoint = [0, 0, 0]\nforce = [0, 0, 1]\n", 9, "loads[0].body"},
      {kFemHead + "[[markers]]\nname = \"tip\"\nbody = 1\npoint = [0, 0, 0]\n", 10, "markers[0].body"},
      // the chain's file and integrator substeps, which the FEM would read and ignore
      {"chain = \"valid_tiny_wing.toml\"\n" + kFemHead, 1, "chain"},
      {kFemHead + "[numerics]\nstructure_substeps = 2\n", 9, "numerics.structure_substeps"},
      // and the FEM's keys in a chain's case
      {kFemHead.substr(0, kFemHead.find("kind")) + "kind = \"flexible\"\nbodies = 3\nelement_size_mm = 1.0\n", 9,
       "structure.element_size_mm"},
      {kFemHead.substr(0, kFemHead.find("kind")) + "kind = \"flexible\"\nbodies = 3\nnewton_matrix_per_piece = true\n", 9,
       "structure.newton_matrix_per_piece"},
  };
  for (const auto& b : cases) {
    const flapsim::InputError e = error_of(b.text);
    EXPECT_EQ(e.line(), b.line) << b.text << "\n" << e.what();
    EXPECT_EQ(e.key(), b.key) << b.text << "\n" << e.what();
    EXPECT_EQ(e.file().find("inline_case.toml") != std::string::npos, true) << e.what();
  }
}

TEST(CaseFemStructure, CheckShowsTheGravityTheStructureCarries) {
  // `flapsim check` named every [structure] key of a FEM case but gravity, which moves its
  // drive moments; its summary now shows it (and nothing without it).
  const std::string with = p::describe_case(case_from_text(kFemHead + "gravity = [0.0, 0.0, -9.81]\n"));
  EXPECT_NE(with.find("gravity                (0, 0, -9.81) m/s^2, ground frame"), std::string::npos) << with;
  EXPECT_EQ(p::describe_case(case_from_text(kFemHead)).find("gravity"), std::string::npos);
}
