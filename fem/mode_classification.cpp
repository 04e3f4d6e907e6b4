#include "fem/mode_classification.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace flapsim::fem {

std::string to_string(ModeKind kind) {
  switch (kind) {
    case ModeKind::Rigid: return "rigid";
    case ModeKind::Bending: return "bending";
    case ModeKind::Torsion: return "torsion";
    case ModeKind::Chordwise: return "chordwise";
    case ModeKind::InPlane: return "in-plane";
  }
  return "unknown";
}

std::vector<double> nodal_masses(const Mesh& mesh, const AssembledSystem& system) {
  std::vector<double> m(mesh.nodes.size(), 0.0);
  for (const ElementMass& e : system.element_masses) {
    if (e.kind == ElementMass::Kind::Shell) {
      for (int n : mesh.triangles[static_cast<size_t>(e.index)]) m[n] += e.mass / 3.0;
    } else {
      for (int n : mesh.beams[static_cast<size_t>(e.index)].nodes) m[n] += e.mass / 2.0;
    }
  }
  return m;
}

ModeShapeMeasures measure_mode_shape(const Mesh& mesh, const std::vector<double>& w,
                                     const Eigen::VectorXd& shape, int strips) {
  ModeShapeMeasures out;
  const int n = mesh.num_nodes();
  double e_ip = 0.0, e_oop = 0.0;
  double ymin = std::numeric_limits<double>::infinity(), ymax = -ymin;
  for (int i = 0; i < n; ++i) {
    const double ux = shape(dof_index(i, UX)), uy = shape(dof_index(i, UY)), uz = shape(dof_index(i, UZ));
    e_ip += w[i] * (ux * ux + uy * uy);
    e_oop += w[i] * uz * uz;
    ymin = std::min(ymin, mesh.nodes[i].y());
    ymax = std::max(ymax, mesh.nodes[i].y());
  }
  const double total = e_ip + e_oop;
  if (!(total > 0.0)) return out;
  out.in_plane = e_ip / total;

  strips = std::max(1, strips);
  const double dy = (ymax - ymin) / strips;
  struct Acc { double W = 0, Wx = 0, Wxx = 0, Wu = 0, Wxu = 0, Wuu = 0, xmin = 1e300, xmax = -1e300; };
  std::vector<Acc> acc(static_cast<size_t>(strips));
  for (int i = 0; i < n; ++i) {
    const int s = std::clamp(static_cast<int>((mesh.nodes[i].y() - ymin) / dy), 0, strips - 1);
    const double x = mesh.nodes[i].x(), u = shape(dof_index(i, UZ));
    Acc& a = acc[static_cast<size_t>(s)];
    a.W += w[i]; a.Wx += w[i] * x; a.Wxx += w[i] * x * x;
    a.Wu += w[i] * u; a.Wxu += w[i] * x * u; a.Wuu += w[i] * u * u;
    a.xmin = std::min(a.xmin, x); a.xmax = std::max(a.xmax, x);
  }
  double eb = 0.0, et = 0.0, ec = 0.0;
  double prev_mean = 0.0;
  for (const Acc& a : acc) {
    if (a.W <= 0.0) continue;
    const double xbar = a.Wx / a.W, ubar = a.Wu / a.W;
    const double sxx = a.Wxx - a.W * xbar * xbar, sxu = a.Wxu - a.W * xbar * ubar;
    const double slope = sxx > 1e-300 ? sxu / sxx : 0.0;
    const double suu = a.Wuu - a.W * ubar * ubar;
    // The fit's energy Σ w (ū + b(x − x̄))² = W ū² + b² Sxx (x̄ the strip's mass centre,
    // so no cross term): the section's translation (bending) and its rotation about its
    // mass centre (torsion). Binning each strip's whole energy by where its fitted line
    // crosses zero called the hawkmoth's second bending mode (435 Hz, its sections
    // twisting about an axis inside the chord as they translate) torsion.
    ec += std::max(0.0, suu - slope * sxu);
    eb += a.W * ubar * ubar;
    et += slope * sxu;  // b² Sxx
    if (std::abs(ubar) > 0.0 && prev_mean * ubar < 0.0 &&
        std::abs(ubar) > 1e-3 * std::sqrt(e_oop / std::max(a.W, 1e-300)))
      ++out.spanwise_sign_changes;
    if (std::abs(ubar) > 0.0) prev_mean = ubar;
  }
  const double eo = eb + et + ec;
  if (eo > 0.0) {
    out.bending = eb / eo;
    out.torsion = et / eo;
    out.chordwise = ec / eo;
  }
  return out;
}

ModeKind classify_mode_shape(const ModeShapeMeasures& m) {
  if (m.in_plane > 0.5) return ModeKind::InPlane;
  if (m.chordwise >= m.bending && m.chordwise >= m.torsion) return ModeKind::Chordwise;
  return m.torsion > m.bending ? ModeKind::Torsion : ModeKind::Bending;
}

std::vector<ModeKind> classify_modes(const Mesh& mesh, const AssembledSystem& system,
                                     const Eigen::MatrixXd& shapes, const Eigen::VectorXd& f,
                                     double rigid_fraction) {
  const std::vector<double> w = nodal_masses(mesh, system);
  const double fmax = f.size() ? f.cwiseAbs().maxCoeff() : 0.0;
  std::vector<ModeKind> kinds;
  for (Eigen::Index k = 0; k < shapes.cols(); ++k) {
    if (std::abs(f(k)) < rigid_fraction * fmax) {
      kinds.push_back(ModeKind::Rigid);
      continue;
    }
    kinds.push_back(classify_mode_shape(measure_mode_shape(mesh, w, shapes.col(k))));
  }
  return kinds;
}

}  // namespace flapsim::fem
