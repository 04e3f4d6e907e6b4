#include "fem/tension_field_membrane.hpp"

#include <cmath>

#include "fem/shell_element.hpp"

namespace flapsim::fem {

MembraneResponse tension_field_response(const Eigen::Vector3d& e, double E, double nu) {
  MembraneResponse r;
  const double mean = 0.5 * (e.x() + e.y());
  const double half_diff = 0.5 * (e.x() - e.y()), half_shear = 0.5 * e.z();
  const double radius = std::hypot(half_diff, half_shear);
  const double e1 = mean + radius, e2 = mean - radius;  // principal strains, ε₁ ≥ ε₂
  if (e2 + nu * e1 >= 0.0) {
    const Eigen::Matrix3d C = plane_stress(E, nu);
    r.stress = C * e;
    r.tangent = C;
    r.energy_density = 0.5 * e.dot(r.stress);
    r.state = MembraneState::Taut;
    return r;
  }
  if (e1 <= 0.0) {
    r.stress.setZero();
    r.tangent.setZero();
    r.energy_density = 0.0;
    r.state = MembraneState::Slack;
    return r;
  }
  // Wrinkled: ε₁ > 0 > ε₂ + ν ε₁ gives ε₁ − ε₂ > (1 + ν) ε₁ > 0, so n₁ is defined:
  // n₁ = (c, s) with cos 2θ = half_diff / radius, sin 2θ = half_shear / radius.
  const double cos2 = half_diff / radius, sin2 = half_shear / radius;
  const double cc = 0.5 * (1.0 + cos2), ss = 0.5 * (1.0 - cos2), cs = 0.5 * sin2;
  // dε₁ = mᵀ dε;  the turn of n₁: t·dε·n₁ = qᵀ dε (t = (−s, c)).
  const Eigen::Vector3d m(cc, ss, cs);
  const Eigen::Vector3d q(-cs, cs, 0.5 * cos2);
  const double s1 = E * e1;  // the tension along n₁ [Pa]
  r.stress = s1 * m;
  // dσ = E m mᵀ dε + s₁ d(n₁⊗n₁), d(n₁⊗n₁) = 2 q (qᵀ dε) / (ε₁ − ε₂) in Voigt form.
  r.tangent = E * m * m.transpose() + (2.0 * s1 / (e1 - e2)) * q * q.transpose();
  r.energy_density = 0.5 * E * e1 * e1;
  r.state = MembraneState::Wrinkled;
  return r;
}

}  // namespace flapsim::fem
