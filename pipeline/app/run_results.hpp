#pragma once
/// \file run_results.hpp
/// \brief What a run reports, defined once. Each result has a key (the summary.json key
/// and sweep.csv column, its unit as a suffix), a unit, a kind, a print format, a short
/// label if it is a column of the sweep table, and a description. From this one list:
///  - summary.json: every result that was set, in the order of the list;
///  - the report `flapsim run` prints: the lines of kRunReport, whose {key} placeholders
///    are filled with the result's value, print format and unit;
///  - sweep.csv and the table `flapsim sweep` prints: the results with a label.
/// How to add a result: docs/output_files.md, "Adding a result or a history column".

#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "pipeline/app/step_zigzag.hpp"
#include "pipeline/io/summary_json.hpp"

namespace flapsim::app {

enum class ResultKind { number, integer, text, flag };

struct ResultDefinition {
  std::string_view key;          ///< summary.json key, sweep.csv column, e.g. "mean_lift_N"
  std::string_view unit;         ///< SI unit as printed ("N", "m/s", "m^2"); "" if none
  ResultKind kind;
  std::string_view format;       ///< printf format of a number in reports and tables
  std::string_view sweep_label;  ///< column title in sweep.csv's table on stdout; "" = not a sweep column
  std::string_view description;  ///< what it is and how it is measured (docs/fsi.md)
};

/// The results of a run, in the order of summary.json. Results marked "(in air)" are set
/// only for runs in air, "error" only for failed and interrupted runs.
inline constexpr auto kRunResults = [] {
  using K = ResultKind;
  return std::array{
      // The case and the setup, known before the first step.
      ResultDefinition{"case", "", K::text, "", "", "name of the case"},
      ResultDefinition{
          "wing_file", "", K::text, "", "",
          "the wing file flown: the case's 'wing' resolved from its folder, or run --wing's (absent "
          "for a case of a chain file alone)"},
      ResultDefinition{
          "structure", "", K::text, "", "",
          "where the structure came from: rigid wing, chain file, or the wing reduced in process"},
      ResultDefinition{"air", "", K::flag, "", "", "true: in air (vortex lattice); false: in vacuum"},
      ResultDefinition{"frequency_hz", "Hz", K::number, "%.6g", "", "flapping frequency f"},
      ResultDefinition{"rotation_phase", "", K::number, "%.4f", "",
                       "the case's rotation phase δψ, fraction of the period"},
      ResultDefinition{"steps_per_cycle", "", K::integer, "", "", "time steps per flapping cycle"},
      ResultDefinition{"cycles", "", K::integer, "", "", "flapping cycles of the case"},
      ResultDefinition{"dt_s", "s", K::number, "%.6g", "", "time step"},
      ResultDefinition{
          "structure_kind", "", K::text, "", "",
          "the case's structure.kind: \"rigid\", \"flexible\" (the bar chain) or \"fem\" (the wing's FEM)"},
      ResultDefinition{"bodies", "", K::integer, "", "", "bodies of the chain (1: rigid wing and FEM)"},
      ResultDefinition{"fem_nodes", "", K::integer, "", "", "nodes of the FEM structure (kind = \"fem\")"},
      ResultDefinition{"spring_scale", "", K::number, "%.6g", "",
                       "factor on every joint spring (flapsim run --spring-scale)"},
      ResultDefinition{
          "inputs_hash", "", K::text, "", "",
          "fingerprint of the resolved case (all but output.vtk_every), wing, chain file and spring "
          "factor (FNV-1a 64, io::input_hash); a sweep re-run keeps a case whose hash is unchanged"},
      ResultDefinition{"reference_area_m2", "m^2", K::number, "%.6g", "",
                       "S of CL: planform area of the outline (in air)"},
      ResultDefinition{"reference_speed_m_s", "m/s", K::number, "%.6g", "",
                       "U_ref of the coefficients: the free-stream speed if there is a free stream, else "
                       "the cycle-mean speed of the span axis at r2·R (in air)"},
      ResultDefinition{"reference_kind", "", K::text, "", "",
                       "which speed U_ref is: \"free_stream\" or \"flapping_r2\" (in air)"},
      ResultDefinition{"flapping_speed_m_s", "m/s", K::number, "%.6g", "",
                       "cycle-mean speed of the span axis at r2·R, base translation included (in air)"},
      ResultDefinition{"free_stream_speed_m_s", "m/s", K::number, "%.6g", "", "|U∞| (in air)"},
      ResultDefinition{"load_method", "", K::text, "", "",
                       "load route: bernoulli or kutta_joukowski (in air)"},
      ResultDefinition{"leading_edge", "", K::text, "", "",
                       "leading-edge model: none, attached, separated or shed (in air)"},
      ResultDefinition{"r2", "", K::number, "%.4f", "",
                       "non-dimensional radius of gyration of the outline's area (in air)"},
      ResultDefinition{"reynolds_number", "", K::number, "%.4g", "",
                       "Re = U c/nu: U the larger of the free-stream speed and the flapping speed at r2 R, "
                       "the mean chord S/R and numerics.kinematic_viscosity; "
                       "below 32 warned (in air; docs/uvlm.md, \"Reynolds number\")"},
      // How the run ended.
      ResultDefinition{"error", "", K::text, "", "",
                       "what stopped the run: the numerical failure, the output error or the signal (failed "
                       "and interrupted runs)"},
      ResultDefinition{"status", "", K::text, "", "",
                       "\"ok\"; \"failed\" (exit status 3, or 4 for an output error); \"interrupted\" "
                       "(SIGINT or SIGTERM, exit status 130 or 143)"},
      ResultDefinition{
          "warnings", "", K::text, "", "",
          "the case's warnings known before its first step (its case and wing files', its "
          "setup's) in a few words, '; '-separated, as sweep.csv's message gives them (set by "
          "flapsim run, flapsim sweep and flapsim optimize when there are any; a sweep run again "
          "repeats them in "
          "the row of a case it keeps)"},
      ResultDefinition{"steps", "", K::integer, "", "", "time steps completed"},
      ResultDefinition{"time_s", "s", K::number, "%.6g", "", "simulated time reached"},
      ResultDefinition{"mean_window_cycles", "", K::number, "%.4g", "",
                       "the cycles the last-cycle means cover: 1, or what was run of the first cycle "
                       "(a run that ended before its first cycle was complete)"},
      // Loads: means over the last cycle (or what was run, if less), trapezoidal rule.
      ResultDefinition{"mean_lift_N", "N", K::number, "%.6g", "mean lift",
                       "mean lift (the force along the lift direction: +z_G in hover, normal to U∞ in a "
                       "free stream) over the last cycle"},
      ResultDefinition{"mean_CL", "", K::number, "%.4f", "mean CL",
                       "mean lift coefficient L / (½ ρ U_ref² S) over the last cycle"},
      ResultDefinition{"mean_Fx_N", "N", K::number, "%.6g", "",
                       "mean aerodynamic force, ground x, last cycle"},
      ResultDefinition{"mean_Fy_N", "N", K::number, "%.6g", "",
                       "mean aerodynamic force, ground y, last cycle"},
      ResultDefinition{"mean_Fz_N", "N", K::number, "%.6g", "",
                       "mean aerodynamic force, ground z, last cycle"},
      ResultDefinition{"mean_drag_N", "N", K::number, "%.6g", "mean drag",
                       "mean drag over the last cycle (along U∞; in hover against the horizontal motion at "
                       "r2·R); negative = thrust (in air)"},
      ResultDefinition{"mean_CD", "", K::number, "%.4f", "mean CD",
                       "mean drag coefficient D / (½ ρ U_ref² S) (in air)"},
      ResultDefinition{
          "mean_CL_on_flapping_speed", "", K::number, "%.4f", "",
          "in a free stream, of a wing that flaps: mean_CL on the flapping speed at r2·R instead of "
          "U∞, L / (½ ρ flapping_speed² S) (the free stream's CL times (U∞ / flapping_speed)²)"},
      ResultDefinition{"mean_CD_on_flapping_speed", "", K::number, "%.4f", "",
                       "in a free stream, of a wing that flaps: mean_CD on the flapping speed at r2·R"},
      ResultDefinition{"mean_side_N", "N", K::number, "%.6g", "", "mean side force, last cycle (in air)"},
      ResultDefinition{"mean_Mx_base_Nm", "Nm", K::number, "%.6g", "",
                       "mean aerodynamic moment about the pivot, ground x, last cycle (in air)"},
      ResultDefinition{"mean_My_base_Nm", "Nm", K::number, "%.6g", "",
                       "mean aerodynamic moment about the pivot, ground y, last cycle (in air)"},
      ResultDefinition{"mean_Mz_base_Nm", "Nm", K::number, "%.6g", "",
                       "mean aerodynamic moment about the pivot, ground z, last cycle (in air)"},
      ResultDefinition{"mean_power_W", "W", K::number, "%.6g", "mean power",
                       "cycle-mean aerodynamic power −Σ F·v over the panels, last cycle (in air)"},
      ResultDefinition{"mean_CP", "", K::number, "%.4f", "",
                       "mean power coefficient P / (½ ρ U_ref³ S), last cycle (in air)"},
      ResultDefinition{"lift_per_power_N_W", "N/W", K::number, "%.4g", "lift/power",
                       "mean lift / mean aerodynamic power, last cycle (in air)"},
      // Over many cycles, for flows that do not repeat (fsi/cycle_statistics.hpp).
      ResultDefinition{
          "settled_cycles", "", K::integer, "", "",
          "whole cycles from settled_from_cycle to the last, over which the settled_ results are "
          "taken (in air, at least 3: runs of 4 cycles or more with the default)"},
      ResultDefinition{"settled_from_cycle", "", K::integer, "", "",
                       "the first settled cycle: numerics.settled_from_cycle, default 2 (the start from rest "
                       "left out) (in air)"},
      ResultDefinition{"settled_mean_lift_N", "N", K::number, "%.6g", "",
                       "mean lift over the settled cycles (from the second on; the result of a run whose "
                       "cycles do not repeat) (in air)"},
      ResultDefinition{"settled_mean_CL", "", K::number, "%.4f", "settled CL",
                       "mean lift coefficient over the settled cycles (in air)"},
      ResultDefinition{
          "settled_CL_standard_error", "", K::number, "%.4f", "",
          "standard error of settled_mean_CL: the standard deviation of the cycles' mean CL over "
          "√settled_cycles (how well the mean is known if the cycles are independent) (in air)"},
      ResultDefinition{"cycle_CL_deviation", "", K::number, "%.4f", "",
                       "standard deviation of the settled cycles' mean CL: ~0 for a periodic run (in air)"},
      ResultDefinition{"largest_CL_jump", "", K::number, "%.3g", "",
                       "largest change of CL from one step to the next after the start (steps 3 on: steps "
                       "1 and 2 carry the start's impulse) (in air)"},
      ResultDefinition{"largest_CL_jump_step", "", K::integer, "", "",
                       "the step largest_CL_jump leads into (in air)"},
      ResultDefinition{
          "cycle_CL_lag_correlation", "", K::number, "%.3f", "",
          "correlation of each settled cycle's mean CL with the next's: near 0 when the cycles are "
          "independent; it does not see cycles still settling (settled_CL_drift does) (in air)"},
      ResultDefinition{
          "settled_CL_drift", "", K::number, "%.4f", "",
          "change of the settled cycles' mean CL from the first to the last along their least-squares line: "
          "independent cycles give it about √12 √((n-1)/(n+1)) settled_CL_standard_error rms (2.8 at 5 "
          "cycles, "
          "3.4 at 60); several times that says the cycles are still settling (in air)"},
      ResultDefinition{"mean_drive_power_W", "W", K::number, "%.6g", "drive power",
                       "cycle-mean power the base supplies to the wing, ω·M + v·F at the pivot (inertial "
                       "plus aerodynamic), last cycle"},
      ResultDefinition{"peak_drive_power_W", "W", K::number, "%.6g", "",
                       "largest power the base supplies in the last cycle"},
      ResultDefinition{
          "peak_drive_moment_Nm", "Nm", K::number, "%.6g", "",
          "largest magnitude of the moment the base exerts on the wing about the pivot, last cycle"},
      // Rotation phases and lags over the last cycle, fractions of the period (docs/fsi.md).
      ResultDefinition{"base_rotation_phase", "", K::number, "%.4f", "",
                       "rotation phase of the base measured from its angles (reproduces the case's δψ)"},
      ResultDefinition{"tip_rotation_phase", "", K::number, "%.4f", "tip phase",
                       "rotation phase of the tip body: its α = 90° crossing minus its stroke reversal"},
      ResultDefinition{"tip_rotation_lag", "", K::number, "%.4f", "tip lag",
                       "tip's α = 90° crossings minus the base's (negative: the tip rotates earlier)"},
      ResultDefinition{"tip_sweep_lag", "", K::number, "%.4f", "",
                       "tip's φ crossings of the base's mean φ minus the base's"},
      ResultDefinition{"outer_body", "", K::integer, "", "",
                       "the body holding 5/6 of the chain length (1-based), the 'outer' section"},
      ResultDefinition{"outer_rotation_phase", "", K::number, "%.4f", "outer phase",
                       "rotation phase of the outer body"},
      ResultDefinition{"outer_rotation_lag", "", K::number, "%.4f", "outer lag",
                       "outer body's α = 90° crossings minus the base's"},
      // The flexible wing's deflection (chains with joints).
      ResultDefinition{
          "peak_tip_bend_deg", "deg", K::number, "%.1f", "",
          "largest |tip bend| during the run: the rotation of the chain's last body or the FEM's "
          "tip section from its rest orientation, in the wing frame, as Rx(bend) Ry(twist) "
          "(fsi::tip_deflection)"},
      ResultDefinition{"peak_tip_twist_deg", "deg", K::number, "%.1f", "",
                       "largest |tip twist| during the run, as peak_tip_bend_deg: the twist about the "
                       "wing frame's span axis y_W (fsi::tip_deflection)"},
      ResultDefinition{
          "largest_tip_zigzag_deg", "deg", K::number, "%.2f", "",
          "largest zigzag of the tip's bend or twist from step to step: over four steps whose "
          "three changes alternate in sign, half the smallest change; a motion at the step's rate "
          "that the steps do not resolve (step_zigzag.hpp; above 1 deg warned)"},
      ResultDefinition{"largest_tip_zigzag_step", "", K::integer, "", "",
                       "the step of largest_tip_zigzag_deg's first turn back"},
      // The numerics.
      ResultDefinition{"mean_coupling_iterations", "", K::number, "%.2f", "iterations",
                       "lattice solves per step, mean over the run"},
      ResultDefinition{"max_coupling_iterations", "", K::integer, "", "",
                       "lattice solves of the hardest step"},
      ResultDefinition{"coupling_tolerance_rad", "rad", K::number, "%.3g", "",
                       "convergence tolerance of the coupling sub-iterations"},
      ResultDefinition{"coupling_method", "", K::text, "", "",
                       "how the sub-iterations update the chain: aitken or iqn_ils (numerics.coupling)"},
      ResultDefinition{"coupling_reuse_steps", "", K::integer, "", "",
                       "iqn_ils: earlier steps whose secant pairs the coupling kept "
                       "(numerics.coupling_reuse_steps); set only when not 0"},
      ResultDefinition{"split_structural_steps", "", K::integer, "", "",
                       "chain solves of a step (in air one per coupling sub-iteration) that did not "
                       "converge whole and were solved in halves (docs/multibody.md, step halving); set "
                       "only when one was"},
      ResultDefinition{"max_structural_pieces", "", K::integer, "", "",
                       "most pieces one such solve took (2 … 64); set only with split_structural_steps"},
      ResultDefinition{
          "restarted_structural_steps", "", K::integer, "", "",
          "chain solves that failed even in halves and were solved as a restart of the "
          "time scheme, backward Euler (docs/multibody.md, step halving); set only when one was"},
      ResultDefinition{"stalled_steps_retried", "", K::integer, "", "",
                       "steps whose coupling stalled and was tried again with the structure solved more "
                       "finely (docs/fsi.md, \"A stalled coupling, tried again\"); set only when one was"},
      ResultDefinition{"wake_panels", "", K::integer, "", "", "wake panels at the end of the run (in air)"},
      ResultDefinition{"wall_time_s", "s", K::number, "%.1f", "wall time", "wall-clock time of the run"},
  };
}();

/// The values of a run's results, by their place in kRunResults.
class RunResults {
 public:
  using Value = std::variant<double, std::int64_t, std::string, bool>;

