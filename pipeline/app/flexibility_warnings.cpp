#include "pipeline/app/flexibility_warnings.hpp"

#include <cmath>
#include <cstdio>
#include <exception>
#include <vector>

#include "reduction/linear_chain.hpp"

namespace flapsim::app {

std::string near_resonance_warning(const io::Case& c, const FsiSetup& setup) {
  const mbd::ChainModel& chain = setup.model.chain;
  if (c.structure.kind != io::Case::Structure::Kind::Flexible || chain.num_dofs() == 0) return "";
  std::vector<reduction::ChainMode> modes;
  try {
    modes = reduction::LinearChain(chain).modes();
  } catch (const std::exception&) {
    return "";  // a chain bent at rest: no linear modes about a straight shape
  }
  const double f = c.kinematics.frequency;
  if (modes.empty() || modes.front().frequency_hz < f) return "";
  // The mode and harmonic with the largest amplification.
  double amplification = 0.0, mode_hz = 0.0;
  int mode = -1, harmonic = 0;
  for (std::size_t i = 0; i < modes.size(); ++i)
    for (int n = 1; n <= 2; ++n) {
      const double r = n * f / modes[i].frequency_hz;
      const double a = 1.0 / std::abs(1.0 - r * r);
      if (a > amplification) {
        amplification = a;
        mode = static_cast<int>(i);
        harmonic = n;
        mode_hz = modes[i].frequency_hz;
      }
    }
  if (!(amplification >= kResonantAmplification)) return "";
  char text[900];
  std::snprintf(text, sizeof text,
                "the chain's mode %d (%s), %.3g Hz, lies near %s %.3g Hz (mode / drive = %.3g): an undamped "
                "oscillator driven there moves %.2g times its static deflection (warned from %g). The "
                "flexible wing's loads then hinge on its exact stiffness and damping (a tapered 0.1 mm PET "
                "plate, first bending 21.6 Hz, at a 20 Hz wingbeat: mean CL -0.16, rigid 3.0; at 0.2 mm, "
                "43 Hz: 5.4). Look at the run's peak_tip_bend_deg and peak_tip_twist_deg (summary.json), "
                "or move the frequency or the stiffness away from resonance (docs/case_file.md, \"Warnings\")",
                mode + 1, modes[static_cast<std::size_t>(mode)].is_bending() ? "bending" : "torsion", mode_hz,
                harmonic == 1 ? "the wingbeat frequency" : "twice the wingbeat frequency", harmonic * f,
                mode_hz / (harmonic * f), amplification, kResonantAmplification);
  return text;
}

std::string large_deflection_warning(const RunResults& results) {
  const double bend = results.number("peak_tip_bend_deg"), twist = results.number("peak_tip_twist_deg");
  if (!(bend > kLargeTipDeflectionDeg) && !(twist > kLargeTipDeflectionDeg)) return "";
  char text[700];
  std::snprintf(text, sizeof text,
                "the wing's tip bent up to %.1f deg and twisted up to %.1f deg against its base (sums of the "
                "joint angles; summary.json peak_tip_bend_deg, peak_tip_twist_deg), beyond the %g deg up to "
                "which the joint springs, derived from the wing's small-rotation FEM, represent it: the "
                "results are those of a wing far more flexible than its model was made for (often a wing "
                "driven near a resonance; docs/case_file.md, \"Warnings\")",
                bend, twist, kLargeTipDeflectionDeg);
  return text;
}

std::string large_deflection_note(const RunResults& results) {
  if (large_deflection_warning(results).empty()) return "";
  char text[160];
  std::snprintf(text, sizeof text, "large deflection: tip bend %.1f deg, twist %.1f deg (over %g deg)",
                results.number("peak_tip_bend_deg"), results.number("peak_tip_twist_deg"), kLargeTipDeflectionDeg);
  return text;
}

}  // namespace flapsim::app
