#include "fem/nonlinear_assembly.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "fem/nodal_rotation.hpp"

namespace flapsim::fem {

namespace {

using Vector18d = Eigen::Matrix<double, 18, 1>;
using Vector12d = Eigen::Matrix<double, 12, 1>;

/// Rotation-invariant frame mass (nonlinear_assembly.hpp): linear-interpolation
/// translational mass and the torsional inertia lumped isotropically.
Matrix12d invariant_frame_mass(double length, const FrameProperties& f) {
  Matrix12d m = Matrix12d::Zero();
  const double c = f.density * f.section.area * length / 6.0;  // [kg]
  const double j = f.density * f.section.polar_moment * length / 2.0;  // [kg·m²]
  for (int d = 0; d < 3; ++d) {
    m(d, d) = m(6 + d, 6 + d) = 2.0 * c;
    m(d, 6 + d) = m(6 + d, d) = c;
    m(3 + d, 3 + d) = m(9 + d, 9 + d) = j;
  }
  return m;
}

template <int N>
void add_triplets(std::vector<Eigen::Triplet<double>>& out, const Eigen::Matrix<double, 6 * N, 6 * N>& m,
                  const int* nodes) {
  for (int a = 0; a < N; ++a)
    for (int b = 0; b < N; ++b)
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
          const double v = m(6 * a + i, 6 * b + j);
          if (v != 0.0) out.emplace_back(dof_index(nodes[a], i), dof_index(nodes[b], j), v);
        }
}

}  // namespace

CorotationalModel make_corotational_model(const StructuralModel& sm, MembraneLaw membrane_law) {
  const Mesh& mesh = sm.mesh;
  if (sm.shell.size() != mesh.triangles.size() || sm.frame.size() != mesh.beams.size())
    throw std::invalid_argument("make_corotational_model: one property entry per element is required");
  CorotationalModel m;
  m.membrane_law = membrane_law;
  m.reference_positions = mesh.nodes;
  std::vector<Eigen::Triplet<double>> mt;
  for (size_t e = 0; e < mesh.triangles.size(); ++e) {
    const auto& t = mesh.triangles[e];
    const std::array<Eigen::Vector3d, 3> p{mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]]};
    if (!((p[1] - p[0]).cross(p[2] - p[0]).norm() > 0.0))
      throw std::invalid_argument("make_corotational_model: triangle " + std::to_string(e) + " has zero area");
    m.shells.push_back(make_corotational_shell(t, p, sm.shell[e]));
    if (membrane_law == MembraneLaw::Film)
      m.films.push_back(make_film_triangle(t, p, sm.shell[e].thickness, sm.shell[e].youngs_modulus,
                                           sm.shell[e].poisson_ratio));
    add_triplets<3>(mt, shell_element(p, sm.shell[e]).mass, t.data());
  }
  if (membrane_law == MembraneLaw::Film) {
    std::vector<double> D(mesh.triangles.size());
    for (size_t e = 0; e < mesh.triangles.size(); ++e) {
      const ShellProperties& s = sm.shell[e];
      D[e] = s.youngs_modulus * s.thickness * s.thickness * s.thickness / (12.0 * (1.0 - s.poisson_ratio * s.poisson_ratio));
    }
    m.hinges = make_film_hinges(mesh.triangles, D, mesh.nodes);
  }
  for (size_t e = 0; e < mesh.beams.size(); ++e) {
    const auto& b = mesh.beams[e];
    const Eigen::Vector3d& a = mesh.nodes[b.nodes[0]];
    const Eigen::Vector3d& c = mesh.nodes[b.nodes[1]];
    if (!((c - a).norm() > 0.0))
      throw std::invalid_argument("make_corotational_model: beam " + std::to_string(e) + " has zero length");
    m.frames.push_back(make_corotational_frame(b.nodes, a, c, sm.frame[e]));
    add_triplets<2>(mt, invariant_frame_mass((c - a).norm(), sm.frame[e]), b.nodes.data());
  }
  m.mass.resize(mesh.num_dofs(), mesh.num_dofs());
  m.mass.setFromTriplets(mt.begin(), mt.end());
  return m;
}

