#include "pipeline/io/chain_file.hpp"

#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/csv_writer.hpp"
#include "wings/input_error.hpp"
#include "wings/toml_reader.hpp"

#include <array>
#include <sstream>
#include <stdexcept>

namespace flapsim::io {

namespace {

using wings::Bounds;
using wings::TomlTable;

constexpr std::array<std::pair<std::string_view, mbd::RootAttachment>, 2> kRootNames{
    {{"rigid", mbd::RootAttachment::rigid}, {"sprung", mbd::RootAttachment::sprung}}};

Eigen::Matrix3d read_matrix3(const TomlTable& t, std::string_view key, double scale) {
  const auto rows = t.get_number_rows(key, 3, 3);
  if (rows.size() != 3) t.fail(key, "expected 3 rows of 3 numbers");
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = rows[i][j] * scale;
  return m;
}

mbd::ChainModel parse_chain(const TomlTable& root) {
  root.expect_only({"length_unit", "root", "root_offset", "root_rotation", "bodies", "name",
                    "description"});
  root.read_length_unit();
  mbd::ChainModel chain;
  chain.root = root.get_choice("root", kRootNames);
  chain.root_offset = root.get_length_vector3("root_offset", Eigen::Vector3d::Zero());
  if (root.has("root_rotation")) chain.root_rotation = read_matrix3(root, "root_rotation", 1.0);
  const auto bodies = root.get_tables("bodies", 1);
  if (bodies.empty()) root.fail("bodies", "a chain needs at least one [[bodies]] entry");
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const TomlTable& t = bodies[i];
    t.expect_only({"length", "mass", "center_of_mass", "inertia", "outboard_joint", "joint", "name"});
    mbd::ChainBody b;
    b.length = t.get_length("length", Bounds::positive());
    b.mass = t.get_double("mass", Bounds::positive());
    b.center_of_mass = t.get_length_vector3("center_of_mass");
    b.inertia = read_matrix3(t, "inertia", 1.0);
    b.outboard_joint = t.get_length_vector3("outboard_joint", Eigen::Vector3d(0.0, b.length, 0.0));
    mbd::ChainJoint j;
    const bool needs_joint = !(i == 0 && chain.root == mbd::RootAttachment::rigid);
    if (auto jt = t.find_table("joint")) {
      jt->expect_only({"bend_stiffness", "twist_stiffness", "bend_damping", "twist_damping",
                       "bend_rest", "twist_rest"});
      j.bend_stiffness = jt->get_double("bend_stiffness", Bounds::non_negative());
      j.twist_stiffness = jt->get_double("twist_stiffness", Bounds::non_negative());
      j.bend_damping = jt->get_double("bend_damping", 0.0, Bounds::non_negative());
      j.twist_damping = jt->get_double("twist_damping", 0.0, Bounds::non_negative());
      j.bend_rest = jt->get_double("bend_rest", 0.0, Bounds::closed(-3.2, 3.2));
      j.twist_rest = jt->get_double("twist_rest", 0.0, Bounds::closed(-3.2, 3.2));
    } else if (needs_joint) {
      t.fail("joint", "missing [bodies.joint] table (springs of the joint inboard of body " +
                          std::to_string(i + 1) + ")");
    }
    // Physical checks per body, located at the body's keys.
    mbd::ChainModel one;
    one.bodies.push_back(b);
    one.joints.push_back(mbd::ChainJoint{});
    try {
      one.validate();
    } catch (const std::invalid_argument& e) {
      std::string msg = e.what();
      const auto pos = msg.find("body 0: ");
      if (pos != std::string::npos) msg = msg.substr(pos + 8);
      t.fail("inertia", msg);
    }
    chain.bodies.push_back(b);
    chain.joints.push_back(j);
  }
  try {
    chain.validate();
  } catch (const std::invalid_argument& e) {
    root.fail("root_rotation", e.what());
  }
  return chain;
}

std::string vec3(const Eigen::Vector3d& v) {
  return "[" + format_number(v.x()) + ", " + format_number(v.y()) + ", " +
         format_number(v.z()) + "]";
}

std::string mat3(const Eigen::Matrix3d& m) {
  return "[" + vec3(m.row(0).transpose()) + ", " + vec3(m.row(1).transpose()) + ", " +
         vec3(m.row(2).transpose()) + "]";
}

}  // namespace

mbd::ChainModel read_chain_file(const std::string& path) {
  return parse_chain(wings::parse_toml_file(path));
}

mbd::ChainModel parse_chain_text(std::string_view text, const std::string& name) {
  return parse_chain(wings::parse_toml_string(text, name));
}

std::string format_chain_file(const mbd::ChainModel& chain) {
  std::ostringstream s;
  s << "# Hencky bar chain (docs/multibody.md). SI units.\n"
    << "# Body frame: origin at the inboard joint, y along the body, x toward the leading edge.\n"
    << "# Joint k: R = Rx(bend) * Ry(twist); inertia about the centre of mass, body axes.\n"
    << "length_unit = \"m\"\n"
    << "root = \"" << wings::choice_name(kRootNames, chain.root) << "\"\n"
    << "root_offset = " << vec3(chain.root_offset) << "\n"
    << "root_rotation = " << mat3(chain.root_rotation) << "   # R_WR, row by row\n";
  for (int k = 0; k < chain.num_bodies(); ++k) {
    const auto& b = chain.bodies[static_cast<std::size_t>(k)];
    const auto& j = chain.joints[static_cast<std::size_t>(k)];
    s << "\n[[bodies]]   # body " << k + 1 << "\n"
      << "length = " << format_number(b.length) << "\n"
      << "mass = " << format_number(b.mass) << "\n"
      << "center_of_mass = " << vec3(b.center_of_mass) << "\n"
      << "inertia = " << mat3(b.inertia) << "\n"
      << "outboard_joint = " << vec3(b.outboard_joint) << "\n";
    if (k == 0 && chain.root == mbd::RootAttachment::rigid) continue;  // welded: no joint
    s << "[bodies.joint]   # inboard of this body\n"
      << "bend_stiffness = " << format_number(j.bend_stiffness) << "\n"
      << "twist_stiffness = " << format_number(j.twist_stiffness) << "\n"
      << "bend_damping = " << format_number(j.bend_damping) << "\n"
      << "twist_damping = " << format_number(j.twist_damping) << "\n"
      << "bend_rest = " << format_number(j.bend_rest) << "\n"
      << "twist_rest = " << format_number(j.twist_rest) << "\n";
  }
  return s.str();
}

void write_chain_file(const std::filesystem::path& path, const mbd::ChainModel& chain) {
  write_text_atomically(path, format_chain_file(chain));
}

}  // namespace flapsim::io
