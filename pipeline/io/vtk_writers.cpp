#include "pipeline/io/vtk_writers.hpp"

#include "pipeline/io/atomic_file.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>
#include <vtkXMLWriter.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace flapsim::io {

namespace {

/// The closing text of every VTK XML file (a file without it is truncated).
constexpr std::string_view kVtkFileTail = "</VTKFile>\n";

void check_index(long index, long n_points, const std::string& what) {
  if (index < 0 || index >= n_points)
    throw std::invalid_argument(what + ": point index " + std::to_string(index) + " is outside 0.." +
                                std::to_string(n_points - 1));
}

void check_fields(const FieldData& data, long expected, const std::string& what) {
  for (const auto& f : data.scalars)
    if (f.values.size() != expected)
      throw std::invalid_argument(what + " field '" + f.name + "' has " + std::to_string(f.values.size()) +
                                  " values, expected " + std::to_string(expected));
  for (const auto& f : data.vectors)
    if (f.values.cols() != expected)
      throw std::invalid_argument(what + " field '" + f.name + "' has " + std::to_string(f.values.cols()) +
                                  " vectors, expected " + std::to_string(expected));
}

vtkNew<vtkPoints> make_points(const Eigen::Matrix3Xd& p) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(p.cols());
  for (Eigen::Index i = 0; i < p.cols(); ++i) points->SetPoint(i, p(0, i), p(1, i), p(2, i));
  return points;
}

/// Copies the fields into a vtkPointData / vtkCellData; the first scalar and the
/// first vector field become the active ones (ParaView colours by them by default).
template <class Attributes>
void add_fields(Attributes* attributes, const FieldData& data) {
  for (std::size_t k = 0; k < data.scalars.size(); ++k) {
    const auto& f = data.scalars[k];
    vtkNew<vtkDoubleArray> a;
    a->SetName(f.name.c_str());
    a->SetNumberOfComponents(1);
    a->SetNumberOfTuples(f.values.size());
    for (Eigen::Index i = 0; i < f.values.size(); ++i) a->SetValue(i, f.values(i));
    if (k == 0) attributes->SetScalars(a);
    else attributes->AddArray(a);
  }
  for (std::size_t k = 0; k < data.vectors.size(); ++k) {
    const auto& f = data.vectors[k];
    vtkNew<vtkDoubleArray> a;
    a->SetName(f.name.c_str());
    a->SetNumberOfComponents(3);
    a->SetNumberOfTuples(f.values.cols());
    for (Eigen::Index i = 0; i < f.values.cols(); ++i) a->SetTypedTuple(i, f.values.col(i).data());
    if (k == 0) attributes->SetVectors(a);
    else attributes->AddArray(a);
  }
}

void add_time_and_fields(vtkDataObject* data, const std::optional<double>& time, const DataSetFields& fields) {
  if (time) {
    vtkNew<vtkDoubleArray> t;
    t->SetName("TimeValue");
    t->SetNumberOfTuples(1);
    t->SetValue(0, *time);
    data->GetFieldData()->AddArray(t);
  }
  for (const auto& [name, value] : fields.numbers) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name.c_str());
    a->SetNumberOfTuples(1);
    a->SetValue(0, value);
    data->GetFieldData()->AddArray(a);
  }
  for (const auto& [name, value] : fields.texts) {
    vtkNew<vtkStringArray> a;
    a->SetName(name.c_str());
    a->SetNumberOfValues(1);
    a->SetValue(0, value);
    data->GetFieldData()->AddArray(a);
  }
}

/// Binary, appended, LZ4-compressed, rendered in memory and written with one call. A frame
/// per step is most of a long run's time otherwise: zlib (a deflate state allocated and
/// cleared for each array) and VTK's file stream (a seek and a small write per array) took
/// 90 % of a 16-wingbeat rigid hover's wall time, 14.5 s against 1.8 s without frames
/// (docs/output_files.md, "Writing cost"). LZ4 files are read by ParaView 5.5 and later.
template <class Writer>
void write_through_memory(Writer* w, const std::filesystem::path& tmp, const std::filesystem::path& path) {
  // A failed write (a full disk) is reported by flapsim with the path (publish_file_atomically);
  // VTK's own report is a dump of its pipeline's internals (12 lines) before that message.
  vtkObject::GlobalWarningDisplayOff();
  w->SetDataModeToAppended();
  w->EncodeAppendedDataOff();
  w->SetCompressorTypeToLZ4();
  w->WriteToOutputStringOn();
  if (w->Write() != 1 || w->GetErrorCode() != 0) throw OutputError(path, "VTK could not render the file");
  const std::string text = w->GetOutputString();
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  if (!out) throw OutputError(path, std::string("cannot open a temporary file: ") + std::strerror(errno));
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (out.fail()) throw OutputError(path, "VTK could not write the file (disk full or file-size limit?)");
}

}  // namespace

