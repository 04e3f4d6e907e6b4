#pragma once
/// \file run_recorder.hpp
/// \brief What a run leaves behind, step by step: a row of history.csv per step (columns
/// in run_history.hpp), the ParaView series every `vtk_every` steps, the samples kept
/// for the end-of-run analysis; at the end (or at a numerical failure) the run's
/// results (run_results.hpp), written as summary.json, and (with the series) the paths of
/// the tip and of the markers over every step (tip_path.vtp, marker_<k>_path.vtp).

#include <array>
#include <chrono>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "pipeline/app/diverged_force.hpp"
#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/app/run_history.hpp"
#include "pipeline/app/run_results.hpp"
#include "pipeline/app/thinned_sample.hpp"
#include "pipeline/fsi/coupled_step.hpp"
#include "pipeline/io/case_model.hpp"
#include "pipeline/io/csv_writer.hpp"
#include "pipeline/io/pvd_series.hpp"
#include "pipeline/io/state_camera.hpp"
#include "pipeline/io/trajectory_vtk.hpp"
#include "pipeline/io/vtk_writers.hpp"

namespace flapsim::app {

/// history.csv is published (a copy flushed to disk and renamed onto it,
/// docs/output_files.md) after 20, 40, 80, … steps, at the latest 2 s after the last
/// publication (once 20 steps are new), and at the end.
inline constexpr int kHistoryPublishEvery = 20;
inline constexpr std::chrono::steady_clock::duration kHistoryMaxPublishInterval = std::chrono::seconds(2);

/// The ParaView series (wing.pvd, wake.pvd, chain.pvd) list their new frames at most once
/// per this interval and at the end: the frames (vtk/*.vtp) are renamed into place without
/// a flush each, and one flush of the file system (io::sync_file_system) precedes each
/// publication, so a .pvd lists only frames on disk (docs/output_files.md). A flush per
/// frame and per .pvd, 12 per step, made `make run` 4× slower on a busy disk.
inline constexpr std::chrono::steady_clock::duration kSeriesPublishInterval = std::chrono::seconds(1);

class RunRecorder {
 public:
  /// \brief Creates the output folder, opens history.csv (and the series if vtk_every > 0)
  /// and sets the results known before the first step.
  /// \param setup        the run's setup (not owned; must outlive the recorder)
  /// \param vtk_every    write the ParaView series every n steps; 0 = never
  /// \param spring_scale the joint-spring factor the setup applied (reported)
  /// \param started      when the run started (wall time, setup included)
  /// \throws io::OutputError if the folder or history.csv cannot be created
  RunRecorder(const io::Case& c, const FsiSetup& setup, const std::filesystem::path& output_dir,
              int vtk_every, double spring_scale, std::chrono::steady_clock::time_point started);

  /// \brief Sets the fingerprint of the run's inputs (io::input_hash), reported as inputs_hash.
  void set_inputs_hash(std::string hash) { results_.set("inputs_hash", std::move(hash)); }

  /// \brief Sets the case's warnings in a few words (RunOptions::warnings), reported as
  /// warnings; none (empty): not reported.
  void set_warnings(std::string notes) {
    if (!notes.empty()) results_.set("warnings", std::move(notes));
  }

  /// \brief Creates the ParaView series (the .pvd files, vtk/) and run.pvsm when frames are
  /// written: called within the run's error handling, so that an output error here (a file
  /// size limit below run.pvsm's size, a file named vtk) still leaves summary.json saying
  /// "failed" (finish). \throws io::OutputError
  void begin();

  /// \brief The sample of the state after a coupled step, measured but not yet recorded: a
  /// step the caller then refuses (a diverged force) is in no output. The next record() of
  /// the same step takes it.
  const StepSample& measure(const fsi::FsiData& data);

  /// \brief Records the state after a coupled step (before the wake is shed).
  void record(const fsi::FsiData& data);

  /// \brief Writes the ParaView frame of the initial state (t = 0, after fsi::initialize,
  /// before the first step): the chain and the lattice in their starting pose, no loads.
  void record_initial(const fsi::FsiData& data);

  /// The sample of the last recorded step (valid after the first record()).
  const StepSample& last() const { return samples_.back(); }

  /// The steps recorded so far (history.csv's rows).
  long recorded_steps() const { return static_cast<long>(samples_.size()); }

  /// \brief Publishes history.csv, computes the results over the last cycle and writes
  /// summary.json with the status ("ok" or "failed") and, for a failed run, the error.
  /// \throws io::OutputError
  RunResults finish(const fsi::FsiData& data, const std::string& status, const std::string& error = {});

