#include "pipeline/io/input_hash.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "wings/input_error.hpp"
#include "wings/toml_reader.hpp"

namespace flapsim::io {

namespace {

void add_part(std::string& out, std::string_view role, const std::string& text) {
  // Role and length first: no two different sequences of parts serialise alike.
  out += role;
  out += ' ';
  out += std::to_string(text.size());
  out += '\n';
  out += text;
  out += '\n';
}

std::string file_bytes(const std::string& path, const std::string& key) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, key, "cannot open the file for reading");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

std::string hash_hex(std::uint64_t hash) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash));
  return buf;
}

std::string canonical_inputs(const std::string& case_file,
                             const std::vector<std::pair<std::string, std::string>>& overrides,
                             const std::string& chain_file) {
  std::string out;
  wings::TomlTable root = wings::parse_toml_file(case_file);
  root.apply_overrides(overrides);
  add_part(out, "case", root.canonical_text());
  if (root.is_string("wing")) {
    const wings::TomlTable wing = wings::parse_toml_file(root.get_path("wing"));
    add_part(out, "wing", wing.canonical_text());
    if (const auto planform = wing.find_table("planform"); planform && planform->is_string("outline_file"))
      add_part(out, "outline", file_bytes(planform->get_path("outline_file"), planform->key_path("outline_file")));
  }
  const std::string chain = !chain_file.empty() ? chain_file : root.is_string("chain") ? root.get_path("chain") : "";
  if (!chain.empty()) add_part(out, "chain", wings::parse_toml_file(chain).canonical_text());
  return out;
}

std::uint64_t input_hash(const std::string& case_file,
                         const std::vector<std::pair<std::string, std::string>>& overrides,
                         const std::string& chain_file) {
  return fnv1a64(canonical_inputs(case_file, overrides, chain_file));
}

}  // namespace flapsim::io
