// The film triangle (fem/film_triangle.hpp) and the film hinge (fem/film_hinge.hpp):
// force = gradient of the energy and tangent = gradient of the force, by central
// differences; rigid-motion invariance; the hinge's bending of a cylinder against
// ½ D κ² per area (plate theory: Timoshenko & Woinowsky-Krieger, "Theory of Plates
// and Shells", §1).

#include <array>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "fem/film_hinge.hpp"
#include "fem/film_triangle.hpp"

namespace flapsim::fem {
namespace {

constexpr double kMylarE = 4.0e9, kMylarNu = 0.38, kFilmT = 25e-6;  // [Pa], [-], [m]

std::array<Eigen::Vector3d, 3> film_reference() {
  return {Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(3e-3, 0.2e-3, 0.1e-3), Eigen::Vector3d(0.8e-3, 2.6e-3, -0.2e-3)};
}

// A strain that is taut in one place, wrinkled in another: stretched along one edge.
std::array<Eigen::Vector3d, 3> stretched(const std::array<Eigen::Vector3d, 3>& X, const Eigen::Matrix3d& stretch) {
  return {stretch * X[0], stretch * X[1], stretch * X[2]};
}

TEST(FilmTriangle, ForceAndTangentAreTheDerivativesOfItsEnergyInEveryRegime) {
  const auto X = film_reference();
  const FilmTriangle film = make_film_triangle({0, 1, 2}, X, kFilmT, kMylarE, kMylarNu);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  // taut (biaxial 1e-3), wrinkled (1e-3 along x, -1e-3 along y), slack (-1e-3 both)
  for (const Eigen::Vector3d& s : {Eigen::Vector3d(1e-3, 1e-3, 1e-3), Eigen::Vector3d(1e-3, -1e-3, 0.0),
                                  Eigen::Vector3d(-1e-3, -1e-3, 0.0)}) {
    const auto x = stretched(X, turn * (Eigen::Matrix3d::Identity() + Eigen::Matrix3d(s.asDiagonal())));
    Eigen::Matrix<double, 9, 1> f;
    Eigen::Matrix<double, 9, 9> K;
    film_triangle_force(film, x, f, &K);
    const double h = 1e-9;  // [m]
    for (int k = 0; k < 9; ++k) {
      auto xp = x, xm = x;
      xp[k / 3](k % 3) += h;
      xm[k / 3](k % 3) -= h;
      Eigen::Matrix<double, 9, 1> fp, fm;
      const double Wp = film_triangle_force(film, xp, fp, nullptr), Wm = film_triangle_force(film, xm, fm, nullptr);
      EXPECT_NEAR((Wp - Wm) / (2 * h), f(k), 1e-6 * f.norm() + 1e-12) << "force " << k;
      EXPECT_LE(((fp - fm) / (2 * h) - K.col(k)).norm(), 1e-5 * K.norm()) << "tangent column " << k;
    }
  }
}

TEST(FilmTriangle, ARigidMotionLeavesItUnstrained) {
  const auto X = film_reference();
  const FilmTriangle film = make_film_triangle({0, 1, 2}, X, kFilmT, kMylarE, kMylarNu);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(2.5, Eigen::Vector3d(-1, 0.3, 2).normalized()).toRotationMatrix();
  std::array<Eigen::Vector3d, 3> x;
  for (int a = 0; a < 3; ++a) x[a] = turn * X[a] + Eigen::Vector3d(0.1, -0.2, 0.3);
  Eigen::Matrix<double, 9, 1> f;
  // round-off: strains of 1e-16 per unit stretch, forces E t ℓ ε ~ 1e-11 N
  EXPECT_LT(film_triangle_strain(film, x).norm(), 1e-13);
  EXPECT_LT(film_triangle_force(film, x, f, nullptr), 1e-26);
  EXPECT_LT(f.norm(), 1e-10);
}

TEST(FilmTriangle, AStretchWithTheSidesHeldIsTautAndOneWithThemFreeWrinkles) {
  // A right triangle stretched by λ along x. Held across (E₂₂ = 0): taut, plane stress
  // S₁₁ = E/(1 − ν²) E₁₁; the force on the stretched corner S₁₁ λ t ℓ/2 (ℓ = 2 mm).
  // Free to contract by more than ν (E₂₂ = −E₁₁): wrinkled, uniaxial S₁₁ = E E₁₁
  // (tension_field_membrane.hpp: ε₂ + ν ε₁ < 0).
  const std::array<Eigen::Vector3d, 3> X{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2e-3, 0, 0), Eigen::Vector3d(0, 2e-3, 0)};
  const FilmTriangle film = make_film_triangle({0, 1, 2}, X, kFilmT, kMylarE, kMylarNu);
  const double lambda = 1.001, E11 = 0.5 * (lambda * lambda - 1.0);
  Eigen::Matrix<double, 9, 1> f;
  film_triangle_force(film, {X[0], lambda * X[1], X[2]}, f, nullptr);
  const double taut = kMylarE / (1 - kMylarNu * kMylarNu) * E11;  // [Pa]
  EXPECT_NEAR(f(3), taut * lambda * kFilmT * 2e-3 / 2.0, 1e-9 * taut * kFilmT * 2e-3);
  EXPECT_NEAR(f(0) + f(3) + f(6), 0.0, 1e-15);
  const double mu = std::sqrt(1.0 - 2.0 * E11);  // E₂₂ = ½(μ² − 1) = −E₁₁
  film_triangle_force(film, {X[0], lambda * X[1], mu * X[2]}, f, nullptr);
  const double wrinkled = kMylarE * E11;  // [Pa]
  EXPECT_NEAR(f(3), wrinkled * lambda * kFilmT * 2e-3 / 2.0, 1e-9 * wrinkled * kFilmT * 2e-3);
  EXPECT_NEAR(f(7), 0.0, 1e-12 * wrinkled * kFilmT * 2e-3);  // nothing across
}

std::array<Eigen::Vector3d, 4> hinge_reference() {
  return {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 3e-3, 0), Eigen::Vector3d(-2.5e-3, 1.2e-3, 0),
          Eigen::Vector3d(2.2e-3, 1.9e-3, 0)};
}

