// The reduction's unit tip moment on a film wing (issue 34, item 10; docs/reduction.md,
// "A tip moment on a film tip"). Reported: the FEM's bending rotation under a positive tip
// moment, read in the chain's coordinates, came out negative on rod-and-film wings (report
// rows -261 % / -122 %). Found: the sign convention holds (the load is the documented
// wrench, and the rod, the wing's beam, turns tip-up), but the load case spreads the couple
// evenly over the tip zone's nodes, which on a film tip are film aft of the rod: the film
// takes it and twists about the rod (trailing edge down inboard, up at the tip), and the
// stations, weighted by mass (film), read that. What the rows read then depends on where the
// measuring body lies in the film's answer (measured on this wing, FEM side:
// +0.034, +0.066, +4.2e-4, -1.6e-4, +0.0050, +0.0075, +0.015 rad at 2, 4, 5, 6, 8, 12, 16 bodies).
// Fixed: the report's bending row is now the rotation conjugate to a moment on the chain's tip
// body, on both sides, positive by construction (second test).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "fem/wing_fem.hpp"
#include "reduction/chain_lumping.hpp"
#include "reduction/linear_chain.hpp"
#include "reduction/reduction_report.hpp"
#include "reduction/tip_loads.hpp"
#include "wings/loader/wing_file.hpp"

namespace flapsim::reduction {
namespace {

TEST(FilmTipMoment, TheLoadIsThePositiveMomentAndTheRodTurnsTipUpWhileTheFilmTwistsAboutIt) {
  const wings::Wing wing =
      wings::load_wing_file(std::string(FLAPSIM_SOURCE_DIR) + "/tests/data/rod_film_75mm_wing.toml");
  const fem::WingFem fem = fem::build_wing_fem(wing);
  const ClampedWingAnalysis an(fem.model.mesh, fem.system, fem.root_clamp);
  const TipZone& zone = an.tip_zone();
  const Eigen::VectorXd& s = an.s();
  const Eigen::VectorXd& n = an.n();
  const double m = an.wrenches()[kBendingMoment].moment_n;
  ASSERT_GT(m, 0.0);

  // (1) The nodal forces are the documented wrench (tip_loads.hpp): no resultant force,
  // moment about e_n = Σ f (s − s_c) = +M (tip up), none about e_s = −Σ f (n − n_c); the
  // frame (e_n, e_s, e_z) is right-handed (e_n × e_s = e_z, axis_frame.hpp), so r × f e_z
  // has e_n component (s − s_c) f.
  const Eigen::VectorXd f = tip_load_vector(zone, s, n, an.wrenches()[kBendingMoment]);
  double fz = 0.0, mn = 0.0, ms = 0.0;
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    const double fi = f[fem::dof_index(static_cast<int>(i), fem::UZ)];
    fz += fi;
    mn += fi * (s[i] - zone.s_centroid);
    ms -= fi * (n[i] - zone.n_centroid);
  }
  EXPECT_NEAR(fz, 0.0, 1e-9 * m / (an.s_tip() - zone.s_start));
  EXPECT_NEAR(mn, m, 1e-9 * m);
  EXPECT_NEAR(ms, 0.0, 1e-9 * m);

  // (2) The rod, the wing's beam, turns tip-up: its u_z grows outboard, 0.8 → 0.95 of the
  // span (it ends 0.8 mm short of the tip), and it is up there. Its line: 0.5 mm behind
  // the leading edge (the largest n; test data file), nearest nodes.
  const Eigen::VectorXd& uz = an.uz().col(kBendingMoment);
  auto nearest = [&](double ss, double nn) {
    Eigen::Index best = 0;
    double bd = 1e300;
    for (Eigen::Index i = 0; i < s.size(); ++i) {
      const double d = std::hypot(s[i] - ss, n[i] - nn);
      if (d < bd) {
        bd = d;
        best = i;
      }
    }
    return best;
  };
  const double n_rod = n.maxCoeff() - 0.5e-3;
  const double tip = an.s_tip();
  EXPECT_GT(uz[nearest(0.95 * tip, n_rod)], uz[nearest(0.8 * tip, n_rod)]);
  EXPECT_GT(uz[nearest(0.95 * tip, n_rod)], 0.0);

