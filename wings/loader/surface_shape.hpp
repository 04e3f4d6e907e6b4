#pragma once
/// \file surface_shape.hpp
/// \brief The wing's aerodynamic surface off the flat planform: linear twist (washout)
/// along the span, a NACA 4-digit mean line (camber) and dihedral, from the wing file's
/// `[surface]` table (docs/wing_file.md). They shape the vortex lattice's reference
/// geometry only (app/lattice_surface.hpp); the FEM, the reduction and the chain stay
/// flat (docs/uvlm.md, "Twist, camber and dihedral").
///
/// Wing frame W: x toward the leading edge, y along the span from the pivot, z = x × y.
/// A point (x, y) of the flat planform, at chord fraction ξ = (x_le − x)/c of its local
/// chord c = x_le − x_te, is moved in three steps:
///  1. camber: z = c z_c(ξ), the NACA 4-digit mean line of largest camber m at ξ = p
///     (Abbott & von Doenhoff 1959, §6.4):
///        z_c = m/p² (2pξ − ξ²)              for ξ < p,
///        z_c = m/(1−p)² ((1 − 2p) + 2pξ − ξ²) for ξ ≥ p;
///  2. twist: the section turned nose up by θ(y) about the spanwise line through its
///     twist axis (x_a = x_le − a c, z = 0), θ linear in y from θ_root at the outline's
///     smallest y to θ_tip at its largest:
///        x' = x_a + (x − x_a) cos θ − z sin θ,  z' = (x − x_a) sin θ + z cos θ;
///  3. dihedral: the whole surface turned tip up by Γ about the x axis (through the pivot):
///        y'' = y cos Γ − z' sin Γ,  z'' = y sin Γ + z' cos Γ.

#include <Eigen/Core>

#include <string>

namespace flapsim::wings {

class TomlTable;

/// The `[surface]` keys, in SI units (angles in radians). All zero: a flat wing.
struct SurfaceShape {
  double twist_root = 0.0;       ///< θ at the outline's smallest y [rad], nose up > 0
  double twist_tip = 0.0;        ///< θ at the outline's largest y [rad]; linear in y between
  double twist_axis = 0.25;      ///< a: chord fraction of the twist axis from the leading edge [-]
  double camber = 0.0;           ///< m: largest camber of the mean line, fraction of the chord [-]
  double camber_position = 0.4;  ///< p: its chord fraction from the leading edge [-]
  double dihedral = 0.0;         ///< Γ [rad], tip up > 0
  int line = 0;                  ///< line of the [surface] table (0: none)

  bool flat() const { return twist_root == 0.0 && twist_tip == 0.0 && camber == 0.0 && dihedral == 0.0; }
};

/// NACA 4-digit mean line z_c/c at chord fraction ξ ∈ [0, 1] (see above); 0 for m = 0.
double naca_mean_line(double m, double p, double xi);
/// Its slope dz_c/dξ.
double naca_mean_line_slope(double m, double p, double xi);

/// Twist θ(y) [rad]: linear from \p y_root (θ_root) to \p y_tip (θ_tip), held beyond.
double twist_at(const SurfaceShape& s, double y, double y_root, double y_tip);

/// \brief The shaped position of the planform point (x, y) [m] whose local chord runs from
/// \p x_le to \p x_te (x_le > x_te) [m]; twist from \p y_root to \p y_tip [m] (steps 1–3).
Eigen::Vector3d shaped_point(const SurfaceShape& s, double x, double y, double x_le, double x_te,
                             double y_root, double y_tip);

/// \brief Reads the `[surface]` table (keys twist_root_deg, twist_tip_deg, twist_axis,
/// camber, camber_max, camber_position, dihedral_deg). Bad values: InputError naming the
/// file, line and key.
SurfaceShape read_surface_shape(const TomlTable& table);

}  // namespace flapsim::wings
