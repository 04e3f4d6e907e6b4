#pragma once
// Small inputs and checks shared by the robustness tests of the command line (exit
// statuses, full disks, output folders, signals).

#include <filesystem>
#include <string>
#include <vector>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace flapsim::test {

inline const std::string kSourceDir = FLAPSIM_SOURCE_DIR;

/// The flat plate of wings/flat_plate.toml with eq. 8 kinematics, 3 x 4 panels, 24 steps
/// per cycle; `extra_numerics` lines are added to [numerics].
inline std::string small_plate_case(const std::string& kind = "rigid", int cycles = 1, int vtk_every = 6,
                                    const std::string& extra_numerics = "", const std::string& head = "") {
  return head + "name = \"plate\"\nwing = \"" + kSourceDir + "/wings/flat_plate.toml\"\n" +
         "[kinematics]\nfrequency_hz = 26.1\nrotation_phase = -0.1\n"
         "sweep = { mean_deg = 10.0, cos_deg = [50.0] }\n"
         "rotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
         "[structure]\nkind = \"" + kind + "\"\n" + (kind == "flexible" ? "bodies = 2\n" : "") +
         "[numerics]\nsteps_per_cycle = 24\ncycles = " + std::to_string(cycles) +
         "\nchordwise_panels = 3\nspanwise_panels = 4\ncore_radius = 0.2\n" + extra_numerics +
         "[output]\nvtk_every = " + std::to_string(vtk_every) + "\n";
}

/// \p text with the first \p from replaced by \p to (unchanged if absent).
inline std::string replace_once(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// The closing text a complete file of each output format ends with ("" = unknown).
inline std::string complete_tail(const std::filesystem::path& file) {
  const std::string ext = file.extension().string();
  if (ext == ".vtu" || ext == ".vtp" || ext == ".pvd") return "</VTKFile>\n";
  if (ext == ".msh") return "$EndElements\n";
  if (ext == ".json") return "}\n";
  if (ext == ".csv" || ext == ".md" || ext == ".toml") return "\n";
  return "";
}

/// Files under the folder that are truncated (do not end as their format ends) or empty.
inline std::vector<std::string> truncated_files(const ScratchDir& dir, const std::filesystem::path& sub) {
  std::vector<std::string> bad;
  if (!std::filesystem::exists(sub)) return bad;
  for (const auto& e : std::filesystem::recursive_directory_iterator(sub)) {
    if (!e.is_regular_file()) continue;
    const std::string text = read_text(e.path());
    const std::string tail = complete_tail(e.path());
    if (text.empty() || (text.size() < tail.size() || text.compare(text.size() - tail.size(), tail.size(), tail) != 0))
      bad.push_back(e.path().lexically_relative(dir.path()).string());
  }
  return bad;
}

/// A chain file of two bodies whose outer joint has almost no stiffness (1e-12 N m/rad) and
/// a tip 100 times heavier than the root body: under a flapping case with 4 steps per cycle
/// it flails and the implicit step fails (exit status 3, docs/reliability.md).
inline const char* const kDivergingTwoBodyChain =
    "root = \"rigid\"\n"
    "[[bodies]]\nlength = 0.02\nmass = 1e-5\ncenter_of_mass = [0, 0.01, 0]\n"
    "inertia = [[4e-10,0,0],[0,1e-11,0],[0,0,4e-10]]\n"
    "[[bodies]]\nlength = 0.02\nmass = 1e-3\ncenter_of_mass = [-0.02, 0.01, 0]\n"
    "inertia = [[4e-8,0,0],[0,1e-12,0],[0,0,4e-8]]\n"
    "[bodies.joint]\nbend_stiffness = 1e-12\ntwist_stiffness = 1e-12\n";

/// Runs `flapsim ARGS` under a file-size limit of `blocks` blocks of /bin/sh's ulimit -f
/// (512 B in dash, 1 KiB in bash), SIGXFSZ as a user's shell leaves it (its default kills
/// the process): flapsim ignores it itself, so a write past the limit fails with EFBIG, as
/// on a full disk. Returns the exit status (−1 if a signal ended the program).
inline int run_flapsim_with_file_limit(const std::string& args, int blocks) {
  return run_flapsim_in_shell("ulimit -f " + std::to_string(blocks) + "; exec", args);
}

}  // namespace flapsim::test
