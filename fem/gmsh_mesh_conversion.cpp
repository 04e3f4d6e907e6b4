#include "fem/gmsh_mesh_conversion.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <map>

namespace flapsim::fem {

namespace {

/// Each triangle starting at its lowest node (orientation kept), the list sorted.
void put_in_canonical_order(std::vector<std::array<int, 3>>& triangles) {
  for (auto& t : triangles) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(triangles.begin(), triangles.end());
}

}  // namespace

Mesh mesh_from_gmsh(const wings::Wing& wing, const GmshWingMesh& g) {
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
  // gmsh returns the same triangles in an order that can change from one run to the next
  // (two meshings of wings/hawkmoth.toml on one machine swapped 26 pairs of element tags).
  // The order sets the node numbering below and the FEM's summation order, and a round-off
  // difference of 1e-11 in the reduced chain moved make run's mean lift by 0.36 %: sorted,
  // the same wing file always gives the same mesh, bit for bit.
  put_in_canonical_order(mesh.triangles);
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
    put_in_canonical_order(mesh.triangles);  // again, in the new numbering
  }
  return mesh;
}

}  // namespace flapsim::fem
