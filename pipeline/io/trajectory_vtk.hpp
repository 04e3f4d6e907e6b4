#pragma once
/// \file trajectory_vtk.hpp
/// \brief A point's path over a run as one ParaView polyline (tip_path.vtp and the markers'
/// marker_<k>_path.vtp of a coupled run, docs/output_files.md): the positions of every
/// recorded step in time order, with their time as point data.

#include <Eigen/Core>

#include <string>
#include <vector>

#include "pipeline/io/vtk_writers.hpp"

namespace flapsim::io {

/// The recorded positions of one point.
struct Trajectory {
  std::string name;                     ///< what the point is ("tip", a marker's name)
  std::vector<double> times;            ///< [s], increasing
  std::vector<Eigen::Vector3d> points;  ///< ground frame [m], one per time
};

/// \brief The trajectory as one polyline through its points (none for fewer than two):
/// point data "t_s" [s] and "t_over_T" (t / period) [-]; field data text "point" = the
/// name.
/// \param period  the wingbeat period [s] (> 0)
/// \throws std::invalid_argument if times and points differ in size or period <= 0
PolyDataMesh trajectory_mesh(const Trajectory& path, double period);

}  // namespace flapsim::io
