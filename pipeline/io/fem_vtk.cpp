#include "pipeline/io/fem_vtk.hpp"

#include <cstdio>

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

void write_fem_vtu(const std::filesystem::path& path, const fem::Mesh& mesh, double clamp_y,
                   const fem::ModalResult& modes, const std::vector<StaticResult>& statics) {
  UnstructuredMesh g = fem_unstructured_mesh(mesh, clamp_y);
  for (Eigen::Index k = 0; k < modes.shapes.cols(); ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "mode_%02d", static_cast<int>(k + 1));
    add_nodal_vector(g, name, modes.shapes.col(k));
  }
  for (const StaticResult& s : statics) add_nodal_vector(g, "static_" + s.load.name, s.displacement, true);
  write_vtu(path, g);
}

void write_modes_csv(const std::filesystem::path& path, const fem::ModalResult& modes,
                     const std::vector<fem::ModeKind>& kinds) {
  std::vector<std::vector<std::string>> rows;
  for (Eigen::Index k = 0; k < modes.frequencies_hz.size(); ++k)
    rows.push_back({std::to_string(k + 1), format_number(modes.frequencies_hz(k)),
                    fem::to_string(kinds.at(static_cast<size_t>(k)))});
  write_csv(path, {"mode", "frequency_hz", "kind"}, rows);
}

}  // namespace flapsim::io
