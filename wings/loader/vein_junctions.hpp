#pragma once
/// \file vein_junctions.hpp
/// \brief Veins that meet: a vein's end written next to another vein, off it by so little
/// that gmsh would mesh the gap into sliver triangles, is taken as on it
/// (docs/wing_file.md, "[[veins]]").

#include <vector>

#include "wings/loader/wing_model.hpp"

namespace flapsim::wings {

/// The smallest angle [deg] a wing mesh's triangles should have; thinner ones are slivers.
/// A convention between two measurements: the shipped hawkmoth's mesh has 1.73° and flies
/// on its FEM; a 0.028° sliver (a spar 1.1 µm inside a swept leading edge) stalled the FEM's
/// Newton (docs/wing_file.md). A gap g beside a vein meshed with elements of size h leaves
/// triangles of about atan(g/h) (measured: 1 µm at 3 mm, 0.023°; 15 µm at 0.5 mm, 1.76°).
inline constexpr double kSliverAngleDeg = 0.5;

/// The largest gap [m] between a vein's end and another vein that is closed:
/// tan(kSliverAngleDeg) h_v for the wing's vein element size h_v, at most 0.1 % of the span
/// (the outline's tolerance for vein points, wing_file.cpp).
double vein_junction_tolerance(double span, double vein_element_size);

/// \brief Closes the gaps of more than \p round_off and at most \p tolerance [m] between a
/// vein's end and another vein: first an end beside an earlier vein's end is moved onto
/// that end exactly; then an end beside another vein's line is moved onto its nearest
/// point (the nearest vein's, veins in their order, each against the others as already
/// moved). Returns the number of ends moved. Only the ends: a vein's inner points next to
/// another vein are where it branches off at a shallow angle, and moving them would fold
/// one onto the other.
///
/// Why: gmsh embeds both veins in the membrane and meshes a gap of micrometres between a
/// vein's end and another vein into slivers (a cross vein written 1 µm off a spar of a
/// 95 mm wing with 3 mm elements: 0.023°). Moved onto the other vein, the end is a junction
/// at which gmsh splits both veins.
int snap_vein_ends_onto_other_veins(std::vector<Vein>& veins, double tolerance, double round_off);

}  // namespace flapsim::wings
