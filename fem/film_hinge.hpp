#pragma once
/// \file film_hinge.hpp
/// \brief The bending of a film without rotations: one hinge per interior edge
/// of the film's triangles, whose energy is the squared change of the dihedral
/// angle between the two triangles (the discrete shell of Grinspun, Hirani,
/// Desbrun & Schröder 2003, "Discrete shells", Proc. SCA; the angle's gradient
/// of Bridson, Marino & Fedkiw 2003, "Simulation of clothing with folds and
/// wrinkles", Proc. SCA, §4).
///
/// A film's bending stiffness D = E t³/12(1 − ν²) is tiny on the wing's scale
/// but not on the mesh's: without it a membrane-only film (film_triangle.hpp)
/// has no out-of-plane stiffness at all where it is flat and slack, and each
/// node becomes a sail of its own. The hinge gives the film its bending back on
/// translations only.
///
/// Edge a–b shared by the triangles (a, b, c) and (b, a, d); θ the dihedral
/// angle, θ₀ its reference value;
///   W = ½ k (θ − θ₀)²,   k = D |e|² / (A_c + A_d)  [N m]
/// (the weight 3|e|²/(A_c + A_d) of Grinspun et al. with its constant chosen
/// for a cylinder). Measured on a mesh of equilateral triangles under small
/// uniform curvatures K (tests fem.FilmHinge.*): the hinges store plate
/// theory's ½ D [ν (tr K)² + (1 − ν) tr K²] per area with ν = −1/3 (a cylinder
/// exactly, a sphere and a saddle within 1 %), i.e. a cylinder's energy is
/// right, a film's doubly curved bending (ν = 0.38 for Mylar) is half that of
/// plate theory for a sphere and 1.5 times for a saddle; a mesh of right
/// triangles bent across its legs stores the cylinder's energy to 1.4 %. The
/// film's bending is a regularisation on the mesh's scale, not a structure: on
/// the wing's scale D k⁴ is far below the film's inertia and tension.
/// Force f = k (θ − θ₀) ∇θ. Tangent: the Gauss–Newton part k ∇θ ∇θᵀ
/// (symmetric, positive semidefinite); the part k (θ − θ₀) ∇²θ is left out, a
/// small fraction of it wherever the film is smooth on the mesh's scale
/// (|θ − θ₀| ≪ 1).

#include <array>
#include <vector>

#include <Eigen/Core>

namespace flapsim::fem {

/// Constant data of one hinge.
struct FilmHinge {
  std::array<int, 4> nodes{};  ///< a, b (the edge), c, d (the opposite corners)
  double stiffness = 0.0;      ///< k [N m]
  double rest_angle = 0.0;     ///< θ₀ [rad]
};

/// \brief Dihedral angle θ [rad] of the hinge at corners x (a, b, c, d) and its
/// gradient ∂θ/∂x (node i's part in grad[3i..3i+2]) [1/m]. Zero for a flat
/// hinge; its sign follows the normal of triangle (a, b, c).
double film_hinge_angle(const std::array<Eigen::Vector3d, 4>& x, Eigen::Matrix<double, 12, 1>* grad);

/// \brief The hinges of every interior edge shared by exactly two of the
/// triangles (node indices), with bending stiffness D [N m] per triangle, at
/// reference positions X [m]. The stiffness of a hinge takes the mean of its
/// two triangles' D.
std::vector<FilmHinge> make_film_hinges(const std::vector<std::array<int, 3>>& triangles,
                                        const std::vector<double>& bending_stiffness,
                                        const std::vector<Eigen::Vector3d>& X);

/// \brief Energy [J], force f = ∂W/∂x [N] and, if asked, the Gauss–Newton
/// tangent [N/m] of one hinge at corners x [m].
double film_hinge_force(const FilmHinge& hinge, const std::array<Eigen::Vector3d, 4>& x,
                        Eigen::Matrix<double, 12, 1>& f, Eigen::Matrix<double, 12, 12>* K);

}  // namespace flapsim::fem
