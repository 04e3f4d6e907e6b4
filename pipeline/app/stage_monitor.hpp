#pragma once
/// \file stage_monitor.hpp
/// \brief A watcher for the commands made of a few long stages (`mesh`, `modes`, `reduce`).
/// gmsh, CHOLMOD and Spectra cannot stop between steps as a run does (interruption.hpp),
/// and a fine mesh keeps them busy for a minute, so a thread of its own watches the command:
///  - **SIGINT / SIGTERM.** The two signals are blocked in the command's threads (and so in
///    the threads gmsh and OpenMP start later) and received by the watcher, which records
///    "interrupted" in the folder's manifest (an atomic write), removes this process's
///    temporary files (`*.tmp.<pid>*`) from the folder and ends the process at once with
///    status 128 + signal (130 for SIGINT, 143 for SIGTERM). The files the command had
///    published stay as they were: each was renamed complete. A signal that comes after
///    the command recorded its end is left alone (the command is finishing).
///    A command that writes no files (`check`) is watched alike without a folder: a signal
///    ends it at once with 128 + signal, saying that nothing was written.
///  - **Progress.** A stage that has lasted 2 s is shown on stderr: "reduce: FEM modes (stage
///    3 of 6): 14 s, 41 s in all". On a terminal the line is redrawn in place once a
///    second and cleared at the end; elsewhere (a log file) one line when the stage passes
///    2 s, then at most one every 30 s, and when a stage so shown ends, its time: "reduce:
///    FEM modes (stage 3 of 6): done in 14.2 s, 41 s in all". FLAPSIM_QUIET=1 silences it.

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>

#include <signal.h>

#include "pipeline/io/output_manifest.hpp"

namespace flapsim::app {

class StageMonitor {
 public:
  struct Options {
    std::chrono::milliseconds show_after{2000};     ///< a stage shorter than this is not shown
    std::chrono::milliseconds live_interval{1000};  ///< terminal: redraw at most this often
    std::chrono::milliseconds log_interval{30000};  ///< not a terminal: one line at most this often per stage
    enum class Display { automatic, live, log, quiet } display = Display::automatic;
    std::FILE* stream = stderr;  ///< not owned
    bool watch_signals = true;   ///< false: progress only (tests in process)
    /// A file of the command's outside its folder (mesh's gmsh file in the system's temporary
    /// folder), removed if the command is interrupted; none if empty.
    std::filesystem::path scratch_file;
  };

  /// \brief Starts watching. Call before any thread is started (before the FEM) so that every
  /// thread of the command inherits the blocked signals.
  /// \param claim         the command's claim on its output folder (outlives the monitor)
  /// \param total_stages  number of stages, for "stage k of n"
  StageMonitor(io::OutputFolderClaim& claim, int total_stages, Options options);
  StageMonitor(io::OutputFolderClaim& claim, int total_stages) : StageMonitor(claim, total_stages, Options{}) {}
  /// \brief Starts watching a command that writes no files (`check`), named \p command in
  /// the progress line ("check: setup (stage 1 of 1): 3 s, 3 s in all").
  StageMonitor(std::string command, int total_stages, Options options);
  /// done().
  ~StageMonitor();
  StageMonitor(const StageMonitor&) = delete;
  StageMonitor& operator=(const StageMonitor&) = delete;

  /// \brief Begins the next stage, named for the progress line ("FEM modes").
  void stage(const std::string& name);

  /// \brief Stops the watcher, clears a live progress line and unblocks the signals. Idempotent.
  /// \return a signal that came after the watcher stopped (SIGINT or SIGTERM; 0 if none): a
  /// command that goes on after the watched stages (`run` after its setup) acts on it.
  int done();

 private:
  void watch();
  void show_progress(std::chrono::steady_clock::time_point now);
  void close_logged_stage(std::chrono::steady_clock::time_point now);  // mutex_ held
  [[noreturn]] void end_interrupted(int signal_number, io::OutputFolderClaim::State found);
  void clear_live_line();

  io::OutputFolderClaim* claim_;  // nullptr: a command that writes no files
  std::string command_;
  int total_;
  Options options_;
  std::mutex mutex_;  // guards the fields below
  std::condition_variable wake_;
  bool stop_ = false;
  int index_ = 0;
  std::string name_;
  std::chrono::steady_clock::time_point start_, stage_start_, last_shown_;
  bool shown_this_stage_ = false;
  std::size_t live_width_ = 0;
  sigset_t old_mask_;
  bool done_ = false;
  int late_signal_ = 0;
  std::thread thread_;
};

}  // namespace flapsim::app
