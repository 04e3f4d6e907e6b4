#include "fem/assembly.hpp"

#include <stdexcept>

#include <Eigen/Dense>
#include <string>

#include "fem/frame_element.hpp"
#include "fem/shell_element.hpp"

namespace flapsim::fem {

namespace {

template <int N>
void scatter(std::vector<Eigen::Triplet<double>>& out, const Eigen::Matrix<double, N, N>& ke,
             const int* nodes) {
  constexpr int nn = N / kDofsPerNode;
  for (int a = 0; a < nn; ++a)
    for (int b = 0; b < nn; ++b)
      for (int i = 0; i < kDofsPerNode; ++i)
        for (int j = 0; j < kDofsPerNode; ++j) {
          const double v = ke(kDofsPerNode * a + i, kDofsPerNode * b + j);
          if (v != 0.0) out.emplace_back(dof_index(nodes[a], i), dof_index(nodes[b], j), v);
        }
}

}  // namespace

AssembledSystem assemble(const StructuralModel& model) {
  const Mesh& mesh = model.mesh;
  if (model.shell.size() != mesh.triangles.size() || model.frame.size() != mesh.beams.size())
    throw std::invalid_argument("assemble: one property entry per element is required");
  const int n = mesh.num_dofs();
  std::vector<Eigen::Triplet<double>> kt, mt;
  kt.reserve(mesh.triangles.size() * 18 * 18 + mesh.beams.size() * 144);
  mt.reserve(mesh.triangles.size() * 18 * 6 + mesh.beams.size() * 144);
  AssembledSystem sys;
  sys.element_masses.reserve(mesh.triangles.size() + mesh.beams.size());

  for (size_t e = 0; e < mesh.triangles.size(); ++e) {
    const auto& t = mesh.triangles[e];
    const std::array<Eigen::Vector3d, 3> p{mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]]};
    const double area = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
    if (!(area > 0.0))
      throw std::invalid_argument("assemble: triangle " + std::to_string(e) + " has zero area");
    const ShellProperties& s = model.shell[e];
    const ShellElementMatrices em = shell_element(p, s);
    scatter<18>(kt, em.stiffness, t.data());
    scatter<18>(mt, em.mass, t.data());

    ElementMass m;
    m.kind = ElementMass::Kind::Shell;
    m.index = static_cast<int>(e);
    const double mu = s.density * s.thickness + s.nonstructural_mass_per_area;
    m.mass = mu * area;
    m.centroid = (p[0] + p[1] + p[2]) / 3.0;
    for (const auto& pi : p) m.second_moment += (mu * area / 12.0) * (pi - m.centroid) * (pi - m.centroid).transpose();
    const Eigen::Vector3d nrm = shell_axes(p).row(2).transpose();
    m.second_moment += mu * area * s.thickness * s.thickness / 12.0 * nrm * nrm.transpose();
    sys.element_masses.push_back(m);
    sys.total_mass += m.mass;
  }
  for (size_t e = 0; e < mesh.beams.size(); ++e) {
    const auto& b = mesh.beams[e];
    const Eigen::Vector3d& a = mesh.nodes[b.nodes[0]];
    const Eigen::Vector3d& c = mesh.nodes[b.nodes[1]];
    const double L = (c - a).norm();
    if (!(L > 0.0))
      throw std::invalid_argument("assemble: beam " + std::to_string(e) + " has zero length");
    const FrameProperties& f = model.frame[e];
    const FrameElementMatrices em = frame_element(a, c, f);
    scatter<12>(kt, em.stiffness, b.nodes.data());
    scatter<12>(mt, em.mass, b.nodes.data());

    ElementMass m;
    m.kind = ElementMass::Kind::Beam;
    m.index = static_cast<int>(e);
    m.mass = f.density * f.section.area * L;
    m.centroid = 0.5 * (a + c);
    const Eigen::Matrix3d R = frame_axes(a, c, f.up);
    const Eigen::Vector3d ex = R.row(0), ey = R.row(1), ez = R.row(2);
    m.second_moment = m.mass * L * L / 12.0 * ex * ex.transpose() +
                      f.density * L * (f.section.I_z * ey * ey.transpose() + f.section.I_y * ez * ez.transpose());
    sys.element_masses.push_back(m);
    sys.total_mass += m.mass;
  }
  sys.stiffness.resize(n, n);
  sys.mass.resize(n, n);
  sys.stiffness.setFromTriplets(kt.begin(), kt.end());
  sys.mass.setFromTriplets(mt.begin(), mt.end());
  return sys;
}

}  // namespace flapsim::fem