  /// The largest tip bend and twist against the base so far (fsi::StructureReadout of
  /// each recorded step; summary.json peak_tip_bend_deg, peak_tip_twist_deg) [deg].
  struct TipDeflection {
    double bend_deg = 0.0, twist_deg = 0.0;
  };
  TipDeflection peak_tip_deflection() const;

  /// The largest change of C_L between two consecutive recorded steps so far, the measured
  /// step that was not recorded (the one that failed) included (diverged_force.hpp; 0
  /// before the second step).
  LiftJump largest_lift_jump() const;

 private:
  void write_series(const fsi::FsiData& data, long step);
  /// The largest change of C_L between two consecutive recorded steps, into step
  /// \p first_step (1-based, ≥ 2) or later.
  LiftJump largest_recorded_jump(long first_step) const;
  /// Flushes the frames written since the last publication and rewrites the .pvd files,
  /// if kSeriesPublishInterval has passed since then or \p now. \throws io::OutputError
  void publish_series(bool now);
  /// Keeps what run.pvsm needs of a written frame (the wing's, or the chain's in vacuum).
  void record_for_state(const io::PolyDataMesh& frame, long step);
  void write_state() const;  ///< run.pvsm (io/pvsm_state.hpp), colour ranges as seen so far
  /// Adds the tip's and the markers' positions at time \p t [s] to their paths.
  void record_paths(double t, const Eigen::Vector3d& tip, std::span<const double> markers);
  /// tip_path.vtp and marker_<k>_path.vtp (atomic). \throws io::OutputError
  void write_paths() const;
  void analyse(const fsi::FsiData& data);
  /// summary.json's window for its means [s]: the period before the last step recorded.
  std::pair<double, double> mean_window() const;
  /// 0 and the time of every recorded step [s]: the series the means take from t = 0.
  std::vector<double> times_from_zero() const;
  /// The mean of a quantity given at every recorded step over mean_window(), the series from
  /// t = 0, where it takes the first step's value (t = 0 has no loads).
  double last_cycle_mean(std::vector<double> per_step) const;
  /// span_loads.csv: each strip's mean lift over the window of summary.json's means (in air).
  /// \throws io::OutputError
  void write_span_loads() const;

  const io::Case& case_;
  const FsiSetup& setup_;
  std::filesystem::path dir_;
  int vtk_every_;
  std::chrono::steady_clock::time_point started_;
  int outer_body_;                ///< 0-based
  io::CsvTimeSeriesWriter history_;
  std::vector<double> row_;
  std::optional<io::PvdSeries> wing_pvd_, wake_pvd_, chain_pvd_;
  std::chrono::steady_clock::time_point series_published_;  ///< last publication of the .pvd files
  /// q_ref = ½ ρ U_ref² of the run's CL (wing.vtp Cp = Δp / q_ref) [Pa]; 0 in vacuum.
  double dynamic_pressure_ = 0.0;
  Eigen::Matrix3Xd rigid_nodes_;   ///< the lattice on the rigid wing at a frame's time [m]
  io::Trajectory tip_path_;                  ///< the tip at t = 0 and after every step
  std::vector<io::Trajectory> marker_paths_;  ///< the case's markers, likewise
  /// What run.pvsm's colour ranges and cameras come from (io::RunState): the wing's
  /// colour field of every panel of every frame after t = 0 (Cp, or Δp [Pa] without
  /// it), the wake's |Γ| [m²/s], the field data names of a frame, the wing's (or
  /// chain's) frames for the cameras.
  std::string wing_field_ = "pressure_jump_Pa";
  ThinnedSample wing_values_, circulation_values_;  ///< at most 2²⁰ values each (thinned_sample.hpp)
  ThinnedSample displacement_values_;               ///< |displacement_m| of a FEM's surface in vacuum [m]
  std::vector<std::string> frame_fields_;
  std::vector<double> frame_times_;  ///< t of the frames written [s] (the state opens at one)
  io::StateCameraChooser camera_;
  std::vector<StepSample> samples_;
  /// The lift of every strip of the lattice at each recorded step, root to tip, step after
  /// step (spanwise_panels values a step) [N] (span_loads.hpp; none in vacuum):
  /// span_loads.csv's means over the last cycle.
  std::vector<double> strip_lift_;
  std::optional<StepSample> measured_;  ///< measure()'s sample until record() takes it
  long measured_step_ = -1;             ///< the step it was measured after
  RunResults results_;
};

}  // namespace flapsim::app