std::vector<int> film_only_rotation_dofs(const CorotationalModel& model) {
  std::vector<int> dofs;
  if (model.membrane_law != MembraneLaw::Film) return dofs;
  std::vector<char> film(static_cast<size_t>(model.num_nodes()), 0), frame(film.size(), 0);
  for (const auto& e : model.films)
    for (int n : e.nodes) film[static_cast<size_t>(n)] = 1;
  for (const auto& e : model.frames)
    for (int n : e.nodes) frame[static_cast<size_t>(n)] = 1;
  for (int n = 0; n < model.num_nodes(); ++n)
    if (film[static_cast<size_t>(n)] && !frame[static_cast<size_t>(n)])
      for (int d = 3; d < kDofsPerNode; ++d) dofs.push_back(kDofsPerNode * n + d);
  return dofs;
}

CorotationalState reference_state(const CorotationalModel& model) {
  CorotationalState s;
  s.position = model.reference_positions;
  s.rotation.assign(model.reference_positions.size(), Eigen::Matrix3d::Identity());
  return s;
}

void apply_increment(CorotationalState& s, const Eigen::VectorXd& du) {
  for (size_t i = 0; i < s.position.size(); ++i) {
    const Eigen::Index k = static_cast<Eigen::Index>(6 * i);
    s.position[i] += du.segment<3>(k);
    const Eigen::Vector3d w = du.segment<3>(k + 3);
    if (w.squaredNorm() > 0.0) s.rotation[i] = rotation_matrix(w) * s.rotation[i];
  }
}

Eigen::VectorXd displacement_vector(const CorotationalModel& model, const CorotationalState& s) {
  Eigen::VectorXd u(model.num_dofs());
  for (int i = 0; i < model.num_nodes(); ++i) {
    u.segment<3>(6 * i) = s.position[i] - model.reference_positions[i];
    u.segment<3>(6 * i + 3) = rotation_vector(s.rotation[i]);
  }
  return u;
}

