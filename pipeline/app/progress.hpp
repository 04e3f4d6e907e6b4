#pragma once
/// \file progress.hpp
/// \brief A one-line progress display on stderr for long runs:
/// "step 120/300  t=0.0460 s  <extra>  ~2.5 min left", redrawn in place (carriage return)
/// at most about five times a second. When the stream is not a terminal (a log file, a
/// batch job's output) a whole line is printed every 30 s of wall time, "… (30.1 s wall,
/// ~2.5 min left)", and at the end, "… (95.2 s wall)"; FLAPSIM_QUIET=1 in the environment
/// silences it entirely. The time left is the steps left at the slower of two paces: the
/// whole run's (wall time so far over the steps done) and the recent one (the steps of the
/// last 30-60 s of wall time), so a run whose steps slow down (a film wing whose FEM steps
/// start to split) says so within a log line or two.

#include <chrono>
#include <cstdio>
#include <functional>
#include <string>
#include <string_view>

namespace flapsim::app {

class ProgressLine {
 public:
  enum class Mode {
    automatic,  ///< terminal -> live, otherwise final_only; FLAPSIM_QUIET=1 -> quiet
    live,       ///< redraw in place and print the final line
    final_only, ///< a line every log interval (30 s) of a long run, and the final line
    quiet       ///< print nothing
  };

  /// \param total   number of steps of the run
  /// \param stream  where to print (not owned); stderr by default
  /// \param mode    see Mode
  explicit ProgressLine(long total, std::FILE* stream = stderr, Mode mode = Mode::automatic);
  /// Prints the final line if finish() was not called (e.g. a run that failed).
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// \brief Reports that \p step steps are done at simulated time \p time [s];
  /// redraws if 0.2 s have passed since the last redraw.
  /// \param extra  short text appended to the line (e.g. "CL=1.93  iters=4")
  void update(long step, double time, std::string_view extra = {});

  /// \brief Reports that the next step is under way (called between its solves, often):
  /// a step that lasts (a film's FEM step in many pieces: minutes) shows the line with
  /// "step N under way for X s" — in a log once a log interval, live once a second.
  /// \param detail  called only when the line is drawn: what the step has done so far
  ///                (e.g. "37 lattice solves, change 2.3e-03 rad"), "" for nothing
  void step_under_way(const std::function<std::string()>& detail = {});

  /// \brief Prints the final line with the last step, time and the wall-clock time,
  /// ending with a newline. Idempotent.
  void finish(std::string_view extra = {});

  Mode mode() const { return mode_; }

  /// \brief Wall time between the lines of Mode::final_only (default 30 s, as the stage
  /// lines of mesh/modes/reduce in a log: stage_monitor.hpp).
  void set_log_interval(std::chrono::milliseconds interval) { log_interval_ = interval; }

  /// \brief The text of a line (no carriage return or newline): "step 120/300  t=0.0460 s  extra".
  static std::string format(long step, long total, double time, std::string_view extra);

  /// \brief "~40 s left", "~2.5 min left", "~1.3 h left": \p wall seconds for \p step of
  /// \p total steps, scaled to the steps left; empty before the first step and after the last.
  static std::string time_left(double wall, long step, long total);

  /// \brief The same with the recent pace \p recent_seconds_per_step [s/step] (0: none
  /// measured yet): the steps left at the slower of it and the whole run's pace.
  static std::string time_left(double wall, long step, long total, double recent_seconds_per_step);

 private:
  void draw(const std::string& line, bool final_line);
  double wall_seconds() const;  ///< since the line was made [s]
  std::string wall_note(bool with_time_left) const;  ///< "  (12.3 s wall)" or "  (12.3 s wall, ~40 s left)"
  long total_;
  std::FILE* stream_;
  Mode mode_;
  long step_ = 0;
  double time_ = 0.0;
  std::string extra_;
  std::size_t last_width_ = 0;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::chrono::steady_clock::time_point step_start_;  ///< when the last step was reported done
  /// Two marks (wall time [s], steps done) at least a log interval apart: the recent pace is
  /// measured from the older one (over the last one to two log intervals).
  double older_mark_wall_ = 0.0, newer_mark_wall_ = 0.0;
  long older_mark_step_ = 0, newer_mark_step_ = 0;
  void mark_pace(double wall, long step);
  double recent_seconds_per_step(double wall) const;  ///< 0 until a mark lies steps behind
  std::string time_left_now(double wall) const;
  bool drawn_ = false;
  std::chrono::milliseconds log_interval_{std::chrono::seconds(30)};
};

}  // namespace flapsim::app
