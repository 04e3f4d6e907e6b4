// flapsim check FILE.toml: validate a wing or case file and print its summary.
#include "pipeline/app/cli/commands.hpp"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>
#include <string>

#include "pipeline/io/case_file.hpp"
#include "pipeline/io/case_summary.hpp"
#include "wings/input_error.hpp"
#include "wings/toml_reader.hpp"
#include "wings/wing_file.hpp"
#include "wings/wing_summary.hpp"

namespace flapsim::cli {

namespace {

/// Reads the file, decides whether it is a wing ([planform]) or a case ([kinematics]),
/// checks it completely (a case's wing file too) and returns the summary text.
/// Nothing is printed until everything has been checked.
std::string check_file(const std::string& path) {
  const wings::TomlTable root = wings::parse_toml_file(path);
  const bool wing = wings::is_wing_document(root), case_file = io::is_case_document(root);
  if (wing && case_file)
    throw InputError(path, root.line_of("planform"), "planform",
                     "a file is either a wing file ([planform]) or a case file ([kinematics]), not both");
  if (wing) return wings::describe_wing(print_wing_warnings(wings::read_wing(root)));
  if (case_file) {
    const io::Case c = io::read_case(root);
    std::string text = io::describe_case(c);
    if (!c.wing_file.empty()) text += "\n" + wings::describe_wing(print_wing_warnings(wings::load_wing_file(c.wing_file)));
    return text;
  }
  throw InputError(path, 1, "",
                   "not a wing file (no [planform] table) nor a case file (no [kinematics] table)");
}

}  // namespace

void add_check_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "check",
      "Check a wing or case file and print its summary.\n"
      "A wing file (it has a [planform] table) prints span, area, mean chord S/R,\n"
      "aspect ratio R^2/S, r2/R, the number of veins and the estimated mass.\n"
      "A case file (it has a [kinematics] table) prints sweep, deviation, rotation and\n"
      "the geometric angle of attack at phases 0, 0.25, 0.5, 0.75, then air, structure\n"
      "and numerics, and checks the wing file it names.\n"
      "Exit status: 0 valid, 2 bad input (the message names file, line and key).\n"
      "Formats: docs/wing_file.md, docs/case_file.md.");
  auto file = std::make_shared<std::string>();
  cmd->add_option("FILE", *file, "wing or case file (TOML)")->required();
  cmd->callback([file] { std::cout << check_file(*file) << std::flush; });
}

}  // namespace flapsim::cli
