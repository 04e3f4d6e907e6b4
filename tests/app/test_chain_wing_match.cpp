// A chain file that does not come from the case's wing is warned about. Before: the
// 10-body hawkmoth chain (33.8 mg, 48.4 mm) run with a 50 mm tapered PET plate (70.9 mg)
// gave mean CL 3.34 without a word — the lattice followed the plate, the structure was
// the hawkmoth's.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>

#include <fstream>
#include <string>

#include "pipeline/app/chain_wing_match.hpp"
#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/io/case_file.hpp"
#include "one_joint_chain.hpp"
#include "robustness_helpers.hpp"

using namespace flapsim::test;

namespace {

std::string warning_with(const ScratchDir& dir, const std::string& wing) {
  std::ofstream(dir / "chain.toml") << kOneJointChain;
  std::ofstream(dir / "case.toml") << "wing = \"" << kSourceDir << "/wings/" << wing
                                   << "\"\nchain = \"chain.toml\"\n[kinematics]\nfrequency_hz = 10\n"
                                      "sweep = { cos_deg = [50.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
                                      "[structure]\nkind = \"flexible\"\nbodies = 2\n";
  const flapsim::io::Case c = flapsim::io::load_case_file((dir / "case.toml").string());
  return flapsim::app::chain_wing_mismatch_warning(flapsim::app::build_fsi_setup(c, {}));
}

TEST(ChainWingMatch, AChainOfAnotherWingIsWarnedWithBothMassesAndLengths) {
  ScratchDir dir("chain_wing_match");
  // wings/hawkmoth.toml: 33.800 mg (flapsim check), span 48.3 mm.
  const std::string w = warning_with(dir, "hawkmoth.toml");
  EXPECT_NE(w.find("the chain (110 mg, 40 mm from the pivot to its last body's end) does not match the case's "
                   "wing 'hawkmoth' (33.8 mg, span 48.3 mm)"),
            std::string::npos) << w;
  // wings/flat_plate.toml: 40 x 10 mm, 0.2 mm PET at 1390 kg/m³ = 111.2 mg (1.1 % from the
  // chain's 110 mg), span 40 mm: a match.
  EXPECT_EQ(warning_with(dir, "flat_plate.toml"), "");
}

// `check --chain` builds the case with that chain, as `run --chain` does, and warns alike
// (make run passes the chain it will use); on a wing file the option is a usage error.
TEST(ChainWingMatch, CheckTakesTheChainRunWouldUse) {
  ScratchDir dir("chain_wing_match_check");
  std::ofstream(dir / "chain.toml") << kOneJointChain;
  std::ofstream(dir / "case.toml") << "wing = \"" << kSourceDir
                                   << "/wings/hawkmoth.toml\"\n[kinematics]\nfrequency_hz = 10\n"
                                      "sweep = { cos_deg = [50.0] }\nrotation = 90.0\n"
                                      "[structure]\nkind = \"flexible\"\nbodies = 2\n";
  const auto check = [&](const std::string& file) {
    const std::string err = (dir / "err.txt").string();
    const int status = std::system(("FLAPSIM_QUIET=1 OMP_NUM_THREADS=1 '" + std::string(FLAPSIM_BINARY) + "' check " +
                                    file + " --chain " + (dir / "chain.toml").string() + " > /dev/null 2> " + err)
                                       .c_str());
    return std::make_pair(WEXITSTATUS(status), read_text(err));
  };
  const auto [status, err] = check((dir / "case.toml").string());
  EXPECT_EQ(status, 0) << err;
  EXPECT_NE(err.find("the chain (110 mg, 40 mm"), std::string::npos) << err;
  EXPECT_EQ(check(kSourceDir + "/wings/hawkmoth.toml").first, 1);
}

// A chain along a swept axis is compared with the wing's reach along that axis, not with
// its span. Before: a swept wing's own chain (reduce runs the axis to the outline's farthest
// point along it: 34.6 mm for a 32 mm span, a 5-point wing swept back by 31°) was warned as
// "another wing's". Here: a plate swept back by 30° whose tip edge is square to its
// leading edge, (0, 0), (−20, 34.641), (−28.660, 29.641), (−10, 0) mm: along the axis
// (−sin 30°, cos 30°) its leading- and trailing-edge tips both lie 40.0 mm from the pivot,
// its span (largest y) is 34.64 mm, 13 % short of the chain's 40 mm; area (shoelace)
// 348.2 mm², 0.227 mm PET at 1390 kg/m³: 109.9 mg against the chain's 110 mg.
TEST(ChainWingMatch, AChainAlongASweptAxisIsComparedWithTheWingsReachAlongIt) {
  ScratchDir dir("chain_wing_match_swept");
  std::ofstream(dir / "swept.toml")
      << "name = \"swept\"\nlength_unit = \"mm\"\n[planform]\n"
         "outline = [[0.0, 0.0], [-20.0, 34.641], [-28.660, 29.641], [-10.0, 0.0]]\nclamp_y = 0.0\n"
         "[materials.pet]\nyoungs_modulus = 4.0e9\npoisson_ratio = 0.38\ndensity = 1390.0\n"
         "[membrane]\nthickness = 0.227\nmaterial = \"pet\"\n[mesh]\nelement_size = 1.0\nvein_element_size = 1.0\n";
  // R_WR = Rz(30°): the root frame's y along (−sin 30°, cos 30°) in the wing frame.
  const std::string rotation = "root_rotation = [[0.8660254037844387, -0.5, 0], [0.5, 0.8660254037844387, 0], [0, 0, 1]]\n";
  const auto warning = [&](const std::string& chain_head) {
    std::ofstream(dir / "chain.toml") << chain_head << kOneJointChain;
    std::ofstream(dir / "case.toml") << "wing = \"swept.toml\"\nchain = \"chain.toml\"\n[kinematics]\nfrequency_hz = 10\n"
                                        "sweep = { cos_deg = [50.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
                                        "[structure]\nkind = \"flexible\"\nbodies = 2\n";
    const flapsim::io::Case c = flapsim::io::load_case_file((dir / "case.toml").string());
    return flapsim::app::chain_wing_mismatch_warning(flapsim::app::build_fsi_setup(c, {}));
  };
  EXPECT_EQ(warning(rotation), "");
  // The same chain along the wing frame's y reaches 40 mm against the 34.64 mm span.
  const std::string w = warning("");
  EXPECT_NE(w.find("(109.9 mg, span 34.64 mm)"), std::string::npos) << w;
}

}  // namespace
