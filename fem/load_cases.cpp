#include "fem/load_cases.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace flapsim::fem {

TipStation tip_station(const Mesh& mesh, double fraction, double half_width) {
  if (mesh.nodes.empty()) throw std::invalid_argument("tip_station: empty mesh");
  double ymin = std::numeric_limits<double>::infinity(), ymax = -ymin;
  for (const auto& p : mesh.nodes) {
    ymin = std::min(ymin, p.y());
    ymax = std::max(ymax, p.y());
  }
  TipStation s;
  s.y = ymin + fraction * (ymax - ymin);
  double hw = half_width > 0.0 ? half_width : 1e-3 * (ymax - ymin);
  for (int attempt = 0; attempt < 60; ++attempt, hw *= 1.5) {
    s.nodes.clear();
    for (int i = 0; i < mesh.num_nodes(); ++i)
      if (std::abs(mesh.nodes[i].y() - s.y) <= hw) s.nodes.push_back(i);
    if (s.nodes.size() >= 2) break;
  }
  if (s.nodes.empty()) throw std::invalid_argument("tip_station: no nodes near the station");
  s.leading_edge_node = s.trailing_edge_node = s.nodes.front();
  for (int i : s.nodes) {
    if (mesh.nodes[i].x() > mesh.nodes[s.leading_edge_node].x()) s.leading_edge_node = i;
    if (mesh.nodes[i].x() < mesh.nodes[s.trailing_edge_node].x()) s.trailing_edge_node = i;
  }
  return s;
}

std::vector<LoadCase> tip_load_cases(const Mesh& mesh, const TipStation& s) {
  const int n = mesh.num_dofs();
  std::vector<LoadCase> out;
  LoadCase le{"tip_force_le", Eigen::VectorXd::Zero(n)};
  le.loads(dof_index(s.leading_edge_node, UZ)) = 1.0;
  LoadCase te{"tip_force_te", Eigen::VectorXd::Zero(n)};
  te.loads(dof_index(s.trailing_edge_node, UZ)) = 1.0;
  LoadCase mx{"tip_moment", Eigen::VectorXd::Zero(n)};
  LoadCase my{"tip_torque", Eigen::VectorXd::Zero(n)};
  const double share = 1.0 / static_cast<double>(s.nodes.size());
  for (int i : s.nodes) {
    mx.loads(dof_index(i, RX)) = share;
    my.loads(dof_index(i, RY)) = share;
  }
  out.push_back(std::move(le));
  out.push_back(std::move(te));
  out.push_back(std::move(mx));
  out.push_back(std::move(my));
  return out;
}

}  // namespace flapsim::fem
