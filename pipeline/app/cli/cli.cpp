#include "pipeline/app/cli/commands.hpp"

#include <CLI/CLI.hpp>

#include <csignal>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <new>
#include <string>

#include "fem/mesh_quality.hpp"
#include "fem/root_clamp_warning.hpp"
#include "pipeline/app/cli/exit_status.hpp"
#include "pipeline/app/cli/thread_options.hpp"
#include "pipeline/app/interruption.hpp"
#include "pipeline/fsi/numerical_failure.hpp"
#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/case_model.hpp"
#include "uvlm/kernel_dispatch.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/toml_reader.hpp"
#include "wings/loader/wing_model.hpp"

namespace flapsim::cli {

void check_chain_option(const std::string& chain_file) {
  if (!chain_file.empty() && !std::filesystem::exists(chain_file))
    throw InputError(chain_file, 0, "--chain", "chain file not found");
  if (!chain_file.empty() && !std::filesystem::is_regular_file(chain_file))
    throw InputError(chain_file, 0, "--chain", "not a regular file (a device, FIFO or folder)");
}

const wings::Wing& print_wing_warnings(const wings::Wing& wing) {
  for (const InputWarning& w : wing.warnings) std::fprintf(stderr, "flapsim: warning: %s\n", w.text().c_str());
  return wing;
}

void print_mesh_warnings(const fem::Mesh& mesh, const wings::Wing& wing) {
  if (const std::string w = fem::sliver_warning(mesh, wing); !w.empty())
    std::fprintf(stderr, "flapsim: warning: %s\n", w.c_str());
  if (const std::string w = fem::root_clamp_warning(mesh, wing); !w.empty())
    std::fprintf(stderr, "flapsim: warning: %s\n", w.c_str());
}

const io::Case& print_case_warnings(const io::Case& c) {
  for (const InputWarning& w : c.warnings) std::fprintf(stderr, "flapsim: warning: %s\n", w.text().c_str());
  return c;
}

void warn_unused_structure_options(const io::Case& c, const std::string& chain_file, double spring_scale) {
  if (c.structure.kind == io::Case::Structure::Kind::Flexible) return;
  const std::string kind(wings::choice_name(io::kStructureKindNames, c.structure.kind));
  if (!chain_file.empty())
    std::fprintf(stderr, "flapsim: warning: --chain %s is not used: %s says structure.kind = \"%s\"\n",
                 chain_file.c_str(), c.file.c_str(), kind.c_str());
  if (spring_scale != 1.0)
    std::fprintf(stderr, "flapsim: warning: --spring-scale is not used: %s says structure.kind = \"%s\"\n",
                 c.file.c_str(), kind.c_str());
}

// The text of an error as printed: every run of more than 4096 bytes without a space (a
// value or key echoed from the input; a 2 MB string value once came back whole, 2 MB on
// stderr; a path is at most 4096 bytes) cut in its middle: its first 200 and last 60 bytes
// kept, on UTF-8 character boundaries, around "...[N bytes cut]...".
static std::string shortened(const std::string& text) {
  constexpr std::size_t kLongestWord = 4096;
  if (text.size() <= kLongestWord) return text;
  const auto continuation = [&](std::size_t k) { return (static_cast<unsigned char>(text[k]) & 0xC0) == 0x80; };
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    std::size_t end = i;
    while (end < text.size() && text[end] != ' ' && text[end] != '\n') ++end;
    if (end - i > kLongestWord) {
      std::size_t head = i + 200, tail = end - 60;
      while (head > i && continuation(head)) --head;
      while (tail < end && continuation(tail)) ++tail;
      out.append(text, i, head - i).append("...[").append(std::to_string(tail - head)).append(" bytes cut]...");
      out.append(text, tail, end - tail);
    } else {
      out.append(text, i, end - i);
    }
    if (end < text.size()) out.push_back(text[end]);
    i = end + 1;
  }
  return out;
}

int run(int argc, char** argv) {
  // A write past the file-size limit (ulimit -f) fails with EFBIG, which the writers report
  // as an output error (exit status 4, temporary files removed), instead of SIGXFSZ killing
  // the program mid-write.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{
      "flapsim: flexible flapping wings, from a wing drawing to lift.\n"
      "Stages: mesh -> modes (FEM) -> reduce (beam, bar chain) -> run (FSI) -> sweep, optimize."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "flapsim 0.1.0");
  add_check_command(app);
  add_mesh_command(app);
  add_modes_command(app);
  add_reduce_command(app);
  add_run_command(app);
  add_sweep_command(app);
  add_optimize_command(app);
  for (CLI::App* command : app.get_subcommands({})) add_threads_option(*command);
  // A first word that is no command: CLI11 says only "A subcommand is required".
  if (argc > 1 && argv[1][0] != '-') {
    std::string names;
    bool known = false;
    for (const CLI::App* command : app.get_subcommands({})) {
      known = known || command->get_name() == argv[1];
      names += (names.empty() ? "" : ", ") + command->get_name();
    }
    if (!known) {
      std::cerr << "flapsim: unknown command '" << argv[1] << "': the commands are " << names
                << " (flapsim --help)\n";
      return kExitUsage;
    }
  }
  if (const std::string w = uvlm::kernel_environment_warning(); !w.empty())
    std::fprintf(stderr, "flapsim: warning: %s\n", w.c_str());
  // The exit-status contract (exit_status.hpp, README.md): each kind of error has one status.
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version print and succeed; any other parse error is a usage error.
    return app.exit(e) == 0 ? kExitOk : kExitUsage;
  } catch (const InputError& e) {
    std::cerr << "flapsim: error: " << shortened(e.what()) << "\n";
    return kExitInput;
  } catch (const NumericalFailure& e) {
    std::cerr << "flapsim: numerical failure: " << shortened(e.what()) << "\n";
    return kExitNumerical;
  } catch (const app::Interrupted& e) {
    std::cerr << "flapsim: " << shortened(e.what()) << "\n";
    return exit_status_of_signal(e.signal_number());
  } catch (const io::OutputError& e) {
    std::cerr << "flapsim: output error: " << shortened(e.what()) << "\n";
    return kExitOutput;
  } catch (const std::bad_alloc&) {
    std::cerr << "flapsim: system error: out of memory (the run's estimate is printed by 'flapsim check')\n";
    return kExitOutput;
  } catch (const std::filesystem::filesystem_error& e) {
    std::cerr << "flapsim: output error: " << shortened(e.what()) << "\n";
    return kExitOutput;
  } catch (const std::exception& e) {
    std::cerr << "flapsim: system error: " << shortened(e.what()) << "\n";
    return kExitOutput;
  }
  return kExitOk;
}

}  // namespace flapsim::cli
