#include "pipeline/io/chain_file.hpp"

#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/csv_writer.hpp"
#include "pipeline/io/input_hash.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/toml_reader.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

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

// The text of a TOML basic string's content: backslash, quote and control characters escaped.
std::string toml_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\\' || c == '"') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      out += buf;
    } else {
      out += c;
    }
  }
  return out;
}

// The fingerprint of a chain's numbers: FNV-1a 64 of its chain-file text without a
// [fem_comparison] (the text round-trips the numbers exactly), 16 hex digits.
std::string chain_fingerprint(const mbd::ChainModel& chain) {
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx",
                static_cast<unsigned long long>(fnv1a_64(format_chain_file(chain, nullptr))));
  return buf;
}

// The static rows' keys in [fem_comparison] (chain, FEM per row; SI per unit load).
// The static rows' keys in [fem_comparison], all or none: where they are read [m], then chain
// and FEM per row (SI per unit load).
constexpr std::array<const char*, 8> kStaticRowKeys = {"measure_s_m",
                                                       "bending_body_s_m",
                                                       "tip_deflection_chain_m_per_n",
                                                       "tip_deflection_fem_m_per_n",
                                                       "tip_bending_rotation_chain_rad_per_n_m",
                                                       "tip_bending_rotation_fem_rad_per_n_m",
                                                       "tip_twist_chain_rad_per_n_m",
                                                       "tip_twist_fem_rad_per_n_m"};

// [fem_comparison]: each kind's three numbers, all or none; the static rows' eight, all or none.
ChainFemRecord parse_fem_comparison(const TomlTable& t) {
  std::vector<std::string> known{"wing",        "chain_fingerprint", "bending_chain_hz", "bending_fem_hz",
                                 "bending_mac", "torsion_chain_hz",  "torsion_fem_hz",   "torsion_mac"};
  known.insert(known.end(), kStaticRowKeys.begin(), kStaticRowKeys.end());
  t.expect_only(known);
  ChainFemRecord r;
  r.wing_file = t.get_string("wing", "");
  for (auto [kind, m] : {std::pair{std::string("bending"), &r.bending}, std::pair{std::string("torsion"), &r.torsion}}) {
    const std::string chain_key = kind + "_chain_hz", fem_key = kind + "_fem_hz", mac_key = kind + "_mac";
    const bool any = t.has(chain_key) || t.has(fem_key) || t.has(mac_key);
    if (!any) continue;
    for (const std::string& k : {chain_key, fem_key, mac_key})
      if (!t.has(k)) t.fail(k, "missing: " + kind + "_chain_hz, " + kind + "_fem_hz and " + kind + "_mac go together");
    m->found = true;
    m->chain_hz = t.get_double(chain_key, Bounds::positive());
    m->fem_hz = t.get_double(fem_key, Bounds::positive());
    m->mac = t.get_double(mac_key, Bounds::closed(0.0, 1.0));
    m->relative_error = reduction::relative_error(m->chain_hz, m->fem_hz);
  }
  if (std::any_of(kStaticRowKeys.begin(), kStaticRowKeys.end(), [&](const char* k) { return t.has(k); })) {
    for (const char* k : kStaticRowKeys)
      if (!t.has(k))
        t.fail(
            k,
            "missing: the static rows' eight keys (measure_s_m, bending_body_s_m and the chain's and FEM's "
            "tip_deflection, tip_bending_rotation and tip_twist) go together");
    ChainFemRecord::StaticRows rows;
    rows.measure_s = t.get_double(kStaticRowKeys[0], Bounds::any());
    rows.bending_body_s = t.get_double(kStaticRowKeys[1], Bounds::any());
    reduction::StaticMatch* matches[3] = {&rows.tip_deflection, &rows.tip_bending_rotation, &rows.tip_twist};
    for (std::size_t k = 0; k < 3; ++k) {
      matches[k]->chain = t.get_double(kStaticRowKeys[2 + 2 * k], Bounds::any());
      matches[k]->fem = t.get_double(kStaticRowKeys[3 + 2 * k], Bounds::any());
      matches[k]->relative_error = reduction::relative_error(matches[k]->chain, matches[k]->fem);
    }
    r.statics = rows;
  }
  return r;
}

