#pragma once
/// \file mode_classification.hpp
/// \brief Names a wing mode from its shape: rigid, bending (spanwise), torsion,
/// chordwise or in-plane. Wing frame: y along the span, x along the chord.
///
/// Method: the out-of-plane displacement uz of the nodes in each of a number of
/// spanwise strips is fitted by least squares with uz ≈ a + b (x − x̄), x̄ the strip's
/// mass centre (a section that translates and rotates rigidly). The fit residual
/// measures chordwise bending (camber); of the fit, the translation W a² counts as
/// bending and the rotation b² Σ w (x − x̄)² as torsion. Energies are mass-weighted.
/// (Binning each strip's whole fit by whether its line changes sign inside the chord
/// called the hawkmoth's second bending mode torsion: its sections also twist.)

#include <string>
#include <vector>

#include <Eigen/Core>

#include "fem/assembly.hpp"
#include "fem/mesh.hpp"

namespace flapsim::fem {

enum class ModeKind { Rigid, Bending, Torsion, Chordwise, InPlane };

/// "rigid", "bending", "torsion", "chordwise", "in-plane".
std::string to_string(ModeKind kind);

/// Shares of the mass-weighted displacement energy of a mode shape.
struct ModeShapeMeasures {
  double in_plane = 0.0;   ///< Σ m (ux² + uy²) / Σ m |u|²
  double bending = 0.0;    ///< share of uz in the strips' translation (fitted mean)
  double torsion = 0.0;    ///< share of uz in the strips' rotation about their mass centre (fitted slope)
  double chordwise = 0.0;  ///< share of uz not explained by the strip-wise linear fit
  int spanwise_sign_changes = 0;  ///< nodal lines of the strip mean displacement along the span
};

/// Lumped mass of each node (element masses shared equally among its nodes) [kg].
std::vector<double> nodal_masses(const Mesh& mesh, const AssembledSystem& system);

/// \brief Measures of one mode shape (full DOF vector).
/// \param strips  number of spanwise strips
ModeShapeMeasures measure_mode_shape(const Mesh& mesh, const std::vector<double>& node_mass,
                                     const Eigen::VectorXd& shape, int strips = 12);

/// \brief The kind of a mode: in-plane if in-plane motion dominates, else the
/// largest of bending, torsion and chordwise. Rigid is decided by the caller
/// from the frequency (see classify_modes).
ModeKind classify_mode_shape(const ModeShapeMeasures& m);

/// \brief Kinds of all modes; modes with |f| below `rigid_fraction` × the
/// largest frequency found are rigid-body modes.
std::vector<ModeKind> classify_modes(const Mesh& mesh, const AssembledSystem& system,
                                     const Eigen::MatrixXd& shapes, const Eigen::VectorXd& frequencies_hz,
                                     double rigid_fraction = 1e-4);

}  // namespace flapsim::fem