  /// A result's place in kRunResults, found at compile time: a key that is not defined
  /// there does not compile (`results.set("mean_lift_N", x)`).
  class Key {
   public:
    consteval Key(const char* key) : index_(find(key)) {}  // NOLINT: implicit on purpose
    std::size_t index() const { return index_; }

   private:
    static consteval std::size_t find(std::string_view key) {
      for (std::size_t i = 0; i < kRunResults.size(); ++i)
        if (kRunResults[i].key == key) return i;
      throw std::logic_error("not a result of kRunResults");  // a compile error in a consteval call
    }
    std::size_t index_;
  };

  RunResults() : values_(kRunResults.size()) {}

  /// \throws std::logic_error if the value does not have the result's kind
  void set(Key key, double value);
  template <std::integral T>
    requires(!std::same_as<T, bool>)
  void set(Key key, T value) {
    put(key.index(), ResultKind::integer, Value(static_cast<std::int64_t>(value)));
  }
  void set(Key key, std::string value);
  void set(Key key, const char* value) { set(key, std::string(value)); }
  void set(Key key, bool value);

  /// The i-th result of kRunResults set at run time (results read back from summary.json).
  /// \throws std::logic_error if the value does not have the result's kind
  void set_value(std::size_t i, Value value);

  bool has(Key key) const { return values_[key.index()].has_value(); }
  /// The number (NaN if not set).
  double number(Key key) const;
  /// The integer (0 if not set).
  std::int64_t integer(Key key) const;
  /// The text ("" if not set).
  std::string text(Key key) const;

