#pragma once
/// \file commands.hpp
/// \brief The flapsim subcommands. Each add_*_command registers one subcommand
/// (its options, --help text and callback) on the application; callbacks report
/// bad input by throwing flapsim::InputError (exit 2), failed runs by throwing
/// flapsim::NumericalFailure (exit 3) and output errors by io::OutputError (exit 4).

#include <string>

namespace CLI { class App; }
namespace flapsim::wings { struct Wing; }
namespace flapsim::io { struct Case; }
namespace flapsim::fem { struct Mesh; }

namespace flapsim::cli {

void add_check_command(CLI::App& app);   ///< flapsim check FILE.toml
void add_mesh_command(CLI::App& app);    ///< flapsim mesh WING.toml -o DIR
void add_modes_command(CLI::App& app);   ///< flapsim modes WING.toml -o DIR
void add_reduce_command(CLI::App& app);  ///< flapsim reduce WING.toml -o DIR --bodies N
void add_run_command(CLI::App& app);     ///< flapsim run CASE.toml -o DIR
void add_sweep_command(CLI::App& app);   ///< flapsim sweep CASE.toml --vary KEY=VALUES -o DIR
void add_optimize_command(CLI::App& app);  ///< flapsim optimize CASE.toml --vary KEY=LO:HI --maximize RESULT -o DIR

/// The --chain option of run and sweep: "" (none) or an existing file.
/// \throws flapsim::InputError (key "--chain") if the file does not exist
void check_chain_option(const std::string& chain_file);

/// Prints the wing's plausibility warnings on stderr ("flapsim: warning: FILE:LINE: key
/// 'KEY': MESSAGE", docs/wing_file.md) and returns the wing.
const wings::Wing& print_wing_warnings(const wings::Wing& wing);

/// Prints the warning for a sliver triangle in the wing's mesh (fem/mesh_quality.hpp), if
/// there is one, as print_wing_warnings.
void print_mesh_warnings(const fem::Mesh& mesh, const wings::Wing& wing);

/// Prints the case's warnings on stderr (io::Case::warnings), as print_wing_warnings.
const io::Case& print_case_warnings(const io::Case& c);

/// A rigid case has no chain and no springs: warns that --chain and --spring-scale (≠ 1)
/// are not used, rather than ignore them silently.
void warn_unused_structure_options(const io::Case& c, const std::string& chain_file, double spring_scale);

/// Parses argv, runs the chosen subcommand, returns the process exit status
/// (exit_status.hpp): 0 ok, 1 usage error, 2 bad input, 3 numerical failure,
/// 4 output or system error, 130/143 interrupted by SIGINT/SIGTERM.
int run(int argc, char** argv);

}  // namespace flapsim::cli
