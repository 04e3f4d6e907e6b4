#include "fem/corotational_shell.hpp"

#include <cmath>

#include "fem/tension_field_membrane.hpp"

namespace flapsim::fem {

CorotationalShell make_corotational_shell(const std::array<int, 3>& nodes,
                                          const std::array<Eigen::Vector3d, 3>& p,
                                          const ShellProperties& s) {
  CorotationalShell e;
  e.nodes = nodes;
  e.reference_axes = shell_axes(p);
  e.local_stiffness = shell_local_stiffness(p, s);
  e.local_stiffness = 0.5 * (e.local_stiffness + e.local_stiffness.transpose()).eval();
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) {
      e.membrane_stiffness(i, j) = e.local_stiffness(kShellMembraneDofs[i], kShellMembraneDofs[j]);
      e.bending_stiffness(i, j) = e.local_stiffness(kShellBendingDofs[i], kShellBendingDofs[j]);
    }
  std::array<double, 3> lx{}, ly{};
  for (int a = 0; a < 3; ++a) {
    const Eigen::Vector3d d = e.reference_axes * (p[a] - p[0]);
    lx[a] = d.x();
    ly[a] = d.y();
  }
  const Eigen::Matrix<double, 9, 3> L9 = opt_basic_lumping(lx, ly, s.thickness);
  e.membrane_lumping.setZero();
  for (int i = 0; i < 9; ++i) e.membrane_lumping.row(kShellMembraneDofs[i]) = L9.row(i);
  e.volume = 0.5 * std::abs(lx[1] * ly[2] - lx[2] * ly[1]) * s.thickness;
  e.youngs_modulus = s.youngs_modulus;
  e.poisson_ratio = s.poisson_ratio;
  e.stiffness_without_basic_membrane =
      e.local_stiffness -
      e.membrane_lumping * plane_stress(s.youngs_modulus, s.poisson_ratio) * e.membrane_lumping.transpose() / e.volume;
  const Eigen::Vector3d c = (p[0] + p[1] + p[2]) / 3.0;
  for (int a = 0; a < 3; ++a) e.reference_local[a] = e.reference_axes * (p[a] - c);
  return e;
}

double ShellLinearLaw::operator()(const Eigen::Matrix<double, 18, 1>& d, Eigen::Matrix<double, 18, 1>& f_local,
                                  Matrix18d* k_local) const {
  Eigen::Matrix<double, 9, 1> dm, db;
  for (int i = 0; i < 9; ++i) {
    dm(i) = d(kShellMembraneDofs[i]);
    db(i) = d(kShellBendingDofs[i]);
  }
  const Eigen::Matrix<double, 9, 1> fm = shell.membrane_stiffness.lazyProduct(dm);
  const Eigen::Matrix<double, 9, 1> fb = shell.bending_stiffness.lazyProduct(db);
  for (int i = 0; i < 9; ++i) {
    f_local(kShellMembraneDofs[i]) = fm(i);
    f_local(kShellBendingDofs[i]) = fb(i);
  }
  if (k_local != nullptr) *k_local = shell.local_stiffness;
  return 0.5 * d.dot(f_local);
}

CorotatedFrame<3> shell_corotated_frame(const std::array<Eigen::Vector3d, 3>& x) {
  CorotatedFrame<3> fr;
  fr.axes = shell_axes(x);
  double lx[3], ly[3];
  for (int a = 0; a < 3; ++a) {
    const Eigen::Vector3d d = fr.axes * (x[a] - x[0]);
    lx[a] = d.x();
    ly[a] = d.y();
  }
  const double twoA = (lx[1] - lx[0]) * (ly[2] - ly[0]) - (lx[2] - lx[0]) * (ly[1] - ly[0]);
  fr.spin_map.setZero();
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    const double dNdx = (ly[b] - ly[c]) / twoA, dNdy = (lx[c] - lx[b]) / twoA;
    fr.spin_map(0, 6 * a + 2) = dNdy;
    fr.spin_map(1, 6 * a + 2) = -dNdx;
  }
  const double l01 = lx[1];  // the current edge 0→1 lies on local x
  fr.spin_map(2, 6 * 1 + 1) = 1.0 / l01;
  fr.spin_map(2, 6 * 0 + 1) = -1.0 / l01;
  return fr;
}

Eigen::Vector3d shell_membrane_strain(const CorotationalShell& e, const Eigen::Matrix<double, 18, 1>& d) {
  return e.membrane_lumping.transpose() * d / e.volume;
}

double ShellTensionFieldLaw::operator()(const Eigen::Matrix<double, 18, 1>& d, Eigen::Matrix<double, 18, 1>& fl,
                                        Matrix18d* kt) const {
  const CorotationalShell& e = shell;
  const MembraneResponse m = tension_field_response(shell_membrane_strain(e, d), e.youngs_modulus, e.poisson_ratio);
  fl.noalias() = e.stiffness_without_basic_membrane * d;
  fl.noalias() += e.membrane_lumping * m.stress;
  if (kt != nullptr) {
    *kt = e.stiffness_without_basic_membrane;
    kt->noalias() += e.membrane_lumping * (m.tangent / e.volume) * e.membrane_lumping.transpose();
  }
  return 0.5 * d.dot(e.stiffness_without_basic_membrane * d) + e.volume * m.energy_density;
}

}  // namespace flapsim::fem
