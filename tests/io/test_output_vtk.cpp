// VTK output read back with VTK's own XML readers: .vtp (polygons, polylines,
// point and cell scalars and vectors), .vtu (triangles, quads, segments) and a
// .pvd series parsed with VTK's XML parser, each listed file read back.

#include "pipeline/io/pvd_series.hpp"
#include "pipeline/io/vtk_writers.hpp"
#include "common/scratch_dir.hpp"

#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <stdexcept>
#include <string>

namespace fs = std::filesystem;
using namespace flapsim::io;
using flapsim::test::ScratchDir;

namespace {

// A 3×2 grid of points, two quads and one triangle, one polyline along an edge.
PolyDataMesh sample_poly_data() {
  PolyDataMesh m;
  m.points.resize(3, 7);
  m.points << 0, 1, 2, 0, 1, 2, 3,
              0, 0, 0, 1, 1, 1, 0.5,
              0, 0.1, 0.2, 0, 0.1, 0.2, 0.25;
  m.polygons = {{0, 1, 4, 3}, {1, 2, 5, 4}, {2, 6, 5}};
  m.lines = {{0, 1, 2, 6}};
  Eigen::VectorXd pressure(7);
  pressure << 1, 2, 3, 4, 5, 6, 7;
  m.point_data.add_scalar("pressure_Pa", pressure);
  Eigen::Matrix3Xd velocity = Eigen::Matrix3Xd::Zero(3, 7);
  velocity.row(2).setLinSpaced(7, -1.0, 1.0);
  m.point_data.add_vector("velocity_m_s", velocity);
  Eigen::VectorXd id(4);  // cells: the line first, then the 3 polygons (VTK's order)
  id << 100, 0, 1, 2;
  m.cell_data.add_scalar("cell_id", id);
  Eigen::Matrix3Xd normal = Eigen::Matrix3Xd::Zero(3, 4);
  normal.row(2).setOnes();
  normal(0, 0) = 9.0;
  m.cell_data.add_vector("normal", normal);
  m.time = 0.0125;
  return m;
}

double component(vtkDataArray* a, vtkIdType i, int c = 0) { return a->GetComponent(i, c); }

vtkSmartPointer<vtkPolyData> read_vtp(const fs::path& p) {
  vtkNew<vtkXMLPolyDataReader> r;
  r->SetFileName(p.c_str());
  r->Update();
  return r->GetOutput();
}

}  // namespace

TEST(OutputVtk, PolyDataReadsBackWithVtkXMLPolyDataReader) {
  ScratchDir dir("vtp");
  const PolyDataMesh m = sample_poly_data();
  const fs::path file = dir / "wing.vtp";
  write_vtp(file, m);
  EXPECT_EQ(dir.files(), std::vector<std::string>{"wing.vtp"});  // no temporary left

  vtkNew<vtkXMLPolyDataReader> reader;
  ASSERT_TRUE(reader->CanReadFile(file.c_str()));
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkPolyData* d = reader->GetOutput();
  ASSERT_EQ(d->GetNumberOfPoints(), 7);
  EXPECT_EQ(d->GetNumberOfPolys(), 3);
  EXPECT_EQ(d->GetNumberOfLines(), 1);
  ASSERT_EQ(d->GetNumberOfCells(), 4);
  EXPECT_EQ(d->GetCellType(0), VTK_POLY_LINE);
  EXPECT_EQ(d->GetCellType(1), VTK_QUAD);
  EXPECT_EQ(d->GetCellType(3), VTK_TRIANGLE);
  for (vtkIdType i = 0; i < 7; ++i)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(d->GetPoint(i)[c], m.points(c, i));

  vtkDataArray* p = d->GetPointData()->GetArray("pressure_Pa");
  vtkDataArray* v = d->GetPointData()->GetArray("velocity_m_s");
  ASSERT_NE(p, nullptr);
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->GetNumberOfComponents(), 3);
  for (vtkIdType i = 0; i < 7; ++i) {
    EXPECT_EQ(component(p, i), m.point_data.scalars[0].values(i));
    EXPECT_EQ(component(v, i, 2), m.point_data.vectors[0].values(2, i));
  }
  vtkDataArray* id = d->GetCellData()->GetArray("cell_id");
  vtkDataArray* n = d->GetCellData()->GetArray("normal");
  ASSERT_NE(id, nullptr);
  ASSERT_NE(n, nullptr);
  EXPECT_EQ(component(id, 0), 100.0);  // the polyline
  EXPECT_EQ(component(id, 3), 2.0);    // the triangle
  EXPECT_EQ(component(n, 0, 0), 9.0);
  EXPECT_EQ(component(n, 2, 2), 1.0);
  // Polygon connectivity survives.
  vtkIdType npts = 0;
  const vtkIdType* ids = nullptr;
  d->GetCellPoints(1, npts, ids);
  ASSERT_EQ(npts, 4);
  EXPECT_EQ(ids[2], 4);
  vtkDataArray* t = d->GetFieldData()->GetArray("TimeValue");
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(component(t, 0), 0.0125);
}

