#include "pipeline/app/flexibility_warnings.hpp"

#include <cmath>
#include <cstdio>
#include <exception>
#include <numbers>
#include <vector>

#include "mbd/quasi_static_deflection.hpp"
#include "pipeline/app/quasi_steady_fluid_loads.hpp"
#include "reduction/linear_chain.hpp"

namespace flapsim::app {

namespace {
/// Peak over static deflection of an undamped oscillator under a load applied at once
/// ([Thomson & Dahleh 1998], ch. 4): a run starts from rest with its first instant's loads.
constexpr double kStepLoadPeak = 2.0;
}  // namespace

ModeResonance strongest_resonance(const std::vector<double>& mode_hz, double f) {
  ModeResonance out;
  for (std::size_t i = 0; i < mode_hz.size(); ++i)
    for (int n = 1; n <= 2; ++n) {
      const double r = n * f / mode_hz[i];
      const double a = 1.0 / std::abs(1.0 - r * r);
      if (a > out.amplification) out = {static_cast<int>(i), n, mode_hz[i], a};
    }
  return out;
}

double highest_resonant_mode_hz(double f) { return 2.0 * f / std::sqrt(1.0 - 1.0 / kResonantAmplification); }

double lowest_resonant_mode_hz(double f) { return f / std::sqrt(1.0 + 1.0 / kResonantAmplification); }

std::string near_resonance_warning(const io::Case& c, const FsiSetup& setup) {
  const mbd::ChainModel& chain = setup.chain();
  if (c.structure.kind != io::Case::Structure::Kind::Flexible || chain.num_dofs() == 0) return "";
  if (!c.kinematics.oscillates()) return "";  // a wing that only revolves: no wingbeat drives it
  std::vector<reduction::ChainMode> modes;
  try {
    modes = reduction::LinearChain(chain).modes();
  } catch (const std::exception&) {
    return "";  // a chain bent at rest: no linear modes about a straight shape
  }
  const double f = c.kinematics.frequency;
  if (modes.empty() || modes.front().frequency_hz < f) return "";
  std::vector<double> mode_hz;
  for (const reduction::ChainMode& m : modes) mode_hz.push_back(m.frequency_hz);
  const ModeResonance near = strongest_resonance(mode_hz, f);
  if (!(near.amplification >= kResonantAmplification)) return "";
  char text[900];
  std::snprintf(text, sizeof text,
                "the chain's mode %d (%s), %.3g Hz, lies near %s %.3g Hz (mode / drive = %.3g): an undamped "
                "oscillator driven there moves %.2g times its static deflection (warned from %g). The "
                "flexible wing's loads then hinge on its exact stiffness and damping (a tapered 0.1 mm PET "
                "plate, first bending 21.6 Hz, at a 20 Hz wingbeat: mean CL -0.16, rigid 3.0; at 0.2 mm, "
                "43 Hz: 5.4). Look at the run's peak_tip_bend_deg and peak_tip_twist_deg (summary.json), "
                "or move the frequency or the stiffness away from resonance (docs/case_file.md, \"Warnings\")",
                near.mode + 1, modes[static_cast<std::size_t>(near.mode)].is_bending() ? "bending" : "torsion",
                near.mode_hz, near.drive(), near.harmonic * f, near.mode_hz / (near.harmonic * f),
                near.amplification, kResonantAmplification);
  return text;
}

std::string inertial_deflection_warning(const io::Case& c, const FsiSetup& setup) {
  const mbd::ChainModel& chain = setup.chain();
  if (c.structure.kind != io::Case::Structure::Kind::Flexible || chain.num_dofs() == 0) return "";
  // The case's [[loads]] count with the inertia: a load present from t = 0 acts at once, as
  // the inertia of a stroke started at its reversal does (a 0.3 N tip load whose linear bend
  // is 137° went unwarned, and the run's failure then blamed the kinematics).
  const fsi::ExternalLoads& point_loads = setup.chain_structure->external_loads;
  const bool loaded = static_cast<bool>(point_loads);
  mbd::QuasiStaticDeflection q;
  try {
    // 64 instants of the cycle: the inertial loads' harmonics up to the 8th are sampled
    // 4 times a period or more.
    const double period = 1.0 / c.kinematics.frequency;
    q = loaded ? mbd::peak_quasi_static_deflection(
                     chain, setup.model.base(), period, 64,
                     [&](double t, const mbd::ChainData&, mbd::Loads& loads) { point_loads(t, loads); })
               : mbd::peak_quasi_static_deflection(chain, setup.model.base(), period, 64);
  } catch (const std::exception&) {
    return "";  // a singular stiffness: the soft-chain and resonance checks speak of it
  }
  constexpr double deg = 180.0 / std::numbers::pi;
  const double bend = kStepLoadPeak * q.tip_bend * deg, twist = kStepLoadPeak * q.tip_twist * deg;
  if (!(bend > kLargeTipDeflectionDeg) && !(twist > kLargeTipDeflectionDeg)) return "";
  char text[1200];
  std::snprintf(text, sizeof text,
                "%s would bend the wing's tip by up to %.1f deg and twist it by "
                "up to %.1f deg against its base, beyond the %g deg its small-rotation joint springs "
                "represent: twice the chain's linear quasi-static deflection under the rigid wing's "
                "inertial loads%s (%.1f and %.1f deg; twice, as a load applied at once moves an undamped "
                "spring; the joint inboard of body %d %s by %.1f deg of it). Expect joints swinging far "
                "past that, results that hinge on the time step, or a numerical failure. Run the wing's own "
                "FEM, geometrically nonlinear (structure.kind = \"fem\"; slower: docs/fem.md), stiffen the "
                "wing (a thicker membrane, veins), lower frequency_hz or the amplitudes, or scale the "
                "springs (--spring-scale) (docs/case_file.md, \"Warnings\")",
                loaded ? "the flapping's inertia with the case's [[loads]]" : "the flapping's inertia alone",
                bend, twist, kLargeTipDeflectionDeg, loaded ? " and the [[loads]]" : "", q.tip_bend * deg,
                q.tip_twist * deg, q.joint + 1, q.twist ? "twisted" : "bent", q.joint_angle * deg);
  return text;
}

std::string fluid_load_deflection_warning(const io::Case& c, const FsiSetup& setup) {
  const mbd::ChainModel& chain = setup.chain();
  if (c.structure.kind != io::Case::Structure::Kind::Flexible || chain.num_dofs() == 0 || !c.air.enabled ||
      !setup.grid || setup.chain_structure->attachment.nodes.empty())
    return "";
  const double period = 1.0 / c.kinematics.frequency;
  const fsi::WingAttachment& attachment = setup.chain_structure->attachment;
  const int nc = setup.grid->chordwise, ns = setup.grid->spanwise;
  const mbd::QuasiStaticLoads fluid = [&](double, const mbd::ChainData& data, mbd::Loads& loads) {
    add_quasi_steady_fluid_loads(attachment, nc, ns, data, c.air.density, c.air.freestream, loads);
  };
  // The run starts from rest with the loads of its first instant applied at once: an undamped
  // spring overshoots the static deflection by as much again, while the rest of the cycle's
  // loads rise from there (quasi-statically, away from a resonance, which its own warning
  // covers). So the estimate is the largest deflection over a cycle plus the deflection at the
  // start: the inertia of a stroke that starts at its reversal counts twice (as in
  // inertial_deflection_warning), the fluid's loads of a wing at rest there once, those of a
  // wing started at speed (a free stream, a revolution without a ramp) twice. The start is
  // taken just after t = 0, where a revolution starts at its full rate.
  mbd::QuasiStaticDeflection inertial, both, start;
  try {
    inertial = mbd::peak_quasi_static_deflection(chain, setup.model.base(), period, 64);
    both = mbd::peak_quasi_static_deflection(chain, setup.model.base(), period, 64, fluid);
    start = mbd::peak_quasi_static_deflection(chain, setup.model.base(), period, 1, fluid, 1e-9 * period);
  } catch (const std::exception&) {
    return "";  // a singular stiffness: the soft-chain and resonance checks speak of it
  }
  constexpr double deg = 180.0 / std::numbers::pi;
  const double bend = (both.tip_bend + start.tip_bend) * deg,
               twist = (both.tip_twist + start.tip_twist) * deg;
  // The inertia alone beyond 30 deg is inertial_deflection_warning's: one warning, not two.
  if (kStepLoadPeak * inertial.tip_bend * deg > kLargeTipDeflectionDeg ||
      kStepLoadPeak * inertial.tip_twist * deg > kLargeTipDeflectionDeg)
    return "";
  if (!(bend > kLargeTipDeflectionDeg) && !(twist > kLargeTipDeflectionDeg)) return "";
  char text[1300];
  std::snprintf(
      text, sizeof text,
      "the fluid's loads with the flapping's inertia would bend the wing's tip by up to %.1f deg and "
      "twist it by up to %.1f deg against its base (the inertia alone %.1f and %.1f deg), beyond the "
      "%g deg its small-rotation joint springs represent: the chain's linear quasi-static deflection "
      "under the rigid wing's inertial loads and the fluid's quasi-steady normal force on each panel "
      "at its speed and angle of attack (density %g kg/m^3; the translational coefficients of a "
      "revolving wing, Dickinson et al. 1999), its largest over a cycle plus its value at the start "
      "(a load applied at once moves an undamped spring twice as far; an estimate). Expect joints "
      "swinging far past that, results that hinge on the time step, or a numerical failure. Stiffen "
      "the wing, lower frequency_hz or the amplitudes, or run the wing's own FEM, geometrically "
      "nonlinear (structure.kind = \"fem\") (docs/case_file.md, \"Warnings\")",
      bend, twist, kStepLoadPeak * inertial.tip_bend * deg, kStepLoadPeak * inertial.tip_twist * deg,
      kLargeTipDeflectionDeg, c.air.density);
  return text;
}

std::string large_motion_at_failure(const FsiSetup& setup, const Eigen::VectorXd& last_q,
                                    double peak_tip_bend_deg, double peak_tip_twist_deg) {
  const mbd::ChainModel& chain = setup.chain();
  if (chain.num_dofs() == 0 || last_q.size() != chain.num_dofs()) return "";
  constexpr double deg = 180.0 / std::numbers::pi;
  Eigen::Index largest = 0;
  const double angle = last_q.cwiseAbs().maxCoeff(&largest) * deg;
  const double bend = peak_tip_bend_deg, twist = peak_tip_twist_deg;
  if (!(angle > kLargeTipDeflectionDeg) && !(bend > kLargeTipDeflectionDeg) && !(twist > kLargeTipDeflectionDeg))
    return "";
  const int body = chain.first_jointed_body() + static_cast<int>(largest) / 2;
  char text[1100];
  std::snprintf(text, sizeof text,
                "By then the wing had moved beyond what its chain represents: the joint inboard of body %d "
                "%s %.1f deg at the last completed step (history.csv %s_%d_rad), and the tip bent up to %.1f "
                "deg and twisted up to %.1f deg against its base (summary.json peak_tip_bend_deg, "
                "peak_tip_twist_deg); the joint springs, derived from the wing's small-rotation FEM, "
                "represent it up to %g deg. A finer time step may go further, but through a "
                "motion the model was not made for: run the wing's own FEM, geometrically nonlinear "
                "(structure.kind = \"fem\"), stiffen the wing, or lower frequency_hz or the amplitudes "
                "(docs/case_file.md, \"Warnings\")",
                body + 1, largest % 2 ? "twisted" : "bent", last_q(largest) * deg,
                largest % 2 ? "twist" : "bend", body + 1, bend, twist, kLargeTipDeflectionDeg);
  return text;
}

std::string fem_motion_at_failure(const io::Case& c, double peak_tip_bend_deg, double peak_tip_twist_deg,
                                  bool in_structure) {
  if (c.structure.kind != io::Case::Structure::Kind::Fem) return "";
  if (!(peak_tip_bend_deg > kLargeTipDeflectionDeg) && !(peak_tip_twist_deg > kLargeTipDeflectionDeg))
    return "";
  char motion[300];
  std::snprintf(motion, sizeof motion,
                "By then the wing's tip had bent up to %.1f deg and twisted up to %.1f deg against its base "
                "(summary.json peak_tip_bend_deg, peak_tip_twist_deg)",
                peak_tip_bend_deg, peak_tip_twist_deg);
  // Measured (5 Dec): cases/film_wing_fem.toml with leading_edge = "shed" stops in its
  // coupling at step 247, the FEM solving every step, the tip twisted 38.8 deg (17.7 with
  // "separated"): where the FEM's iterations did not stop, no word of them or of stiffening.
  if (!in_structure) return motion;
  // Measured (1 Dec): a paddle-shaped 50 um film wing (60 mm, 62 mg, FEM mode 1 at 30.5 Hz)
  // in cases/hover_flexible.toml's stroke at 20 Hz on its FEM: tip bent up to 106 deg, the FEM
  // step failed at t = 0.0653 s with 100 steps a cycle and at t = 0.0555 s with 200; at 12 Hz
  // (tip 67 deg) it ran its 3 wingbeats.
  return std::string(motion) +
         ": the FEM's Newton iterations stopped on a wing swinging that far, flapped too fast for its "
         "stiffness and mass. A finer time step may not take it further (a 50 um film paddle at 20 Hz, "
         "its first mode 30 Hz, tip bent 106 deg, stopped sooner with 200 steps a cycle than with 100): "
         "stiffen the wing (a thicker membrane, veins), or lower frequency_hz or the amplitudes (at 12 Hz "
         "the paddle ran through; docs/fsi.md, \"Failures\")";
}

std::string large_deflection_warning(const RunResults& results) {
  // The FEM is geometrically nonlinear: a large deflection is within what it represents.
  if (results.has("fem_nodes")) return "";
  const double bend = results.number("peak_tip_bend_deg"), twist = results.number("peak_tip_twist_deg");
  if (!(bend > kLargeTipDeflectionDeg) && !(twist > kLargeTipDeflectionDeg)) return "";
  char text[900];
  std::snprintf(text, sizeof text,
                "the wing's tip bent up to %.1f deg and twisted up to %.1f deg against its base (in the wing "
                "frame; summary.json peak_tip_bend_deg, peak_tip_twist_deg), beyond the %g deg up to "
                "which the joint springs, derived from the wing's small-rotation FEM, represent it: the "
                "results are those of a wing far more flexible than its model was made for (often a wing "
                "driven near a resonance); the wing's own FEM is geometrically nonlinear (structure.kind = "
                "\"fem\"; docs/case_file.md, \"Warnings\")",
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
