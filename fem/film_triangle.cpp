#include "fem/film_triangle.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

#include "fem/tension_field_membrane.hpp"

namespace flapsim::fem {

FilmTriangle make_film_triangle(const std::array<int, 3>& nodes, const std::array<Eigen::Vector3d, 3>& p,
                                double thickness, double youngs_modulus, double poisson_ratio) {
  // Reference plane axes: e1 along edge 0→1, e3 the normal, e2 = e3 × e1.
  const Eigen::Vector3d a = p[1] - p[0], b = p[2] - p[0];
  const Eigen::Vector3d n = a.cross(b);
  const double twice_area = n.norm();
  if (!(twice_area > 0.0)) throw std::invalid_argument("make_film_triangle: the triangle has zero area");
  const Eigen::Vector3d e1 = a.normalized(), e3 = n / twice_area, e2 = e3.cross(e1);
  const double X[3] = {0.0, a.dot(e1), b.dot(e1)}, Y[3] = {0.0, a.dot(e2), b.dot(e2)};
  FilmTriangle f;
  f.nodes = nodes;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    f.shape_gradient(i, 0) = (Y[j] - Y[k]) / twice_area;
    f.shape_gradient(i, 1) = (X[k] - X[j]) / twice_area;
  }
  f.volume = 0.5 * twice_area * thickness;
  f.youngs_modulus = youngs_modulus;
  f.poisson_ratio = poisson_ratio;
  return f;
}

namespace {

std::array<Eigen::Vector3d, 2> deformed_tangents(const FilmTriangle& film, const std::array<Eigen::Vector3d, 3>& x) {
  std::array<Eigen::Vector3d, 2> g{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  for (int i = 0; i < 3; ++i)
    for (int a = 0; a < 2; ++a) g[a] += film.shape_gradient(i, a) * x[i];
  return g;
}

}  // namespace

Eigen::Vector3d film_triangle_strain(const FilmTriangle& film, const std::array<Eigen::Vector3d, 3>& x) {
  const auto g = deformed_tangents(film, x);
  return {0.5 * (g[0].squaredNorm() - 1.0), 0.5 * (g[1].squaredNorm() - 1.0), g[0].dot(g[1])};
}

double film_triangle_force(const FilmTriangle& film, const std::array<Eigen::Vector3d, 3>& x,
                           Eigen::Matrix<double, 9, 1>& f, Eigen::Matrix<double, 9, 9>* K) {
  const auto g = deformed_tangents(film, x);
  const Eigen::Vector3d e(0.5 * (g[0].squaredNorm() - 1.0), 0.5 * (g[1].squaredNorm() - 1.0), g[0].dot(g[1]));
  const MembraneResponse m = tension_field_response(e, film.youngs_modulus, film.poisson_ratio);
  const Eigen::Vector3d& S = m.stress;
  Eigen::Matrix<double, 3, 9> B;
  for (int i = 0; i < 3; ++i) {
    const double n1 = film.shape_gradient(i, 0), n2 = film.shape_gradient(i, 1);
    B.block<1, 3>(0, 3 * i) = n1 * g[0].transpose();
    B.block<1, 3>(1, 3 * i) = n2 * g[1].transpose();
    B.block<1, 3>(2, 3 * i) = n1 * g[1].transpose() + n2 * g[0].transpose();
  }
  f.noalias() = film.volume * (B.transpose() * S);
  if (K != nullptr) {
    K->noalias() = film.volume * (B.transpose() * m.tangent * B);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double ni1 = film.shape_gradient(i, 0), ni2 = film.shape_gradient(i, 1);
        const double nj1 = film.shape_gradient(j, 0), nj2 = film.shape_gradient(j, 1);
        const double s = S(0) * ni1 * nj1 + S(1) * ni2 * nj2 + S(2) * (ni1 * nj2 + ni2 * nj1);
        K->block<3, 3>(3 * i, 3 * j).diagonal().array() += film.volume * s;
      }
  }
  return film.volume * m.energy_density;
}

}  // namespace flapsim::fem