TEST(OutputVtk, UnstructuredGridReadsBackWithVtkXMLUnstructuredGridReader) {
  ScratchDir dir("vtu");
  UnstructuredMesh m;
  m.points.resize(3, 6);
  m.points << 0, 1, 1, 0, 2, 2,
              0, 0, 1, 1, 0, 1,
              0, 0, 0, 0, 0, 0;
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.quads = {{1, 4, 5, 2}};
  m.segments = {{0, 1}, {1, 4}};
  Eigen::Matrix3Xd mode1 = Eigen::Matrix3Xd::Zero(3, 6);
  mode1.row(2) = m.points.row(0).array().square();
  m.point_data.add_vector("mode_1", mode1);
  m.point_data.add_vector("mode_2", -mode1);
  m.point_data.add_scalar("thickness_m", Eigen::VectorXd::Constant(6, 1e-5));
  Eigen::VectorXd kind(5);
  kind << 0, 0, 0, 1, 1;
  m.cell_data.add_scalar("is_vein", kind);
  const fs::path file = dir / "fem.vtu";
  write_vtu(file, m);
  EXPECT_EQ(dir.files(), std::vector<std::string>{"fem.vtu"});

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  ASSERT_TRUE(reader->CanReadFile(file.c_str()));
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkUnstructuredGrid* g = reader->GetOutput();
  ASSERT_EQ(g->GetNumberOfPoints(), 6);
  ASSERT_EQ(g->GetNumberOfCells(), 5);
  EXPECT_EQ(g->GetCellType(0), VTK_TRIANGLE);
  EXPECT_EQ(g->GetCellType(1), VTK_TRIANGLE);
  EXPECT_EQ(g->GetCellType(2), VTK_QUAD);
  EXPECT_EQ(g->GetCellType(3), VTK_LINE);
  EXPECT_EQ(g->GetCellType(4), VTK_LINE);
  vtkIdType npts = 0;
  const vtkIdType* ids = nullptr;
  g->GetCellPoints(4, npts, ids);
  ASSERT_EQ(npts, 2);
  EXPECT_EQ(ids[0], 1);
  EXPECT_EQ(ids[1], 4);
  vtkDataArray* m1 = g->GetPointData()->GetArray("mode_1");
  vtkDataArray* m2 = g->GetPointData()->GetArray("mode_2");
  vtkDataArray* th = g->GetPointData()->GetArray("thickness_m");
  ASSERT_TRUE(m1 && m2 && th);
  for (vtkIdType i = 0; i < 6; ++i) {
    EXPECT_EQ(component(m1, i, 2), mode1(2, i));
    EXPECT_EQ(component(m2, i, 2), -mode1(2, i));
    EXPECT_EQ(component(th, i), 1e-5);
  }
  vtkDataArray* vein = g->GetCellData()->GetArray("is_vein");
  ASSERT_NE(vein, nullptr);
  EXPECT_EQ(component(vein, 2), 0.0);
  EXPECT_EQ(component(vein, 3), 1.0);
}

TEST(OutputVtk, InconsistentMeshesAreRejectedAndNothingIsWritten) {
  ScratchDir dir("vtk_bad");
  PolyDataMesh bad_index = sample_poly_data();
  bad_index.polygons[0][2] = 7;  // only 7 points
  EXPECT_THROW(write_vtp(dir / "a.vtp", bad_index), std::invalid_argument);
  PolyDataMesh bad_field = sample_poly_data();
  bad_field.cell_data.scalars[0].values.resize(3);  // 4 cells
  EXPECT_THROW(write_vtp(dir / "b.vtp", bad_field), std::invalid_argument);
  UnstructuredMesh u;
  u.points = Eigen::Matrix3Xd::Zero(3, 2);
  u.segments = {{0, 2}};
  EXPECT_THROW(write_vtu(dir / "c.vtu", u), std::invalid_argument);
  EXPECT_TRUE(dir.files().empty());
}