NonlinearAssembler::NonlinearAssembler(const CorotationalModel& model, Constraints constraints, TangentForm form)
    : model_(model), constraints_(std::move(constraints)), form_(form), free_dofs_(constraints_.free_dofs()) {
  const bool lower = form == TangentForm::SymmetricLower;
  if (constraints_.num_dofs() != model.num_dofs())
    throw std::invalid_argument("NonlinearAssembler: constraints do not match the model's DOF count");
  const std::vector<int> fi = constraints_.free_index();
  const int nf = constraints_.num_free();
  std::vector<Eigen::Triplet<double>> t;
  auto pattern = [&](const int* nodes, int nn) {
    for (int a = 0; a < nn; ++a)
      for (int b = 0; b < nn; ++b)
        for (int i = 0; i < 6; ++i)
          for (int j = 0; j < 6; ++j) {
            const int r = fi[dof_index(nodes[a], i)], c = fi[dof_index(nodes[b], j)];
            if (r >= 0 && c >= 0 && (r >= c || !lower)) t.emplace_back(r, c, 0.0);
          }
  };
  for (const auto& e : model.shells) pattern(e.nodes.data(), 3);
  for (const auto& e : model.frames) pattern(e.nodes.data(), 2);
  for (const auto& e : model.hinges) pattern(e.nodes.data(), 4);
  tangent_.resize(nf, nf);
  tangent_.setFromTriplets(t.begin(), t.end());
  tangent_.makeCompressed();
  auto slot = [&](int gr, int gc) {
    const int r = fi[gr], c = fi[gc];
    if (r < 0 || c < 0 || (lower && r < c)) return -1;
    const int* begin = tangent_.innerIndexPtr() + tangent_.outerIndexPtr()[c];
    const int* end = tangent_.innerIndexPtr() + tangent_.outerIndexPtr()[c + 1];
    const int* it = std::lower_bound(begin, end, r);
    return static_cast<int>(it - tangent_.innerIndexPtr());
  };
  auto fill = [&](auto& slots, const int* nodes, int nn) {
    for (int a = 0; a < nn; ++a)
      for (int b = 0; b < nn; ++b)
        for (int i = 0; i < 6; ++i)
          for (int j = 0; j < 6; ++j)
            slots[(6 * a + i) * 6 * nn + 6 * b + j] = slot(dof_index(nodes[a], i), dof_index(nodes[b], j));
  };
  shell_slots_.resize(model.shells.size());
  frame_slots_.resize(model.frames.size());
  for (size_t e = 0; e < model.shells.size(); ++e) fill(shell_slots_[e], model.shells[e].nodes.data(), 3);
  for (size_t e = 0; e < model.frames.size(); ++e) fill(frame_slots_[e], model.frames[e].nodes.data(), 2);
  auto range_of = [](const auto& slots) {
    std::array<int, 2> range{std::numeric_limits<int>::max(), -1};
    for (int q : slots)
      if (q >= 0) range = {std::min(range[0], q), std::max(range[1], q)};
    return range;
  };
  shell_slot_range_.resize(model.shells.size());
  frame_slot_range_.resize(model.frames.size());
  for (size_t e = 0; e < model.shells.size(); ++e) shell_slot_range_[e] = range_of(shell_slots_[e]);
  for (size_t e = 0; e < model.frames.size(); ++e) frame_slot_range_[e] = range_of(frame_slots_[e]);
  hinge_slots_.resize(model.hinges.size());
  for (size_t e = 0; e < model.hinges.size(); ++e) fill(hinge_slots_[e], model.hinges[e].nodes.data(), 4);
  hinge_f_.resize(model.hinges.size());
  hinge_K_.resize(model.hinges.size());
  mass_values_.assign(static_cast<size_t>(tangent_.nonZeros()), 0.0);
  translation_slots_.resize(static_cast<size_t>(model.num_nodes()));
  for (int n = 0; n < model.num_nodes(); ++n)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        translation_slots_[static_cast<size_t>(n)][static_cast<size_t>(3 * i + j)] = [&] {
          const int s = slot(dof_index(n, i), dof_index(n, j));  // -1, or where the entry would be
          const int r = fi[dof_index(n, i)];
          return s >= 0 && s < tangent_.nonZeros() && tangent_.innerIndexPtr()[s] == r ? s : -1;
        }();
  for (int c = 0; c < model.mass.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(model.mass, c); it; ++it) {
      const int s = slot(static_cast<int>(it.row()), c);
      if (s >= 0) mass_values_[static_cast<size_t>(s)] += it.value();
    }
  shell_K_.resize(model.shells.size());
  shell_f_.resize(model.shells.size());
  frame_K_.resize(model.frames.size());
  frame_f_.resize(model.frames.size());
  energy_.resize(model.shells.size() + model.frames.size() + model.hinges.size());
  for (int k = 0; k < 3; ++k) {
    path_shell_d_[static_cast<size_t>(k)].resize(model.shells.size());
    path_frame_d_[static_cast<size_t>(k)].resize(model.frames.size());
  }
}

void NonlinearAssembler::record_correction_path(const CorotationalState& state, int point) {
  if (point < 0 || point > 2) throw std::invalid_argument("record_correction_path: point must be 0, 1 or 2");
  // The deformations alone (the forces at the path's points are not needed): the elements
  // that take a linearised geometric force, linear shells and frames.
  record_deformations(state, false, path_shell_d_[static_cast<size_t>(point)],
                      path_frame_d_[static_cast<size_t>(point)]);
}

void NonlinearAssembler::record_step_start(const CorotationalState& state) {
  start_shell_d_.resize(model_.shells.size());
  start_frame_d_.resize(model_.frames.size());
  record_deformations(state, true, start_shell_d_, start_frame_d_);
}

