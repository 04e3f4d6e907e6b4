#pragma once
/// \file lattice_surface.hpp
/// \brief The vortex lattice's reference surface from the wing file: the flat planform
/// grid (uvlm/planform_grid.hpp) moved by the wing's `[surface]` twist, camber and
/// dihedral (wings/loader/surface_shape.hpp). Lattice-only: the FEM and the chain stay flat.

#include "uvlm/planform_grid.hpp"
#include "wings/loader/wing_model.hpp"

namespace flapsim::app {

/// \brief Moves the nodes of \p grid (a grid of \p wing's outline) onto the wing's shaped
/// surface: each node by wings::shaped_point with the chord of its station (the grid's
/// first and last node of the station), the twist running from the outline's smallest y
/// to its largest. A flat wing's grid is left as it is, bit for bit.
void shape_lattice_surface(const wings::Wing& wing, uvlm::PlanformGrid& grid);

}  // namespace flapsim::app
