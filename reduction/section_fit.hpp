#pragma once
/// \file section_fit.hpp
/// \brief Deflection, bending rotation and twist of a wing section, fitted by least
/// squares to the out-of-plane displacements of the nodes in a narrow band around
/// the section (docs/reduction.md, "Section rotations").

#include <Eigen/Core>

#include <vector>

namespace flapsim::reduction {

/// Rigid-section motion at an axis position.
struct SectionMotion {
  double w = 0.0;      ///< out-of-plane deflection on the axis [m]
  double theta = 0.0;  ///< bending rotation about e_n (outboard side up > 0) [rad]
  double phi = 0.0;    ///< twist about e_s, right-handed (u_z = −φ n) [rad]
};

/// \brief Least-squares section fits at fixed axis positions.
///
/// For each section s*, the nodes with |s_i − s*| ≤ h are fitted by
/// u_z ≈ c₀ + c₁Δs + c₂n + c₃Δs·n + c₄Δs² + c₅n², Δs = s_i − s*; w = c₀, θ = c₁,
/// φ = −c₂. The band is widened (h ×1.25 per try) until it holds at least
/// `min_nodes` nodes and the fit has full rank. The fit's rows for c₀, c₁, c₂ are
/// stored, so sampling a displacement field costs one dot product per quantity.
class SectionSampler {
 public:
  /// \param s            span coordinate of each node along the axis [m]
  /// \param n            chordwise coordinate of each node from the axis [m]
  /// \param sections     axis positions s* of the sections [m]
  /// \param half_width   initial band half-width h [m] (> 0)
  /// \param min_nodes    minimum number of nodes in a band (≥ 6)
  SectionSampler(const Eigen::VectorXd& s, const Eigen::VectorXd& n,
                 const std::vector<double>& sections, double half_width, int min_nodes = 8);

  /// \brief The rigid-section motion of section \p k for the out-of-plane
  /// displacement \p uz (one value per node) [m].
  SectionMotion sample(int k, const Eigen::VectorXd& uz) const;

  /// \brief Sections' motions for one field, in order.
  std::vector<SectionMotion> sample_all(const Eigen::VectorXd& uz) const;

  int num_sections() const { return static_cast<int>(bands_.size()); }
  double section_position(int k) const { return bands_[static_cast<std::size_t>(k)].s_star; }
  /// Band half-width finally used for section k [m].
  double band_half_width(int k) const { return bands_[static_cast<std::size_t>(k)].half_width; }
  /// Smallest and largest n of the nodes in the band of section k [m].
  double n_min(int k) const { return bands_[static_cast<std::size_t>(k)].n_min; }
  double n_max(int k) const { return bands_[static_cast<std::size_t>(k)].n_max; }

 private:
  struct Band {
    double s_star = 0.0, half_width = 0.0, n_min = 0.0, n_max = 0.0;
    std::vector<int> nodes;
    Eigen::Matrix3Xd rows;  ///< pseudo-inverse rows for w, θ, φ (3 × band size), one column per band node
  };
  std::vector<Band> bands_;
};

}  // namespace flapsim::reduction
