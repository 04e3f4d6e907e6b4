#include "reduction/station_mode_kind.hpp"

#include "fem/mesh.hpp"

namespace flapsim::reduction {

std::string to_string(StationModeKind kind) {
  switch (kind) {
    case StationModeKind::bending: return "bending";
    case StationModeKind::torsion: return "torsion";
    case StationModeKind::film: return "film";
  }
  return "?";
}

StationModeMeasures classify_by_stations(const LumpedChain& lc, const Eigen::VectorXd& x) {
  StationModeMeasures m;
  const StationCompliance& st = lc.stations;
  const int ns = st.size();
  const Eigen::VectorXd u = st.station_motion(x);
  double rigid = 0.0, all = 0.0;
  for (int k = 0; k < ns; ++k) {
    const StationBand& b = st.stations[static_cast<std::size_t>(k)];
    const Eigen::Vector3d uk = u.segment<3>(3 * k);
    for (std::size_t i = 0; i < b.nodes.size(); ++i) {
      const double uz = x[fem::dof_index(b.nodes[i], fem::UZ)];
      const double fit = b.basis.row(static_cast<Eigen::Index>(i)).dot(uk);
      rigid += b.mass[static_cast<Eigen::Index>(i)] * fit * fit;
      all += b.mass[static_cast<Eigen::Index>(i)] * uz * uz;
    }
  }
  m.beam_share = all > 0.0 ? rigid / all : 0.0;
  m.joint_angles = lc.joint_stiffness.joint_angles(u);
  const Eigen::VectorXd& phi = m.joint_angles;
  Eigen::VectorXd bend = phi, twist = phi;
  for (Eigen::Index d = 0; d < phi.size(); ++d) (d % 2 == 0 ? twist : bend)[d] = 0.0;
  const Eigen::MatrixXd& k = lc.joint_stiffness.stiffness;
  const double eb = bend.dot(k * bend), et = twist.dot(k * twist);
  m.bending_share = eb + et > 0.0 ? eb / (eb + et) : 0.0;
  m.kind = m.beam_share < 0.5 ? StationModeKind::film
                              : (m.bending_share >= 0.5 ? StationModeKind::bending : StationModeKind::torsion);
  return m;
}

std::vector<StationModeMeasures> classify_modes_by_stations(const LumpedChain& lc, const Eigen::MatrixXd& shapes) {
  std::vector<StationModeMeasures> out;
  for (Eigen::Index c = 0; c < shapes.cols(); ++c) out.push_back(classify_by_stations(lc, shapes.col(c)));
  return out;
}

}  // namespace flapsim::reduction