void NonlinearAssembler::record_deformations(const CorotationalState& state, bool all_shells,
                                             std::vector<Eigen::Matrix<double, 18, 1>>& shell_d,
                                             std::vector<Eigen::Matrix<double, 12, 1>>& frame_d) const {
  const int ns =
      model_.membrane_law == MembraneLaw::Elastic || (all_shells && model_.membrane_law != MembraneLaw::Film)
          ? static_cast<int>(model_.shells.size())
          : 0;
  const int nb = static_cast<int>(model_.frames.size());
  const auto& p = state.position;
  const auto& r = state.rotation;
#pragma omp parallel for schedule(static) if (ns + nb > 512)
  for (int e = 0; e < ns; ++e) {
    const CorotationalShell& el = model_.shells[static_cast<size_t>(e)];
    const std::array<Eigen::Vector3d, 3> x{p[el.nodes[0]], p[el.nodes[1]], p[el.nodes[2]]};
    const std::array<Eigen::Matrix3d, 3> R{r[el.nodes[0]], r[el.nodes[1]], r[el.nodes[2]]};
    std::array<Eigen::Vector3d, 3> xbar;
    eicr_deformation<3>(el.reference_local, el.reference_axes, shell_corotated_frame(x).axes, x, R, xbar,
                        shell_d[static_cast<size_t>(e)]);
  }
#pragma omp parallel for schedule(static) if (ns + nb > 512)
  for (int e = 0; e < nb; ++e) {
    const CorotationalFrame& el = model_.frames[static_cast<size_t>(e)];
    const std::array<Eigen::Vector3d, 2> x{p[el.nodes[0]], p[el.nodes[1]]};
    const std::array<Eigen::Matrix3d, 2> R{r[el.nodes[0]], r[el.nodes[1]]};
    std::array<Eigen::Vector3d, 2> xbar;
    eicr_deformation<2>(el.reference_local, el.reference_axes, frame_corotated_frame(el, x, R).axes, x, R, xbar,
                        frame_d[static_cast<size_t>(e)]);
  }
}

void NonlinearAssembler::add_translation_blocks(const std::vector<int>& nodes,
                                                const std::vector<Eigen::Matrix3d>& blocks, double factor) {
  if (nodes.size() != blocks.size())
    throw std::invalid_argument("add_translation_blocks: one block per node is required");
  double* val = tangent_.valuePtr();
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const auto& sl = translation_slots_.at(static_cast<size_t>(nodes[k]));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (const int s = sl[static_cast<size_t>(3 * i + j)]; s >= 0) val[s] += factor * blocks[k](i, j);
  }
}

void NonlinearAssembler::load_mass_into_tangent() {
  std::copy(mass_values_.begin(), mass_values_.end(), tangent_.valuePtr());
}

