#include "fem/corotational_frame.hpp"

#include "fem/block_rotation.hpp"

namespace flapsim::fem {

CorotationalFrame make_corotational_frame(const std::array<int, 2>& nodes, const Eigen::Vector3d& a,
                                          const Eigen::Vector3d& b, const FrameProperties& props) {
  CorotationalFrame e;
  e.nodes = nodes;
  e.reference_axes = frame_axes(a, b, props.up);
  const Matrix12d T = block_rotation<12>(e.reference_axes);
  e.local_stiffness = T * frame_element(a, b, props).stiffness * T.transpose();
  e.local_stiffness = 0.5 * (e.local_stiffness + e.local_stiffness.transpose()).eval();
  const Eigen::Vector3d c = 0.5 * (a + b);
  e.reference_local[0] = e.reference_axes * (a - c);
  e.reference_local[1] = e.reference_axes * (b - c);
  return e;
}

CorotatedFrame<2> frame_corotated_frame(const CorotationalFrame& e, const std::array<Eigen::Vector3d, 2>& x,
                                        const std::array<Eigen::Matrix3d, 2>& R) {
  const Eigen::Vector3d z0 = e.reference_axes.row(2).transpose();
  const Eigen::Vector3d chord = x[1] - x[0];
  const double l = chord.norm();
  const Eigen::Vector3d e1 = chord / l;
  const Eigen::Vector3d qa[2] = {R[0] * z0, R[1] * z0};
  const Eigen::Vector3d q = 0.5 * (qa[0] + qa[1]);
  const Eigen::Vector3d e3 = (q - q.dot(e1) * e1).normalized();
  const Eigen::Vector3d e2 = e3.cross(e1);
  CorotatedFrame<2> fr;
  fr.axes.row(0) = e1.transpose();
  fr.axes.row(1) = e2.transpose();
  fr.axes.row(2) = e3.transpose();
  auto& G = fr.spin_map;
  G.setZero();
  G(1, 6 + 2) = -1.0 / l;
  G(1, 2) = 1.0 / l;
  G(2, 6 + 1) = 1.0 / l;
  G(2, 1) = -1.0 / l;
  const Eigen::Vector3d qt = fr.axes * q;
  for (int a = 0; a < 2; ++a) {
    const Eigen::Vector3d qat = fr.axes * qa[a];
    G(0, 6 * a + 3) += 0.5 * qat.z() / qt.z();
    G(0, 6 * a + 5) -= 0.5 * qat.x() / qt.z();
  }
  G.row(0) += (qt.x() / qt.z()) * G.row(2);
  return fr;
}

}  // namespace flapsim::fem