  // (3) The film aft of the rod goes down at 0.6 of the span, ten times (measured over a
  // thousand times) the rod's motion there: the film, not the beam, answers the couple,
  // and the stations average the film.
  const double film = uz[nearest(0.6 * tip, n_rod - 10e-3)];
  std::printf("film tip moment %.3g N m: rod u_z %.4g m (0.8 span), %.4g m (0.95); film 10 mm aft at 0.6 span %.4g m, "
              "rod there %.4g m\n",
              m, uz[nearest(0.8 * tip, n_rod)], uz[nearest(0.95 * tip, n_rod)], film, uz[nearest(0.6 * tip, n_rod)]);
  EXPECT_LT(film, 0.0);
  EXPECT_GT(std::abs(film), 10.0 * std::abs(uz[nearest(0.6 * tip, n_rod)]));
}

// The fix: the report's bending-rotation row reads the rotation conjugate to the load, on
// both sides, for a moment M_n on the chain's tip body (docs/reduction.md, "A tip moment on a
// film tip"). Before, it read the tip-zone moment's rotation at the measuring body through
// the stations, i.e. the film's twist there: FEM −1.56e-4 rad at 6 bodies (row −71 %), and
// +4.2e-4 … +0.066 rad at 2, 4, 5, 8, 12, 16 bodies with the chain's own reading as low as
// −1.3e-4 (rows −36 … −131 %). Each asserted number's source is written beside it.
TEST(FilmTipMoment, TheBendingRowComparesTheRotationConjugateToTheSameMomentOnBothSides) {
  const wings::Wing wing =
      wings::load_wing_file(std::string(FLAPSIM_SOURCE_DIR) + "/tests/data/rod_film_75mm_wing.toml");
  const fem::WingFem fem = fem::build_wing_fem(wing);
  const fem::WingModes modes = fem::wing_modes(fem, 6);
  const ClampedWingAnalysis an(fem.model.mesh, fem.system, fem.root_clamp);
  const double m = an.wrenches()[kBendingMoment].moment_n;
  const Eigen::Index nn = an.nodes().cols();
  const int ndof = fem::kDofsPerNode * static_cast<int>(nn);
  for (int nb : {2, 4, 5, 6, 8, 12, 16}) {
    SCOPED_TRACE("bodies " + std::to_string(nb));
    const LumpedChain lc = lump_into_chain(an, nb);
    const ChainFemComparison c = compare_chain_with_fem(an, lc, modes.modes, modes.kinds);
    const LinearChain lin(lc.chain);
    const int tip = nb - 1;
    const double s_j = lc.joint_s.back();  // the tip body's inboard joint [m]
    EXPECT_DOUBLE_EQ(c.bending_body_s, s_j);

    // (1) Positive on both sides. Source: f ≠ 0 and K positive definite on the free DOFs give
    // fᵀ K⁻¹ f > 0; Q ≠ 0 and K_c positive definite (joint_stiffness.hpp: min eigenvalue > 0)
    // give Qᵀ K_c⁻¹ Q > 0. Without the fix the FEM side was −1.56e-4 rad at 6 bodies.
    EXPECT_GT(c.tip_bending_rotation.fem, 0.0);
    EXPECT_GT(c.tip_bending_rotation.chain, 0.0);
    EXPECT_GT(lc.joint_stiffness.min_eigenvalue, 0.0);

    // (2) The FEM side is the rotation conjugate to the moment spread over the tip body's
    // strip by mass, recomputed here from its definition: nodal forces on the strip's free
    // nodes, f_i = m_i (λ₀ + λ₁ (s_i − s_j) − λ₂ n_i) with the 3 × 3 system solved here; their
    // resultant is the moment M_n and nothing else (checked to 1e-9 of M_n), and fᵀ x / M_n
    // with x = K⁻¹ f equals the row to 1e-9 (one factorisation, the same solve).
    std::vector<int> strip;
    for (Eigen::Index i = 0; i < nn; ++i)
      if (!an.clamped()[static_cast<std::size_t>(i)] && an.s()[i] >= s_j) strip.push_back(static_cast<int>(i));
    Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
    for (int i : strip) {
      const int d = fem::dof_index(i, fem::UZ);
      const Eigen::Vector3d b(1.0, an.s()[i] - s_j, -an.n()[i]);
      g += fem.system.mass.coeff(d, d) * b * b.transpose();
    }
    const Eigen::Vector3d lambda = g.inverse() * Eigen::Vector3d(0.0, m, 0.0);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(ndof);
    double fz = 0.0, mn = 0.0, ms = 0.0;
    for (int i : strip) {
      const int d = fem::dof_index(i, fem::UZ);
      f[d] = fem.system.mass.coeff(d, d) * Eigen::Vector3d(1.0, an.s()[i] - s_j, -an.n()[i]).dot(lambda);
      fz += f[d];
      mn += f[d] * (an.s()[i] - s_j);
      ms -= f[d] * an.n()[i];
    }
    EXPECT_NEAR(fz * (an.s_tip() - s_j), 0.0, 1e-9 * m);
    EXPECT_NEAR(mn, m, 1e-9 * m);
    EXPECT_NEAR(ms, 0.0, 1e-9 * m);
    const double theta_fem = f.dot(Eigen::VectorXd(an.solve(f))) / m;
    EXPECT_NEAR(c.tip_bending_rotation.fem * m / theta_fem, 1.0, 1e-9);  // the row is per unit moment

    // (3) The chain side is the rotation conjugate to the same load mapped to the chain: the
    // same nodal forces, each a point force on the tip body at its node (not the moment the
    // code applies), give the generalized force Q_f; Q_fᵀ K_c⁻¹ Q_f / M_n equals the row to
    // 1e-9 (a rigid body takes a couple of forces as their moment).
    Eigen::VectorXd q_f = Eigen::VectorXd::Zero(lin.num_dofs());
    for (int i : strip)
      q_f += lin.generalized_force(tip, Eigen::Vector3d(an.n()[i], an.s()[i], 0.0),
                                   Eigen::Vector3d(0.0, 0.0, f[fem::dof_index(i, fem::UZ)]), Eigen::Vector3d::Zero());
    const double theta_chain = q_f.dot(lin.static_response(q_f)) / m;
    EXPECT_NEAR(c.tip_bending_rotation.chain * m / theta_chain, 1.0, 1e-9);

    // (4) And the chain's number is the FEM's own conjugate rotation under the chain's
    // station loads Tᵀ Q of that Q (exact at the stations, joint_stiffness.hpp): the FEM with
    // the two loads of the same moment on the same body, to 1e-8. The row's error is
    // therefore how differently the FEM takes the moment spread by mass over the whole strip
    // and concentrated on the stations' bands, not a sign or a reading.
    const Eigen::VectorXd f_st = lc.stations.load_vector(lc.joint_stiffness.station_loads(q_f), ndof);
    EXPECT_NEAR(f_st.dot(Eigen::VectorXd(an.solve(f_st))) / m / theta_chain, 1.0, 1e-8);
    std::printf(
        "rod-film 75 mm, %2d bodies: bending row FEM %.4g, chain %.4g rad/(N m) (%+.1f %%), the load case "
        "%.3g N m\n",
        nb, c.tip_bending_rotation.fem, c.tip_bending_rotation.chain,
        100 * c.tip_bending_rotation.relative_error, m);
  }
}

}  // namespace
}  // namespace flapsim::reduction
