#include "fem/shell_element.hpp"
#include "fem/block_rotation.hpp"

#include <cmath>

#include <Eigen/Dense>

namespace flapsim::fem {

namespace {

using Row9 = Eigen::Matrix<double, 1, 9>;
using Mat29 = Eigen::Matrix<double, 2, 9>;

/// Corner rotation vector β = (βx, βy) = (θy, −θx) of node a as a 2×9 map.
Mat29 corner_beta(int a) {
  Mat29 G = Mat29::Zero();
  G(0, 3 * a + 2) = 1.0;   // βx = θy
  G(1, 3 * a + 1) = -1.0;  // βy = −θx
  return G;
}

/// Midside β of edge i→j: the tangential part from the cubic w along the edge
/// (zero transverse shear at the midpoint), the normal part linear between the
/// corners: the discrete Kirchhoff constraints of DKT.
Mat29 midside_beta(int i, int j, const std::array<double, 3>& x, const std::array<double, 3>& y) {
  const double dx = x[j] - x[i], dy = y[j] - y[i];
  const double l = std::sqrt(dx * dx + dy * dy);
  const Eigen::Vector2d s(dx / l, dy / l), n(s.y(), -s.x());
  const Mat29 Ci = corner_beta(i), Cj = corner_beta(j);
  Row9 bs = -0.25 * s.transpose() * (Ci + Cj);
  bs(3 * j) += -1.5 / l;
  bs(3 * i) += 1.5 / l;
  const Row9 bn = 0.5 * n.transpose() * (Ci + Cj);
  return s * bs + n * bn;
}

/// ∂β/∂x and ∂β/∂y at (ξ, η) as a 3×9 curvature matrix.
Eigen::Matrix<double, 3, 9> dkt_B(const std::array<double, 3>& x, const std::array<double, 3>& y,
                                  double xi, double eta) {
  // Quadratic shape functions in area coordinates L0 = 1−ξ−η, L1 = ξ, L2 = η:
  // corners L(2L−1), midsides 4 Li Lj for the edges (1,2), (2,0), (0,1).
  const double L[3] = {1.0 - xi - eta, xi, eta};
  const double dL[3][2] = {{-1.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}};
  Eigen::Matrix2d J;
  J << x[1] - x[0], y[1] - y[0], x[2] - x[0], y[2] - y[0];
  const Eigen::Matrix2d Jinv = J.inverse();
  auto grad = [&](double dxi, double deta) -> Eigen::Vector2d {
    return Jinv * Eigen::Vector2d(dxi, deta);
  };
  Eigen::Matrix<double, 2, 9> dbx = Eigen::Matrix<double, 2, 9>::Zero();  // rows ∂/∂x, ∂/∂y of βx
  Eigen::Matrix<double, 2, 9> dby = Eigen::Matrix<double, 2, 9>::Zero();
  auto add = [&](const Eigen::Vector2d& g, const Mat29& G) {
    dbx += g * G.row(0);
    dby += g * G.row(1);
  };
  for (int a = 0; a < 3; ++a) {
    const double f = 4.0 * L[a] - 1.0;
    add(grad(f * dL[a][0], f * dL[a][1]), corner_beta(a));
  }
  const int edge[3][2] = {{1, 2}, {2, 0}, {0, 1}};
  for (const auto& e : edge) {
    const int i = e[0], j = e[1];
    const double gx = 4.0 * (dL[i][0] * L[j] + L[i] * dL[j][0]);
    const double gy = 4.0 * (dL[i][1] * L[j] + L[i] * dL[j][1]);
    add(grad(gx, gy), midside_beta(i, j, x, y));
  }
  Eigen::Matrix<double, 3, 9> B;
  B.row(0) = dbx.row(0);
  B.row(1) = dby.row(1);
  B.row(2) = dbx.row(1) + dby.row(0);
  return B;
}

}  // namespace

Eigen::Matrix3d plane_stress(double E, double nu) {
  Eigen::Matrix3d C;
  C << 1.0, nu, 0.0, nu, 1.0, 0.0, 0.0, 0.0, 0.5 * (1.0 - nu);
  return C * (E / (1.0 - nu * nu));
}

Eigen::Matrix<double, 9, 3> opt_basic_lumping(const std::array<double, 3>& x, const std::array<double, 3>& y,
                                              double h) {
  // Notation of Felippa (2003): xij = xi − xj, nodes 1, 2, 3 = indices 0, 1, 2.
  const double x12 = x[0] - x[1], x23 = x[1] - x[2], x31 = x[2] - x[0];
  const double y12 = y[0] - y[1], y23 = y[1] - y[2], y31 = y[2] - y[0];
  const double x21 = -x12, x32 = -x23, x13 = -x31;
  const double y21 = -y12, y32 = -y23, y13 = -y31;
  // Force lumping of a constant stress field, drilling share α_b.
  const double ab = 1.5;
  Eigen::Matrix<double, 9, 3> Lm;
  Lm << y23, 0.0, x32,
        0.0, x32, y23,
        ab / 6 * y23 * (y13 - y21), ab / 6 * x32 * (x31 - x12), ab / 3 * (x31 * y13 - x12 * y21),
        y31, 0.0, x13,
        0.0, x13, y31,
        ab / 6 * y31 * (y21 - y32), ab / 6 * x13 * (x12 - x23), ab / 3 * (x12 * y21 - x23 * y32),
        y12, 0.0, x21,
        0.0, x21, y12,
        ab / 6 * y12 * (y32 - y13), ab / 6 * x21 * (x23 - x31), ab / 3 * (x23 * y32 - x31 * y13);
  return Lm * (0.5 * h);
}

Eigen::Matrix3d shell_axes(const std::array<Eigen::Vector3d, 3>& p) {
  const Eigen::Vector3d ex = (p[1] - p[0]).normalized();
  const Eigen::Vector3d ez = (p[1] - p[0]).cross(p[2] - p[0]).normalized();
  const Eigen::Vector3d ey = ez.cross(ex);
  Eigen::Matrix3d R;
  R.row(0) = ex.transpose();
  R.row(1) = ey.transpose();
  R.row(2) = ez.transpose();
  return R;
}

Eigen::Vector3d dkt_curvature(const std::array<double, 3>& x, const std::array<double, 3>& y,
                              const Eigen::Matrix<double, 9, 1>& u, double xi, double eta) {
  return dkt_B(x, y, xi, eta) * u;
}

Matrix9d dkt_stiffness(const std::array<double, 3>& x, const std::array<double, 3>& y,
                       double D, double nu) {
  Eigen::Matrix3d Db;
  Db << 1.0, nu, 0.0, nu, 1.0, 0.0, 0.0, 0.0, 0.5 * (1.0 - nu);
  Db *= D;
  const double area = 0.5 * ((x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]));
  // B is linear in (ξ, η): the 3-point midside rule integrates BᵀDB exactly.
  const double pts[3][2] = {{0.5, 0.0}, {0.5, 0.5}, {0.0, 0.5}};
  Matrix9d K = Matrix9d::Zero();
  for (const auto& q : pts) {
    const auto B = dkt_B(x, y, q[0], q[1]);
    K += (area / 3.0) * B.transpose() * Db * B;
  }
  return K;
}

