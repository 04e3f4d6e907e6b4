#include "pipeline/fsi/fem_added_mass.hpp"

#include <algorithm>
#include <array>

namespace flapsim::fsi {

LumpedAddedMass lump_added_mass(const FemAttachment& attachment, const fem::Mesh& mesh,
                                PanelLoadResponse& response, const Eigen::Matrix3d& base_rotation,
                                int lattice_nodes) {
  const std::size_t panels = attachment.panels.size();
  // δF of every panel for a unit velocity of the whole wing along each ground axis.
  std::array<Eigen::Matrix3Xd, 3> df;
  uvlm::LeadingEdgeColumn unused_edge;  // the leading-edge force's part is not lumped
  for (int j = 0; j < 3; ++j) {
    Eigen::Matrix3Xd dv = Eigen::Matrix3Xd::Zero(3, lattice_nodes);
    dv.row(j).setOnes();
    response.force_change(dv, df[static_cast<std::size_t>(j)], unused_edge);
  }
  std::vector<Eigen::Matrix3d> node_blocks(static_cast<std::size_t>(mesh.num_nodes()), Eigen::Matrix3d::Zero());
  std::vector<char> touched(static_cast<std::size_t>(mesh.num_nodes()), 0);
  LumpedAddedMass lumped;
  for (std::size_t k = 0; k < panels; ++k) {
    const Eigen::Index p = static_cast<Eigen::Index>(k);
    Eigen::Matrix3d G;
    for (int j = 0; j < 3; ++j) G.col(j) = df[static_cast<std::size_t>(j)].col(p);
    // n_k: the direction the panel's force changes in (G's largest column).
    Eigen::Index largest = 0;
    G.colwise().norm().maxCoeff(&largest);
    const double length = G.col(largest).norm();
    if (!(length > 0.0)) continue;
    const Eigen::Vector3d n = G.col(largest) / length;
    const double m = std::max(0.0, -n.dot(G * n));
    if (m == 0.0) continue;
    lumped.total += m;
    const Eigen::Vector3d n_w = base_rotation.transpose() * n;
    const Eigen::Matrix3d block = m * n_w * n_w.transpose();
    const ShellPoint& s = attachment.panels[k];
    std::array<double, 3> w{};
    double sum = 0.0;
    for (std::size_t i = 0; i < 3; ++i) sum += w[i] = std::max(0.0, s.weights[i]);
    const auto& tri = mesh.triangles[static_cast<std::size_t>(s.triangle)];
    for (std::size_t i = 0; i < 3; ++i) {
      const auto node = static_cast<std::size_t>(tri[i]);
      node_blocks[node] += (w[i] / sum) * block;
      touched[node] = 1;
    }
  }
  for (std::size_t n = 0; n < touched.size(); ++n)
    if (touched[n]) {
      lumped.nodes.push_back(static_cast<int>(n));
      lumped.blocks.push_back(node_blocks[n]);
    }
  return lumped;
}

}  // namespace flapsim::fsi
