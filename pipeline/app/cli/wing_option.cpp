#include "pipeline/app/cli/wing_option.hpp"

#include <cstdio>

#include "pipeline/io/case_file.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/toml_reader.hpp"

namespace flapsim::cli {

namespace {

// A TOML basic string of any text (TOML 1.0, "String"): quotes, backslashes and control
// characters escaped.
std::string toml_basic_string(const std::string& text) {
  std::string out = "\"";
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20 || c == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04X", static_cast<unsigned>(c));
      out += escaped;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

}  // namespace

void apply_wing_option(wings::TomlTable& case_root, const std::string& wing_file,
                       const std::string& chain_file) {
  if (wing_file.empty()) return;
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(wing_file, ec)) throw InputError(wing_file, 0, "--wing", "wing file not found");
  if (!fs::is_regular_file(wing_file, ec))
    throw InputError(wing_file, 0, "--wing", "not a regular file (a device, FIFO or folder)");
  if (case_root.has("chain") && chain_file.empty())
    throw InputError(
        case_root.file(), case_root.line_of("chain"), "chain",
        "the case flies its own chain file, reduced from its own wing, not from " + wing_file +
            ": give that wing's chain with --chain too ('flapsim reduce " + wing_file +
            " -o DIR' makes DIR/chain.toml), or use a case without 'chain', which reduces its wing "
            "as it runs");
  // The case resolves 'wing' against its own folder: an absolute path stays as it is.
  case_root.apply_overrides(
      {{"wing", toml_basic_string(fs::absolute(wing_file).lexically_normal().string())}});
}

std::filesystem::path default_run_folder(const std::string& case_name, const std::string& wing_file) {
  const std::string name =
      wing_file.empty() ? case_name : case_name + "_" + std::filesystem::path(wing_file).stem().string();
  return std::filesystem::path("out") / io::folder_name_of(name);
}

}  // namespace flapsim::cli
