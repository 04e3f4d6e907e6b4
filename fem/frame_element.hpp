#pragma once
/// \file frame_element.hpp
/// \brief Two-node 3-D Euler–Bernoulli frame element (veins): axial, torsion and
/// bending in two planes, 6 DOF per node, consistent mass including the torsional
/// inertia ρ I_p.

#include <Eigen/Core>

#include "fem/section_properties.hpp"

namespace flapsim::fem {

/// Material and section of one frame element (section taken at its midpoint).
struct FrameProperties {
  double youngs_modulus = 0.0;  ///< E [Pa]
  double shear_modulus = 0.0;   ///< G [Pa]
  double density = 0.0;         ///< ρ [kg/m³]
  SectionProperties section;
  /// Direction that local z should follow (projected normal to the element):
  /// the shell normal for veins in a wing [-]. Need not be unit length.
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
};

using Matrix12d = Eigen::Matrix<double, 12, 12>;

/// Stiffness and mass of one frame element in global axes, DOF order per node
/// (ux, uy, uz, rx, ry, rz), node 0 then node 1.
struct FrameElementMatrices {
  Matrix12d stiffness;  ///< [N/m, N, N·m] blocks
  Matrix12d mass;       ///< [kg, kg·m, kg·m²] blocks
};

/// \brief Local-to-global rotation: rows are the local x, y, z axes in global
/// coordinates (x along the element, z as close to `up` as possible).
/// \param a, b  end points [m]
/// \param up    preferred local z direction
Eigen::Matrix3d frame_axes(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                           const Eigen::Vector3d& up);

/// \brief Element matrices of a straight frame element between `a` and `b`.
/// \param a, b   end points [m]
/// \param props  material, section and orientation
FrameElementMatrices frame_element(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                   const FrameProperties& props);

}  // namespace flapsim::fem
