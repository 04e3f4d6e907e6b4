#pragma once
/// \file structural_model.hpp
/// \brief A mesh plus the material of every element: everything assembly needs.

#include <vector>

#include "fem/frame_element.hpp"
#include "fem/mesh.hpp"
#include "fem/shell_element.hpp"
#include "wings/loader/wing_model.hpp"

namespace flapsim::fem {

/// The constant FEM model: mesh and element properties (one entry per element).
struct StructuralModel {
  Mesh mesh;
  std::vector<ShellProperties> shell;  ///< one per mesh.triangles[i]
  std::vector<FrameProperties> frame;  ///< one per mesh.beams[i]
};

/// \brief Membrane properties of a wing as shell properties.
ShellProperties shell_properties(const wings::Membrane& membrane);

/// \brief The model of a wing on a given mesh: membrane properties on every
/// triangle; on every beam the section of its vein at the element midpoint
/// (linear taper with arc length along the vein), local z = the wing normal +z.
/// \param wing  the wing (SI units)
/// \param mesh  a mesh of the wing whose beams carry vein indices into wing.veins
StructuralModel wing_structural_model(const wings::Wing& wing, Mesh mesh);

/// \brief Fraction of arc length (0 at the first point, 1 at the last) of the
/// point of a polyline closest to `p`.
double polyline_arc_fraction(const std::vector<Eigen::Vector2d>& polyline, const Eigen::Vector2d& p);

}  // namespace flapsim::fem
