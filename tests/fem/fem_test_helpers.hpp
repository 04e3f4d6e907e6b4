#pragma once
// Small builders shared by the FEM tests: uniform shell/beam models on
// structured meshes and dense solves with prescribed DOF values.

#include <Eigen/Dense>

#include "fem/assembly.hpp"
#include "fem/section_properties.hpp"
#include "fem/structural_model.hpp"
#include "fem/structured_mesh.hpp"

namespace flapsim::fem::testing {

inline ShellProperties shell(double E, double nu, double h, double rho) {
  ShellProperties s;
  s.youngs_modulus = E;
  s.poisson_ratio = nu;
  s.thickness = h;
  s.density = rho;
  return s;
}

inline StructuralModel uniform_shell_model(Mesh mesh, const ShellProperties& s) {
  StructuralModel m;
  m.shell.assign(mesh.triangles.size(), s);
  m.mesh = std::move(mesh);
  return m;
}

inline StructuralModel uniform_beam_model(Mesh mesh, const FrameProperties& f) {
  StructuralModel m;
  m.frame.assign(mesh.beams.size(), f);
  m.mesh = std::move(mesh);
  return m;
}

/// The soft cantilever rod of the nonlinear dynamics tests: a frame along x, L = 1 m,
/// 10 elements, solid, 20 mm across, E = 1e8 Pa, G = E/2.6, ρ = 1000 kg/m³.
inline StructuralModel soft_rod() {
  wings::Section sec;
  sec.outer_diameter = 0.02;
  sec.wall = 0.01;
  FrameProperties f;
  f.youngs_modulus = 1e8;
  f.shear_modulus = 1e8 / 2.6;
  f.density = 1000.0;
  f.section = section_properties(sec);
  return uniform_beam_model(line_mesh({0, 0, 0}, {1, 0, 0}, 10), f);
}

/// Bending stiffness D = E h³ / (12 (1 − ν²)).
inline double plate_D(const ShellProperties& s) {
  return s.youngs_modulus * s.thickness * s.thickness * s.thickness /
         (12.0 * (1.0 - s.poisson_ratio * s.poisson_ratio));
}

/// Solve K u = F with u prescribed (value) on the DOFs where `prescribed` is true.
inline Eigen::VectorXd solve_prescribed(const Eigen::MatrixXd& K, const Eigen::VectorXd& F,
                                        const std::vector<bool>& prescribed,
                                        const Eigen::VectorXd& value) {
  const int n = static_cast<int>(K.rows());
  std::vector<int> fr, pr;
  for (int i = 0; i < n; ++i) (prescribed[i] ? pr : fr).push_back(i);
  Eigen::MatrixXd Kff(fr.size(), fr.size());
  Eigen::VectorXd rhs(fr.size());
  for (size_t a = 0; a < fr.size(); ++a) {
    rhs(a) = F(fr[a]);
    for (size_t b = 0; b < fr.size(); ++b) Kff(a, b) = K(fr[a], fr[b]);
    for (int p : pr) rhs(a) -= K(fr[a], p) * value(p);
  }
  const Eigen::VectorXd uf = Kff.ldlt().solve(rhs);
  Eigen::VectorXd u = value;
  for (size_t a = 0; a < fr.size(); ++a) u(fr[a]) = uf(a);
  return u;
}

}  // namespace flapsim::fem::testing
