// The gmsh side of fem/gmsh_boundary.hpp, built as the shared module libflapsim_gmsh.so
// (the only code linked against gmsh). Meshes a wing with gmsh's C++ API (OpenCASCADE
// kernel): the outline is a plane surface, every vein segment a line; occ::fragment
// makes them conformal, so the vein beam elements share nodes with the membrane
// triangles. Element size: Mesh.MeshSizeMax = element_size, refined to
// vein_element_size near the veins by a Distance/Threshold size field.
// No exception leaves the module: errors are returned in GmshWingMesh::status.
#include "fem/gmsh_boundary.hpp"

#include <gmsh.h>
#include <omp.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>

namespace flapsim::fem {
namespace {

std::mutex& gmsh_mutex() {
  static std::mutex m;
  return m;
}

void ensure_gmsh_initialized() {
  static bool done = false;
  if (done) return;
  // gmsh's initialisation and its thread options set OpenMP's thread count; keep the one
  // the command chose (--threads, docs/performance.md) for the FEM's own loops.
  const int threads = omp_get_max_threads();
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", std::getenv("FLAPSIM_GMSH_VERBOSE") ? 1 : 0);
  gmsh::option::setNumber("General.Verbosity", 1);
  // gmsh meshes on one thread: on several, the surfaces the veins cut the membrane into
  // were meshed in an order that changed from run to run, and so did the mesh (node
  // positions, hence every mode; test fem.WingMeshReproducible.*).
  gmsh::option::setNumber("General.NumThreads", 1);
  gmsh::option::setNumber("Mesh.MaxNumThreads1D", 1);
  gmsh::option::setNumber("Mesh.MaxNumThreads2D", 1);
  gmsh::option::setNumber("Mesh.MaxNumThreads3D", 1);
  omp_set_num_threads(threads);
  std::atexit([] { gmsh::finalize(); });
  done = true;
}

void mesh_locked(const GmshWingRequest& request, GmshWingMesh& result) {
  namespace occ = gmsh::model::occ;
  const double h = request.element_size;
  const double hv = request.vein_element_size;

  gmsh::clear();
  gmsh::model::add(request.model_name);

  // 1. The outline as one plane surface.
  std::vector<int> pts, lines;
  for (const auto& p : request.outline) pts.push_back(occ::addPoint(p[0], p[1], 0.0));
  for (size_t i = 0; i < pts.size(); ++i) lines.push_back(occ::addLine(pts[i], pts[(i + 1) % pts.size()]));
  const int loop = occ::addCurveLoop(lines);
  const int surface = occ::addPlaneSurface({loop});

  // 2. Vein segments as lines.
  gmsh::vectorpair tools;
  for (const auto& s : request.vein_segments) {
    const int a = occ::addPoint(s.a[0], s.a[1], 0.0);
    const int b = occ::addPoint(s.b[0], s.b[1], 0.0);
    tools.push_back({1, occ::addLine(a, b)});
  }

  // 3. Fragment: veins embedded in (or cutting) the membrane, all conformal.
  gmsh::vectorpair out;
  std::vector<gmsh::vectorpair> out_map;
  if (!tools.empty()) {
    occ::fragment({{2, surface}}, tools, out, out_map);
  } else {
    out_map.push_back({{2, surface}});
  }
  occ::synchronize();

  const auto& segs = request.vein_segments;
  std::map<int, int> curve_vein;  // curve tag -> vein index (first vein wins on overlap)
  for (size_t k = 0; k < segs.size() && k + 1 < out_map.size(); ++k)
    for (const auto& dt : out_map[k + 1])
      if (dt.first == 1) curve_vein.emplace(dt.second, segs[k].vein);
  std::vector<int> surfaces;
  for (const auto& dt : out_map[0])
    if (dt.first == 2) surfaces.push_back(dt.second);
  if (surfaces.empty()) {
    result.status = GmshWingMesh::Status::no_surface;
    gmsh::clear();
    return;
  }

  // 4. Size field: vein_element_size on the veins, growing to element_size.
  gmsh::option::setNumber("Mesh.MeshSizeMax", h);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0.25 * hv);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.Algorithm", 6);  // Frontal-Delaunay: well-shaped triangles
  if (!curve_vein.empty() && hv < h) {
    std::vector<double> curves;
    for (const auto& cv : curve_vein) curves.push_back(cv.first);
    const int dist = gmsh::model::mesh::field::add("Distance");
    gmsh::model::mesh::field::setNumbers(dist, "CurvesList", curves);
    gmsh::model::mesh::field::setNumber(dist, "NumPointsPerCurve", 100);
    const int thr = gmsh::model::mesh::field::add("Threshold");
    gmsh::model::mesh::field::setNumber(thr, "InField", dist);
    gmsh::model::mesh::field::setNumber(thr, "SizeMin", hv);
    gmsh::model::mesh::field::setNumber(thr, "SizeMax", h);
    gmsh::model::mesh::field::setNumber(thr, "DistMin", 0.5 * hv);
    gmsh::model::mesh::field::setNumber(thr, "DistMax", 0.5 * hv + 3.0 * h);
    gmsh::model::mesh::field::setAsBackgroundMesh(thr);
  }

