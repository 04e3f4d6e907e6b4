#include "fem/assembly.hpp"

#include <exception>
#include <stdexcept>
#include <thread>

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

/// The triplets and element masses of a range of triangles and of beams, in element order.
struct AssemblyPart {
  std::vector<Eigen::Triplet<double>> kt, mt;
  std::vector<ElementMass> masses;
};

void assemble_part(const StructuralModel& model, std::size_t tri_begin, std::size_t tri_end,
                   std::size_t beam_begin, std::size_t beam_end, AssemblyPart& part) {
  const Mesh& mesh = model.mesh;
  const std::size_t nt = tri_end - tri_begin, nb = beam_end - beam_begin;
  part.kt.reserve(nt * 18 * 18 + nb * 144);
  part.mt.reserve(nt * 18 * 6 + nb * 144);
  part.masses.reserve(nt + nb);
  for (size_t e = tri_begin; e < tri_end; ++e) {
    const auto& t = mesh.triangles[e];
    const std::array<Eigen::Vector3d, 3> p{mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]]};
    const double area = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
    if (!(area > 0.0))
      throw std::invalid_argument("assemble: triangle " + std::to_string(e) + " has zero area");
    const ShellProperties& s = model.shell[e];
    const ShellElementMatrices em = shell_element(p, s);
    scatter<18>(part.kt, em.stiffness, t.data());
    scatter<18>(part.mt, em.mass, t.data());

    ElementMass m;
    m.kind = ElementMass::Kind::Shell;
    m.index = static_cast<int>(e);
    const double mu = s.density * s.thickness + s.nonstructural_mass_per_area;
    m.mass = mu * area;
    m.centroid = (p[0] + p[1] + p[2]) / 3.0;
    for (const auto& pi : p) m.second_moment += (mu * area / 12.0) * (pi - m.centroid) * (pi - m.centroid).transpose();
    const Eigen::Vector3d nrm = shell_axes(p).row(2).transpose();
    m.second_moment += mu * area * s.thickness * s.thickness / 12.0 * nrm * nrm.transpose();
    part.masses.push_back(m);
  }
  for (size_t e = beam_begin; e < beam_end; ++e) {
    const auto& b = mesh.beams[e];
    const Eigen::Vector3d& a = mesh.nodes[b.nodes[0]];
    const Eigen::Vector3d& c = mesh.nodes[b.nodes[1]];
    const double L = (c - a).norm();
    if (!(L > 0.0))
      throw std::invalid_argument("assemble: beam " + std::to_string(e) + " has zero length");
    const FrameProperties& f = model.frame[e];
    const FrameElementMatrices em = frame_element(a, c, f);
    scatter<12>(part.kt, em.stiffness, b.nodes.data());
    scatter<12>(part.mt, em.mass, b.nodes.data());

    ElementMass m;
    m.kind = ElementMass::Kind::Beam;
    m.index = static_cast<int>(e);
    m.mass = f.density * f.section.area * L;
    m.centroid = 0.5 * (a + c);
    const Eigen::Matrix3d R = frame_axes(a, c, f.up);
    const Eigen::Vector3d ex = R.row(0), ey = R.row(1), ez = R.row(2);
    m.second_moment = m.mass * L * L / 12.0 * ex * ex.transpose() +
                      f.density * L * (f.section.I_z * ey * ey.transpose() + f.section.I_y * ez * ez.transpose());
    part.masses.push_back(m);
  }
}

/// Runs \p a on a second thread and \p b on this one; rethrows the first failure.
template <typename A, typename B>
void side_by_side(A&& a, B&& b) {
  std::exception_ptr failed;
  std::thread worker([&] {
    try {
      a();
    } catch (...) {
      failed = std::current_exception();
    }
  });
  try {
    b();
  } catch (...) {
    worker.join();
    throw;
  }
  worker.join();
  if (failed) std::rethrow_exception(failed);
}

}  // namespace

AssembledSystem assemble(const StructuralModel& model, int threads) {
  const Mesh& mesh = model.mesh;
  if (model.shell.size() != mesh.triangles.size() || model.frame.size() != mesh.beams.size())
    throw std::invalid_argument("assemble: one property entry per element is required");
  const int n = mesh.num_dofs();
  const std::size_t nt = mesh.triangles.size(), nb = mesh.beams.size();
  AssemblyPart first;
  if (threads > 1 && nt > 1) {
    // Triangles [0, nt/2) on a second thread; the rest of them and the beams here.
    AssemblyPart second;
    side_by_side([&] { assemble_part(model, 0, nt / 2, 0, 0, first); },
                 [&] { assemble_part(model, nt / 2, nt, 0, nb, second); });
    first.kt.insert(first.kt.end(), second.kt.begin(), second.kt.end());
    first.mt.insert(first.mt.end(), second.mt.begin(), second.mt.end());
    first.masses.insert(first.masses.end(), second.masses.begin(), second.masses.end());
  } else {
    assemble_part(model, 0, nt, 0, nb, first);
  }
  AssembledSystem sys;
  sys.element_masses = std::move(first.masses);
  for (const ElementMass& m : sys.element_masses) sys.total_mass += m.mass;
  sys.stiffness.resize(n, n);
  sys.mass.resize(n, n);
  if (threads > 1) {
    side_by_side([&] { sys.stiffness.setFromTriplets(first.kt.begin(), first.kt.end()); },
                 [&] { sys.mass.setFromTriplets(first.mt.begin(), first.mt.end()); });
  } else {
    sys.stiffness.setFromTriplets(first.kt.begin(), first.kt.end());
    sys.mass.setFromTriplets(first.mt.begin(), first.mt.end());
  }
  return sys;
}

}  // namespace flapsim::fem
