#pragma once
/// \file wing_mesher.hpp
/// \brief Meshes a wing with gmsh's C++ API (OpenCASCADE kernel; called through the
/// module libflapsim_gmsh.so, loaded on the first mesh: fem/gmsh_boundary.hpp): the outline is
/// a plane surface, every vein segment a line; occ::fragment makes them conformal,
/// so the vein beam elements share nodes with the membrane triangles. Element
/// size: Mesh.MeshSizeMax = wing.mesh.element_size, refined to
/// wing.mesh.vein_element_size near the veins by a Distance/Threshold size field.

#include <filesystem>

#include "fem/mesh.hpp"
#include "wings/loader/wing_model.hpp"

namespace flapsim::fem {

/// Overrides of the wing file's mesh settings (0 = use the wing's value).
struct MeshOptions {
  double element_size = 0.0;       ///< [m]
  double vein_element_size = 0.0;  ///< [m]
  /// If not empty, the gmsh mesh is also saved there (format from the
  /// extension, normally .msh; written to a temporary name and renamed).
  std::filesystem::path msh_path;
};

/// \brief Mesh a wing (in the wing frame, z = 0).
/// Beams carry the index of their vein in wing.veins; node order of each beam
/// follows the vein's direction. Throws flapsim::InputError (naming the wing
/// file) if gmsh cannot build the geometry or the mesh, std::runtime_error if the
/// gmsh module is missing (fem/gmsh_module_loader.hpp).
/// gmsh has global state: calls are serialised by a mutex, and gmsh is
/// initialised once per process (finalised at exit).
Mesh mesh_wing(const wings::Wing& wing, const MeshOptions& options = {});

}  // namespace flapsim::fem