  /// The value of the i-th result of kRunResults, if set.
  const std::optional<Value>& at(std::size_t i) const { return values_.at(i); }

 private:
  void put(std::size_t index, ResultKind kind, Value value);
  std::vector<std::optional<Value>> values_;
};

/// \brief summary.json: every result that is set, in the order of kRunResults.
io::SummaryJson summary_json(const RunResults& results);

/// One line of the report `flapsim run` prints. {key} is replaced by the value of the
/// result `key` in its print format, followed by its unit.
struct ReportLine {
  std::string_view text;
  bool (*shown)(const RunResults&) = nullptr;  ///< nullptr: always shown
};

/// A change of C_L from one step to the next (after the start) beyond which a run with
/// leading_edge = "shed" is said to have had its sheet come apart near the wing (the report's
/// warning). Measured (2 Dec, the rigid and flexible hawkmoth, Robofly, a delta, a swept, an
/// odd and a film wing, hovering and revolving): runs whose sheet stayed together changed by
/// 7.0 at most (an AR-4 plate shedding at 20°; the other models 3.5 at most after the start's
/// two steps), runs whose sheet came apart by 9.4–142 (a revolving delta wing's 12 cycles that
/// ended "ok" at a mean CL of 1.03 against 1.5 in its first revolution: 39; the hover of a
/// delta: 28), the forward flight of docs/fsi.md "Failures" by 10–80 a step. A sheet that
/// strikes the wing at a reversal spikes as 1/Δt (Lua et al.'s hover at 200 steps a cycle:
/// 20–41, its mean over many cycles within 3 % of the measurement, docs/uvlm.md): warned
/// too, and the warning says how to tell the two apart.
inline constexpr double kSheetApartClJump = 10.0;

/// A run with leading_edge = "shed" whose lift jumped beyond kSheetApartClJump (the report's
/// warning; after_run_notes.hpp for sweeps and the optimiser).
inline bool shed_sheet_came_apart(const RunResults& r) {
  return r.has("leading_edge") && r.text("leading_edge") == "shed" && r.has("largest_CL_jump") &&
         r.number("largest_CL_jump") > kSheetApartClJump;
}

/// A run whose tip zigzagged from step to step beyond kStepZigzagWarnedDeg (step_zigzag.hpp).
inline bool tip_zigzagged(const RunResults& r) {
  return r.has("largest_tip_zigzag_deg") && r.number("largest_tip_zigzag_deg") > kStepZigzagWarnedDeg;
}

/// Whether the settled cycles' mean CL drifts beyond three times the rms of the drift of as
/// many independent cycles, √12 √((n − 1)/(n + 1)) standard errors (cycle_statistics.hpp): a
/// convention, a chance of about 0.3 % for independent normal cycles), and by more than 0.1 %
/// of the settled mean (a periodic run's cycles agree to round-off, whose drift is no
/// transient). A periodic run's cycles 2–5 approaching their limit drift by 17 standard errors
/// over 999 cycles (4.9 times; 0.03 %: below the floor, not noted; a 20-cycle plate's, 2 %).
inline bool settled_cycles_drift(const RunResults& r) {
  if (!r.has("settled_CL_drift") || !r.has("settled_CL_standard_error") || !r.has("settled_cycles") ||
      !r.has("settled_mean_CL"))
    return false;
  const double n = static_cast<double>(r.integer("settled_cycles"));
  const double rms = std::sqrt(12.0 * (n - 1.0) / (n + 1.0)) * r.number("settled_CL_standard_error");
  const double drift = std::abs(r.number("settled_CL_drift"));
  return drift > 3.0 * rms && drift > 1e-3 * std::abs(r.number("settled_mean_CL"));
}

inline constexpr std::array kRunReport = {
    ReportLine{"case {case}, wing {wing_file}: {structure}",
               [](const RunResults& r) { return r.has("wing_file"); }},
    ReportLine{"case {case}: {structure}", [](const RunResults& r) { return !r.has("wing_file"); }},
    // In vacuum there is no lift, and no speed to make a coefficient of: "mean lift 0 N,
    // mean CL 0.0000" read as a result.
    ReportLine{"mean lift (last cycle) {mean_lift_N}, mean CL {mean_CL}",
               [](const RunResults& r) { return r.has("mean_power_W"); }},
    ReportLine{"note: the run ended within its first cycle: its means cover {mean_window_cycles} of a cycle "
               "from the start, not a cycle's",
               [](const RunResults& r) {
                 return r.has("mean_window_cycles") && r.number("mean_window_cycles") < 1.0;
               }},
    ReportLine{
        "over {settled_cycles} cycles from cycle {settled_from_cycle}: mean lift {settled_mean_lift_N}, "
        "mean CL {settled_mean_CL} ± {settled_CL_standard_error} (standard error; the cycles' mean CL "
        "scatter by {cycle_CL_deviation})",
        [](const RunResults& r) { return r.has("settled_mean_CL"); }},
    ReportLine{
        "note: the settled cycles' mean CL drifts by {settled_CL_drift} from the first to the last, "
        "beyond three times what independent cycles give: the first of them are still the start's "
        "transient; numerics.settled_from_cycle later (or more cycles) for a settled mean (docs/fsi.md, "
        "\"summary.json\")",
        [](const RunResults& r) { return settled_cycles_drift(r); }},
    // A shed sheet that came apart near the wing without driving the force past the
    // diverged-force bound: the run ends "ok" on a flow that is not the air's.
    ReportLine{"warning: with leading_edge = \"shed\" the lift coefficient changed by {largest_CL_jump} from "
               "one step to the next (into step {largest_CL_jump_step}; history.csv CL): the leading-edge "
               "sheet came apart near the wing, or struck it (runs whose sheet stayed together changed by "
               "7 at most); if the lift around that step runs away rather than spiking at a reversal, the "
               "results from there on are not the flow's; numerics.sheet_core_radius = 0.5 keeps the sheet "
               "together in more runs, leading_edge = \"separated\", the default, sheds none (docs/fsi.md, "
               "\"Failures\")",
               shed_sheet_came_apart},
    // A structure that rings at the step's rate (step_zigzag.hpp) ends "ok" on a motion that
    // is the integrator's, not the wing's.
    ReportLine{
        "warning: the wing's tip zigzags from step to step, by up to {largest_tip_zigzag_deg} (its bend or "
        "twist turning back at two steps in a row, the largest at step {largest_tip_zigzag_step}; "
        "history.csv tip_bend_deg, tip_twist_deg): a motion at the step's rate, which the steps do not "
        "resolve and the integrator pumps; the loads, the drive's power and the tip's motion from there "
        "on are not the wing's. Lower numerics.rho_infinity (the FEM's default is 0.5, the chain's 0.9; "
        "0 damps such a motion within a step), or take more steps_per_cycle (docs/fsi.md, \"A tip that "
        "zigzags from step to step\")",
        tip_zigzagged},
    ReportLine{"in vacuum (air = \"none\"): no aerodynamic loads, no lift",
               [](const RunResults& r) { return !r.has("mean_power_W"); }},
    ReportLine{
        "mean drag {mean_drag_N} (CD {mean_CD}), aerodynamic power {mean_power_W}, lift/power "
        "{lift_per_power_N_W}; coefficients on {reference_speed_m_s} ({reference_kind}), Reynolds number "
        "{reynolds_number}",
        [](const RunResults& r) {
          return r.has("mean_power_W") && std::isfinite(r.number("lift_per_power_N_W"));
        }},
    // A wing held still in a free stream does no work on the air: no lift per power (it read
    // "lift/power nan N/W"; summary.json's value is null).
    ReportLine{
        "mean drag {mean_drag_N} (CD {mean_CD}), aerodynamic power {mean_power_W} (a wing that does "
        "no work on the air: no lift/power); coefficients on {reference_speed_m_s} ({reference_kind}), "
        "Reynolds number {reynolds_number}",
        [](const RunResults& r) {
          return r.has("mean_power_W") && !std::isfinite(r.number("lift_per_power_N_W"));
        }},
    // A flapping wing in a free stream: its coefficients on U∞ grow as (flapping speed / U∞)²
    // (a 40 mm wing at 200 Hz in a 1 m/s stream: CL 1495); the flapping speed's as well.
    ReportLine{
        "on the flapping speed at r2, {flapping_speed_m_s} (the free stream {free_stream_speed_m_s}): CL "
        "{mean_CL_on_flapping_speed}, CD {mean_CD_on_flapping_speed}",
        [](const RunResults& r) { return r.has("mean_CL_on_flapping_speed"); }},
    ReportLine{"drive: mean power {mean_drive_power_W} (peak {peak_drive_power_W}), peak moment "
               "{peak_drive_moment_Nm}"},
    ReportLine{"coupling: {mean_coupling_iterations} sub-iterations per step on average "
               "(max {max_coupling_iterations})",
               [](const RunResults& r) { return r.integer("max_coupling_iterations") > 1; }},
    ReportLine{"structure: {split_structural_steps} chain solves did not converge whole and were solved in "
               "halves (up to {max_structural_pieces} pieces): the chain moves too fast for the time step "
               "there; check the results with more "
               "steps_per_cycle (docs/multibody.md, \"Step halving\")",
               [](const RunResults& r) {
                 return r.has("split_structural_steps") && r.text("structure_kind") != "fem";
               }},
    ReportLine{"structure: {restarted_structural_steps} chain solves failed even in halves and were "
               "restarted as backward Euler (first order, damping what the step does not resolve): a load "
               "applied at once, or a step far too long for the chain; check the results with more "
               "steps_per_cycle (docs/multibody.md, \"Step halving\")",
               [](const RunResults& r) { return r.has("restarted_structural_steps"); }},
    ReportLine{"coupling: {stalled_steps_retried} steps stalled and were tried again with the structure "
               "solved more finely (docs/fsi.md, \"A stalled coupling, tried again\")",
               [](const RunResults& r) { return r.has("stalled_steps_retried"); }},
    ReportLine{"structure: {split_structural_steps} FEM steps did not converge whole and were solved in "
               "pieces (up to {max_structural_pieces}): motions of the mesh's scale faster than the time "
               "step (a thin film's wrinkles) there (docs/fsi.md, \"Step halving of the FEM\")",
               [](const RunResults& r) {
                 return r.has("split_structural_steps") && r.text("structure_kind") == "fem";
               }},
    // Only for a wing that reverses its stroke: a revolving wing or a plate held in a free
    // stream has no rotation phase ("base nan, tip nan" read as a failure).
    ReportLine{"rotation phase: base {base_rotation_phase}, tip {tip_rotation_phase}; "
               "tip alpha lag {tip_rotation_lag} of the period",
               [](const RunResults& r) { return std::isfinite(r.number("base_rotation_phase")); }},
};

/// \brief The report: the shown lines of kRunReport, each ending with a newline.
/// \throws std::logic_error on a placeholder that names no result
std::string run_report(const RunResults& results);

/// \brief One result's value as text: a number in its print format, an integer, the
/// text, true/false; "-" if not set. No unit.
std::string format_result(const RunResults& results, std::size_t index);

/// \brief The results that are columns of a sweep (a sweep_label), in order.
std::vector<std::size_t> sweep_results();

/// \brief Their sweep.csv cells: numbers in shortest round-trip form, "nan" if not set.
std::vector<std::string> sweep_cells(const RunResults& results);

/// A column of sweep.csv that is not a result of a run: how and where a case of the sweep
/// ran. sweep.csv is: one column per varied key (its dotted name), the results with a
/// sweep label (sweep_results()), then these, in this order.
struct SweepColumn {
  std::string_view key;          ///< column name
  std::string_view description;  ///< what it holds (docs/sweeps.md)
};

inline constexpr std::array kSweepColumns = {
    SweepColumn{"folder",
                "the case's sub-folder of the sweep's output folder (its summary.json, history.csv)"},
    SweepColumn{"status",
                "ok; failed (numerical failure, exit status 3 of a run); error (the case could not run, "
                "e.g. a wing the reduction refuses or a file that cannot be written)"},
    SweepColumn{"message",
                "why the case failed; \"kept\" for a case whose summary.json from an earlier run matched "
                "its inputs (not run again); then the case's warnings in a few words (its case and wing "
                "files', its setup's, a large deflection; a kept case's as its run gave them); else empty"},
    SweepColumn{"rank", "MPI rank that ran the case (0 without mpirun)"},
    SweepColumn{"host", "name of the machine that ran the case"},
};

}  // namespace flapsim::app
