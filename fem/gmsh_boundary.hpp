#pragma once
/// \file gmsh_boundary.hpp
/// \brief What fem/ asks of gmsh and what it gets back, in plain data. gmsh and the
/// libraries it needs (OpenCASCADE, VTK, MPI, X11: about 90 shared libraries) are not
/// linked into flapsim: the gmsh calls live in a separate shared module,
/// `libflapsim_gmsh.so` (fem/gmsh_module.cpp), loaded on the first mesh
/// (fem/gmsh_module_loader.hpp). Commands that do not mesh never load gmsh, so they start
/// in a fraction of the time (docs/performance.md, "Start-up").
///
/// Both sides are compiled from this header in the same build; kGmshBoundaryVersion
/// guards against a module left over from another build.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace flapsim::fem {

/// Change when a struct below changes: the loader refuses a module of another version.
inline constexpr int kGmshBoundaryVersion = 1;

/// The module's file name; installed next to the flapsim program.
inline constexpr const char* kGmshModuleFile = "libflapsim_gmsh.so";

/// One straight piece of a vein (zero-length pieces already dropped).
struct GmshVeinSegment {
  int vein = -1;                ///< index of the vein (into GmshWingRequest::vein_names)
  std::array<double, 2> a{};    ///< start (x, y) [m], in the vein's direction
  std::array<double, 2> b{};    ///< end (x, y) [m]
};

/// A wing to mesh in its plane (z = 0); sizes already resolved and checked (> 0).
struct GmshWingRequest {
  std::string model_name;                     ///< gmsh model name
  std::vector<std::array<double, 2>> outline; ///< (x, y) [m], ≥ 3 points, closed implicitly
  std::vector<GmshVeinSegment> vein_segments;
  std::vector<std::string> vein_names;        ///< physical group names, by vein index
  double element_size = 0.0;                  ///< Mesh.MeshSizeMax [m]
  double vein_element_size = 0.0;             ///< size on the veins [m], ≤ element_size
  std::string msh_path;                       ///< if not empty, gmsh also saves its mesh there
};

/// The line elements gmsh made on one vein curve.
struct GmshVeinCurve {
  int vein = -1;                        ///< index of the vein
  std::vector<std::size_t> line_nodes;  ///< 2 gmsh node tags per line element
};

/// gmsh's mesh, as gmsh numbers it (fem/wing_mesher.cpp renumbers and orients it).
struct GmshWingMesh {
  enum class Status {
    ok,
    no_surface,     ///< the outline gave no surface
    out_of_memory,  ///< std::bad_alloc inside gmsh
    failed          ///< any other gmsh error; `error` says what
  };
  Status status = Status::failed;
  std::string error;
  std::vector<std::size_t> node_tags;   ///< one per node
  std::vector<double> coordinates;      ///< x, y, z per node [m]
  std::vector<std::size_t> triangle_nodes;  ///< 3 node tags per triangle, surfaces in order
  std::vector<GmshVeinCurve> vein_curves;   ///< by increasing gmsh curve tag
};

/// The module's entry points (extern "C" names, looked up with dlsym).
using GmshBoundaryVersionFn = int();
using MeshWithGmshFn = void(const GmshWingRequest& request, GmshWingMesh& result) noexcept;
inline constexpr const char* kGmshBoundaryVersionSymbol = "flapsim_gmsh_boundary_version";
inline constexpr const char* kMeshWithGmshSymbol = "flapsim_mesh_with_gmsh";

}  // namespace flapsim::fem
