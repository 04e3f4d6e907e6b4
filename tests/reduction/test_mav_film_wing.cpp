// The shipped man-made MAV film wing (wings/mav_film_wing.toml; issue 17): carbon
// leading-edge rod, root spar and diagonal batten with a 25 µm Mylar film. The earlier
// lumping failed for every number of bodies ("non-positive spring"); with the joint
// stiffness by reciprocity it reduces for 4, 8, 10 and 16 bodies with K symmetric
// positive definite, its film modes are named "film", and chain vs FEM is reported.
// Measured (4 / 8 / 10 / 16 bodies): the FEM's first mode (13.60 Hz, the film and batten
// rotating about the leading-edge rod, beam share 0.98, named torsion) against the chain's
// first torsion mode −5.6 / −3.2 / +2.1 / −0.2 % (MAC 0.90); the first reciprocity chain
// (mid-span fitted slopes) gave −32.6 % at 10 bodies. The FEM's beam share of its higher
// modes is low (film modes from 47 Hz); the station classification finds a bending mode
// among the first 12 only at 4 and 8 bodies, and the chain misses it (+144 %, +91 %).

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cstdio>
#include <string>

#include "fem/wing_fem.hpp"
#include "reduction/chain_lumping.hpp"
#include "reduction/reduction_report.hpp"
#include "wings/wing_file.hpp"

namespace flapsim::reduction {
namespace {

TEST(MavFilmWing, ReducesForFourToSixteenBodiesWithPositiveDefiniteStiffness) {
  const wings::Wing wing = wings::load_wing_file(std::string(FLAPSIM_SOURCE_DIR) + "/wings/mav_film_wing.toml");
  const fem::WingFem fem = fem::build_wing_fem(wing);
  const fem::WingModes modes = fem::wing_modes(fem, 12);
  const ClampedWingAnalysis analysis(fem.model.mesh, fem.system, fem.root_clamp);
  for (int nb : {4, 8, 10, 16}) {
    const LumpedChain lc = lump_into_chain(analysis, nb);
    const Eigen::MatrixXd& k = lc.chain.stiffness_matrix;
    EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-12 * k.cwiseAbs().maxCoeff()) << nb;
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(k, Eigen::EigenvaluesOnly);
    EXPECT_GT(es.eigenvalues()(0), 0.0) << nb;
    EXPECT_NEAR(lc.chain.total_mass(), lc.fem_mass, 1e-12 * lc.fem_mass) << nb;
    const ChainFemComparison c = compare_chain_with_fem(analysis, lc, modes.modes, modes.kinds);
    std::printf("MAV film wing N_b=%2d: FEM bending %.2f Hz / chain %.2f Hz (%+.1f %%, MAC %.3f), FEM torsion %.2f Hz / "
                "chain %.2f Hz (%+.1f %%, MAC %.3f)\n",
                nb, c.bending.fem_hz, c.bending.chain_hz, 100 * c.bending.relative_error, c.bending.mac,
                c.torsion.fem_hz, c.torsion.chain_hz, 100 * c.torsion.relative_error, c.torsion.mac);
    for (const ModeMatch& p : c.beam_mode_pairs)
      std::printf("  FEM beam mode %2d (%s) %7.2f Hz ~ chain mode %2d %7.2f Hz (%+.1f %%, MAC %.3f)\n", p.fem_mode + 1,
                  c.fem_kinds[static_cast<std::size_t>(p.fem_mode)].c_str(), p.fem_hz, p.chain_mode + 1, p.chain_hz,
                  100 * p.relative_error, p.mac);
    // The first FEM mode is a beam (torsion) mode the chain follows: a guard at about twice
    // the largest error measured above.
    ASSERT_TRUE(c.torsion.found) << nb;
    EXPECT_EQ(c.torsion.fem_mode, 0) << nb;
    EXPECT_NEAR(c.torsion.relative_error, 0.0, 0.10) << nb;
    EXPECT_GT(c.torsion.mac, 0.8) << nb;
    if (nb == 10) {
      int film = 0;
      for (std::size_t i = 0; i < c.fem_kinds.size(); ++i) {
        std::printf("  FEM mode %2zu %8.2f Hz  %-8s beam share %.3f (shape: %s)\n", i + 1, c.fem_hz[i],
                    c.fem_kinds[i].c_str(), c.fem_beam_share[i], c.fem_shape_kinds[i].c_str());
        film += c.fem_kinds[i] == "film";
      }
      // Film modes (most of the motion not carried by the stations' rigid sections) are
      // named so, not "bending" (issue 17: the FEM's shape classification called the
      // film wing's 59.5 Hz mode "bending").
      EXPECT_GE(film, 1);
    }
  }
}

}  // namespace
}  // namespace flapsim::reduction
