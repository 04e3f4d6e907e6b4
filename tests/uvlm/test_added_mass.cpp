// The lattice's linearised added-mass response (uvlm/added_mass.hpp) against the change of
// the loads the lattice itself computes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <utility>

#include "tilted_plate.hpp"
#include "uvlm/added_mass.hpp"
#include "uvlm/planform_grid.hpp"
#include "uvlm/vortex_lattice.hpp"

namespace {

using namespace flapsim;

// The plate of tilted_plate.hpp tilted by 0.2 rad, so that its normals are not a coordinate axis.
Eigen::Matrix3Xd tilted_plate(const uvlm::VortexLatticeModel& m) { return test::tilted_plate(m, 0.2); }

// A 4 × 8 plate model with the given leading edge (Bernoulli loads).
uvlm::VortexLatticeModel plate_model(uvlm::LeadingEdge edge) {
  uvlm::VortexLatticeModel m;
  m.chordwise = 4;
  m.spanwise = 8;
  m.wake_capacity = 5;
  m.leading_edge = edge;
  return m;
}

// A free stream of 5 m/s with steps of 1 ms (U Δt = half a chord), air of 1.225 kg/m³.
const Eigen::Vector3d kPlateStream(5.0, 0.0, 0.0);
constexpr double kPlateStep = 1e-3, kPlateRho = 1.225;

// Three accepted steps of the plate at rest in that stream (Γ ≠ 0, BDF2 rates).
void fly_three_steps(const uvlm::VortexLatticeModel& m, uvlm::VortexLatticeData& d, const Eigen::Matrix3Xd& nodes) {
  for (int n = 0; n < 3; ++n) {
    uvlm::solve(m, d, nodes, Eigen::Matrix3Xd::Zero(3, m.nodes()), kPlateStream, kPlateStep, kPlateRho);
    uvlm::advance(m, d);
  }
}

// A random velocity pattern of the lattice's nodes [m/s], components in [−1, 1].
Eigen::Matrix3Xd random_node_velocities(const uvlm::VortexLatticeModel& m, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::Matrix3Xd dv(3, m.nodes());
  for (Eigen::Index k = 0; k < dv.size(); ++k) dv.data()[k] = u(rng);
  return dv;
}

// The central difference (F(+ε δv) − F(−ε δv)) / 2ε of the lattice's panel forces about the
// nodes at rest, in the stream given; leaves the lattice solved at rest (where the
// response is taken).
Eigen::Matrix3Xd force_difference(const uvlm::VortexLatticeModel& m, uvlm::VortexLatticeData& d,
                                  const Eigen::Matrix3Xd& nodes, const Eigen::Matrix3Xd& dv,
                                  const Eigen::Vector3d& stream, double dt, double rho, double eps) {
  uvlm::solve(m, d, nodes, eps * dv, stream, dt, rho);
  const Eigen::Matrix3Xd plus = d.loads.force;
  uvlm::solve(m, d, nodes, -eps * dv, stream, dt, rho);
  const Eigen::Matrix3Xd difference = (plus - d.loads.force) / (2.0 * eps);
  uvlm::solve(m, d, nodes, Eigen::Matrix3Xd::Zero(3, m.nodes()), stream, dt, rho);
  return difference;
}

TEST(AddedMass, TheResponseIsTheDerivativeOfTheLoadsOfAPlateAtRestInStillAir) {
  // At rest in still air every circulation is zero, so the loads' only first-order part in
  // the node velocities is ρ A n ∂Γ/∂t (the V·∇Γ and suction terms are products of two
  // small quantities): the response must equal the central difference of the loads the
  // lattice computes, (F(+ε δv) − F(−ε δv)) / 2ε, whose error is O(ε²) — after one accepted
  // step (BDF1 rate) and after two (BDF2, the factor 3/2; or backward Euler again with
  // first_order_circulation_rate, the factor 1: the response then 2/3 of BDF2's), by both
  // load routes.
  for (const uvlm::LoadMethod method : {uvlm::LoadMethod::Bernoulli, uvlm::LoadMethod::KuttaJoukowski}) {
    Eigen::Matrix3Xd second_order_response;
    for (const auto& [accepted, first_order] : {std::pair{1, false}, std::pair{2, false}, std::pair{2, true}}) {
      uvlm::VortexLatticeModel m;
      m.chordwise = 4;
      m.spanwise = 8;
      m.wake_capacity = 4;
      m.load_method = method;
      m.first_order_circulation_rate = first_order;
      const Eigen::Matrix3Xd nodes = tilted_plate(m);
      const Eigen::Matrix3Xd rest = Eigen::Matrix3Xd::Zero(3, m.nodes());
      const Eigen::Vector3d still = Eigen::Vector3d::Zero();
      const double dt = 1e-3, rho = 1.225;
      uvlm::VortexLatticeData d(m);
      for (int n = 0; n < accepted; ++n) {
        uvlm::solve(m, d, nodes, rest, still, dt, rho);
        uvlm::advance(m, d);
      }
      const Eigen::Matrix3Xd dv = random_node_velocities(m, 11);
      const Eigen::Matrix3Xd difference = force_difference(m, d, nodes, dv, still, dt, rho, 1e-4);
      uvlm::AddedMassScratch scratch(m);
      Eigen::Matrix3Xd response;
      uvlm::added_mass_force_change(m, d, dv, scratch, response);
      const double scale = difference.cwiseAbs().maxCoeff();
      ASSERT_GT(scale, 0.0);
      EXPECT_LT((response - difference).cwiseAbs().maxCoeff(), 1e-6 * scale)
          << "load route " << static_cast<int>(method) << ", after " << accepted << " accepted steps"
          << (first_order ? ", first order" : "");
      if (accepted == 2 && !first_order) second_order_response = response;
      if (first_order) {  // the same δΓ, its rate 1/Δt against 3/(2Δt)
        EXPECT_LT((response - (2.0 / 3.0) * second_order_response).cwiseAbs().maxCoeff(), 1e-12 * scale);
      }
      // Linear in δv: twice the change, twice the response.
      Eigen::Matrix3Xd doubled;
      uvlm::added_mass_force_change(m, d, 2.0 * dv, scratch, doubled);
      EXPECT_LT((doubled - 2.0 * response).cwiseAbs().maxCoeff(), 1e-12 * scale);
    }
  }
}

TEST(AddedMass, TheQuasiSteadyTermMakesTheResponseTheLoadsDerivativeInAFreeStream) {
  // The same plate at 0.2 rad in a free stream of 5 m/s (Γ ≠ 0; U Δt = half a chord),
  // Bernoulli loads without a leading-edge force, after three accepted steps: the response
  // against the central difference of the loads, relative to its size. What the response
  // leaves out does not act on a flat plate (the bound vortices' velocity at its panels is
  // normal to them, where ∇Γ has no part): measured 8.5e-11 with the pressure's
  // quasi-steady term, bound 1e-6; 0.73 with ∂Γ/∂t alone (bound: more than 0.1).
  const uvlm::VortexLatticeModel m = plate_model(uvlm::LeadingEdge::None);
  const Eigen::Matrix3Xd nodes = tilted_plate(m);
  uvlm::VortexLatticeData d(m);
  fly_three_steps(m, d, nodes);
  const Eigen::Matrix3Xd dv = random_node_velocities(m, 5);
  const Eigen::Matrix3Xd difference =
      force_difference(m, d, nodes, dv, kPlateStream, kPlateStep, kPlateRho, 1e-5);
  uvlm::AddedMassScratch scratch(m);
  const auto error = [&](uvlm::AddedMassTerms terms) {
    Eigen::Matrix3Xd response;
    uvlm::added_mass_force_change(m, d, dv, scratch, response, terms);
    return (response - difference).norm() / difference.norm();
  };
  const double unsteady = error(uvlm::AddedMassTerms::Unsteady), pressure = error(uvlm::AddedMassTerms::Pressure);
  std::printf("[ value ] the response off the loads' derivative by %.3g (∂Γ/∂t), %.3g (and V·∇Γ)\n", unsteady,
              pressure);
  EXPECT_GT(unsteady, 0.1);
  EXPECT_LT(pressure, 1e-6);
}

TEST(AddedMass, WithTheLeadingEdgeForceTheResponseIsTheLoadsDerivativeInAFreeStream) {
  // The plate of the test above with an attached and a separated (Polhamus) leading-edge
  // force: AddedMassTerms::All (leading_edge_response.hpp) against the
  // central difference of the forces, Bernoulli loads: the whole response is the
  // derivative (measured 1.3e-10 attached, 1.1e-10 separated; bound 1e-6), and without the
  // edge's part it is off by the suction's change (measured 0.27 and 0.26: bound more than
  // 0.01).
  for (const uvlm::LeadingEdge edge : {uvlm::LeadingEdge::Attached, uvlm::LeadingEdge::Separated}) {
    const uvlm::VortexLatticeModel m = plate_model(edge);
    const Eigen::Matrix3Xd nodes = tilted_plate(m);
    uvlm::VortexLatticeData d(m);
    fly_three_steps(m, d, nodes);
    const Eigen::Matrix3Xd dv = random_node_velocities(m, 7);
    const Eigen::Matrix3Xd difference =
        force_difference(m, d, nodes, dv, kPlateStream, kPlateStep, kPlateRho, 1e-5);
    uvlm::AddedMassScratch scratch(m);
    Eigen::Matrix3Xd all, pressure;
    uvlm::added_mass_force_change(m, d, dv, scratch, all, uvlm::AddedMassTerms::All);
    uvlm::added_mass_force_change(m, d, dv, scratch, pressure, uvlm::AddedMassTerms::Pressure);
    const double error = (all - difference).norm() / difference.norm();
    const double without = (pressure - difference).norm() / difference.norm();
    std::printf("[ value ] %s edge: the response off the loads' derivative by %.3g (%.3g without the edge)\n",
                edge == uvlm::LeadingEdge::Attached ? "attached" : "separated", error, without);
    EXPECT_LT(error, 1e-6);
    EXPECT_GT(without, 1e-2);

  }
}

TEST(AddedMass, AHeavingPlateFeelsAForceAgainstItsAcceleration) {
  // A uniform heave δv = n (every node moving along the plate's normal) must be met by a
  // total force along −n (the air resists the acceleration), and the steady lattice
  // (∂Γ/∂t = 0) has no added mass at all.
  uvlm::VortexLatticeModel m;
  m.chordwise = 4;
  m.spanwise = 8;
  m.wake_capacity = 4;
  const Eigen::Matrix3Xd nodes = tilted_plate(m);
  const Eigen::Vector3d normal = Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()).toRotationMatrix() *
                                 Eigen::Vector3d::UnitZ();
  uvlm::VortexLatticeData d(m);
  uvlm::solve(m, d, nodes, Eigen::Matrix3Xd::Zero(3, m.nodes()), Eigen::Vector3d::Zero(), 1e-3, 1.225);
  Eigen::Matrix3Xd heave(3, m.nodes());
  heave.colwise() = normal;
  uvlm::AddedMassScratch scratch(m);
  Eigen::Matrix3Xd df;
  uvlm::added_mass_force_change(m, d, heave, scratch, df);
  const Eigen::Vector3d total = df.rowwise().sum();
  EXPECT_LT(total.dot(normal), 0.0);
  EXPECT_LT((total - total.dot(normal) * normal).norm(), 1e-12 * total.norm());  // along n only

  uvlm::VortexLatticeModel steady = m;
  steady.steady_wake_length = 1.0;
  uvlm::VortexLatticeData ds(steady);
  uvlm::solve(steady, ds, nodes, Eigen::Matrix3Xd::Zero(3, m.nodes()), Eigen::Vector3d(1.0, 0.0, 0.0), 1e-3, 1.225);
  uvlm::AddedMassScratch steady_scratch(steady);
  uvlm::added_mass_force_change(steady, ds, heave, steady_scratch, df);
  EXPECT_EQ(df.cwiseAbs().maxCoeff(), 0.0);
  // A velocity field of the wrong size is refused.
  EXPECT_THROW(uvlm::added_mass_force_change(m, d, Eigen::Matrix3Xd::Zero(3, 5), scratch, df), std::invalid_argument);
}

}  // namespace
