#pragma once
/// \file film_wrinkle_warning.hpp
/// \brief A warning for a `kind = "fem"` case whose membrane is a thin film against its
/// mesh: a compression of a fraction of a per mille buckles it into wrinkles of the mesh's
/// own wavelength, the FEM then splits its steps where they form (docs/fsi.md, "Step halving
/// of the FEM"), and the run takes many times what `check` estimates (docs/fsi.md, "Film
/// wings").

#include <optional>
#include <string>

#include "fem/structural_model.hpp"
#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/io/case_model.hpp"

namespace flapsim::app {

/// \brief The membrane strain (compression, > 0) at which a flat plate of thickness t [m]
/// and Poisson's ratio ν buckles into a wrinkle of wavelength λ [m]: where the membrane
/// force's geometric stiffness N k² equals the bending stiffness D k⁴ (N = E t ε,
/// D = E t³/(12 (1 − ν²)), k = 2π/λ): ε = (2π t/λ)² / (12 (1 − ν²)).
double mesh_wrinkle_strain(double thickness, double poisson_ratio, double wavelength);

/// The strain below which a membrane is warned about (typical_membrane_wrinkle): the 75 mm
/// film wing (elements of 2.17 mm) at 25 µm (5.1e-4) split 45 % of its steps, at 50 µm
/// (2.1e-3) 3 %, at 100 µm (8.2e-3) none (docs/fsi.md, "Film wings"); the MAV film wing is
/// at 3.8e-4, the hawkmoth's membrane (120 µm, 0.49 mm) at 0.22. A 13 mm bumblebee-size
/// forewing of a 4 µm membrane on 0.23 mm elements (1.06e-3, tests/data/
/// bumblebee_forewing_4um.toml) split each of its first 10 steps at 150 Hz into up to 64
/// pieces, unwarned below the first threshold of 1e-3. A convention from these measurements,
/// between the wings that split most steps and the 50 µm film that splits few.
inline constexpr double kFilmWrinkleStrain = 1.5e-3;

/// numerics.rho_infinity of a film's FEM (below kFilmWrinkleStrain) whose case leaves the key
/// out (app::make_fem_structure): its wrinkles oscillate far faster than a step, and only
/// ρ∞ = 0 removes them within one (docs/case_file.md, "[structure]"). A film whose case leaves
/// `structure.newton_geometric_terms` out takes "current".
inline constexpr double kFilmRhoInfinity = 0.0;

/// The membrane's typical element: the shell triangle at the median of mesh_wrinkle_strain
/// over all of them, each with its mean edge as the wavelength.
struct MembraneWrinkle {
  double strain = 0.0;     ///< mesh_wrinkle_strain
  double thickness = 0.0;  ///< [m]
  double size = 0.0;       ///< mean edge [m]
};
/// std::nullopt for a model without shells.
std::optional<MembraneWrinkle> typical_membrane_wrinkle(const fem::StructuralModel& model);

/// The membrane's thickness over the wing's mean chord below which it is a film whatever its
/// mesh: mesh_wrinkle_strain grows as the mesh is refined (its wavelength the element) while a
/// film's splitting does not ease. A two-vein rounded wing of 25 µm Mylar, 11.6 mm mean chord
/// (2.15e-3), on 1 mm elements (2.5e-3, above kFilmWrinkleStrain) split 18 of its first 19
/// steps in 170 s with neither warning nor film settings, and ran all 80 in 36 s with them; the
/// 75 mm film wing at 50 µm (3.3e-3) split 3 % of its steps, the MAV film wing at 125 µm
/// (3.2e-3) and the hawkmoth (7.1e-3) are no films. A convention between them (2 Dec).
inline constexpr double kFilmThicknessOverChord = 2.5e-3;

/// A thin film: the typical element wrinkles below kFilmWrinkleStrain, or the membrane is
/// thinner than kFilmThicknessOverChord of the wing's mean chord [m]. What the warning below and
/// the FEM's film settings (app::make_fem_structure) both go by.
inline bool is_thin_film(const std::optional<MembraneWrinkle>& typical, double mean_chord) {
  return typical &&
         (typical->strain < kFilmWrinkleStrain || typical->thickness < kFilmThicknessOverChord * mean_chord);
}

/// \brief "" or the warning for a `kind = "fem"` case whose typical membrane element
/// wrinkles below kFilmWrinkleStrain; it names the film's defaults the case takes, or a
/// written rho_infinity above kFilmRhoInfinity.
std::string film_wrinkle_warning(const io::Case& c, const FsiSetup& setup);

}  // namespace flapsim::app
