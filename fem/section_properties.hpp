#pragma once
/// \file section_properties.hpp
/// \brief Cross-section constants of a vein (frame element) from its shape:
/// area, second moments, torsion constant and polar moment.

#include "wings/loader/wing_model.hpp"

namespace flapsim::fem {

/// Section constants in the frame element's local axes: local x along the
/// element, local z the shell normal (out of the wing plane), local y = z × x
/// (in the wing plane).
struct SectionProperties {
  double area = 0.0;         ///< A [m²]
  double I_y = 0.0;          ///< second moment about local y: out-of-plane bending [m⁴]
  double I_z = 0.0;          ///< second moment about local z: in-plane bending [m⁴]
  double torsion_constant = 0.0;  ///< St Venant J [m⁴]
  double polar_moment = 0.0;      ///< I_p = I_y + I_z, for torsional inertia ρ I_p [m⁴]
};

/// \brief Section constants of a hollow circle (D, wall t; t >= D/2 is solid)
/// or a rectangle (width in the wing plane, height normal to it).
/// Rectangle torsion uses the series approximation
/// J = a b³ [1/3 − 0.21 (b/a)(1 − b⁴/(12 a⁴))], a >= b the sides (Roark, Table 10.1),
/// good to about 4 % for every aspect ratio.
/// \param section  the section (SI units)
SectionProperties section_properties(const wings::Section& section);

/// \brief The section a fraction s ∈ [0, 1] along a vein: linear taper of
/// D and wall (or width and height) from `root` (s = 0) to `tip` (s = 1).
/// Both ends must have the same shape (the root's shape is kept otherwise).
wings::Section interpolate_section(const wings::Section& root, const wings::Section& tip, double s);

}  // namespace flapsim::fem
