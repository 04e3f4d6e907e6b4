#include "pipeline/app/optimize/optimum_case.hpp"

#include <toml++/toml.h>

#include <sstream>

#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/case_file.hpp"
#include "pipeline/io/csv_writer.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/toml_key_path.hpp"
#include "wings/loader/toml_reader.hpp"

namespace flapsim::optimize {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kWingPrefix = "wing.";

toml::table parse(const std::string& path) {
  (void)wings::parse_toml_file(path);  // the project's checks and messages (size, syntax)
  try {
    return toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    throw InputError(path, static_cast<int>(e.source().begin.line), "", std::string(e.description()));
  }
}

// A path of a file as written from DIR: relative when it can be.
std::string from_dir(const std::string& path, const fs::path& dir) {
  const fs::path p = fs::absolute(path).lexically_normal();
  const fs::path rel = p.lexically_relative(fs::absolute(dir).lexically_normal());
  return rel.empty() ? p.string() : rel.generic_string();
}

// A path key of a table, written relative to the file's folder, rewritten relative to DIR.
void move_path(toml::table& t, const std::string& key, const fs::path& from_folder, const fs::path& dir) {
  toml::node* n = t.get(key);
  if (!n || !n->is_string()) return;
  const fs::path p(n->as_string()->get());
  t.insert_or_assign(key, from_dir(p.is_absolute() ? p.string() : (from_folder / p).string(), dir));
}

void set_number(toml::table& root, const std::string& dotted, double value) {
  wings::ValueSlot slot;
  try {
    slot = wings::find_value_slot(root, dotted, true);
  } catch (const wings::KeyPathError&) {
    return;  // resolve_case refused such a key before any run
  }
  // An integer key stays an integer (resolve_case accepted the value, so it is integral).
  const toml::node* old = slot.get();
  if (old && old->is_integer())
    slot.set(toml::value<std::int64_t>(static_cast<std::int64_t>(value)));
  else
    slot.set(toml::value<double>(value));
}

std::string text_of(const toml::table& t) {
  std::ostringstream s;
  s << toml::toml_formatter(t) << '\n';
  return s.str();
}

// The wing file the points fly: --wing's, else the case's.
std::string flown_wing(const sweep::SweepInputs& inputs) {
  return inputs.wing_file.empty() ? io::load_case_file(inputs.case_file).wing_file : inputs.wing_file;
}

}  // namespace

std::optional<double> value_in_inputs(const sweep::SweepInputs& inputs, const std::string& key) {
  if (sweep::key_target(key) == sweep::KeyTarget::spring_scale) return inputs.spring_scale;
  std::string file = inputs.case_file;
  std::string dotted = key;
  if (sweep::key_target(key) == sweep::KeyTarget::wing_file) {
    file = flown_wing(inputs);
    dotted = key.substr(kWingPrefix.size());
    if (file.empty()) return std::nullopt;
  }
  toml::table root = parse(file);
  try {
    const toml::node* n = wings::find_value_slot(root, dotted, false).get();
    if (n)
      if (const auto v = n->value<double>()) return *v;
  } catch (const wings::KeyPathError&) {
  }
  return std::nullopt;  // not in the file (its default applies), or not a number key
}

WrittenCase write_case_at(const sweep::SweepInputs& inputs, const sweep::CasePoint& point, const fs::path& dir,
                          const std::string& name, const std::string& header) {
  WrittenCase out;
  out.spring_scale = inputs.spring_scale;
  toml::table c = parse(inputs.case_file);
  const fs::path case_folder = fs::path(inputs.case_file).parent_path();
  bool wing_varied = false;
  for (const sweep::Assignment& a : point) {
    switch (sweep::key_target(a.key)) {
      case sweep::KeyTarget::case_file: set_number(c, a.key, a.value); break;
      case sweep::KeyTarget::wing_file: wing_varied = true; break;
      case sweep::KeyTarget::spring_scale: out.spring_scale = a.value; break;
    }
  }
  move_path(c, "wing", case_folder, dir);
  move_path(c, "chain", case_folder, dir);
  if (!inputs.wing_file.empty()) c.insert_or_assign("wing", from_dir(inputs.wing_file, dir));
  if (!inputs.chain_file.empty()) c.insert_or_assign("chain", from_dir(inputs.chain_file, dir));
  std::string head;
  std::string comment;
  for (std::istringstream lines(header); std::getline(lines, head);) comment += "# " + head + "\n";
  if (out.spring_scale != 1.0)
    comment += "# Run with --spring-scale " + io::format_number(out.spring_scale) +
               " (the factor on every joint spring has no case key).\n";
  if (wing_varied) {
    const std::string wing_path = flown_wing(inputs);
    toml::table w = parse(wing_path);
    for (const sweep::Assignment& a : point)
      if (sweep::key_target(a.key) == sweep::KeyTarget::wing_file)
        set_number(w, a.key.substr(kWingPrefix.size()), a.value);
    if (toml::table* planform = w["planform"].as_table())
      move_path(*planform, "outline_file", fs::path(wing_path).parent_path(), dir);
    out.wing_file = dir / (name + "_wing.toml");
    io::write_text_atomically(out.wing_file, comment + "# The wing of " + name + ".toml.\n\n" + text_of(w));
    c.insert_or_assign("wing", out.wing_file.filename().string());
  }
  out.case_file = dir / (name + ".toml");
  io::write_text_atomically(out.case_file, comment + "\n" + text_of(c));
  return out;
}

}  // namespace flapsim::optimize
