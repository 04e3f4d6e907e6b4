#pragma once
/// \file fem_structure_setup.hpp
/// \brief The structure of a case with `[structure] kind = "fem"`: the wing's own shell and
/// vein FEM (fem::build_wing_fem: the mesh, elements and materials `flapsim modes` uses, or
/// the case's element sizes), geometrically nonlinear, its root clamp (nodes at or below
/// the wing's clamp_y) driven by the base motion, the lattice on its shell (docs/fsi.md,
/// "The FEM as the structure").

#include <memory>

#include <Eigen/Core>

#include "fem/wing_mesher.hpp"
#include "mbd/base_motion.hpp"
#include "pipeline/fsi/fem_structure.hpp"
#include "pipeline/io/case_model.hpp"
#include "wings/loader/wing_model.hpp"

namespace flapsim::app {

/// \brief Refuses the case's mesh sizes (`element_size_mm`, `vein_element_size_mm`, already
/// in `mesh` [m]; 0 = the wing file's) that the wing file's own rules would refuse: veins finer
/// than or as fine as the membrane, an element at most half the span, and the element budget
/// of wings/loader/mesh_budget.hpp (a typo of 0.01 for 1 asked gmsh for 10⁸ triangles).
/// \throws flapsim::InputError naming the case file, line and key
void check_case_mesh_sizes(const io::Case& c, const wings::Wing& wing, const fem::MeshOptions& mesh);

/// numerics.rho_infinity of a FEM that is no film (film_wrinkle_warning.hpp: 0 for a film)
/// whose case leaves the key out, where the chain keeps the general 0.9. A plate's shell and
/// veins have modes far above what the steps resolve, and with 0.9 the integrator pumped energy
/// into them through the structure's nonlinearity (docs/fem.md, "Energy over 100 periods"):
/// four 50 µm plates of users (40–60 mm, 5–10 mm chord, one spar; docs/fsi.md, "A tip that
/// zigzags from step to step") zigzagged by 3–6° from step to step within two wingbeats and
/// ended "ok" on loads that were not theirs (one in vacuum with a negative mean drive power),
/// by 0.12° or less with 0.5. On resolved modes 0.5 adds little: the generalized-α scheme's
/// damping ratio at ωΔt = 0.22 (the hawkmoth's first bending at 100 steps a cycle) is 1.9e-4
/// (7.7e-7 with 0.9), and `cases/hover_flexible_fem.toml` moved by +0.08 % in mean lift, +0.09 %
/// in aerodynamic power and +0.7 % in peak tip bend (measured 5 Dec, before this default).
inline constexpr double kFemRhoInfinity = 0.5;

/// \brief Builds the FEM structure of a case.
/// \param lattice_nodes  lattice nodes in the wing frame, (nc+1)(ns+1) columns [m]; empty in vacuum
/// \param span           the wing's span R [m] (the scale of the coupling's change measure)
/// \throws flapsim::InputError if the wing cannot be meshed or nothing is clamped
std::shared_ptr<const fsi::FemStructureModel> make_fem_structure(const io::Case& c, const wings::Wing& wing,
                                                                 const mbd::BaseMotion& base,
                                                                 const Eigen::Matrix3Xd& lattice_nodes,
                                                                 double span);

}  // namespace flapsim::app