  // Physical groups: what mesh.msh readers (and ParaView) see.
  const int membrane_group = gmsh::model::addPhysicalGroup(2, surfaces);
  gmsh::model::setPhysicalName(2, membrane_group, "membrane");
  for (size_t v = 0; v < request.vein_names.size(); ++v) {
    std::vector<int> cs;
    for (const auto& cv : curve_vein)
      if (cv.second == static_cast<int>(v)) cs.push_back(cv.first);
    if (cs.empty()) continue;
    const int g = gmsh::model::addPhysicalGroup(1, cs);
    gmsh::model::setPhysicalName(1, g, request.vein_names[v]);
  }

  gmsh::model::mesh::generate(2);

  // 5. The mesh as gmsh numbers it.
  std::vector<double> param;
  gmsh::model::mesh::getNodes(result.node_tags, result.coordinates, param, -1, -1, false, false);
  for (int s : surfaces) {
    std::vector<std::size_t> etags, enodes;
    gmsh::model::mesh::getElementsByType(2, etags, enodes, s);
    result.triangle_nodes.insert(result.triangle_nodes.end(), enodes.begin(),
                                 enodes.begin() + static_cast<std::ptrdiff_t>(enodes.size() / 3 * 3));
  }
  for (const auto& cv : curve_vein) {
    std::vector<std::size_t> etags;
    GmshVeinCurve curve{cv.second, {}};
    gmsh::model::mesh::getElementsByType(1, etags, curve.line_nodes, cv.first);
    curve.line_nodes.resize(curve.line_nodes.size() / 2 * 2);
    result.vein_curves.push_back(std::move(curve));
  }

  if (!request.msh_path.empty()) {
    const std::filesystem::path path = request.msh_path;
    std::filesystem::path tmp = path;
    std::string tmp_name = ".";  // appended piece by piece: GCC 12 warns (-Wrestrict) on "." + string
    tmp_name += path.stem().string();
    tmp_name += ".tmp";
    tmp_name += path.extension().string();
    tmp.replace_filename(tmp_name);
    try {
      gmsh::write(tmp.string());
      std::filesystem::rename(tmp, path);
    } catch (...) {
      std::error_code ec;
      std::filesystem::remove(tmp, ec);  // never leave a half-written file behind
      throw;
    }
  }
  gmsh::clear();
  result.status = GmshWingMesh::Status::ok;
}

/// gmsh::clear() may itself throw (gmsh throws its messages as std::string).
void clear_quietly() noexcept {
  try {
    gmsh::clear();
  } catch (...) {
  }
}

void fail(GmshWingMesh& result, GmshWingMesh::Status status, std::string error) noexcept {
  clear_quietly();
  result = GmshWingMesh{};
  result.status = status;
  try {
    result.error = std::move(error);
  } catch (...) {
  }
}

}  // namespace
}  // namespace flapsim::fem

extern "C" __attribute__((visibility("default"))) int flapsim_gmsh_boundary_version() {
  return flapsim::fem::kGmshBoundaryVersion;
}

extern "C" __attribute__((visibility("default"))) void flapsim_mesh_with_gmsh(
    const flapsim::fem::GmshWingRequest& request, flapsim::fem::GmshWingMesh& result) noexcept {
  using flapsim::fem::GmshWingMesh;
  using Status = GmshWingMesh::Status;
  result = GmshWingMesh{};
  try {
    std::lock_guard<std::mutex> lock(flapsim::fem::gmsh_mutex());
    try {
      flapsim::fem::ensure_gmsh_initialized();
      flapsim::fem::mesh_locked(request, result);
    } catch (const std::bad_alloc&) {
      flapsim::fem::fail(result, Status::out_of_memory, "");
    } catch (const std::exception& e) {
      flapsim::fem::fail(result, Status::failed, e.what());
    } catch (const std::string& message) {  // gmsh's own errors
      flapsim::fem::fail(result, Status::failed, message);
    } catch (...) {
      std::string last;
      try {
        gmsh::logger::getLastError(last);
      } catch (...) {
      }
      flapsim::fem::fail(result, Status::failed, last.empty() ? std::string("unknown error") : last);
    }
  } catch (...) {  // the mutex itself
    result.status = Status::failed;
  }
}