double NonlinearAssembler::evaluate(const CorotationalState& s, Eigen::VectorXd& f_int, bool tangent,
                                    const TangentExtras& ex) {
  const int ns = static_cast<int>(model_.shells.size());
  const int nb = static_cast<int>(model_.frames.size());
#pragma omp parallel for schedule(static) if (ns + nb > 512)
  for (int e = 0; e < ns; ++e) {
    const CorotationalShell& el = model_.shells[static_cast<size_t>(e)];
    const std::array<Eigen::Vector3d, 3> x{s.position[el.nodes[0]], s.position[el.nodes[1]], s.position[el.nodes[2]]};
    const std::array<Eigen::Matrix3d, 3> R{s.rotation[el.nodes[0]], s.rotation[el.nodes[1]], s.rotation[el.nodes[2]]};
    EicrDamping<3> damp;
    if (ex.damping_rate > 0.0 && ex.damping != 0.0)
      damp = {&start_shell_d_.at(static_cast<size_t>(e)), ex.damping * ex.damping_rate};
    Matrix18d* K = tangent ? &shell_K_[static_cast<size_t>(e)] : nullptr;
    if (model_.membrane_law == MembraneLaw::Film) {  // translations only, no damping
      Eigen::Matrix<double, 9, 1> f9;
      Eigen::Matrix<double, 9, 9> K9;
      energy_[static_cast<size_t>(e)] =
          film_triangle_force(model_.films[static_cast<size_t>(e)], x, f9, K != nullptr ? &K9 : nullptr);
      Vector18d& f18 = shell_f_[static_cast<size_t>(e)];
      f18.setZero();
      for (int a = 0; a < 3; ++a) f18.segment<3>(6 * a) = f9.segment<3>(3 * a);
      if (K != nullptr) {
        K->setZero();
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) K->block<3, 3>(6 * a, 6 * b) = K9.block<3, 3>(3 * a, 3 * b);
      }
      continue;
    }
    const bool symmetric = form_ == TangentForm::SymmetricLower;
    energy_[static_cast<size_t>(e)] =
        model_.membrane_law == MembraneLaw::TensionField
            ? eicr_force_with_law<3>(ShellTensionFieldLaw{el}, el.reference_local, el.reference_axes,
                                     shell_corotated_frame(x), x, R, shell_f_[static_cast<size_t>(e)], K, damp,
                                     symmetric)
            : [&] {
                const size_t i = static_cast<size_t>(e);
                Vector18d g;  // the local force along the last correction, taken linearly
                const bool linearised = ex.linearised_geometric_force && K != nullptr;
                if (linearised) {
                  const Vector18d d_lin =
                      4.0 * path_shell_d_[1][i] - 2.0 * path_shell_d_[0][i] - path_shell_d_[2][i];
                  // with the damping's part taken the same way: (a₁/h) k (d_lin − d_n)
                  g = damp.start_deformation != nullptr
                          ? Vector18d(el.local_stiffness * ((1.0 + damp.coefficient) * d_lin -
                                                            damp.coefficient * *damp.start_deformation))
                          : Vector18d(el.local_stiffness * d_lin);
                }
                return eicr_force_with_law<3>(ShellLinearLaw{el}, el.reference_local, el.reference_axes,
                                              shell_corotated_frame(x), x, R, shell_f_[i], K, damp, symmetric,
                                              linearised ? &g : nullptr);
              }();
  }
#pragma omp parallel for schedule(static) if (ns + nb > 512)
  for (int e = 0; e < nb; ++e) {
    const CorotationalFrame& el = model_.frames[static_cast<size_t>(e)];
    const std::array<Eigen::Vector3d, 2> x{s.position[el.nodes[0]], s.position[el.nodes[1]]};
    const std::array<Eigen::Matrix3d, 2> R{s.rotation[el.nodes[0]], s.rotation[el.nodes[1]]};
    const size_t i = static_cast<size_t>(e);
    EicrDamping<2> damp;
    if (ex.damping_rate > 0.0 && ex.damping != 0.0)
      damp = {&start_frame_d_.at(i), ex.damping * ex.damping_rate};
    Vector12d g;  // the local force along the last correction, taken linearly
    const bool linearised = ex.linearised_geometric_force && tangent;
    if (linearised) {
      const Vector12d d_lin = 4.0 * path_frame_d_[1][i] - 2.0 * path_frame_d_[0][i] - path_frame_d_[2][i];
      g = damp.start_deformation != nullptr
              ? Vector12d(el.local_stiffness *
                          ((1.0 + damp.coefficient) * d_lin - damp.coefficient * *damp.start_deformation))
              : Vector12d(el.local_stiffness * d_lin);
    }
    energy_[static_cast<size_t>(ns + e)] =
        eicr_force<2>(el.local_stiffness, el.reference_local, el.reference_axes, frame_corotated_frame(el, x, R), x,
                      R, frame_f_[i], tangent ? &frame_K_[i] : nullptr, damp, form_ == TangentForm::SymmetricLower,
                      linearised ? &g : nullptr);
  }
  const int nh = static_cast<int>(model_.hinges.size());
