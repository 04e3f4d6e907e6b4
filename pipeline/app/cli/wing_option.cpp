#include "pipeline/app/cli/wing_option.hpp"

#include "pipeline/app/wing_override.hpp"
#include "pipeline/io/case_file.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/toml_reader.hpp"

namespace flapsim::cli {

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
        "the case flies its own chain file, not one reduced from " + wing_file +
            ": give that wing's chain with --chain too ('flapsim reduce " + wing_file +
            " -o DIR' makes DIR/chain.toml), or use a case without 'chain', which reduces its wing "
            "as it runs");
  case_root.apply_overrides({app::wing_file_override(wing_file)});
}

std::filesystem::path default_run_folder(const std::string& case_name, const std::string& wing_file) {
  const std::string name =
      wing_file.empty() ? case_name : case_name + "_" + std::filesystem::path(wing_file).stem().string();
  return std::filesystem::path("out") / io::folder_name_of(name);
}

}  // namespace flapsim::cli