Matrix9d opt_membrane_stiffness(const std::array<double, 3>& x, const std::array<double, 3>& y,
                                double E, double nu, double h) {
  // Notation of Felippa (2003): xij = xi − xj, nodes 1, 2, 3 = indices 0, 1, 2.
  const double x12 = x[0] - x[1], x23 = x[1] - x[2], x31 = x[2] - x[0];
  const double y12 = y[0] - y[1], y23 = y[1] - y[2], y31 = y[2] - y[0];
  const double x21 = -x12, x32 = -x23, x13 = -x31;
  const double y21 = -y12, y32 = -y23, y13 = -y31;
  const double A = 0.5 * (y21 * x13 - x21 * y13);
  const double V = A * h;
  const Eigen::Matrix3d C = plane_stress(E, nu);

  // Basic stiffness: force lumping of a constant stress field.
  const Eigen::Matrix<double, 9, 3> Lm = opt_basic_lumping(x, y, h);
  Matrix9d K = Lm * C * Lm.transpose() / V;

  // Higher-order stiffness on the deviatoric corner rotations θ̃ = θ − θ_CST.
  Eigen::Matrix<double, 3, 9> T = Eigen::Matrix<double, 3, 9>::Zero();
  for (int r = 0; r < 3; ++r) {
    T(r, 0) = x32; T(r, 1) = y32;
    T(r, 3) = x13; T(r, 4) = y13;
    T(r, 6) = x21; T(r, 7) = y21;
  }
  T /= 4.0 * A;
  T(0, 2) = T(1, 5) = T(2, 8) = 1.0;

  const double l21 = x21 * x21 + y21 * y21, l32 = x32 * x32 + y32 * y32,
               l13 = x13 * x13 + y13 * y13;
  Eigen::Matrix3d Te;
  Te << y23 * y13 * l21, y31 * y21 * l32, y12 * y32 * l13,
        x23 * x13 * l21, x31 * x21 * l32, x12 * x32 * l13,
        (y23 * x31 + x32 * y13) * l21, (y31 * x12 + x13 * y21) * l32, (y12 * x23 + x21 * y32) * l13;
  Te /= 4.0 * A * A;
  const Eigen::Matrix3d Cnat = Te.transpose() * C * Te;

  const double b[10] = {0.0, 1.0, 2.0, 1.0, 0.0, 1.0, -1.0, -1.0, -1.0, -2.0};  // β1..β9 (OPT)
  const double beta0 = std::max(0.5 * (1.0 - 4.0 * nu * nu), 0.01);
  auto Q = [&](int a1, int a2, int a3, int a4, int a5, int a6, int a7, int a8, int a9) {
    Eigen::Matrix3d q;
    q << b[a1] / l21, b[a2] / l21, b[a3] / l21,
         b[a4] / l32, b[a5] / l32, b[a6] / l32,
         b[a7] / l13, b[a8] / l13, b[a9] / l13;
    return Eigen::Matrix3d(q * (2.0 * A / 3.0));
  };
  const Eigen::Matrix3d Q1 = Q(1, 2, 3, 4, 5, 6, 7, 8, 9);
  const Eigen::Matrix3d Q2 = Q(9, 7, 8, 3, 1, 2, 6, 4, 5);
  const Eigen::Matrix3d Q3 = Q(5, 6, 4, 8, 9, 7, 2, 3, 1);
  const Eigen::Matrix3d Q4 = 0.5 * (Q1 + Q2), Q5 = 0.5 * (Q2 + Q3), Q6 = 0.5 * (Q3 + Q1);
  const Eigen::Matrix3d Kth = 0.75 * beta0 * V *
      (Q4.transpose() * Cnat * Q4 + Q5.transpose() * Cnat * Q5 + Q6.transpose() * Cnat * Q6);
  K += T.transpose() * Kth * T;
  return 0.5 * (K + K.transpose());
}

