#pragma once
/// \file sweep_progress.hpp
/// \brief What a sweep shows on stderr while its cases run. Each finished case gives a
/// line (sweep_runner); between them, the cases under way on this process show their
/// steps as `flapsim run`'s progress line does:
///   "sweep 3/10 done; under way: 03_0.1 step 120/300, 04_0.2 step 80/300  (45.2 s)"
/// redrawn in place on a terminal (at most five times a second), and in a log (stderr not a
/// terminal: a batch job, mpirun's forwarded output) as a whole line when the log interval
/// (30 s) has passed since the last line of the sweep. Under MPI each rank shows its own
/// cases; a rank other than 0 names itself ("sweep rank 2: under way: ...") and leaves the
/// finished lines to rank 0. FLAPSIM_QUIET=1 or --quiet: nothing.

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdio>
#include <map>
#include <mutex>
#include <string>
#include <thread>

#include "pipeline/app/progress.hpp"

namespace flapsim::sweep {

class SweepProgress {
 public:
  /// \param total     the sweep's cases
  /// \param finished  cases finished already (kept from an earlier run)
  /// \param rank      this process's MPI rank (0 without MPI)
  /// \param mode      as app::ProgressLine's (automatic: live on a terminal, else log lines)
  SweepProgress(std::size_t total, std::size_t finished, int rank, app::ProgressLine::Mode mode,
                std::chrono::milliseconds log_interval = std::chrono::seconds(30), std::FILE* stream = stderr);
  ~SweepProgress();
  SweepProgress(const SweepProgress&) = delete;
  SweepProgress& operator=(const SweepProgress&) = delete;

  /// A case starts on this process; \p label names it (its folder).
  void started(std::size_t index, const std::string& label);
  /// Case \p index has done \p step of its \p total steps (cheap: called every step).
  void step(std::size_t index, long step, long total);
  /// Case \p index has ended on this process (it leaves the line of cases under way).
  void ended(std::size_t index);
  /// Prints \p line (a finished case's, without newline) as a line of its own, clearing the
  /// live line first; \p finished is the count of finished cases after it.
  void print_line(const std::string& line, std::size_t finished);

  app::ProgressLine::Mode mode() const { return mode_; }

  /// The text of a progress line (without carriage return or newline).
  std::string format_line() const;  // caller holds no lock

 private:
  struct Running {
    std::string label;
    long step = 0, total = 0;
  };
  void tick();
  std::string format_locked() const;
  void draw_locked(const std::string& text, bool whole_line);

  std::size_t total_, finished_;
  int rank_;
  app::ProgressLine::Mode mode_;
  std::chrono::milliseconds log_interval_;
  std::FILE* stream_;
  std::chrono::steady_clock::time_point start_, last_line_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::map<std::size_t, Running> running_;  ///< by case index
  std::size_t live_width_ = 0;              ///< characters of the live line on screen (0: none)
  std::thread ticker_;
};

}  // namespace flapsim::sweep
