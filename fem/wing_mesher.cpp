#include "fem/wing_mesher.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "fem/gmsh_boundary.hpp"
#include "fem/gmsh_mesh_conversion.hpp"
#include "fem/gmsh_module_loader.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/planform_geometry.hpp"
#include "wings/loader/vein_junctions.hpp"

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

/// The wing as gmsh is asked to mesh it: sizes resolved and checked, \p veins (the wing's,
/// their junctions closed for the resolved vein size) returned, zero-length vein segments
/// dropped.
GmshWingRequest request_for(const wings::Wing& wing, const MeshOptions& options,
                            std::vector<wings::Vein>& veins) {
  const double h = options.element_size > 0.0 ? options.element_size : wing.mesh.element_size;
  double hv = options.vein_element_size > 0.0 ? options.vein_element_size : wing.mesh.vein_element_size;
  if (!(h > 0.0)) throw InputError(wing.source_file, 0, "mesh.element_size", "must be positive");
  if (!(hv > 0.0)) hv = h;
  hv = std::min(hv, h);
  if (wing.outline.size() < 3) throw InputError(wing.source_file, 0, "planform", "outline needs at least 3 points");
  // A vein's end written so near another vein that the gap would be meshed into slivers is
  // on it (wings/loader/vein_junctions.hpp); round-off is left alone, as on the outline.
  veins = wing.veins;
  wings::snap_vein_ends_onto_other_veins(veins, wings::vein_junction_tolerance(wing.span, hv),
                                         1e-12 * wing.span);

  GmshWingRequest r;
  r.model_name = wing.name.empty() ? "wing" : wing.name;
  for (const auto& p : wing.outline) r.outline.push_back({p.x(), p.y()});
  for (size_t v = 0; v < veins.size(); ++v) {
    const auto& P = veins[v].points;
    for (size_t i = 0; i + 1 < P.size(); ++i) {
      if ((P[i + 1] - P[i]).norm() < 1e-9 * h) continue;
      r.vein_segments.push_back({static_cast<int>(v), {P[i].x(), P[i].y()}, {P[i + 1].x(), P[i + 1].y()}});
    }
    r.vein_names.push_back(veins[v].name);
  }
  r.element_size = h;
  r.vein_element_size = hv;
  r.msh_path = options.msh_path.string();
  return r;
}

/// The vein that vein \p v lies along, if one does: each of v's points on one other vein's
/// line (to round-off, 1e-9 of the span), so that gmsh's fragments give their shared line
/// to one of them.
std::optional<std::size_t> vein_lying_along(const std::vector<wings::Vein>& veins, std::size_t v,
                                            double span) {
  for (std::size_t u = 0; u < veins.size(); ++u) {
    if (u == v || veins[u].points.empty() || veins[v].points.empty()) continue;
    bool along = true;
    for (const Eigen::Vector2d& p : veins[v].points)
      along = along && (wings::nearest_point_on_polyline(veins[u].points, p) - p).norm() <= 1e-9 * span;
    if (along) return u;
  }
  return std::nullopt;
}

/// No vein lies along another: gmsh would mesh the shared line once and give its elements
/// to one of the two (the other vein's section lost there, or the vein without elements).
void check_no_vein_along_another(const wings::Wing& wing, const std::vector<wings::Vein>& veins) {
  for (std::size_t v = 0; v < veins.size(); ++v)
    if (const auto under = vein_lying_along(veins, v, wing.span)) {
      const auto& vein = wing.veins[v];
      throw InputError(wing.source_file, vein.line, vein.key.empty() ? std::string("veins") : vein.key,
                       "vein '" + vein.name + "' lies along vein '" + wing.veins[*under].name +
                           "': gmsh meshes the two as one line and gives its elements to one of them (ends "
                           "written within the junction tolerance of a vein are moved onto it, docs/"
                           "wing_file.md, \"[[veins]]\"); to stiffen a stretch of a vein give it a tapered "
                           "section or split it into veins end to end, or move this vein apart");
    }
}

/// Every vein embedded in the membrane: each node of its beam elements is a node of a
/// shell triangle. A vein (or a piece of one) that gmsh leaves outside the surface shares
/// no nodes with it and would float unsupported (singular stiffness in modes/reduce):
/// refused here, naming the vein, rather than there.
void check_veins_embedded(const wings::Wing& wing, const Mesh& mesh) {
  std::vector<char> on_membrane(mesh.nodes.size(), 0);
  for (const auto& t : mesh.triangles)
    for (int n : t) on_membrane[static_cast<std::size_t>(n)] = 1;
  std::vector<char> has_beams(wing.veins.size(), 0);
  for (const auto& b : mesh.beams) {
    const auto v = static_cast<std::size_t>(b.vein);
    has_beams[v] = 1;
    for (int n : b.nodes) {
      if (on_membrane[static_cast<std::size_t>(n)]) continue;
      const auto& vein = wing.veins[v];
      const Eigen::Vector3d& x = mesh.nodes[static_cast<std::size_t>(n)];
      throw InputError(wing.source_file, vein.line, vein.key.empty() ? std::string("veins") : vein.key,
                       "vein '" + vein.name + "' is not embedded in the membrane: its mesh node at (x, y) = (" +
                           std::to_string(x.x() * 1e3) + ", " + std::to_string(x.y() * 1e3) +
                           ") mm is not a node of any membrane triangle (the vein leaves the outline "
                           "there; move it inside or onto the outline)");
    }
  }
  for (std::size_t v = 0; v < wing.veins.size(); ++v)
    if (!has_beams[v]) {
      const auto& vein = wing.veins[v];
      throw InputError(wing.source_file, vein.line, vein.key.empty() ? std::string("veins") : vein.key,
                       "vein '" + vein.name + "' has no elements in the mesh (shorter than the mesh "
                       "tolerance, or outside the membrane)");
    }
}

}  // namespace

Mesh mesh_wing(const wings::Wing& wing, const MeshOptions& options) {
  std::vector<wings::Vein> veins;  // the wing's, their junctions closed
  const GmshWingRequest request = request_for(wing, options, veins);
  check_no_vein_along_another(wing, veins);
  MeshWithGmshFn& mesh_with_gmsh = gmsh_mesher();
  GmshWingMesh result;
  mesh_with_gmsh(request, result);
  switch (result.status) {
    case GmshWingMesh::Status::ok: {
      Mesh mesh = mesh_from_gmsh(wing, result);
      check_veins_embedded(wing, mesh);
      return mesh;
    }
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
