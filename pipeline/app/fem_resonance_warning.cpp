#include "pipeline/app/fem_resonance_warning.hpp"

#include <algorithm>
#include <cstdio>
#include <exception>

#include "fem/assembly.hpp"
#include "fem/modal_solver.hpp"
#include "pipeline/app/flexibility_warnings.hpp"

namespace flapsim::app {

FemNaturalModes fem_resonance_modes(const io::Case& c, const FsiSetup& setup) {
  if (c.structure.kind != io::Case::Structure::Kind::Fem || !setup.fem_structure) return {};
  const fsi::FemStructureModel& fem = *setup.fem_structure;
  const fem::AssembledSystem system = fem::assemble(fem.structural);
  const fem::Constraints& clamp = fem.dynamics.eliminated;
  const double top = highest_resonant_mode_hz(c.kinematics.frequency);
  const int free = clamp.num_free();
  fem::ModalOptions options;  // those of `flapsim modes` (fem::wing_modes) but the count
  fem::ModalResult modes;
  for (int want = 4;; want *= 2) {
    options.num_modes = std::min({want, kMaxFemResonanceModes, free - 1});
    modes = fem::solve_modes(system.stiffness, system.mass, clamp, options);
    const Eigen::Index found = modes.frequencies_hz.size();
    if (found == 0 || modes.frequencies_hz(found - 1) > top || options.num_modes >= kMaxFemResonanceModes ||
        options.num_modes >= free - 1)
      break;
  }
  FemNaturalModes out;
  out.frequencies_hz.assign(modes.frequencies_hz.data(), modes.frequencies_hz.data() + modes.frequencies_hz.size());
  // Clamped: no rigid-body modes (rigid_fraction 0, as fem::wing_modes).
  out.kinds = fem::classify_modes(fem.structural.mesh, system, modes.shapes, modes.frequencies_hz, 0.0);
  return out;
}

namespace {

/// The warning for a wing whose first mode lies below the fundamental's resonance band.
std::string driven_above_first_mode_warning(const FemNaturalModes& modes, double f) {
  // Below the fundamental's band: the drive is above the first mode. A base-driven
  // oscillator at r = f / f1 > 1 moves against its base by r² / (r² − 1) times the
  // base's motion (the motion relative to a moving support, undamped; [Thomson & Dahleh
  // 1998] ch. 3): about as far as the base itself moves, the flapping's tens of degrees.
  const double r = f / modes.frequencies_hz[0];
  char text[900];
  std::snprintf(
      text, sizeof text,
      "the FEM's mode 1 (%s shape), %.4g Hz, lies below the wingbeat frequency %.3g Hz (drive / mode = "
      "%.3g): a wing driven above its first mode deforms against its base by about as much as the "
      "base moves (%.2f times it, undamped), tens of degrees at the tip where the flapping swings "
      "tens of degrees; an FEM step follows such motion only in many pieces, if at all (the wing's "
      "natural modes clamped at its root, in vacuum, as `flapsim modes` finds them on this mesh). "
      "Stiffen the wing (veins, a thicker membrane) or lower frequency_hz below the first mode "
      "(docs/case_file.md, \"Warnings\")",
      fem::to_string(modes.kinds[0]).c_str(), modes.frequencies_hz[0], f, r, r * r / (r * r - 1.0));
  return text;
}

}  // namespace

std::string fem_near_resonance_warning(const io::Case& c, const FsiSetup& setup) {
  if (c.structure.kind != io::Case::Structure::Kind::Fem || !setup.fem_structure) return "";
  if (!c.kinematics.oscillates()) return "";  // a wing that only revolves: no wingbeat drives it
  FemNaturalModes modes;
  try {
    modes = fem_resonance_modes(c, setup);
  } catch (const std::exception&) {
    return "";
  }
  const double f = c.kinematics.frequency;
  if (!modes.frequencies_hz.empty() && modes.frequencies_hz[0] < lowest_resonant_mode_hz(f))
    return driven_above_first_mode_warning(modes, f);
  const ModeResonance near = strongest_resonance(modes.frequencies_hz, f);
  if (near.mode < 0 || !(near.amplification >= kResonantAmplification)) return "";
  const auto kind = [&](int mode) { return fem::to_string(modes.kinds[static_cast<std::size_t>(mode)]); };
  // The FEM's other modes within the band (each lies near one harmonic at most: the bands
  // of f and 2 f do not overlap), lowest first, at most kListed of them.
  constexpr int kListed = 3;
  std::string others;
  int listed = 0, unlisted = 0;
  for (std::size_t i = 0; i < modes.frequencies_hz.size(); ++i) {
    if (static_cast<int>(i) == near.mode) continue;
    const ModeResonance other = strongest_resonance({modes.frequencies_hz[i]}, f);
    if (!(other.amplification >= kResonantAmplification)) continue;
    if (listed == kListed) {
      ++unlisted;
      continue;
    }
    ++listed;
    char line[200];
    std::snprintf(line, sizeof line, "%s mode %d (%s shape), %.4g Hz, near %s (mode / drive = %.3g, %.2g times)",
                  others.empty() ? "" : ";", static_cast<int>(i) + 1, kind(static_cast<int>(i)).c_str(),
                  other.mode_hz, other.drive(), other.mode_hz / (other.harmonic * f), other.amplification);
    others += line;
  }
  if (unlisted > 0) others += "; and " + std::to_string(unlisted) + " more";
  char text[2400];
  std::snprintf(
      text, sizeof text,
      "the FEM's mode %d (%s shape), %.4g Hz, lies near %s %.3g Hz (mode / drive = %.3g): an undamped "
      "oscillator driven there moves %.2g times its static deflection (warned from %g; the wing's "
      "natural modes clamped at its root, in vacuum, as `flapsim modes` finds them on this mesh).%s%s "
      "Its response then hinges on the FEM's exact stiffness and damping and on the air's added mass, "
      "which lowers the modes (a 13 mm wing of a 4 um membrane, mode 1 at 186.5 Hz, flapped at "
      "150 Hz: its tip bent past 75 deg within a fifth of a wingbeat), and on the time it takes: "
      "driven near a mode the FEM halves its steps, beyond the time estimated here (a 40 mm swept "
      "wing of a 50 um membrane at 30 Hz, mode 1 at 38.4 Hz: 20 steps in 194 s against 1.4 s "
      "estimated, 9 of them solved in up to 64 pieces). Look at the run's "
      "peak_tip_bend_deg and peak_tip_twist_deg (summary.json), or move the frequency or the "
      "stiffness away from resonance (docs/case_file.md, \"Warnings\")",
      near.mode + 1, kind(near.mode).c_str(), near.mode_hz, near.drive(), near.harmonic * f,
      near.mode_hz / (near.harmonic * f), near.amplification, kResonantAmplification,
      others.empty() ? "" : " Also in the band:", others.empty() ? "" : (others + ".").c_str());
  return text;
}

}  // namespace flapsim::app
