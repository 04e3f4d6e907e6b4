#include "fem/wing_mesher.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <map>
#include <new>
#include <string>

#include "fem/gmsh_boundary.hpp"
#include "fem/gmsh_module_loader.hpp"
#include "wings/input_error.hpp"

namespace flapsim::fem {

namespace {

/// gmsh failed on the wing's geometry or mesh sizes: bad input (exit 2) naming the keys
/// that decide them.
[[noreturn]] void throw_meshing_failed(const wings::Wing& wing, const std::string& detail) {
  throw InputError(wing.source_file, 0, "planform",
                   "gmsh cannot mesh this wing (" + detail +
                       "); check the outline (planform.outline or planform.outline_file: no slivers or "
                       "near-touching edges), the veins and mesh.element_size");
}

/// The wing as gmsh is asked to mesh it: sizes resolved and checked, zero-length vein
/// segments dropped.
GmshWingRequest request_for(const wings::Wing& wing, const MeshOptions& options) {
  const double h = options.element_size > 0.0 ? options.element_size : wing.mesh.element_size;
  double hv = options.vein_element_size > 0.0 ? options.vein_element_size : wing.mesh.vein_element_size;
  if (!(h > 0.0)) throw InputError(wing.source_file, 0, "mesh.element_size", "must be positive");
  if (!(hv > 0.0)) hv = h;
  hv = std::min(hv, h);
  if (wing.outline.size() < 3) throw InputError(wing.source_file, 0, "planform", "outline needs at least 3 points");

  GmshWingRequest r;
  r.model_name = wing.name.empty() ? "wing" : wing.name;
  for (const auto& p : wing.outline) r.outline.push_back({p.x(), p.y()});
  for (size_t v = 0; v < wing.veins.size(); ++v) {
    const auto& P = wing.veins[v].points;
    for (size_t i = 0; i + 1 < P.size(); ++i) {
      if ((P[i + 1] - P[i]).norm() < 1e-9 * h) continue;
      r.vein_segments.push_back({static_cast<int>(v), {P[i].x(), P[i].y()}, {P[i + 1].x(), P[i + 1].y()}});
    }
    r.vein_names.push_back(wing.veins[v].name);
  }
  r.element_size = h;
  r.vein_element_size = hv;
  r.msh_path = options.msh_path.string();
  return r;
}

/// gmsh's mesh with contiguous node numbering, triangles counter-clockwise seen from +z,
/// beams along their vein's direction, unused nodes dropped.
Mesh from_gmsh(const wings::Wing& wing, const GmshWingMesh& g) {
  Mesh mesh;
  std::map<std::size_t, int> index;
  for (size_t i = 0; i < g.node_tags.size(); ++i) {
    index[g.node_tags[i]] = static_cast<int>(mesh.nodes.size());
    mesh.nodes.emplace_back(g.coordinates[3 * i], g.coordinates[3 * i + 1], 0.0);
  }
  const auto& tn = g.triangle_nodes;
  for (size_t e = 0; e + 2 < tn.size(); e += 3) {
    std::array<int, 3> t{index.at(tn[e]), index.at(tn[e + 1]), index.at(tn[e + 2])};
    // Counter-clockwise seen from +z, so element normals point along the wing's z.
    const Eigen::Vector3d n = (mesh.nodes[t[1]] - mesh.nodes[t[0]]).cross(mesh.nodes[t[2]] - mesh.nodes[t[0]]);
    if (n.z() < 0.0) std::swap(t[1], t[2]);
    mesh.triangles.push_back(t);
  }
  for (const auto& curve : g.vein_curves) {
    const auto& P = wing.veins[static_cast<size_t>(curve.vein)].points;
    const Eigen::Vector2d dir = P.back() - P.front();
    const auto& ln = curve.line_nodes;
    for (size_t e = 0; e + 1 < ln.size(); e += 2) {
      BeamElement b{{index.at(ln[e]), index.at(ln[e + 1])}, curve.vein};
      const Eigen::Vector2d d = (mesh.nodes[b.nodes[1]] - mesh.nodes[b.nodes[0]]).head<2>();
      if (d.dot(dir) < 0.0) std::swap(b.nodes[0], b.nodes[1]);
      mesh.beams.push_back(b);
    }
  }
  for (const auto& v : wing.veins) mesh.vein_names.push_back(v.name);

  // Drop nodes no element uses (e.g. isolated geometry points).
  std::vector<int> used(mesh.nodes.size(), -1);
  int next = 0;
  auto mark = [&](int n) { if (used[n] < 0) used[n] = next++; };
  for (const auto& t : mesh.triangles) for (int n : t) mark(n);
  for (const auto& b : mesh.beams) for (int n : b.nodes) mark(n);
  if (next != static_cast<int>(mesh.nodes.size())) {
    std::vector<Eigen::Vector3d> nodes(static_cast<size_t>(next));
    for (size_t i = 0; i < used.size(); ++i) if (used[i] >= 0) nodes[used[i]] = mesh.nodes[i];
    for (auto& t : mesh.triangles) for (int& n : t) n = used[n];
    for (auto& b : mesh.beams) for (int& n : b.nodes) n = used[n];
    mesh.nodes = std::move(nodes);
  }
  return mesh;
}

}  // namespace

Mesh mesh_wing(const wings::Wing& wing, const MeshOptions& options) {
  const GmshWingRequest request = request_for(wing, options);
  MeshWithGmshFn& mesh_with_gmsh = gmsh_mesher();
  GmshWingMesh result;
  mesh_with_gmsh(request, result);
  switch (result.status) {
    case GmshWingMesh::Status::ok:
      return from_gmsh(wing, result);
    case GmshWingMesh::Status::no_surface:
      throw InputError(wing.source_file, 0, "planform", "gmsh could not build the wing surface");
    case GmshWingMesh::Status::out_of_memory:
      throw std::bad_alloc();
    case GmshWingMesh::Status::failed:
      break;
  }
  throw_meshing_failed(wing, result.error.empty() ? std::string("unknown error") : result.error);
}

}  // namespace flapsim::fem