void write_vtp(const std::filesystem::path& path, const PolyDataMesh& mesh, Flush flush) {
  const std::string what = "write_vtp '" + path.string() + "'";
  const long np = mesh.points.cols();
  vtkNew<vtkCellArray> polys, lines;
  for (std::size_t c = 0; c < mesh.polygons.size(); ++c) {
    const auto& poly = mesh.polygons[c];
    if (poly.size() < 3) throw std::invalid_argument(what + ": polygon " + std::to_string(c) + " has fewer than 3 points");
    polys->InsertNextCell(static_cast<vtkIdType>(poly.size()));
    for (int i : poly) {
      check_index(i, np, what);
      polys->InsertCellPoint(i);
    }
  }
  for (std::size_t c = 0; c < mesh.lines.size(); ++c) {
    const auto& line = mesh.lines[c];
    if (line.size() < 2) throw std::invalid_argument(what + ": line " + std::to_string(c) + " has fewer than 2 points");
    lines->InsertNextCell(static_cast<vtkIdType>(line.size()));
    for (int i : line) {
      check_index(i, np, what);
      lines->InsertCellPoint(i);
    }
  }
  vtkNew<vtkCellArray> verts;
  for (int i : mesh.vertices) {
    check_index(i, np, what);
    verts->InsertNextCell(1);
    verts->InsertCellPoint(i);
  }
  check_fields(mesh.point_data, np, what + ": point");
  check_fields(mesh.cell_data, static_cast<long>(mesh.vertices.size() + mesh.polygons.size() + mesh.lines.size()),
               what + ": cell");

  vtkNew<vtkPolyData> data;
  data->SetPoints(make_points(mesh.points));
  if (!mesh.polygons.empty()) data->SetPolys(polys);
  if (!mesh.lines.empty()) data->SetLines(lines);
  if (!mesh.vertices.empty()) data->SetVerts(verts);
  add_fields(data->GetPointData(), mesh.point_data);
  add_fields(data->GetCellData(), mesh.cell_data);
  add_time_and_fields(data, mesh.time, mesh.field_data);

  publish_file_atomically(path, [&](const std::filesystem::path& tmp) {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(data);
    write_through_memory(writer.GetPointer(), tmp, path);
  }, kVtkFileTail, flush);
}

void write_vtu(const std::filesystem::path& path, const UnstructuredMesh& mesh) {
  const std::string what = "write_vtu '" + path.string() + "'";
  const long np = mesh.points.cols();
  const long nc = static_cast<long>(mesh.triangles.size() + mesh.quads.size() + mesh.segments.size());
  check_fields(mesh.point_data, np, what + ": point");
  check_fields(mesh.cell_data, nc, what + ": cell");

  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(make_points(mesh.points));
  grid->Allocate(nc);
  auto insert = [&](int type, const auto& cell) {
    vtkIdType ids[4];
    for (std::size_t i = 0; i < cell.size(); ++i) {
      check_index(cell[i], np, what);
      ids[i] = cell[i];
    }
    grid->InsertNextCell(type, static_cast<vtkIdType>(cell.size()), ids);
  };
  for (const auto& t : mesh.triangles) insert(VTK_TRIANGLE, t);
  for (const auto& q : mesh.quads) insert(VTK_QUAD, q);
  for (const auto& s : mesh.segments) insert(VTK_LINE, s);
  add_fields(grid->GetPointData(), mesh.point_data);
  add_fields(grid->GetCellData(), mesh.cell_data);
  add_time_and_fields(grid, mesh.time, mesh.field_data);

  publish_file_atomically(path, [&](const std::filesystem::path& tmp) {
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetInputData(grid);
    write_through_memory(writer.GetPointer(), tmp, path);
  }, kVtkFileTail);
}

}  // namespace flapsim::io
