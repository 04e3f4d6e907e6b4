#include "pipeline/io/fem_vtk.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "pipeline/io/csv_writer.hpp"

namespace flapsim::io {

UnstructuredMesh fem_unstructured_mesh(const fem::Mesh& mesh, double clamp_y) {
  UnstructuredMesh g;
  g.points.resize(3, mesh.num_nodes());
  Eigen::VectorXd clamped(mesh.num_nodes());
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    g.points.col(i) = mesh.nodes[static_cast<size_t>(i)];
    clamped(i) = mesh.nodes[static_cast<size_t>(i)].y() <= clamp_y ? 1.0 : 0.0;
  }
  g.triangles = mesh.triangles;
  Eigen::VectorXd vein(static_cast<Eigen::Index>(mesh.triangles.size() + mesh.beams.size()));
  vein.head(static_cast<Eigen::Index>(mesh.triangles.size())).setConstant(-1.0);
  for (size_t b = 0; b < mesh.beams.size(); ++b) {
    g.segments.push_back(mesh.beams[b].nodes);
    vein(static_cast<Eigen::Index>(mesh.triangles.size() + b)) = mesh.beams[b].vein;
  }
  g.point_data.add_scalar("clamped", clamped);
  g.cell_data.add_scalar("vein", vein);
  return g;
}

void add_nodal_vector(UnstructuredMesh& grid, const std::string& name, const Eigen::VectorXd& dofs,
                      bool with_rotations) {
  const Eigen::Index n = grid.points.cols();
  Eigen::Matrix3Xd t(3, n), r(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    t.col(i) = dofs.segment<3>(fem::kDofsPerNode * i);
    r.col(i) = dofs.segment<3>(fem::kDofsPerNode * i + 3);
  }
  grid.point_data.add_vector(name, t);
  if (with_rotations) grid.point_data.add_vector(name + "_rotation", r);
}

namespace {

// Largest nodal translation |(u_x, u_y, u_z)| of a full DOF vector.
double largest_translation(const Eigen::VectorXd& dofs) {
  double m = 0.0;
  for (Eigen::Index i = 0; i + 2 < dofs.size(); i += fem::kDofsPerNode)
    m = std::max(m, dofs.segment<3>(i).norm());
  return m;
}

}  // namespace

void write_fem_vtu(const std::filesystem::path& path, const fem::Mesh& mesh, double clamp_y,
                   const fem::ModalResult& modes, const std::vector<ModeLabel>& labels,
                   const std::vector<StaticResult>& statics) {
  if (labels.size() != static_cast<std::size_t>(modes.shapes.cols()))
    throw std::invalid_argument("write_fem_vtu: " + std::to_string(labels.size()) + " mode labels for " +
                                std::to_string(modes.shapes.cols()) + " modes");
  UnstructuredMesh g = fem_unstructured_mesh(mesh, clamp_y);
  double span = 0.0;
  for (const auto& p : mesh.nodes) span = std::max(span, p.y());
  const double shown = kModeViewFraction * span;  // [m]
  g.field_data.add_number("span_m", span);
  g.field_data.add_number("mode_view_fraction", kModeViewFraction);
  for (Eigen::Index k = 0; k < modes.shapes.cols(); ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "mode_%02d", static_cast<int>(k + 1));
    const double largest = largest_translation(modes.shapes.col(k));
    const double scale = largest > 0.0 ? shown / largest : 1.0;
    add_nodal_vector(g, name, modes.shapes.col(k) * scale);
    g.field_data.add_number(std::string(name) + "_frequency_Hz", modes.frequencies_hz(k));
    const ModeLabel& label = labels[static_cast<std::size_t>(k)];
    g.field_data.add_text(std::string(name) + "_kind", label.kind);
    g.field_data.add_number(std::string(name) + "_beam_share", label.beam_share);
    g.field_data.add_text(std::string(name) + "_shape_kind", label.shape_kind);
    g.field_data.add_number(std::string(name) + "_scale", scale);
  }
  for (const StaticResult& s : statics) {
    // A force case loads translations [N], a moment case rotations [N·m] (fem/load_cases.hpp).
    double force = 0.0;
    for (Eigen::Index i = 0; i + 2 < s.load.loads.size(); i += fem::kDofsPerNode)
      force += s.load.loads.segment<3>(i).norm();
    const std::string per = force > 0.0 ? "_per_N" : "_per_N_m";
    const std::string base = "static_" + s.load.name;
    const Eigen::Index n = g.points.cols();
    Eigen::Matrix3Xd t(3, n), r(3, n);
    for (Eigen::Index i = 0; i < n; ++i) {
      t.col(i) = s.displacement.segment<3>(fem::kDofsPerNode * i);
      r.col(i) = s.displacement.segment<3>(fem::kDofsPerNode * i + 3);
    }
    g.point_data.add_vector(base + "_m" + per, t);
    g.point_data.add_vector(base + "_rotation_rad" + per, r);
    const double largest = largest_translation(s.displacement);
    g.field_data.add_number(base + "_view_scale", largest > 0.0 ? shown / largest : 1.0);
  }
  write_vtu(path, g);
}

void write_modes_csv(const std::filesystem::path& path, const fem::ModalResult& modes,
                     const std::vector<ModeLabel>& labels) {
  std::vector<std::vector<std::string>> rows;
  for (Eigen::Index k = 0; k < modes.frequencies_hz.size(); ++k) {
    const ModeLabel& label = labels.at(static_cast<std::size_t>(k));
    rows.push_back({std::to_string(k + 1), format_number(modes.frequencies_hz(k)), label.kind,
                    format_number(label.beam_share), label.shape_kind});
  }
  write_csv(path, {"mode", "frequency_hz", "kind", "beam_share", "shape_kind"}, rows);
}

}  // namespace flapsim::io