// A problem the whole chain's validation finds (mbd::ChainModel::validate: "chain: body 3:
// mass must be > 0", "chain: joint 2: ...", "chain: stiffness matrix ..."), located at the
// key it concerns: a body's key in its [[bodies]] table, a joint's [bodies.joint], the root's
// keys. (Every such error used to be reported at root_rotation.)
[[noreturn]] void fail_at_the_key(const TomlTable& root, const std::vector<TomlTable>& bodies,
                                  const std::string& what) {
  std::string msg = what.rfind("chain: ", 0) == 0 ? what.substr(7) : what;
  const auto numbered = [&](const char* head, std::size_t& index) {
    if (msg.rfind(head, 0) != 0) return false;
    const std::size_t colon = msg.find(": ");
    const int k = std::atoi(msg.c_str() + std::char_traits<char>::length(head));
    if (colon == std::string::npos || k < 1 || static_cast<std::size_t>(k) > bodies.size()) return false;
    index = static_cast<std::size_t>(k - 1);
    msg = msg.substr(colon + 2);
    return true;
  };
  std::size_t k = 0;
  if (numbered("body ", k)) {
    const TomlTable& t = bodies[k];
    const bool about_inertia = msg.find("inertia") != std::string::npos || msg.find("principal") != std::string::npos;
    std::string key = "inertia";
    if (msg.rfind("length", 0) == 0) key = "length";
    else if (msg.rfind("mass", 0) == 0) key = "mass";
    else if (msg.rfind("non-finite", 0) == 0 || !about_inertia) key = "center_of_mass";
    t.fail(key, msg);
  }
  if (numbered("joint ", k)) {
    const TomlTable& t = bodies[k];
    t.fail("joint", "the joint inboard of body " + std::to_string(k + 1) + ": " + msg);
  }
  if (msg.rfind("stiffness matrix", 0) == 0) root.fail("joint_stiffness", msg);
  if (msg.rfind("damping matrix", 0) == 0) root.fail("joint_damping", msg);
  if (msg.rfind("welded bodies", 0) == 0) root.fail("welded_bodies", msg);
  if (msg.rfind("root offset", 0) == 0) root.fail("root_offset", msg);
  if (msg.rfind("root rotation", 0) == 0) root.fail("root_rotation", msg);
  root.fail("bodies", msg);
}

mbd::ChainModel parse_chain(const TomlTable& root, std::optional<ChainFemRecord>* fem) {
  // A wing or case file where a chain file belongs (--chain, a case's chain): say so.
  if (!root.has("bodies")) {
    if (root.has("planform"))
      root.fail("planform", "this is a wing file (it has [planform]), not a chain file (no [[bodies]]): "
                            "'flapsim reduce' makes the wing's chain file; without a chain file a flexible case "
                            "reduces its wing in process");
    if (root.has("kinematics"))
      root.fail("kinematics", "this is a case file (it has [kinematics]), not a chain file (no [[bodies]])");
  }
  root.expect_only({"length_unit", "root", "welded_bodies", "root_offset", "root_rotation",
                    "joint_stiffness", "joint_damping", "bodies", "name", "description", "fem_comparison"});
  root.read_length_unit();
  mbd::ChainModel chain;
  chain.root = root.get_choice("root", kRootNames);
  if (root.has("welded_bodies")) {
    if (chain.root != mbd::RootAttachment::rigid)
      root.fail("welded_bodies", "only a rigid root welds bodies to it (root = \"rigid\")");
    chain.welded_bodies = root.get_int("welded_bodies", Bounds::closed(1, 1e9));
  }
  const bool full_stiffness = root.has("joint_stiffness");
  chain.root_offset = root.get_length_vector3("root_offset", Eigen::Vector3d::Zero());
  if (root.has("root_rotation")) chain.root_rotation = read_matrix3(root, "root_rotation", 1.0);
  const auto bodies = root.get_tables("bodies", 1);
  if (bodies.empty()) root.fail("bodies", "a chain needs at least one [[bodies]] entry");
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const TomlTable& t = bodies[i];
    t.expect_only({"length", "mass", "center_of_mass", "inertia", "outboard_joint", "joint", "name"});
    mbd::ChainBody b;
    b.length = t.get_length("length", Bounds::positive());
    b.mass = t.get_double("mass", Bounds::non_negative());  // > 0 unless welded (checked below)
    b.center_of_mass = t.get_length_vector3("center_of_mass");
    b.inertia = read_matrix3(t, "inertia", 1.0);
    b.outboard_joint = t.get_length_vector3("outboard_joint", Eigen::Vector3d(0.0, b.length, 0.0));
    mbd::ChainJoint j;
    const bool needs_joint =
        !full_stiffness && !(chain.root == mbd::RootAttachment::rigid && static_cast<int>(i) < chain.welded_bodies);
    if (auto jt = t.find_table("joint")) {
      // A body welded to a rigid root has no joint: its springs would be read and ignored.
      if (chain.root == mbd::RootAttachment::rigid && static_cast<int>(i) < chain.welded_bodies)
        t.fail(
            "joint",
            "body " + std::to_string(i + 1) + " is welded to the rigid root (root = \"rigid\"" +
                (chain.welded_bodies > 1 ? ", welded_bodies = " + std::to_string(chain.welded_bodies) : "") +
                "): it has no joint, and its [bodies.joint] would be ignored; drop the table, or "
                "give the root its springs with root = \"sprung\"");
      if (full_stiffness) {  // the springs are the matrix: no per-joint springs
        jt->expect_only({"bend_damping", "twist_damping", "bend_rest", "twist_rest"});
      } else {
        jt->expect_only({"bend_stiffness", "twist_stiffness", "bend_damping", "twist_damping",
                         "bend_rest", "twist_rest"});
        j.bend_stiffness = jt->get_double("bend_stiffness", Bounds::non_negative());
        j.twist_stiffness = jt->get_double("twist_stiffness", Bounds::non_negative());
      }
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
      const auto pos = msg.find("body 1: ");
      if (pos != std::string::npos) msg = msg.substr(pos + 8);
      t.fail("inertia", msg);
    }
    chain.bodies.push_back(b);
    chain.joints.push_back(j);
  }
  if (chain.root == mbd::RootAttachment::rigid && chain.welded_bodies > chain.num_bodies())
    root.fail("welded_bodies", "the chain has only " + std::to_string(chain.num_bodies()) + " bodies");
  for (const char* key : {"joint_stiffness", "joint_damping"}) {
    if (!root.has(key)) continue;
    const std::size_t n = static_cast<std::size_t>(chain.num_dofs());
    const auto rows = root.get_number_rows(key, n, n);
    if (rows.size() != n)
      root.fail(key, "expected " + std::to_string(n) + " rows of " + std::to_string(n) +
                         " numbers (bend and twist of each of the " + std::to_string(n / 2) + " joints)");
    Eigen::MatrixXd m(n, n);
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t c = 0; c < n; ++c) m(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = rows[r][c];
    (std::string_view(key) == "joint_stiffness" ? chain.stiffness_matrix : chain.damping_matrix) = m;
    try {
      chain.validate();
    } catch (const std::invalid_argument& e) {
      const std::string msg = e.what();
      if (msg.find("matrix") != std::string::npos) root.fail(key, msg);
    }
  }
  try {
    chain.validate();
  } catch (const std::invalid_argument& e) {
    fail_at_the_key(root, bodies, e.what());
  }
  if (auto t = root.find_table("fem_comparison")) {
    ChainFemRecord r = parse_fem_comparison(*t);
    // A chain changed after reduce compared it (springs edited by hand): the record no
    // longer describes it and is dropped.
    const bool same_chain = !t->has("chain_fingerprint") || t->get_string("chain_fingerprint") == chain_fingerprint(chain);
    if (fem) {
      if (same_chain) *fem = std::move(r);
      else fem->reset();
    }
  } else if (fem) {
    fem->reset();
  }
  return chain;
}

