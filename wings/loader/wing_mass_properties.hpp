#pragma once
/// \file wing_mass_properties.hpp
/// \brief Vein section areas, tapering, vein lengths and a quick mass estimate of a
/// wing from its file alone (before any FEM): membrane area × thickness × density,
/// plus non-structural mass per area × area, plus Σ ∫ A(s) ρ ds over the veins.
/// Where a vein lies on the membrane both are counted, as in the FEM, which puts
/// shell and beam elements on the same nodes.

#include <Eigen/Core>

#include "wings/loader/wing_model.hpp"

namespace flapsim::wings {

/// Cross-section area [m²]: π t (D − t) for a hollow circle (π D²/4 when t >= D/2),
/// width × height for a rectangle.
double section_area(const Section& section);

/// Section at arc-length fraction u ∈ [0, 1] along a vein: every dimension linear
/// in u between root_section (u = 0) and tip_section (u = 1).
Section section_at(const Vein& vein, double u);

/// Polyline length of a vein [m].
double vein_length(const Vein& vein);

/// ∫ ρ A(s) ds along the vein [kg] (composite Simpson; exact for linear tapers of
/// a hollow circle, whose area is quadratic in s).
double vein_mass(const Vein& vein);

struct WingMassEstimate {
  double membrane = 0.0;       ///< ρ_m h S [kg]
  double nonstructural = 0.0;  ///< m_ns S [kg]
  double veins = 0.0;          ///< Σ vein_mass [kg]
  double total() const { return membrane + nonstructural + veins; }
};

/// Mass of the wing from its geometry and materials [kg].
WingMassEstimate estimate_wing_mass(const Wing& wing);

/// Mass properties of the flat wing (in its plane z = 0): the membrane and non-structural
/// mass spread evenly over the outline, each vein's ρ A(s) along its polyline.
struct WingInertia {
  double mass = 0.0;                                         ///< [kg]
  Eigen::Vector2d center_of_mass = Eigen::Vector2d::Zero();  ///< (x, y) [m]
  /// About the centre of mass, wing axes (x chordwise, y spanwise, z normal) [kg m²]:
  /// I_xx = ∫ y'² dm, I_yy = ∫ x'² dm, I_zz = I_xx + I_yy, I_xy = −∫ x' y' dm.
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};
WingInertia estimate_wing_inertia(const Wing& wing);

}  // namespace flapsim::wings