#pragma omp parallel for schedule(static) if (nh > 512)
  for (int e = 0; e < nh; ++e) {
    const FilmHinge& h = model_.hinges[static_cast<size_t>(e)];
    const std::array<Eigen::Vector3d, 4> x{s.position[h.nodes[0]], s.position[h.nodes[1]], s.position[h.nodes[2]],
                                           s.position[h.nodes[3]]};
    energy_[static_cast<size_t>(ns + nb + e)] = film_hinge_force(
        h, x, hinge_f_[static_cast<size_t>(e)], tangent ? &hinge_K_[static_cast<size_t>(e)] : nullptr);
  }
  f_int.setZero(model_.num_dofs());
  double energy = 0.0;
  for (double w : energy_) energy += w;
  for (int e = 0; e < ns; ++e)
    for (int a = 0; a < 3; ++a) f_int.segment<6>(6 * model_.shells[e].nodes[a]) += shell_f_[e].segment<6>(6 * a);
  for (int e = 0; e < nb; ++e)
    for (int a = 0; a < 2; ++a) f_int.segment<6>(6 * model_.frames[e].nodes[a]) += frame_f_[e].segment<6>(6 * a);
  for (int e = 0; e < nh; ++e)
    for (int a = 0; a < 4; ++a) f_int.segment<3>(6 * model_.hinges[e].nodes[a]) += hinge_f_[e].segment<3>(3 * a);
  if (tangent) {
    // The tangent's values in kScatterParts ranges, one a thread: each range takes the mass
    // term and then the elements' entries that fall in it, element by element in order, so
    // every entry's sum runs in element order whatever the thread count (the same bits).
    double* val = tangent_.valuePtr();
    const long nnz = tangent_.nonZeros();
#pragma omp parallel for schedule(static, 1) if (ns + nb > 512)
    for (int part = 0; part < kScatterParts; ++part) {
      const int lo = static_cast<int>(nnz * part / kScatterParts), hi = static_cast<int>(nnz * (part + 1) / kScatterParts);
      for (int i = lo; i < hi; ++i) val[i] = ex.mass_scale * mass_values_[static_cast<size_t>(i)];
      auto inside = [&](const std::array<int, 2>& range) { return range[1] >= lo && range[0] < hi; };
      for (int e = 0; e < ns; ++e) {
        if (!inside(shell_slot_range_[static_cast<size_t>(e)])) continue;
        const double* k = shell_K_[e].data();  // column-major: k[col * 18 + row]
        const auto& sl = shell_slots_[e];
        for (int r = 0; r < 18; ++r)
          for (int c = 0; c < 18; ++c)
            if (const int q = sl[r * 18 + c]; q >= lo && q < hi) val[q] += k[c * 18 + r];
      }
      for (int e = 0; e < nb; ++e) {
        if (!inside(frame_slot_range_[static_cast<size_t>(e)])) continue;
        const double* k = frame_K_[e].data();
        const auto& sl = frame_slots_[e];
        for (int r = 0; r < 12; ++r)
          for (int c = 0; c < 12; ++c)
            if (const int q = sl[r * 12 + c]; q >= lo && q < hi) val[q] += k[c * 12 + r];
      }
      for (int e = 0; e < nh; ++e) {  // translations only: row 3a+i of K is DOF 6a+i
        const auto& K = hinge_K_[e];
        const auto& sl = hinge_slots_[e];
        for (int a = 0; a < 4; ++a)
          for (int i = 0; i < 3; ++i)
            for (int b = 0; b < 4; ++b)
              for (int j = 0; j < 3; ++j) {
                const int q = sl[(6 * a + i) * 24 + 6 * b + j];
                if (q >= lo && q < hi) val[q] += K(3 * a + i, 3 * b + j);
              }
      }
    }
  }
  return energy;
}

}  // namespace flapsim::fem
