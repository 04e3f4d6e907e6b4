// chain.toml (pipeline/io/chain_file.hpp): write/read round trip, the shipped 3-body chain,
// and errors that name file, line and key.

#include "mbd/chain_test_models.hpp"

#include "pipeline/io/chain_file.hpp"
#include "wings/loader/input_error.hpp"

#include <gtest/gtest.h>

#include <string>

namespace flapsim::mbd {
namespace {

void expect_same_chain(const ChainModel& a, const ChainModel& b) {
  ASSERT_EQ(a.num_bodies(), b.num_bodies());
  EXPECT_EQ(a.root, b.root);
  EXPECT_EQ(a.root_offset, b.root_offset);
  EXPECT_EQ(a.root_rotation, b.root_rotation);
  EXPECT_EQ(a.first_jointed_body(), b.first_jointed_body());
  EXPECT_EQ(a.stiffness(), b.stiffness());
  EXPECT_EQ(a.damping(), b.damping());
  for (int i = 0; i < a.num_bodies(); ++i) {
    EXPECT_EQ(a.bodies[i].length, b.bodies[i].length);
    EXPECT_EQ(a.bodies[i].mass, b.bodies[i].mass);
    EXPECT_EQ(a.bodies[i].center_of_mass, b.bodies[i].center_of_mass);
    EXPECT_EQ(a.bodies[i].inertia, b.bodies[i].inertia);
    EXPECT_EQ(a.bodies[i].outboard_joint, b.bodies[i].outboard_joint);
    if (i < a.first_jointed_body()) continue;
    if (a.stiffness_matrix.size() == 0) {  // with a full K the joints' springs are not used
      EXPECT_EQ(a.joints[i].bend_stiffness, b.joints[i].bend_stiffness);
      EXPECT_EQ(a.joints[i].twist_stiffness, b.joints[i].twist_stiffness);
    }
    EXPECT_EQ(a.joints[i].bend_damping, b.joints[i].bend_damping);
    EXPECT_EQ(a.joints[i].twist_damping, b.joints[i].twist_damping);
    EXPECT_EQ(a.joints[i].bend_rest, b.joints[i].bend_rest);
    EXPECT_EQ(a.joints[i].twist_rest, b.joints[i].twist_rest);
  }
}

TEST(ChainFile, RoundTripIsExact) {
  const ChainModel chain = test::general_chain();  // sprung root, offsets, full tensors
  expect_same_chain(chain, io::parse_chain_text(io::format_chain_file(chain), "rt.toml"));
}

// Issue 17: the chain file stores the full joint stiffness and damping (and welded
// bodies) exactly; per-joint springs are then absent from the file.
TEST(ChainFile, FullJointStiffnessRoundTripIsExact) {
  ChainModel chain = test::three_body_chain_coupled();
  const std::string text = io::format_chain_file(chain);
  EXPECT_NE(text.find("joint_stiffness = ["), std::string::npos);
  EXPECT_EQ(text.find("bend_stiffness"), std::string::npos);
  expect_same_chain(chain, io::parse_chain_text(text, "rt.toml"));
  chain = test::three_body_chain();  // two welded bodies, one joint with a 2 x 2 K
  chain.welded_bodies = 2;
  chain.stiffness_matrix = Eigen::Matrix2d{{3e-3, 4e-4}, {4e-4, 1e-3}};
  expect_same_chain(chain, io::parse_chain_text(io::format_chain_file(chain), "rt.toml"));
}

TEST(ChainFile, IndefiniteJointStiffnessIsAnInputErrorAtItsKey) {
  ChainModel chain = test::three_body_chain_coupled();
  chain.stiffness_matrix(0, 0) = -1e-3;  // not positive semi-definite
  try {
    io::parse_chain_text(io::format_chain_file(chain), "bad.toml");
    FAIL() << "accepted an indefinite stiffness";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("joint_stiffness"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("positive semi-definite"), std::string::npos) << e.what();
  }
}

TEST(ChainFile, ShippedThreeBodyChainIsTheTestedChain) {
  expect_same_chain(test::three_body_chain(),
                    io::read_chain_file(FLAPSIM_SOURCE_DIR "/cases/chains/three_body.toml"));
}

TEST(ChainFile, LengthUnitScalesLengthsOnly) {
  const std::string text = R"(length_unit = "mm"
root = "sprung"
[[bodies]]
length = 10
mass = 1e-5
center_of_mass = [0, 5, 0]
inertia = [[1e-10, 0, 0], [0, 2e-10, 0], [0, 0, 3e-10]]
[bodies.joint]
bend_stiffness = 1e-3
twist_stiffness = 2e-3
)";
  const ChainModel c = io::parse_chain_text(text, "mm.toml");
  EXPECT_DOUBLE_EQ(c.bodies[0].length, 0.01);
  EXPECT_DOUBLE_EQ(c.bodies[0].center_of_mass.y(), 0.005);
  EXPECT_DOUBLE_EQ(c.bodies[0].outboard_joint.y(), 0.01);  // default (0, length, 0)
  EXPECT_DOUBLE_EQ(c.bodies[0].mass, 1e-5);                // SI, not scaled
  EXPECT_DOUBLE_EQ(c.joints[0].bend_stiffness, 1e-3);
}

void expect_error(const std::string& text, int line, const std::string& key) {
  try {
    io::parse_chain_text(text, "bad.toml");
    FAIL() << "no InputError for key " << key;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "bad.toml");
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.key(), key) << e.what();
  }
}

