#include "fem/wing_mesher.hpp"

#include <gmsh.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <new>
#include <set>
#include <stdexcept>
#include <string>

#include "wings/input_error.hpp"

#include <omp.h>

namespace flapsim::fem {

namespace {

std::mutex& gmsh_mutex() {
  static std::mutex m;
  return m;
}

void ensure_gmsh_initialized() {
  static bool done = false;
  if (done) return;
  // gmsh's initialisation sets OpenMP's thread count (its General.NumThreads); keep the
  // one the command chose (--threads, docs/performance.md).
  const int threads = omp_get_max_threads();
  gmsh::initialize(0, nullptr, false);
  omp_set_num_threads(threads);
  gmsh::option::setNumber("General.Terminal", std::getenv("FLAPSIM_GMSH_VERBOSE") ? 1 : 0);
  gmsh::option::setNumber("General.Verbosity", 1);
  std::atexit([] { gmsh::finalize(); });
  done = true;
}

struct VeinCurve {
  int vein;
  Eigen::Vector2d a, b;  // segment end points, in the vein's direction
};

Mesh mesh_locked(const wings::Wing& wing, const MeshOptions& options) {
  namespace occ = gmsh::model::occ;
  const double h = options.element_size > 0.0 ? options.element_size : wing.mesh.element_size;
  double hv = options.vein_element_size > 0.0 ? options.vein_element_size : wing.mesh.vein_element_size;
  if (!(h > 0.0)) throw InputError(wing.source_file, 0, "mesh.element_size", "must be positive");
  if (!(hv > 0.0)) hv = h;
  hv = std::min(hv, h);
  if (wing.outline.size() < 3) throw InputError(wing.source_file, 0, "planform", "outline needs at least 3 points");

  gmsh::clear();
  gmsh::model::add(wing.name.empty() ? "wing" : wing.name);

  // 1. The outline as one plane surface.
  std::vector<int> pts, lines;
  for (const auto& p : wing.outline) pts.push_back(occ::addPoint(p.x(), p.y(), 0.0));
  for (size_t i = 0; i < pts.size(); ++i) lines.push_back(occ::addLine(pts[i], pts[(i + 1) % pts.size()]));
  const int loop = occ::addCurveLoop(lines);
  const int surface = occ::addPlaneSurface({loop});

  // 2. Vein segments as lines (zero-length segments skipped).
  std::vector<VeinCurve> segs;
  gmsh::vectorpair tools;
  for (size_t v = 0; v < wing.veins.size(); ++v) {
    const auto& P = wing.veins[v].points;
    for (size_t i = 0; i + 1 < P.size(); ++i) {
      if ((P[i + 1] - P[i]).norm() < 1e-9 * h) continue;
      const int a = occ::addPoint(P[i].x(), P[i].y(), 0.0);
      const int b = occ::addPoint(P[i + 1].x(), P[i + 1].y(), 0.0);
      tools.push_back({1, occ::addLine(a, b)});
      segs.push_back({static_cast<int>(v), P[i], P[i + 1]});
    }
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

  std::map<int, int> curve_vein;  // curve tag -> vein index (first vein wins on overlap)
  for (size_t k = 0; k < segs.size() && k + 1 < out_map.size(); ++k)
    for (const auto& dt : out_map[k + 1])
      if (dt.first == 1) curve_vein.emplace(dt.second, segs[k].vein);
  std::vector<int> surfaces;
  for (const auto& dt : out_map[0])
    if (dt.first == 2) surfaces.push_back(dt.second);
  if (surfaces.empty()) throw InputError(wing.source_file, 0, "planform", "gmsh could not build the wing surface");

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
  for (size_t v = 0; v < wing.veins.size(); ++v) {
    std::vector<int> cs;
    for (const auto& cv : curve_vein)
      if (cv.second == static_cast<int>(v)) cs.push_back(cv.first);
    if (cs.empty()) continue;
    const int g = gmsh::model::addPhysicalGroup(1, cs);
    gmsh::model::setPhysicalName(1, g, wing.veins[v].name);
  }

  gmsh::model::mesh::generate(2);

  // 5. Read the mesh back: contiguous node numbering.
  std::vector<std::size_t> node_tags;
  std::vector<double> coord, param;
  gmsh::model::mesh::getNodes(node_tags, coord, param, -1, -1, false, false);
  Mesh mesh;
  std::map<std::size_t, int> index;
  for (size_t i = 0; i < node_tags.size(); ++i) {
    index[node_tags[i]] = static_cast<int>(mesh.nodes.size());
    mesh.nodes.emplace_back(coord[3 * i], coord[3 * i + 1], 0.0);
  }
  for (int s : surfaces) {
    std::vector<std::size_t> etags, enodes;
    gmsh::model::mesh::getElementsByType(2, etags, enodes, s);
    for (size_t e = 0; e + 2 < enodes.size(); e += 3) {
      std::array<int, 3> t{index.at(enodes[e]), index.at(enodes[e + 1]), index.at(enodes[e + 2])};
      // Counter-clockwise seen from +z, so element normals point along the wing's z.
      const Eigen::Vector3d n = (mesh.nodes[t[1]] - mesh.nodes[t[0]]).cross(mesh.nodes[t[2]] - mesh.nodes[t[0]]);
      if (n.z() < 0.0) std::swap(t[1], t[2]);
      mesh.triangles.push_back(t);
    }
  }
  for (const auto& cv : curve_vein) {
    std::vector<std::size_t> etags, enodes;
    gmsh::model::mesh::getElementsByType(1, etags, enodes, cv.first);
    const auto& P = wing.veins[static_cast<size_t>(cv.second)].points;
    const Eigen::Vector2d dir = P.back() - P.front();
    for (size_t e = 0; e + 1 < enodes.size(); e += 2) {
      BeamElement b{{index.at(enodes[e]), index.at(enodes[e + 1])}, cv.second};
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

  if (!options.msh_path.empty()) {
    std::filesystem::path tmp = options.msh_path;
    // ".NAME.tmp.msh": gmsh takes the format from the extension. Appended piece by piece:
    // GCC 12's -Wrestrict misfires on `"." + std::string&&` (GCC bug 105329).
    std::string staging_name(".");
    staging_name.append(options.msh_path.stem().string()).append(".tmp").append(options.msh_path.extension().string());
    tmp.replace_filename(staging_name);
    try {
      gmsh::write(tmp.string());
      std::filesystem::rename(tmp, options.msh_path);
    } catch (...) {
      std::error_code ec;
      std::filesystem::remove(tmp, ec);  // never leave a half-written file behind
      throw;
    }
  }
  gmsh::clear();
  return mesh;
}

}  // namespace

namespace {

/// gmsh::clear() may itself throw (gmsh throws its messages as std::string); inside an
/// error handler that would end the process (std::terminate), so it is made silent.
void clear_quietly() noexcept {
  try {
    gmsh::clear();
  } catch (...) {
  }
}

/// gmsh failed on the wing's geometry or mesh sizes: bad input (exit 2) naming the keys
/// that decide them.
[[noreturn]] void throw_meshing_failed(const wings::Wing& wing, const std::string& detail) {
  throw InputError(wing.source_file, 0, "planform",
                   "gmsh cannot mesh this wing (" + detail +
                       "); check the outline (planform.outline or planform.outline_file: no slivers or "
                       "near-touching edges), the veins and mesh.element_size");
}

}  // namespace

Mesh mesh_wing(const wings::Wing& wing, const MeshOptions& options) {
  std::lock_guard<std::mutex> lock(gmsh_mutex());
  ensure_gmsh_initialized();
  try {
    return mesh_locked(wing, options);
  } catch (const InputError&) {
    clear_quietly();
    throw;
  } catch (const std::bad_alloc&) {
    clear_quietly();
    throw;
  } catch (const std::exception& e) {
    clear_quietly();
    throw_meshing_failed(wing, e.what());
  } catch (const std::string& message) {  // gmsh's own errors
    clear_quietly();
    throw_meshing_failed(wing, message);
  } catch (...) {
    std::string last;
    try { gmsh::logger::getLastError(last); } catch (...) {}
    clear_quietly();
    throw_meshing_failed(wing, last.empty() ? std::string("unknown error") : last);
  }
}

}  // namespace flapsim::fem
