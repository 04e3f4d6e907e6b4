#pragma once
/// \file vtk_writers.hpp
/// \brief VTK XML output (.vtp poly data, .vtu unstructured grids) from plain
/// Eigen/std data, so callers need no VTK headers. Files are binary (appended,
/// LZ4-compressed), readable by ParaView 5.5 and later and VTK's XML readers, written to a
/// temporary name and renamed.

#include <Eigen/Core>

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pipeline/io/atomic_file.hpp"

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

/// Field data: values of the whole data set (not per point or cell), e.g. a mode's
/// frequency or a time step's lift. ParaView shows them in the Information panel and
/// plots them over time with "Plot Data Over Time"; VTK readers return them from
/// GetFieldData().
struct DataSetFields {
  std::vector<std::pair<std::string, double>> numbers;     ///< one double each (vtkDoubleArray)
  std::vector<std::pair<std::string, std::string>> texts;  ///< one string each (vtkStringArray)

  void add_number(std::string name, double value) { numbers.emplace_back(std::move(name), value); }
  void add_text(std::string name, std::string value) { texts.emplace_back(std::move(name), std::move(value)); }
};

/// Points, surfaces and polylines (.vtp): wing surface, wake sheet, bar chain, joints.
/// Cell numbering follows VTK's order for poly data: the vertices first, then the
/// lines, then the polygons. cell_data fields have vertices.size() + lines.size() +
/// polygons.size() entries in that order.
struct PolyDataMesh {
  Eigen::Matrix3Xd points;                   ///< [m], one column per point
  std::vector<std::vector<int>> polygons;    ///< point indices, ≥ 3 each, counter-clockwise seen from the normal
  std::vector<std::vector<int>> lines;       ///< polylines, ≥ 2 point indices each
  std::vector<int> vertices;                 ///< points shown as vertex cells (VTK_VERTEX), one index each
  FieldData point_data;                      ///< points.cols() values per field
  FieldData cell_data;                       ///< lines.size() + polygons.size() values per field
  DataSetFields field_data;                  ///< values of the whole data set
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
  DataSetFields field_data;                   ///< values of the whole data set
  std::optional<double> time;                 ///< [s] stored as field data "TimeValue" if set
};

/// \brief Writes a .vtp file atomically.
/// \param flush  Flush::deferred for the frames of a time series whose .pvd is published
///               after sync_file_system (atomic_file.hpp)
/// \throws std::invalid_argument on an out-of-range index, a too-short cell or a
///         field of the wrong size; OutputError if the file cannot be written
void write_vtp(const std::filesystem::path& path, const PolyDataMesh& mesh, Flush flush = Flush::now);

/// \brief Writes a .vtu file atomically.
/// \throws std::invalid_argument on an out-of-range index or a field of the wrong
///         size; OutputError if the file cannot be written
void write_vtu(const std::filesystem::path& path, const UnstructuredMesh& mesh);

}  // namespace flapsim::io
