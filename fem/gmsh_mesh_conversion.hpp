#pragma once
/// \file gmsh_mesh_conversion.hpp
/// \brief gmsh's mesh of a wing (fem/gmsh_boundary.hpp, as gmsh numbers it) turned into the
/// FEM's Mesh: contiguous node numbering, triangles counter-clockwise seen from +z, beams
/// along their vein's direction, unused nodes dropped, and a canonical order, so that the
/// same triangles in any order give the same Mesh, bit for bit.

#include "fem/gmsh_boundary.hpp"
#include "fem/mesh.hpp"
#include "wings/loader/wing_model.hpp"

namespace flapsim::fem {

/// The Mesh of gmsh's nodes, triangles and vein lines for `wing` (its veins give each beam
/// its vein index and direction). Nodes keep gmsh's order (its node tags do not change
/// from run to run; the order of its triangles does); triangles are sorted, each starting
/// at its lowest node with its orientation kept. Nodes no element uses are dropped, the
/// others renumbered in the order the sorted triangles, then the beams, first use them.
Mesh mesh_from_gmsh(const wings::Wing& wing, const GmshWingMesh& g);

}  // namespace flapsim::fem
