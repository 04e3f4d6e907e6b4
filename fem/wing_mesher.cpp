#include "fem/wing_mesher.hpp"

#include <Eigen/Dense>

#include <new>
#include <string>

#include "fem/gmsh_boundary.hpp"
#include "fem/gmsh_mesh_conversion.hpp"
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

}  // namespace

Mesh mesh_wing(const wings::Wing& wing, const MeshOptions& options) {
  const GmshWingRequest request = request_for(wing, options);
  MeshWithGmshFn& mesh_with_gmsh = gmsh_mesher();
  GmshWingMesh result;
  mesh_with_gmsh(request, result);
  switch (result.status) {
    case GmshWingMesh::Status::ok:
      return mesh_from_gmsh(wing, result);
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