TEST(FilmHinge, ForceIsTheGradientOfItsEnergyAndTheAngleGradientIsExact) {
  const auto X = hinge_reference();
  const std::vector<std::array<int, 3>> tris{{0, 1, 2}, {1, 0, 3}};
  const double D = kMylarE * std::pow(kFilmT, 3) / (12 * (1 - kMylarNu * kMylarNu));
  const std::vector<FilmHinge> hinges = make_film_hinges(tris, {D, D}, {X.begin(), X.end()});
  ASSERT_EQ(hinges.size(), 1u);
  std::array<Eigen::Vector3d, 4> x;
  for (int a = 0; a < 4; ++a) x[a] = hinges[0].nodes[a] == a ? X[a] : X[static_cast<size_t>(hinges[0].nodes[a])];
  x[2].z() += 0.4e-3;  // fold it
  x[3].z() += 0.9e-3;
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.2, 1, -0.5).normalized()).toRotationMatrix();
  for (auto& p : x) p = turn * p;
  Eigen::Matrix<double, 12, 1> g, f;
  Eigen::Matrix<double, 12, 12> K;
  film_hinge_angle(x, &g);
  film_hinge_force(hinges[0], x, f, &K);
  const double h = 1e-9;
  for (int k = 0; k < 12; ++k) {
    auto xp = x, xm = x;
    xp[k / 3](k % 3) += h;
    xm[k / 3](k % 3) -= h;
    EXPECT_NEAR((film_hinge_angle(xp, nullptr) - film_hinge_angle(xm, nullptr)) / (2 * h), g(k), 1e-6 * g.norm());
    Eigen::Matrix<double, 12, 1> fp;
    const double Wp = film_hinge_force(hinges[0], xp, fp, nullptr), Wm = film_hinge_force(hinges[0], xm, fp, nullptr);
    EXPECT_NEAR((Wp - Wm) / (2 * h), f(k), 1e-6 * f.norm());
  }
  // Gauss–Newton tangent: symmetric, positive semidefinite, rank one along ∇θ.
  EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
  EXPECT_NEAR(g.dot(K * g) / g.squaredNorm(), hinges[0].stiffness * g.squaredNorm(), 1e-9 * K.norm());
}

