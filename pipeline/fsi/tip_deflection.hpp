#pragma once
/// \file tip_deflection.hpp
/// \brief The tip's bend and twist as every structure records them (history.csv
/// tip_bend_deg, tip_twist_deg; docs/fsi.md, "The FEM as the structure"): the tip
/// section's rotation relative to its rest orientation, in the wing frame W, split as
/// Rx(bend) Ry(twist) — the chain's joint convention (mbd/chain_model.hpp), about x_W and
/// y_W whatever axis a chain's bodies lie along, so that chain and FEM runs compare column
/// by column.

#include <Eigen/Core>

#include <cmath>

namespace flapsim::fsi {

struct TipDeflection {
  double bend = 0.0;   ///< about x_W, > 0 toward +z [rad]
  double twist = 0.0;  ///< about the bent y_W, > 0 nose-down [rad]
};

/// \brief Bend and twist of \p rel, the tip's rotation relative to its rest orientation,
/// in W (rel = Rx(bend) Ry(twist) exactly when it is such a product).
inline TipDeflection tip_deflection(const Eigen::Matrix3d& rel) {
  TipDeflection d;
  d.bend = std::atan2(rel(2, 1), rel(1, 1));
  const double cb = std::cos(d.bend), sb = std::sin(d.bend);
  Eigen::Matrix3d rx;
  rx << 1.0, 0.0, 0.0, 0.0, cb, -sb, 0.0, sb, cb;
  const Eigen::Matrix3d ry = rx.transpose() * rel;
  d.twist = std::atan2(ry(0, 2), ry(0, 0));
  return d;
}

}  // namespace flapsim::fsi