namespace {

// Corner coordinates in the element's own axes R (origin at corner 0) [m].
void local_corners(const std::array<Eigen::Vector3d, 3>& p, const Eigen::Matrix3d& R, std::array<double, 3>& x,
                   std::array<double, 3>& y) {
  for (int a = 0; a < 3; ++a) {
    const Eigen::Vector3d d = R * (p[a] - p[0]);
    x[a] = d.x();
    y[a] = d.y();
  }
}

}  // namespace

Matrix18d shell_local_stiffness(const std::array<Eigen::Vector3d, 3>& p, const ShellProperties& s) {
  std::array<double, 3> x{}, y{};
  local_corners(p, shell_axes(p), x, y);
  const double h = s.thickness, E = s.youngs_modulus, nu = s.poisson_ratio;
  const double D = E * h * h * h / (12.0 * (1.0 - nu * nu));
  const Matrix9d Km = opt_membrane_stiffness(x, y, E, nu, h);
  const Matrix9d Kb = dkt_stiffness(x, y, D, nu);
  Matrix18d k = Matrix18d::Zero();
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) {
      k(kShellMembraneDofs[i], kShellMembraneDofs[j]) = Km(i, j);
      k(kShellBendingDofs[i], kShellBendingDofs[j]) = Kb(i, j);
    }
  return k;
}

ShellElementMatrices shell_element(const std::array<Eigen::Vector3d, 3>& p,
                                   const ShellProperties& s) {
  const Eigen::Matrix3d R = shell_axes(p);
  std::array<double, 3> x{}, y{};
  local_corners(p, R, x, y);
  const double A = 0.5 * (x[1] * y[2] - x[2] * y[1]);
  const double h = s.thickness;
  const Matrix18d k = shell_local_stiffness(p, s);
  Matrix18d m = Matrix18d::Zero();
  const double mu = s.density * h + s.nonstructural_mass_per_area;  // [kg/m²]
  const double rot = s.density * h * h * h / 12.0 * A / 3.0;         // [kg·m²]
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      const double c = mu * A / 12.0 * (a == b ? 2.0 : 1.0);
      for (int d = 0; d < 3; ++d) m(6 * a + d, 6 * b + d) += c;
    }
    for (int d = 3; d < 6; ++d) m(6 * a + d, 6 * a + d) += rot;
  }
  const Matrix18d T = block_rotation<18>(R);
  ShellElementMatrices out;
  out.stiffness = T.transpose() * k * T;
  out.mass = T.transpose() * m * T;
  return out;
}

}  // namespace flapsim::fem