// Energy of the hinges whose triangles lie inside the patch's inner part, against plate
// theory's ½ D [ν (tr K)² + (1 − ν) tr K²] over the area they stand for (Σ (A_c + A_d)/3).
double hinge_energy_ratio(const std::vector<Eigen::Vector3d>& X, const std::vector<std::array<int, 3>>& tris,
                          const Eigen::Matrix2d& K, double nu, double inner) {
  const double D = kMylarE * std::pow(kFilmT, 3) / (12 * (1 - kMylarNu * kMylarNu));
  const std::vector<FilmHinge> hinges = make_film_hinges(tris, std::vector<double>(tris.size(), D), X);
  std::vector<Eigen::Vector3d> x;
  for (const auto& p : X) x.emplace_back(p.x(), p.y(), 0.5 * p.head<2>().dot(K * p.head<2>()));  // z = ½ Xᵀ K X
  double W = 0.0, area = 0.0;
  for (const FilmHinge& h : hinges) {
    bool inside = true;
    for (int n : h.nodes) inside = inside && X[static_cast<size_t>(n)].head<2>().cwiseAbs().maxCoeff() < inner;
    if (!inside) continue;
    Eigen::Matrix<double, 12, 1> f;
    W += film_hinge_force(h, {x[h.nodes[0]], x[h.nodes[1]], x[h.nodes[2]], x[h.nodes[3]]}, f, nullptr);
    const Eigen::Vector3d e = X[h.nodes[1]] - X[h.nodes[0]];
    area += (e.cross(X[h.nodes[2]] - X[h.nodes[0]]).norm() + e.cross(X[h.nodes[3]] - X[h.nodes[0]]).norm()) / 6.0;
  }
  const double plate = 0.5 * D * (nu * K.trace() * K.trace() + (1 - nu) * (K * K).trace());  // [J/m²]
  return W / (plate * area);
}

TEST(FilmHinge, OnEquilateralTrianglesItStoresPlateBendingWithPoissonRatioMinusOneThird) {
  // Equilateral mesh of side 1 mm over ±20 mm; paraboloids z = ½ Xᵀ K X of curvature
  // 1/(300 mm) (slopes below 0.07 in the part measured, so the surface's curvature is K
  // to 0.7 %): a cylinder across the edges, one along them, a sphere, a saddle. Across an
  // edge of normal n the flat triangles turn by h (nᵀKn − tᵀKt/3) (h = √3 s/2), which
  // sums to plate theory's energy with ν = −1/3 (film_hinge.hpp); the cylinder is exact.
  const double s = 1e-3, h = std::sqrt(3.0) / 2 * s, k = 1.0 / 300e-3;
  std::vector<Eigen::Vector3d> X;
  const int n = 40;
  for (int j = -n / 2; j <= n / 2; ++j)
    for (int i = -n / 2; i <= n / 2; ++i) X.emplace_back(s * (i + 0.5 * (j & 1)), h * j, 0.0);
  std::vector<std::array<int, 3>> tris;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      if (j % 2 == 0) {
        tris.push_back({a, b, c});
        tris.push_back({b, d, c});
      } else {
        tris.push_back({a, b, d});
        tris.push_back({a, d, c});
      }
    }
  const double inner = 15e-3;
  for (const Eigen::Matrix2d& K : {Eigen::Matrix2d(Eigen::Vector2d(k, 0).asDiagonal()),
                                   Eigen::Matrix2d(Eigen::Vector2d(0, k).asDiagonal()),
                                   Eigen::Matrix2d(Eigen::Vector2d(k, k).asDiagonal()),
                                   Eigen::Matrix2d(Eigen::Vector2d(k, -k).asDiagonal())})
    EXPECT_NEAR(hinge_energy_ratio(X, tris, K, -1.0 / 3.0, inner), 1.0, 0.015) << K;
}

TEST(FilmHinge, OnRightTrianglesBentAcrossTheirLegsItStoresTheCylindersEnergy) {
  // The other mesh (film_hinge.hpp): squares of 1 mm halved by alternating diagonals; a
  // cylinder about y turns only the hinges across the y-edges, by κ s (the triangles'
  // chord planes), k = D s²/s²: ½ D κ² s² per square, plate theory's ½ D κ² per area.
  const double s = 1e-3, k = 1.0 / 300e-3;
  const int n = 40;
  std::vector<Eigen::Vector3d> X;
  for (int j = -n / 2; j <= n / 2; ++j)
    for (int i = -n / 2; i <= n / 2; ++i) X.emplace_back(s * i, s * j, 0.0);
  std::vector<std::array<int, 3>> tris;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      if ((i + j) % 2 == 0) {
        tris.push_back({a, b, d});
        tris.push_back({a, d, c});
      } else {
        tris.push_back({a, b, c});
        tris.push_back({b, d, c});
      }
    }
  EXPECT_NEAR(hinge_energy_ratio(X, tris, Eigen::Matrix2d(Eigen::Vector2d(k, 0).asDiagonal()), 1.0 / 3.0, 15e-3),
              1.0, 0.02);
}

}  // namespace
}  // namespace flapsim::fem
