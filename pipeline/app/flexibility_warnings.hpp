#pragma once
/// \file flexibility_warnings.hpp
/// \brief Warnings about a flexible wing whose results hinge on its resonance: before a
/// run, a chain mode near the wingbeat frequency or twice it; after a run, a tip bent or
/// twisted beyond the small rotations the joint springs were derived for.
/// (A chain whose first mode lies below the wingbeat: soft_chain_warning, fsi_setup.hpp.)

#include <string>
#include <vector>

#include <Eigen/Core>

#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/app/run_results.hpp"
#include "pipeline/io/case_model.hpp"

namespace flapsim::app {

/// The dynamic amplification 1 / |1 − (n f / f_mode)²| of an undamped oscillator of
/// frequency f_mode driven at n f ([Thomson & Dahleh 1998], ch. 3, docs/references.md) from
/// which a chain mode is said to be near resonance. A convention (the response is then
/// more resonant than static), not calibrated on any result.
inline constexpr double kResonantAmplification = 2.0;

/// The tip's bend or twist relative to the base [deg] beyond which a run is warned about:
/// the joint springs come from the linear (small-rotation) FEM of the wing; at 30°
/// sin θ / θ = 0.955, the small-rotation assumption is off by about 5 %. A convention.
inline constexpr double kLargeTipDeflectionDeg = 30.0;

/// The mode and harmonic of the largest dynamic amplification (strongest_resonance).
struct ModeResonance {
  int mode = -1;               ///< 0-based index into the modes given; -1: none
  int harmonic = 0;            ///< n: driven at n f (1 or 2)
  double mode_hz = 0.0;        ///< the mode's frequency f_i [Hz]
  double amplification = 0.0;  ///< 1 / |1 − (n f / f_i)²|
  /// n f in words, for the warnings: "the wingbeat frequency" or "twice the wingbeat frequency".
  const char* drive() const { return harmonic == 1 ? "the wingbeat frequency" : "twice the wingbeat frequency"; }
};

/// \brief Of the modes' frequencies \p mode_hz [Hz] and the harmonics n = 1, 2 of the
/// wingbeat frequency \p f [Hz], the pair of largest amplification 1 / |1 − (n f / f_i)²|
/// (the first such pair on a tie; mode −1 when there is no mode). Near resonance when
/// amplification ≥ kResonantAmplification: f_i within 0.82…1.41 f or 1.63…2.83 f.
ModeResonance strongest_resonance(const std::vector<double>& mode_hz, double f);

/// \brief The highest mode frequency [Hz] that can lie near resonance at a wingbeat of \p f
/// [Hz]: 2 f / √(1 − 1/kResonantAmplification) = 2.83 f (above it, the amplification at 2 f
/// is below kResonantAmplification, and at f lower still).
double highest_resonant_mode_hz(double f);

/// \brief The lowest mode frequency [Hz] near resonance with a wingbeat of \p f [Hz]:
/// f / √(1 + 1/kResonantAmplification) = 0.82 f (below it the drive is above the mode, and
/// the amplification at f is below kResonantAmplification).
double lowest_resonant_mode_hz(double f);

/// \brief "" or the warning for a flexible chain with a mode whose dynamic amplification
/// at the wingbeat frequency f or at 2 f (the lift's and the inertial loads' main
/// harmonic) is kResonantAmplification or more; names the mode, its frequency, the ratio
/// and the amplification. "" when the first mode lies below f (soft_chain_warning says so).
std::string near_resonance_warning(const io::Case& c, const FsiSetup& setup);

/// \brief "" or the warning for a flexible chain that the flapping's inertia alone bends beyond
/// small rotations: twice its linear quasi-static tip bend or twist under the rigid wing's
/// inertial loads (mbd/quasi_static_deflection.hpp; twice: the peak of a load applied at
/// once to an undamped oscillator, [Thomson & Dahleh 1998] ch. 4, as a run starts from rest)
/// exceeds kLargeTipDeflectionDeg. Names the numbers and the joint that bends most.
std::string inertial_deflection_warning(const io::Case& c, const FsiSetup& setup);

/// \brief "" or the warning for a flexible chain in a fluid that the fluid's loads, with the
/// flapping's inertia, bend beyond small rotations: its linear quasi-static tip bend or twist
/// under the rigid wing's inertial loads and the fluid's quasi-steady normal force on each
/// panel (quasi_steady_fluid_loads.hpp), the largest over a cycle plus the one at the start
/// (the start's loads applied at once), exceeds kLargeTipDeflectionDeg while the inertia alone
/// does not (that is inertial_deflection_warning's). A wing in water or oil (a dynamically
/// scaled model) bends under the fluid, not its inertia.
std::string fluid_load_deflection_warning(const io::Case& c, const FsiSetup& setup);

/// \brief "" or a sentence to add to a run's numerical failure when the chain had moved
/// beyond small rotations by then: its largest joint angle at the last accepted step
/// (`last_q`, over the chain's Φ [rad]), or its tip bend or twist so far (summary.json's
/// peak_tip_bend_deg, peak_tip_twist_deg [deg]), over kLargeTipDeflectionDeg. Names the joint (by
/// the body it carries, as chain.toml and history.csv number them) and the angles.
std::string large_motion_at_failure(const FsiSetup& setup, const Eigen::VectorXd& last_q,
                                    double peak_tip_bend_deg, double peak_tip_twist_deg);

/// \brief "" or a sentence to add to a numerical failure of a run on the wing's FEM
/// (structure.kind = "fem") whose tip had bent or twisted by more than
/// kLargeTipDeflectionDeg by then (`peak_tip_bend_deg`, `peak_tip_twist_deg` [deg], as
/// summary.json's): the FEM represents such a motion, but a wing that swings that far (one
/// flapped too fast for its stiffness and mass) may fold beyond what its Newton iterations
/// follow, and a finer time step does not take it further (docs/fsi.md, "Failures"). Only
/// when the FEM's own iterations stopped (`in_structure`) does it say so and what to change;
/// a failure elsewhere (the coupling, the lattice) gets how far the tip had swung alone.
std::string fem_motion_at_failure(const io::Case& c, double peak_tip_bend_deg, double peak_tip_twist_deg,
                                  bool in_structure);

/// \brief "" or the warning for a run whose peak tip bend or twist (peak_tip_bend_deg,
/// peak_tip_twist_deg) exceeds kLargeTipDeflectionDeg, with the numbers.
std::string large_deflection_warning(const RunResults& results);

/// \brief The same in a few words for the message column of sweep.csv: "" or
/// "large deflection: tip bend 103.5 deg, twist 31.8 deg (over 30 deg)".
std::string large_deflection_note(const RunResults& results);

}  // namespace flapsim::app
