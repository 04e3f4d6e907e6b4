#pragma once
/// \file fem_mesh_resolution_warning.hpp
/// \brief A warning for a `kind = "fem"` case whose membrane mesh is coarse against the
/// wing's chord: a mesh of a few elements across the chord cannot bend into the camber, nor
/// twist into the chordwise shape, that a film wing's lift comes from, and the lattice's
/// nodes (tied to the shell elements, docs/fsi.md, "Attachment to the FEM") follow its flat
/// facets. `[structure] element_size_mm` (or the wing file's [mesh] sizes) coarser than the
/// chord was accepted without a word (a 37.5 mm mesh on a 20 mm chord: 20 nodes).

#include <string>

#include "pipeline/app/fsi_setup.hpp"

namespace flapsim::app {

/// Fewer elements than this across the mean chord are warned about. A convention: the
/// shipped FEM cases have 7 (the 75 mm film wing, 2.17 mm elements), 16 (the MAV film wing)
/// and 35 (the hawkmoth) across theirs, and the 75 mm film wing's lift moved by 0.5 % from
/// 7 to 9 (docs/fsi.md, "Film wings").
inline constexpr double kMinFemElementsAcrossChord = 4.0;

/// \brief "" or the warning for a `kind = "fem"` case whose typical membrane element (the
/// median of the shell triangles' mean edges) fits fewer than kMinFemElementsAcrossChord
/// times into the wing's mean chord S/R.
std::string fem_mesh_resolution_warning(const FsiSetup& setup);

}  // namespace flapsim::app