TEST(ChainFile, BadInputNamesFileLineAndKey) {
  const std::string head = "root = \"rigid\"\n[[bodies]]\nlength = 0.01\nmass = 1e-5\n"
                           "center_of_mass = [0, 0.005, 0]\n";
  const std::string inertia = "inertia = [[1e-10, 0, 0], [0, 1e-10, 0], [0, 0, 2e-10]]\n";
  // negative mass (line 4)
  expect_error("root = \"rigid\"\n[[bodies]]\nlength = 0.01\nmass = -1e-5\ncenter_of_mass = [0, 0, 0]\n" + inertia,
               4, "bodies[0].mass");
  // inertia violating the triangle inequality (line 6)
  expect_error(head + "inertia = [[1e-10, 0, 0], [0, 1e-10, 0], [0, 0, 5e-10]]\n", 6, "bodies[0].inertia");
  // second body without its joint springs (its [[bodies]] at line 7)
  expect_error(head + inertia + "[[bodies]]\nlength = 0.01\nmass = 1e-5\ncenter_of_mass = [0, 0, 0]\n" + inertia,
               7, "bodies[1].joint");
  // typo in a key (line 7)
  expect_error(head + inertia + "outbord_joint = [0, 0.01, 0]\n", 7, "bodies[0].outbord_joint");
  // unknown root choice (line 1)
  expect_error("root = \"welded\"\n[[bodies]]\nlength = 0.01\nmass = 1e-5\ncenter_of_mass = [0, 0, 0]\n" + inertia,
               1, "root");
  // springs for the first body of a rigid root, welded to it: they were read and ignored
  // (its [bodies.joint] at line 7)
  expect_error(head + inertia + "[bodies.joint]\nbend_stiffness = 0.02\ntwist_stiffness = 0.01\n", 7,
               "bodies[0].joint");
}


// A moving body (jointed, not welded) of zero mass passes the per-body reading (a welded
// body may be massless) and is refused by the whole chain's validation
// (mbd::ChainModel::validate: "body 2: mass must be > 0"). Before, every error of that
// validation was reported at the key root_rotation (line 1); now at the body's own key.
TEST(ChainFile, AChainValidationErrorNamesTheBodysKeyAndLine) {
  const std::string inertia = "inertia = [[1e-10, 0, 0], [0, 1e-10, 0], [0, 0, 2e-10]]\n";
  const std::string body1 = "root = \"rigid\"\n[[bodies]]\nlength = 0.01\nmass = 1e-5\n"
                            "center_of_mass = [0, 0.005, 0]\n" + inertia;            // lines 1-6
  const std::string body2 = "[[bodies]]\nlength = 0.01\nmass = 0\n"                  // lines 7-9
                            "center_of_mass = [0, 0.005, 0]\n" + inertia +             // lines 10-11
                            "[bodies.joint]\nbend_stiffness = 1e-3\ntwist_stiffness = 1e-4\n";
  expect_error(body1 + body2, 9, "bodies[1].mass");
  // A non-symmetric joint-stiffness matrix is reported at its key (line 1 of this text).
  const std::string matrix = "joint_stiffness = [[1e-3, 1e-4], [0, 1e-4]]\n";
  const std::string body2_no_springs = "[[bodies]]\nlength = 0.01\nmass = 1e-5\n"
                                       "center_of_mass = [0, 0.005, 0]\n" + inertia;
  expect_error(matrix + body1 + body2_no_springs, 1, "joint_stiffness");
}

}  // namespace
}  // namespace flapsim::mbd
