#pragma once
/// \file vtk_writers.hpp
/// \brief VTK XML output (.vtp poly data, .vtu unstructured grids) from plain
/// Eigen/std data, so callers need no VTK headers. Files are binary (appended,
/// zlib-compressed), readable by ParaView and VTK's XML readers, written to a
/// temporary name and renamed.

#include <Eigen/Core>

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace flapsim::io {

/// A named scalar field: one value per point (or per cell).
struct ScalarField {
  std::string name;
  Eigen::VectorXd values;
};

/// A named 3-vector field: one column per point (or per cell).
struct VectorField {
  std::string name;
  Eigen::Matrix3Xd values;
};

/// Point or cell data of a data set.
struct FieldData {
  std::vector<ScalarField> scalars;
  std::vector<VectorField> vectors;

  void add_scalar(std::string name, Eigen::VectorXd values) {
    scalars.push_back({std::move(name), std::move(values)});
  }
  void add_vector(std::string name, Eigen::Matrix3Xd values) {
    vectors.push_back({std::move(name), std::move(values)});
  }
  bool empty() const { return scalars.empty() && vectors.empty(); }
};

/// Surfaces and polylines (.vtp): wing surface, wake sheet, bar chain.
/// Cell numbering follows VTK's order for poly data: the lines first
/// (0 … lines.size()−1), then the polygons. cell_data fields have
/// lines.size() + polygons.size() entries in that order.
struct PolyDataMesh {
  Eigen::Matrix3Xd points;                   ///< [m], one column per point
  std::vector<std::vector<int>> polygons;    ///< point indices, ≥ 3 each, counter-clockwise seen from the normal
  std::vector<std::vector<int>> lines;       ///< polylines, ≥ 2 point indices each
  FieldData point_data;                      ///< points.cols() values per field
  FieldData cell_data;                       ///< lines.size() + polygons.size() values per field
  std::optional<double> time;                ///< [s] stored as field data "TimeValue" if set
};

/// Finite-element style meshes (.vtu): shell triangles, quads and beam segments.
/// Cell numbering: triangles first, then quads, then segments; cell_data fields
/// have triangles.size() + quads.size() + segments.size() entries in that order.
struct UnstructuredMesh {
  Eigen::Matrix3Xd points;                    ///< [m], one column per point
  std::vector<std::array<int, 3>> triangles;  ///< VTK_TRIANGLE
  std::vector<std::array<int, 4>> quads;      ///< VTK_QUAD (corners in order around the quad)
  std::vector<std::array<int, 2>> segments;   ///< VTK_LINE
  FieldData point_data;                       ///< points.cols() values per field
  FieldData cell_data;                        ///< one value per cell, in the order above
  std::optional<double> time;                 ///< [s] stored as field data "TimeValue" if set
};

/// \brief Writes a .vtp file atomically.
/// \throws std::invalid_argument on an out-of-range index, a too-short cell or a
///         field of the wrong size; OutputError if the file cannot be written
void write_vtp(const std::filesystem::path& path, const PolyDataMesh& mesh);

/// \brief Writes a .vtu file atomically.
/// \throws std::invalid_argument on an out-of-range index or a field of the wrong
///         size; OutputError if the file cannot be written
void write_vtu(const std::filesystem::path& path, const UnstructuredMesh& mesh);

}  // namespace flapsim::io