std::string vec3(const Eigen::Vector3d& v) {
  // Appended piece by piece: GCC 12's -Wrestrict misfires on `"[" + std::string&&` (GCC bug 105329).
  std::string s("[");
  s.append(format_number(v.x())).append(", ").append(format_number(v.y())).append(", ");
  s.append(format_number(v.z())).append("]");
  return s;
}

std::string mat3(const Eigen::Matrix3d& m) {
  std::string s("[");
  s.append(vec3(m.row(0).transpose())).append(", ").append(vec3(m.row(1).transpose())).append(", ");
  s.append(vec3(m.row(2).transpose())).append("]");
  return s;
}

}  // namespace

ChainFemRecord chain_fem_record(const std::string& wing_file, const reduction::ChainFemComparison& c) {
  ChainFemRecord r{wing_file, c.bending, c.torsion, ChainFemRecord::StaticRows{}};
  r.statics->measure_s = c.measure_s;
  r.statics->bending_body_s = c.bending_body_s;
  r.statics->tip_deflection = c.tip_deflection;
  r.statics->tip_bending_rotation = c.tip_bending_rotation;
  r.statics->tip_twist = c.tip_twist;
  return r;
}

mbd::ChainModel read_chain_file(const std::string& path, std::optional<ChainFemRecord>* fem) {
  return parse_chain(wings::parse_toml_file(path), fem);
}

mbd::ChainModel parse_chain_text(std::string_view text, const std::string& name, std::optional<ChainFemRecord>* fem) {
  return parse_chain(wings::parse_toml_string(text, name), fem);
}

