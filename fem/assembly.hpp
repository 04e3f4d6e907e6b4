#pragma once
/// \file assembly.hpp
/// \brief Global stiffness and mass matrices (sparse, both triangles stored) and
/// the mass of every element, for strip sums in the reduction stage.

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "fem/structural_model.hpp"

namespace flapsim::fem {

using SparseMatrix = Eigen::SparseMatrix<double>;  ///< column-major, full symmetric storage

/// Mass of one element as a rigid body: what the reduction sums over strips.
struct ElementMass {
  enum class Kind { Shell, Beam };
  Kind kind = Kind::Shell;
  int index = 0;                 ///< into mesh.triangles or mesh.beams
  double mass = 0.0;             ///< [kg], structural + non-structural
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< centre of mass [m]
  /// Second moment about the centroid, ∫ (r − c)(r − c)ᵀ dm [kg·m²]; the
  /// inertia tensor is tr(S)·I − S (see inertia_tensor()).
  Eigen::Matrix3d second_moment = Eigen::Matrix3d::Zero();

  /// Inertia tensor about the element's own centroid [kg·m²].
  Eigen::Matrix3d inertia_tensor() const {
    return second_moment.trace() * Eigen::Matrix3d::Identity() - second_moment;
  }
};

/// K, M and the element masses of a model.
struct AssembledSystem {
  SparseMatrix stiffness;  ///< K [N/m, N, N·m], size num_dofs²
  SparseMatrix mass;       ///< M [kg, kg·m, kg·m²], consistent
  std::vector<ElementMass> element_masses;  ///< shells first, then beams
  double total_mass = 0.0;                  ///< Σ element masses [kg]
};

/// \brief Assemble K and M (triplets, summed) and the element masses.
/// \param model  mesh and element properties; triangles must have non-zero area
///               and beams non-zero length (throws std::invalid_argument otherwise)
///
/// With \p threads ≥ 2 the element matrices are computed in two halves on two threads and
/// K and M are built side by side; the triplets keep the serial order, so the matrices are
/// the same bits as with one thread.
AssembledSystem assemble(const StructuralModel& model, int threads = 1);

}  // namespace flapsim::fem
