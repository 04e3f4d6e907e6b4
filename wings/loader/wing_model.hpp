#pragma once
/// \file wing_model.hpp
/// \brief What a wing is, after its file has been read and checked: planform,
/// veins, membrane, materials and meshing hints, all in SI units in the wing
/// frame W (y along the span from the pivot, x chordwise toward the leading
/// edge, z = x × y). Read by wings/loader/wing_file.hpp; used by fem/, pipeline/io and pipeline/app.

#include <Eigen/Core>

#include <string>
#include <vector>

#include "wings/loader/input_warning.hpp"
#include "wings/loader/surface_shape.hpp"

namespace flapsim::wings {

/// Isotropic linear-elastic material.
struct Material {
  double youngs_modulus = 0.0;  ///< E [Pa]
  double poisson_ratio = 0.3;   ///< ν [-]
  double density = 0.0;         ///< ρ [kg/m³]
};

/// Cross-section of a vein (a frame element) at one point along it.
struct Section {
  enum class Shape { HollowCircle, Rectangle };
  Shape shape = Shape::HollowCircle;
  double outer_diameter = 0.0;  ///< HollowCircle: D [m]
  double wall = 0.0;            ///< HollowCircle: wall thickness t [m]; t >= D/2 is solid
  double width = 0.0;           ///< Rectangle: side in the wing plane [m]
  double height = 0.0;          ///< Rectangle: side normal to the wing plane [m]
};

/// A vein: a polyline in the wing plane, its section tapering linearly with
/// arc length from `root_section` (first point) to `tip_section` (last point).
struct Vein {
  std::string name;
  std::vector<Eigen::Vector2d> points;  ///< (x, y) [m], in order along the vein
  Section root_section;
  Section tip_section;
  Material material;
  /// Where the vein's points are given, for messages about it after meshing.
  int line = 0;
  std::string key;  ///< e.g. "veins[2].points"
};

/// The membrane: a thin shell over the whole planform.
struct Membrane {
  double thickness = 0.0;               ///< h [m]
  Material material;
  double nonstructural_mass_per_area = 0.0;  ///< scales etc. [kg/m²]; adds mass, no stiffness
};

/// Meshing hints for the FEM stage.
struct MeshSettings {
  double element_size = 0.0;       ///< target membrane element size [m]
  double vein_element_size = 0.0;  ///< target element size along veins [m] (<= element_size)
};

/// Where the outline has a gap along the chord that the vortex lattice cannot follow: a
/// line y = const that crosses the outline more than twice (a slot from the tip, a hooked
/// edge). The lattice spans each section from its leading to its trailing edge
/// (uvlm/planform_grid.hpp) and would cover the gap; the FEM follows the outline.
struct LatticeGap {
  double area_share = 0.0;  ///< gap area over the wing's area (0: none)
  double y_from = 0.0, y_to = 0.0;  ///< the band of such sections [m]
  int crossings = 0;        ///< the most crossings of one section
  /// "from y = 15 to 40 mm a line along the chord crosses the outline 4 times (a slot or a
  /// hooked edge): the vortex lattice … would cover the gap, 33.3 % of the wing's area"
  std::string description;
  std::string file, key;    ///< where the outline is given
  int line = 0;
};

/// The whole wing.
struct Wing {
  std::string name;         ///< short name, e.g. "hawkmoth" (from the file)
  std::string source_file;  ///< path of the TOML file it was read from
  /// Closed, simple polygon (last point not repeated), counter-clockwise, (x, y) [m].
  std::vector<Eigen::Vector2d> outline;
  double span = 0.0;        ///< pivot-to-tip length R [m] (max y of the outline)
  std::vector<Vein> veins;
  Membrane membrane;
  MeshSettings mesh;
  /// FEM root boundary: nodes with y <= clamp_y are clamped [m].
  double clamp_y = 0.0;
  /// Lines of clamp_y and [mesh] element_size in source_file (0: not written), for the
  /// errors of stages that find the clamp or the mesh leaves too little to work with.
  int clamp_y_line = 0, element_size_line = 0;
  /// Accepted but implausible values (wing_file.hpp, "Plausibility"), in file order.
  std::vector<InputWarning> warnings;
  /// A gap the vortex lattice would cover (area_share 0 if none or negligible, below 1 %);
  /// a run in air refuses such a wing (app/fsi_setup), the FEM stages warn.
  LatticeGap lattice_gap;
  /// Twist, camber and dihedral of the lattice's reference surface ([surface]; flat if
  /// absent). Lattice-only: the FEM, the reduction and the chain use the flat planform.
  SurfaceShape surface;
  /// How an outline read from a drawing was taken from it (which shape, the orientation,
  /// the pivot, the scale), for `check`; empty for any other outline.
  std::string drawing;
};

}  // namespace flapsim::wings
