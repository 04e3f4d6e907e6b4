#include "fem/corotational_shell.hpp"

#include "fem/block_rotation.hpp"

namespace flapsim::fem {

CorotationalShell make_corotational_shell(const std::array<int, 3>& nodes,
                                          const std::array<Eigen::Vector3d, 3>& p,
                                          const ShellProperties& s) {
  CorotationalShell e;
  e.nodes = nodes;
  e.reference_axes = shell_axes(p);
  // shell_element returns Tᵀ k T with T = diag(T₀, …): undo the rotation.
  const Matrix18d T = block_rotation<18>(e.reference_axes);
  e.local_stiffness = T * shell_element(p, s).stiffness * T.transpose();
  e.local_stiffness = 0.5 * (e.local_stiffness + e.local_stiffness.transpose()).eval();
  const Eigen::Vector3d c = (p[0] + p[1] + p[2]) / 3.0;
  for (int a = 0; a < 3; ++a) e.reference_local[a] = e.reference_axes * (p[a] - c);
  return e;
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

}  // namespace flapsim::fem
