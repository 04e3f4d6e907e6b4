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

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "fem/wing_fem.hpp"
#include "reduction/chain_lumping.hpp"
#include "reduction/tip_loads.hpp"
#include "wings/wing_file.hpp"

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

}  // namespace
}  // namespace flapsim::reduction
