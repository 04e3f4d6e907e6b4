// The meshes of a run's view fields (pipeline/io/fsi_vtk.hpp, trajectory_vtk.hpp) on inputs
// made by hand: the chain's spring moments with a coupled stiffness matrix and rest angles,
// the wing's Cp and displacement, a path's polyline, and their refusals.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <stdexcept>
#include <string>

#include "mbd/chain_data.hpp"
#include "mbd/chain_kinematics.hpp"
#include "mbd/chain_model.hpp"
#include "pipeline/io/fsi_vtk.hpp"
#include "pipeline/io/trajectory_vtk.hpp"

namespace run_view_meshes {

using namespace flapsim;

const io::ScalarField& cell_scalar(const io::PolyDataMesh& mesh, const std::string& name) {
  for (const auto& f : mesh.cell_data.scalars)
    if (f.name == name) return f;
  throw std::logic_error("no cell field " + name);
}

TEST(RunViewMeshes, JointMomentsAreTheCoupledStiffnessTimesTheDeflection) {
  // A sprung two-body cantilever (Φ = [θ₀, α₀, θ₁, α₁]) with a full stiffness matrix coupling
  // bend and twist and the two joints, rest angles θ₀ = 0.1, α₁ = −0.05 rad.
  mbd::ChainModel chain = mbd::make_uniform_cantilever_chain(0.04, 1e-4, 1e-5, 0.01, 1e-8, 2);
  ASSERT_EQ(chain.num_dofs(), 4);
  chain.joints[0].bend_rest = 0.1;
  chain.joints[1].twist_rest = -0.05;
  chain.stiffness_matrix.resize(4, 4);
  chain.stiffness_matrix << 2.0, 0.5, 0.2, 0.0,  //
      0.5, 3.0, 0.0, 0.1,                       //
      0.2, 0.0, 4.0, 0.3,                       //
      0.0, 0.1, 0.3, 5.0;
  chain.stiffness_matrix *= 1e-3;  // [N m/rad]
  mbd::ChainData data(chain);
  const Eigen::VectorXd q = (Eigen::VectorXd(4) << 0.3, 0.02, -0.1, 0.05).finished();
  mbd::forward_kinematics(chain, data, mbd::BasePose{}, q, Eigen::VectorXd::Zero(4));
  io::PolyDataMesh mesh = io::chain_mesh(chain, data, 0.0);
  io::add_joint_fields(mesh, chain, data, q);

  // K (Φ − Φ_rest) by hand, Φ − Φ_rest = [0.2, 0.02, −0.1, 0.1]:
  //   θ₀: 2·0.2 + 0.5·0.02 + 0.2·(−0.1) = 0.39;   α₀: 0.5·0.2 + 3·0.02 + 0.1·0.1 = 0.17;
  //   θ₁: 0.2·0.2 + 4·(−0.1) + 0.3·0.1 = −0.33;   α₁: 0.1·0.02 + 0.3·(−0.1) + 5·0.1 = 0.472 (× 1e-3 N m).
  const double bend_moment[2] = {0.39e-3, -0.33e-3}, twist_moment[2] = {0.17e-3, 0.472e-3};
  for (int body = 0; body < 2; ++body)
    for (const int cell : {body, 2 + body}) {  // the body's joint line and its centre-of-mass line
      EXPECT_EQ(cell_scalar(mesh, "bend_rad").values(cell), q(2 * body));
      EXPECT_EQ(cell_scalar(mesh, "twist_rad").values(cell), q(2 * body + 1));
      EXPECT_NEAR(cell_scalar(mesh, "bend_moment_Nm").values(cell), bend_moment[body], 1e-15);
      EXPECT_NEAR(cell_scalar(mesh, "twist_moment_Nm").values(cell), twist_moment[body], 1e-15);
    }
  EXPECT_THROW(io::add_joint_fields(mesh, chain, data, Eigen::VectorXd::Zero(3)), std::invalid_argument);
}

TEST(RunViewMeshes, CpAndDisplacementOfAWingFrame) {
  io::PolyDataMesh wing;
  wing.points = (Eigen::Matrix3Xd(3, 4) << 0, 1, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0.5).finished();
  wing.polygons.push_back({0, 1, 2, 3});
  EXPECT_THROW(io::add_wing_reference_fields(wing, 2.0, wing.points), std::invalid_argument);  // no Δp yet
  wing.cell_data.add_scalar("pressure_jump_Pa", Eigen::VectorXd::Constant(1, -3.0));
  Eigen::Matrix3Xd rigid = wing.points;
  rigid(2, 3) = 0.0;
  EXPECT_THROW(io::add_wing_reference_fields(wing, 0.0, rigid), std::invalid_argument);
  EXPECT_THROW(io::add_wing_reference_fields(wing, 2.0, rigid.leftCols(3)), std::invalid_argument);
  io::add_wing_reference_fields(wing, 2.0, rigid);
  EXPECT_EQ(cell_scalar(wing, "Cp").values(0), -1.5);  // −3 Pa / 2 Pa
  const io::VectorField& d = wing.point_data.vectors.back();
  EXPECT_EQ(d.name, "displacement_m");
  EXPECT_EQ(d.values.col(3), Eigen::Vector3d(0.0, 0.0, 0.5));
  EXPECT_EQ(d.values.leftCols(3).cwiseAbs().maxCoeff(), 0.0);
}

TEST(RunViewMeshes, APathIsOnePolylineInTimeOrder) {
  io::Trajectory path{"tip", {0.0, 0.01, 0.02}, {Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(1, 2, 0)}};
  const io::PolyDataMesh mesh = io::trajectory_mesh(path, 0.04);
  ASSERT_EQ(mesh.lines.size(), 1u);
  EXPECT_EQ(mesh.lines[0], (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(mesh.points.col(2), Eigen::Vector3d(1, 2, 0));
  EXPECT_DOUBLE_EQ(mesh.point_data.scalars[1].values(2), 0.5);  // t_over_T = 0.02 s / 0.04 s
  ASSERT_EQ(mesh.field_data.texts.size(), 1u);
  EXPECT_EQ(mesh.field_data.texts[0].second, "tip");
  path.times.resize(1);
  path.points.resize(1);
  EXPECT_TRUE(io::trajectory_mesh(path, 0.04).lines.empty());  // one point: no line
  path.times.push_back(0.01);
  EXPECT_THROW(io::trajectory_mesh(path, 0.04), std::invalid_argument);
  path.points.emplace_back(0, 0, 0);
  EXPECT_THROW(io::trajectory_mesh(path, 0.0), std::invalid_argument);
}

}  // namespace run_view_meshes
