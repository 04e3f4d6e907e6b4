#pragma once
/// \file mesh_budget.hpp
/// \brief Checks that a wing can be meshed within bounds before gmsh is called: the
/// outline is not a sliver, and the mesh sizes do not ask for more elements than the
/// documented budget (docs/wing_file.md, "[mesh]"). Without them a tiny element_size
/// meant minutes of meshing and then std::bad_alloc.

#include "wings/wing_model.hpp"

namespace flapsim::wings {

/// The most triangles and vein elements a wing mesh may have (about 3 million FEM
/// degrees of freedom: the FEM then needs several GB).
inline constexpr double kMaxMeshElements = 500000.0;

/// The largest aspect ratio R²/S of an outline: thinner is a sliver, not a wing.
inline constexpr double kMaxAspectRatio = 1000.0;

/// \brief Estimated element count of the wing's mesh: membrane triangles of size h cover
/// the area S at about S / (√3/4 · h²) (equilateral triangles), plus the refined band
/// along the veins (length L, half width 0.5·h_v + 3·h as the size field of
/// fem/wing_mesher.cpp) at the vein size h_v.
double estimated_mesh_elements(const Wing& wing);

}  // namespace flapsim::wings
