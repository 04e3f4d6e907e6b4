#include "pipeline/app/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace flapsim::app {

namespace {

constexpr auto kRedrawInterval = std::chrono::milliseconds(200);  // ~5 Hz

ProgressLine::Mode resolve(ProgressLine::Mode mode, std::FILE* stream) {
  if (mode != ProgressLine::Mode::automatic) return mode;
  if (const char* q = std::getenv("FLAPSIM_QUIET"); q && std::strcmp(q, "1") == 0)
    return ProgressLine::Mode::quiet;
  if (stream && ::isatty(::fileno(stream))) return ProgressLine::Mode::live;
  return ProgressLine::Mode::final_only;
}

}  // namespace

ProgressLine::ProgressLine(long total, std::FILE* stream, Mode mode)
    : total_(total), stream_(stream), mode_(resolve(mode, stream)),
      start_(std::chrono::steady_clock::now()), last_draw_(start_), step_start_(start_) {
  if (!stream_) mode_ = Mode::quiet;
}

ProgressLine::~ProgressLine() { finish(); }

std::string ProgressLine::format(long step, long total, double time, std::string_view extra) {
  char buf[96];
  std::snprintf(buf, sizeof(buf), "step %ld/%ld  t=%.4f s", step, total, time);
  std::string line(buf);
  if (!extra.empty()) {
    line += "  ";
    line += extra;
  }
  return line;
}

void ProgressLine::update(long step, double time, std::string_view extra) {
  step_ = step;
  time_ = time;
  step_start_ = std::chrono::steady_clock::now();
  mark_pace(std::chrono::duration<double>(step_start_ - start_).count(), step);
  if (mode_ == Mode::final_only) {
    // A log (a batch job's output) gets a whole line now and then: a run of hours
    // otherwise showed nothing until its end. Not at the last step: finish() prints it.
    extra_.assign(extra);
    const auto now = step_start_;
    if (now - last_draw_ >= log_interval_ && step_ < total_) {
      last_draw_ = now;
      draw(format(step_, total_, time_, extra_) + wall_note(true), true);
    }
    return;
  }
  if (mode_ != Mode::live) {
    extra_.assign(extra);  // kept for the final line
    return;
  }
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && now - last_draw_ < kRedrawInterval) {
    extra_.assign(extra);
    return;
  }
  extra_.assign(extra);
  last_draw_ = now;
  std::string line = format(step_, total_, time_, extra_);
  // The time left appears once the run has shown its pace (a second of wall time).
  if (const double wall = wall_seconds(); wall >= 1.0)
    if (const std::string left = time_left_now(wall); !left.empty()) line += "  " + left;
  draw(line, false);
}

void ProgressLine::step_under_way(const std::function<std::string()>& detail) {
  if (mode_ != Mode::final_only && mode_ != Mode::live) return;
  const auto now = std::chrono::steady_clock::now();
  const auto interval = mode_ == Mode::live ? std::chrono::milliseconds(1000) : log_interval_;
  if (now - last_draw_ < interval || now - step_start_ < interval) return;
  last_draw_ = now;
  char note[64];
  std::snprintf(note, sizeof note, "  step %ld under way for %.0f s", step_ + 1,
                std::chrono::duration<double>(now - step_start_).count());
  std::string line = format(step_, total_, time_, extra_) + note;
  if (detail)
    if (const std::string d = detail(); !d.empty()) line += ": " + d;
  draw(line + wall_note(false), mode_ == Mode::final_only);
}

void ProgressLine::finish(std::string_view extra) {
  if (finished_) return;
  finished_ = true;
  if (mode_ == Mode::quiet) return;
  if (!extra.empty()) extra_.assign(extra);
  draw(format(step_, total_, time_, extra_) + wall_note(false), true);
}

std::string ProgressLine::time_left(double wall, long step, long total) {
  return time_left(wall, step, total, 0.0);
}

std::string ProgressLine::time_left(double wall, long step, long total, double recent_seconds_per_step) {
  if (step <= 0 || step >= total || !(wall > 0.0)) return {};
  const double pace = std::max(wall / static_cast<double>(step), recent_seconds_per_step);  // [s/step]
  const double left = pace * static_cast<double>(total - step);                             // [s]
  char buf[32];
  if (left < 90.0)
    std::snprintf(buf, sizeof(buf), "~%.0f s left", left);
  else if (left < 5400.0)
    std::snprintf(buf, sizeof(buf), "~%.1f min left", left / 60.0);
  else
    std::snprintf(buf, sizeof(buf), "~%.1f h left", left / 3600.0);
  return buf;
}

void ProgressLine::mark_pace(double wall, long step) {
  const double interval = std::chrono::duration<double>(log_interval_).count();  // [s]
  if (wall - newer_mark_wall_ < interval) return;
  older_mark_wall_ = newer_mark_wall_;
  older_mark_step_ = newer_mark_step_;
  newer_mark_wall_ = wall;
  newer_mark_step_ = step;
}

double ProgressLine::recent_seconds_per_step(double wall) const {
  // From the older mark: the start until the second mark is set, then a log interval or
  // two back.
  if (step_ <= older_mark_step_) return 0.0;
  return (wall - older_mark_wall_) / static_cast<double>(step_ - older_mark_step_);
}

std::string ProgressLine::time_left_now(double wall) const {
  return time_left(wall, step_, total_, recent_seconds_per_step(wall));
}

double ProgressLine::wall_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::string ProgressLine::wall_note(bool with_time_left) const {
  const double wall = wall_seconds();
  char buf[48];
  std::snprintf(buf, sizeof(buf), "  (%.1f s wall", wall);
  std::string note = buf;
  if (const std::string left = with_time_left ? time_left_now(wall) : std::string(); !left.empty())
    note += ", " + left;
  return note + ")";
}

void ProgressLine::draw(const std::string& line, bool final_line) {
  std::string out;
  if (mode_ == Mode::live) {
    out += '\r';
    out += line;
    // Blank out the rest of a longer previous line.
    if (line.size() < last_width_) out.append(last_width_ - line.size(), ' ');
    last_width_ = line.size();
  } else {
    out = line;
  }
  if (final_line) out += '\n';
  std::fwrite(out.data(), 1, out.size(), stream_);
  std::fflush(stream_);
  drawn_ = true;
}

}  // namespace flapsim::app
