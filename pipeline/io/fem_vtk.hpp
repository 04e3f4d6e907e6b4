#pragma once
/// \file fem_vtk.hpp
/// \brief FEM results as VTK unstructured grids (mesh.vtu, fem.vtu): the wing's
/// triangles and vein segments with mode shapes and static displacements as
/// point-data vectors, ready for ParaView's "Warp By Vector".

#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fem/load_cases.hpp"
#include "fem/mesh.hpp"
#include "fem/mode_classification.hpp"
#include "fem/modal_solver.hpp"
#include "pipeline/io/vtk_writers.hpp"

namespace flapsim::io {

/// \brief The mesh as VTK cells: triangles first, then vein segments. Cell data
/// "vein" (vein index, −1 on membrane triangles); point data "clamped" (1 at
/// nodes with y <= clamp_y, else 0).
UnstructuredMesh fem_unstructured_mesh(const fem::Mesh& mesh, double clamp_y);

/// \brief Adds the translations of a full DOF vector as point vector `name`
/// and, if `with_rotations`, its rotations as `name + "_rotation"`.
void add_nodal_vector(UnstructuredMesh& grid, const std::string& name, const Eigen::VectorXd& dofs,
                      bool with_rotations = false);

/// Static results to show: one displacement field per load case.
struct StaticResult {
  fem::LoadCase load;
  Eigen::VectorXd displacement;  ///< full DOF vector [m, rad]
};

/// Largest displacement of a mode shape in fem.vtu, as a fraction of the span R
/// (the largest y of the mesh): ParaView's "Warp By Vector" at its default scale 1
/// then shows the mode clearly without leaving the picture.
inline constexpr double kModeViewFraction = 0.1;

/// How a mode is named (docs/reduction.md, "Mode kinds from the stations").
struct ModeLabel {
  std::string kind;        ///< from the chain's stations: "bending", "torsion", "film" or "in-plane"
  double beam_share = 0.0; ///< share of the motion the stations' rigid sections carry [-]
  std::string shape_kind;  ///< fem::classify_modes (strip fits of the whole shape)
};

/// \brief Writes fem.vtu: the mesh plus, as point vectors,
///  - "mode_NN" for each mode: the mass-normalised shape (translations) times the
///    factor that makes its largest nodal displacement kModeViewFraction · R [m];
///    field data "mode_NN_frequency_Hz", "mode_NN_kind" (bending, torsion or film,
///    text), "mode_NN_beam_share", "mode_NN_shape_kind" (text) and "mode_NN_scale"
///    (the factor, [m per mass-normalised unit, m·kg^½]);
///  - "static_<case>_m_per_N" (force cases) or "static_<case>_m_per_N_m" (moment
///    cases): the displacement under the unit load, and its rotations
///    "static_<case>_rotation_rad_per_N[_m]"; field data "static_<case>_view_scale",
///    the Warp By Vector scale factor that moves the largest node by kModeViewFraction · R.
/// Field data also carries "span_m" and "mode_view_fraction".
/// \param labels  one per mode
void write_fem_vtu(const std::filesystem::path& path, const fem::Mesh& mesh, double clamp_y,
                   const fem::ModalResult& modes, const std::vector<ModeLabel>& labels,
                   const std::vector<StaticResult>& statics);

/// \brief Writes modes.csv: columns mode, frequency_hz, kind, beam_share, shape_kind.
void write_modes_csv(const std::filesystem::path& path, const fem::ModalResult& modes,
                     const std::vector<ModeLabel>& labels);

}  // namespace flapsim::io
