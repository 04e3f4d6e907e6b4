#pragma once
/// \file fsi_vtk.hpp
/// \brief ParaView pictures of a coupled run, one file per written step: the deformed
/// wing surface (quads; cell data pressure jump, circulation, force; point data
/// velocity), the wake sheet (quads; cell data circulation) and the bar chain (one line
/// per body from its inboard to its outboard joint; cell data body index). Plain
/// PolyDataMesh, written by write_vtp.

#include "mbd/chain_data.hpp"
#include "mbd/chain_model.hpp"
#include "pipeline/io/vtk_writers.hpp"
#include "uvlm/vortex_lattice.hpp"

namespace flapsim::io {

/// \brief The lattice surface of the last solve as quads (normals along the panel normals).
PolyDataMesh wing_surface_mesh(const uvlm::VortexLatticeModel& model,
                                       const uvlm::VortexLatticeData& data, double time);

/// \brief The wake sheet (rings between shed rows, the newest row at the trailing edge).
PolyDataMesh wake_mesh(const uvlm::VortexLatticeModel& model,
                               const uvlm::VortexLatticeData& data, double time);

/// \brief The chain as lines, plus each body's centre of mass as a point cell.
PolyDataMesh chain_mesh(const mbd::ChainModel& chain, const mbd::ChainData& data,
                                double time);

}  // namespace flapsim::io
