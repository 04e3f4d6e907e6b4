#include "fem/frame_element.hpp"
#include "fem/block_rotation.hpp"

#include <cmath>

#include <Eigen/Dense>

namespace flapsim::fem {

Eigen::Matrix3d frame_axes(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                           const Eigen::Vector3d& up) {
  const Eigen::Vector3d ex = (b - a).normalized();
  Eigen::Vector3d ez = up - up.dot(ex) * ex;
  if (ez.norm() < 1e-8 * up.norm() || up.norm() == 0.0) {
    // `up` along the element: any normal will do (round sections only then).
    const Eigen::Vector3d trial = std::abs(ex.x()) < 0.9 ? Eigen::Vector3d::UnitX()
                                                         : Eigen::Vector3d::UnitY();
    ez = trial - trial.dot(ex) * ex;
  }
  ez.normalize();
  const Eigen::Vector3d ey = ez.cross(ex);
  Eigen::Matrix3d R;
  R.row(0) = ex.transpose();
  R.row(1) = ey.transpose();
  R.row(2) = ez.transpose();
  return R;
}

FrameElementMatrices frame_element(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                   const FrameProperties& p) {
  const double L = (b - a).norm();
  const double E = p.youngs_modulus, G = p.shear_modulus, rho = p.density;
  const SectionProperties& s = p.section;
  Matrix12d k = Matrix12d::Zero();
  Matrix12d m = Matrix12d::Zero();
  // Local DOF indices: node 0 (u0 v1 w2 tx3 ty4 tz5), node 1 (+6).
  auto add2 = [](Matrix12d& M, int i, int j, double c) {  // c·[1 −1; −1 1]-type pattern
    M(i, i) += c; M(j, j) += c; M(i, j) -= c; M(j, i) -= c;
  };
  auto add2mass = [](Matrix12d& M, int i, int j, double c) {  // c·[2 1; 1 2]
    M(i, i) += 2 * c; M(j, j) += 2 * c; M(i, j) += c; M(j, i) += c;
  };
  // Axial and torsion.
  add2(k, 0, 6, E * s.area / L);
  add2(k, 3, 9, G * s.torsion_constant / L);
  add2mass(m, 0, 6, rho * s.area * L / 6.0);
  add2mass(m, 3, 9, rho * s.polar_moment * L / 6.0);
  // Bending: (v, θz) about local z uses I_z with v' = θz; (w, θy) about local y
  // uses I_y with w' = −θy, hence the flipped signs of the coupling terms.
  auto bending = [&](int d0, int r0, double I, double sign) {
    const int idx[4] = {d0, r0, d0 + 6, r0 + 6};
    const double c = E * I / (L * L * L);
    const double kb[4][4] = {{12, 6 * L, -12, 6 * L},
                             {6 * L, 4 * L * L, -6 * L, 2 * L * L},
                             {-12, -6 * L, 12, -6 * L},
                             {6 * L, 2 * L * L, -6 * L, 4 * L * L}};
    const double cm = rho * s.area * L / 420.0;
    const double mb[4][4] = {{156, 22 * L, 54, -13 * L},
                             {22 * L, 4 * L * L, 13 * L, -3 * L * L},
                             {54, 13 * L, 156, -22 * L},
                             {-13 * L, -3 * L * L, -22 * L, 4 * L * L}};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        // Rows/columns 1 and 3 are rotations: flip their coupling with displacements.
        const double f = ((i % 2) != (j % 2)) ? sign : 1.0;
        k(idx[i], idx[j]) += c * kb[i][j] * f;
        m(idx[i], idx[j]) += cm * mb[i][j] * f;
      }
  };
  bending(1, 5, s.I_z, +1.0);
  bending(2, 4, s.I_y, -1.0);

  const Eigen::Matrix3d R = frame_axes(a, b, p.up);
  const Matrix12d T = block_rotation<12>(R);
  FrameElementMatrices out;
  out.stiffness = T.transpose() * k * T;
  out.mass = T.transpose() * m * T;
  return out;
}

}  // namespace flapsim::fem