TEST(OutputVtk, PvdSeriesIsValidAfterEveryStepAndListsReadableFiles) {
  ScratchDir dir("pvd");
  const fs::path pvd = dir / "wing.pvd";
  PvdSeries series(pvd);
  const double times[] = {0.0, 0.0005, 0.001};
  for (int step = 0; step <= 3; ++step) {
    // Parse the .pvd as it is on disk now: a Collection listing `step` data sets.
    vtkNew<vtkXMLDataParser> parser;
    parser->SetFileName(pvd.c_str());
    ASSERT_EQ(parser->Parse(), 1) << "step " << step;
    vtkXMLDataElement* root = parser->GetRootElement();
    ASSERT_NE(root, nullptr);
    EXPECT_STREQ(root->GetName(), "VTKFile");
    EXPECT_STREQ(root->GetAttribute("type"), "Collection");
    vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
    ASSERT_NE(collection, nullptr);
    ASSERT_EQ(collection->GetNumberOfNestedElements(), step);
    for (int k = 0; k < step; ++k) {
      vtkXMLDataElement* ds = collection->GetNestedElement(k);
      EXPECT_STREQ(ds->GetName(), "DataSet");
      double t = -1;
      ASSERT_TRUE(ds->GetScalarAttribute("timestep", t));
      EXPECT_EQ(t, times[k]);
      const char* file = ds->GetAttribute("file");
      ASSERT_NE(file, nullptr);
      EXPECT_EQ(std::string(file), "wing/" + PvdSeries::step_file_name("wing", k, "vtp"));
      // Relative to the .pvd's directory, as ParaView resolves it.
      auto data = read_vtp(pvd.parent_path() / file);
      EXPECT_EQ(data->GetNumberOfPoints(), 7);
      EXPECT_EQ(data->GetNumberOfCells(), 4);
      EXPECT_EQ(component(data->GetPointData()->GetArray("pressure_Pa"), 0), 1.0 + k);
    }
    if (step == 3) break;
    PolyDataMesh m = sample_poly_data();
    m.point_data.scalars[0].values.array() += step;
    m.time = times[step];
    const fs::path file = dir / "wing" / PvdSeries::step_file_name("wing", step, "vtp");
    write_vtp(file, m);
    // Alternate absolute names and names relative to the current directory (as a
    // run writing into "-o out/case" has them): both are stored relative to the .pvd.
    if (step % 2 == 0) series.add(times[step], file);
    else series.add(times[step], fs::relative(file, fs::current_path()));
  }
  EXPECT_EQ(series.size(), 3u);
  EXPECT_TRUE(dir.temporaries().empty());
  EXPECT_EQ(PvdSeries::step_file_name("wake", 12, "vtp"), "wake_000012.vtp");
}

namespace {

// The data sets the .pvd on disk lists now.
int listed(const fs::path& pvd) {
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(pvd.c_str());
  if (parser->Parse() != 1) return -1;
  vtkXMLDataElement* collection = parser->GetRootElement()->FindNestedElementWithName("Collection");
  return collection ? collection->GetNumberOfNestedElements() : -1;
}

}  // namespace

// A run's frames are written with Flush::deferred and listed in batches (append, then one
// sync_file_system and publish): before, each frame and each .pvd rewrite was flushed on
// its own, 12 fsyncs per step — `make run` spent 8 of its 11 s waiting for the disk here.
TEST(OutputVtk, DeferredFramesAreCompleteAndListedWhenTheSeriesIsPublished) {
  ScratchDir dir("pvd_deferred");
  const fs::path pvd = dir / "wing.pvd";
  PvdSeries series(pvd);
  for (int step = 0; step < 3; ++step) {
    const fs::path file = dir / "vtk" / PvdSeries::step_file_name("wing", step, "vtp");
    write_vtp(file, sample_poly_data(), Flush::deferred);
    series.append(0.001 * step, file);
    EXPECT_EQ(read_vtp(file)->GetNumberOfPoints(), 7);  // renamed complete, no temporary
    EXPECT_EQ(listed(pvd), 0);                          // not listed before publication
  }
  EXPECT_EQ(series.unpublished(), 3u);
  sync_file_system(dir.path());
  series.publish();
  EXPECT_EQ(listed(pvd), 3);
  EXPECT_EQ(series.unpublished(), 0u);
  EXPECT_TRUE(dir.temporaries().empty());
}
