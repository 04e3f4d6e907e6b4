// The reduction's ParaView files (io::write_reduction_vtk): reduction.vtm opens as a
// multiblock of stations, bodies, joints and centres of mass with VTK's own reader;
// each block carries only the fields that apply to it (no zeros standing in for
// "does not apply") and the values that were written.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkCellData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLMultiBlockDataReader.h>

#include "common/scratch_dir.hpp"
#include "pipeline/io/reduction_files.hpp"

namespace flapsim {
namespace {

TEST(ReductionVtk, FourBlocksEachWithItsOwnFields) {
  // A beam of 5 stations along an axis tilted by psi = 0.1 rad and a rigid-root chain
  // of 3 bodies of 10 mm (joints 2 and 3 carry springs; body 1 is welded to the base).
  reduction::BeamProperties beam;
  beam.axis.psi = 0.1;
  for (int k = 0; k < 5; ++k) {
    reduction::BeamStation st;
    st.s = 0.003 + 0.006 * k;
    st.EI = 1e-4 * (5 - k);
    st.GJ = 2e-5;
    st.mass_per_length = 1e-3;
    beam.stations.push_back(st);
  }
  reduction::LumpedChain lc;
  lc.body_length = 0.01;
  for (int k = 0; k < 3; ++k) {
    mbd::ChainBody b;
    b.length = 0.01;
    b.mass = 1e-5 * (k + 1);
    b.center_of_mass = Eigen::Vector3d(0.001, 0.005, 0.0);
    lc.chain.bodies.push_back(b);
    mbd::ChainJoint j;
    j.bend_stiffness = k == 0 ? 0.0 : 0.01 * k;
    j.twist_stiffness = k == 0 ? 0.0 : 0.002 * k;
    lc.chain.joints.push_back(j);
  }
  lc.chain.root = mbd::RootAttachment::rigid;
  const test::ScratchDir dir("reduction_vtk");
  io::write_reduction_vtk(dir.path(), beam, lc);

  auto reader = vtkSmartPointer<vtkXMLMultiBlockDataReader>::New();
  reader->SetFileName((dir / "reduction.vtm").c_str());
  reader->Update();
  auto* mb = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
  ASSERT_NE(mb, nullptr);
  ASSERT_EQ(mb->GetNumberOfBlocks(), 4u);
  const char* names[] = {"stations", "bodies", "joints", "centres_of_mass"};
  for (unsigned i = 0; i < 4; ++i)
    EXPECT_STREQ(mb->GetMetaData(i)->Get(vtkCompositeDataSet::NAME()), names[i]);
  auto block = [&](unsigned i) { return vtkPolyData::SafeDownCast(mb->GetBlock(i)); };

  vtkPolyData* stations = block(0);
  ASSERT_NE(stations, nullptr);
  EXPECT_EQ(stations->GetNumberOfPoints(), 5);
  ASSERT_NE(stations->GetPointData()->GetArray("EI_N_m2"), nullptr);
  EXPECT_DOUBLE_EQ(stations->GetPointData()->GetArray("EI_N_m2")->GetTuple1(4), 1e-4);
  EXPECT_EQ(stations->GetPointData()->GetArray("mass_kg"), nullptr);  // a body property

  vtkPolyData* bodies = block(1);
  ASSERT_NE(bodies, nullptr);
  EXPECT_EQ(bodies->GetNumberOfCells(), 3);
  EXPECT_DOUBLE_EQ(bodies->GetCellData()->GetArray("mass_kg")->GetTuple1(2), 3e-5);
  EXPECT_EQ(bodies->GetPointData()->GetArray("EI_N_m2"), nullptr);

  // Rigid root: only bodies 2 and 3 have a joint with springs; no zero for body 1.
  vtkPolyData* joints = block(2);
  ASSERT_NE(joints, nullptr);
  EXPECT_EQ(joints->GetNumberOfPoints(), 2);
  EXPECT_EQ(joints->GetNumberOfVerts(), 2);
  EXPECT_DOUBLE_EQ(joints->GetPointData()->GetArray("joint")->GetTuple1(0), 2.0);
  EXPECT_DOUBLE_EQ(joints->GetPointData()->GetArray("k_theta_N_m_per_rad")->GetTuple1(0), 0.01);
  EXPECT_DOUBLE_EQ(joints->GetPointData()->GetArray("k_alpha_N_m_per_rad")->GetTuple1(1), 0.004);
  // Joint of body 2 at s = a on the axis: (sin psi, cos psi) a.
  double p[3];
  joints->GetPoint(0, p);
  EXPECT_NEAR(p[0], 0.01 * std::sin(0.1), 1e-15);
  EXPECT_NEAR(p[1], 0.01 * std::cos(0.1), 1e-15);

  vtkPolyData* coms = block(3);
  ASSERT_NE(coms, nullptr);
  EXPECT_EQ(coms->GetNumberOfVerts(), 3);
  EXPECT_DOUBLE_EQ(coms->GetPointData()->GetArray("mass_kg")->GetTuple1(0), 1e-5);
  EXPECT_EQ(coms->GetPointData()->GetArray("k_theta_N_m_per_rad"), nullptr);
}

}  // namespace
}  // namespace flapsim