std::string format_chain_file(const mbd::ChainModel& chain, const ChainFemRecord* fem) {
  std::ostringstream s;
  s << "# Hencky bar chain (docs/multibody.md). SI units.\n"
    << "# Body frame: origin at the inboard joint, y along the body, x toward the leading edge.\n"
    << "# Joint k: R = Rx(bend) * Ry(twist); inertia about the centre of mass, body axes.\n"
    << "length_unit = \"m\"\n"
    << "root = \"" << wings::choice_name(kRootNames, chain.root) << "\"\n"
    << "root_offset = " << vec3(chain.root_offset) << "\n"
    << "root_rotation = " << mat3(chain.root_rotation) << "   # R_WR, row by row\n";
  if (chain.root == mbd::RootAttachment::rigid && chain.welded_bodies > 1)
    s << "welded_bodies = " << chain.welded_bodies << "   # bodies in the root clamp, welded to the root\n";
  auto matrix = [&](const char* key, const Eigen::MatrixXd& m, const char* what) {
    s << "# " << what << " over [bend, twist] of joints " << chain.first_jointed_body() + 1 << " ... "
      << chain.num_bodies() << ", row by row\n"
      << key << " = [\n";
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
      s << "  [";
      for (Eigen::Index c = 0; c < m.cols(); ++c) s << (c ? ", " : "") << format_number(m(r, c));
      s << "],\n";
    }
    s << "]\n";
  };
  const bool full = chain.stiffness_matrix.size() > 0;
  if (full) matrix("joint_stiffness", chain.stiffness_matrix, "Joint stiffness K [N m/rad]");
  if (chain.damping_matrix.size() > 0) matrix("joint_damping", chain.damping_matrix, "Joint damping C [N m s/rad]");
  if (fem) {
    s << "\n# The chain against the FEM of its wing, as 'flapsim reduce' found it (its report.md has the whole\n"
      << "# comparison); 'flapsim run' and 'check' of this chain repeat a miss of over 10 % (docs/reduction.md).\n"
      << "[fem_comparison]\n"
      << "wing = \"" << toml_escape(fem->wing_file) << "\"\n"
      << "chain_fingerprint = \"" << chain_fingerprint(chain)
      << "\"   # of the chain's numbers above and below: a chain edited since is not described by this table\n";
    for (auto [kind, m] : {std::pair{"bending", &fem->bending}, std::pair{"torsion", &fem->torsion}}) {
      if (!m->found) {
        s << "# no " << kind << " mode among the FEM modes computed\n";
        continue;
      }
      s << kind << "_chain_hz = " << format_number(m->chain_hz) << "   # first " << kind << " mode [Hz]\n"
        << kind << "_fem_hz = " << format_number(m->fem_hz) << "\n"
        << kind << "_mac = " << format_number(m->mac) << "   # modal assurance criterion of the two shapes\n";
    }
    if (fem->statics) {
      const ChainFemRecord::StaticRows& r = *fem->statics;
      s << "# The static rows of report.md: chain and FEM per unit load (docs/reduction.md)\n"
        << kStaticRowKeys[0] << " = " << format_number(r.measure_s)
        << "   # where tip deflection and twist are read [m]\n"
        << kStaticRowKeys[1] << " = " << format_number(r.bending_body_s)
        << "   # where the tip body starts [m]\n";
      const reduction::StaticMatch* matches[3] = {&r.tip_deflection, &r.tip_bending_rotation, &r.tip_twist};
      for (std::size_t k = 0; k < 3; ++k)
        s << kStaticRowKeys[2 + 2 * k] << " = " << format_number(matches[k]->chain) << "\n"
          << kStaticRowKeys[3 + 2 * k] << " = " << format_number(matches[k]->fem) << "\n";
    }
  }
  for (int k = 0; k < chain.num_bodies(); ++k) {
    const auto& b = chain.bodies[static_cast<std::size_t>(k)];
    const auto& j = chain.joints[static_cast<std::size_t>(k)];
    s << "\n[[bodies]]   # body " << k + 1 << "\n"
      << "length = " << format_number(b.length) << "\n"
      << "mass = " << format_number(b.mass) << "\n"
      << "center_of_mass = " << vec3(b.center_of_mass) << "\n"
      << "inertia = " << mat3(b.inertia) << "\n"
      << "outboard_joint = " << vec3(b.outboard_joint) << "\n";
    if (k < chain.first_jointed_body()) continue;  // welded: no joint
    s << "[bodies.joint]   # inboard of this body\n";
    if (!full)
      s << "bend_stiffness = " << format_number(j.bend_stiffness) << "\n"
        << "twist_stiffness = " << format_number(j.twist_stiffness) << "\n";
    s << "bend_damping = " << format_number(j.bend_damping) << "\n"
      << "twist_damping = " << format_number(j.twist_damping) << "\n"
      << "bend_rest = " << format_number(j.bend_rest) << "\n"
      << "twist_rest = " << format_number(j.twist_rest) << "\n";
  }
  return s.str();
}

void write_chain_file(const std::filesystem::path& path, const mbd::ChainModel& chain, const ChainFemRecord* fem) {
  write_text_atomically(path, format_chain_file(chain, fem));
}

}  // namespace flapsim::io
