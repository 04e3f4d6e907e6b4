#pragma once
/// \file setup_warnings.hpp
/// \brief The warnings about a case that need its built setup (the chain, the wing), in
/// the order `check`, `run` and `sweep` report them: a tip beyond Mach 0.3, a Reynolds
/// number below 32, a wing that moves trailing edge first, a chain file
/// that does not match the wing, a chain file that misses its wing's FEM modes (as reduce
/// found), a chain driven above or near its resonance, an FEM near its resonance, a chain
/// the flapping's inertia alone bends beyond 30°, a coupling tolerance below the
/// single-precision wake sums' floor, an FEM membrane that wrinkles at its mesh's scale (a
/// thin film), an FEM mesh with fewer than four elements across the chord.

#include <string>
#include <vector>

#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/io/case_model.hpp"

namespace flapsim::app {

/// \brief The warnings that apply (full texts; none: empty).
std::vector<std::string> setup_warnings(const io::Case& c, const FsiSetup& setup);

/// \brief A warning's first clause, up to its first ": " — what it found, with the numbers
/// (for the message column of sweep.csv): "the chain's mode 1 (bending), 21.6 Hz, lies near
/// the wingbeat frequency 20 Hz (mode / drive = 1.08)".
std::string warning_headline(const std::string& warning);

/// \brief The case file's and the wing file's warnings in a few words, each named by its key
/// as `flapsim sweep` names keys: "numerics.far_wake_cycles: far_wake_cycles = 1 in hover is
/// outside …", "wing.materials.pet.density: 5 kg/m³ is below …" (the warning up to its
/// first ": "); \p wing may be null.
std::vector<std::string> file_warning_notes(const io::Case& c, const wings::Wing* wing);

/// \brief Notes, "; "-separated: join_notes({"a", "b"}) is "a; b" (summary.json's
/// "warnings", sweep.csv's message).
std::string join_notes(const std::vector<std::string>& notes);

}  // namespace flapsim::app
