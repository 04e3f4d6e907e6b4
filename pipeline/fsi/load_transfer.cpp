#include "pipeline/fsi/load_transfer.hpp"

#include <stdexcept>

namespace flapsim::fsi {

void add_panel_loads(const WingAttachment& attachment, const mbd::ChainData& data,
                     const uvlm::PanelLoads& panels, mbd::Loads& loads) {
  const Eigen::Index np = panels.force.cols();
  if (static_cast<std::size_t>(np) != attachment.panel_body.size() ||
      loads.num_bodies() != attachment.num_bodies)
    throw std::invalid_argument("add_panel_loads: panel or body count does not match the attachment");
  for (Eigen::Index p = 0; p < np; ++p) {
    const int body = attachment.panel_body[static_cast<std::size_t>(p)];
    const mbd::BodyKinematics& b = data.bodies[static_cast<std::size_t>(body)];
    const Eigen::Vector3d local = b.rotation.transpose() * (panels.point.col(p) - b.origin);
    loads.add_force(body, local, panels.force.col(p), mbd::LoadFrame::ground);
  }
}

}  // namespace flapsim::fsi
