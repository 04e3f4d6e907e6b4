#include "pipeline/app/chain_wing_match.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "wings/loader/wing_mass_properties.hpp"

namespace flapsim::app {

std::string chain_wing_mismatch_warning(const FsiSetup& setup) {
  if (!setup.wing || setup.structure_source.rfind("chain file", 0) != 0) return "";
  const mbd::ChainModel& chain = setup.chain();
  double chain_mass = 0.0, chain_length = chain.root_offset.norm();  // [kg], [m]
  for (const auto& b : chain.bodies) {
    chain_mass += b.mass;
    chain_length += b.length;
  }
  const double wing_mass = wings::estimate_wing_mass(*setup.wing).total();
  // The wing's reach along the chain's axis (the root frame's y in the wing frame W): its
  // span when the axis is W's y, longer for a swept axis, which reduce runs to the outline's
  // farthest point along it.
  const Eigen::Vector3d axis = chain.root_rotation.col(1);
  double reach = 0.0;  // [m]
  for (const Eigen::Vector2d& p : setup.wing->outline) reach = std::max(reach, p.x() * axis.x() + p.y() * axis.y());
  const bool along_y = std::abs(axis.y() - 1.0) < 1e-9;
  const auto differs = [](double a, double b) { return !(std::abs(a - b) <= kChainWingMismatch * std::abs(b)); };
  if (!differs(chain_mass, wing_mass) && !differs(chain_length, reach)) return "";
  char reach_text[96];
  if (along_y) std::snprintf(reach_text, sizeof reach_text, "span %.4g mm", reach * 1e3);
  else std::snprintf(reach_text, sizeof reach_text, "%.4g mm from the pivot along the chain's axis", reach * 1e3);
  char text[800];
  std::snprintf(text, sizeof text,
                "the chain (%.4g mg, %.4g mm from the pivot to its last body's end) does not match the case's "
                "wing '%s' (%.4g mg, %s): more than %g %% apart. Was the chain reduced from another "
                "wing? The lattice follows this wing's outline, the structure is the chain's (flapsim reduce "
                "the case's wing, or name its chain.toml; ignore if intended, e.g. docs/wing_file.md's closed "
                "outline for a slotted wing)",
                chain_mass * 1e6, chain_length * 1e3, setup.wing->name.c_str(), wing_mass * 1e6, reach_text,
                100 * kChainWingMismatch);
  return text;
}

}  // namespace flapsim::app
