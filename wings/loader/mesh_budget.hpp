#pragma once
/// \file mesh_budget.hpp
/// \brief Checks that a wing can be meshed within bounds before gmsh is called: the
/// outline is not a sliver, and the mesh sizes do not ask for more elements than the
/// documented budget (docs/wing_file.md, "[mesh]"). Without them a tiny element_size
/// meant minutes of meshing and then std::bad_alloc.

#include <optional>
#include <string>

#include "wings/loader/wing_model.hpp"

namespace flapsim::wings {

/// The most triangles and vein elements a wing mesh may have (about 3 million FEM
/// degrees of freedom: the FEM then needs several GB).
inline constexpr double kMaxMeshElements = 500000.0;

/// The largest aspect ratio R²/S of an outline: thinner is a sliver, not a wing.
inline constexpr double kMaxAspectRatio = 1000.0;
/// Outline points closer than this share of the outline's size (its largest |coordinate|) are
/// a repeat: gmsh merges them and cannot create the edge between them.
inline constexpr double kNearRepeat = 1e-6;

/// \brief Estimated element count of the wing's mesh: membrane triangles of size h cover
/// the area S at about S / (√3/4 · h²) (equilateral triangles), plus the refined band
/// along the veins (length L, half width 0.5·h_v + 3·h as the size field of
/// fem/wing_mesher.cpp) at the vein size h_v.
double estimated_mesh_elements(const Wing& wing);

/// Where a file sets a wing's mesh sizes: the names of its two keys, which of them it gives,
/// and the unit its messages write lengths in (a wing file's [mesh], or a case's
/// [structure] element_size_mm overriding it).
struct MeshSizeKeys {
  std::string element = "element_size", vein = "vein_element_size";
  bool element_given = false, vein_given = false;
  double length_scale = 1.0;  ///< metres per unit [m]
  std::string unit = "m";
  /// The membrane's size named in the veins' message where `element` was not given (the
  /// case's vein size against the wing file's membrane size); empty: `element`.
  std::string element_not_given;
};

/// A mesh size refused: the key to name (one of MeshSizeKeys') and why.
struct MeshSizeProblem {
  std::string key, what;
};

/// \brief The first of the mesh-size rules the wing's sizes break, or none: the veins' size
/// at most the membrane's, the membrane's at most half the span, and at most
/// kMaxMeshElements elements (blaming the veins' key where it is given and the finer).
std::optional<MeshSizeProblem> mesh_size_problem(const Wing& wing, const MeshSizeKeys& keys);

}  // namespace flapsim::wings
