#include "pipeline/app/sweep/sweep_progress.hpp"

#include <cstdlib>
#include <cstring>
#include <unistd.h>

namespace flapsim::sweep {

namespace {

using Clock = std::chrono::steady_clock;
using Mode = app::ProgressLine::Mode;
constexpr auto kRedrawInterval = std::chrono::milliseconds(200);  // as run's live line
constexpr std::size_t kLiveCases = 3;  // cases named on a live line (it must fit a terminal's width)

Mode resolve(Mode mode, std::FILE* stream) {
  if (mode != Mode::automatic) return mode;
  if (const char* q = std::getenv("FLAPSIM_QUIET"); q && std::strcmp(q, "1") == 0) return Mode::quiet;
  if (stream && ::isatty(::fileno(stream))) return Mode::live;
  return Mode::final_only;
}

}  // namespace

SweepProgress::SweepProgress(std::size_t total, std::size_t finished, int rank, Mode mode,
                             std::chrono::milliseconds log_interval, std::FILE* stream)
    : total_(total), finished_(finished), rank_(rank), mode_(resolve(mode, stream)), log_interval_(log_interval),
      stream_(stream), start_(Clock::now()), last_line_(start_) {
  if (!stream_) mode_ = Mode::quiet;
  if (mode_ == Mode::live || mode_ == Mode::final_only) ticker_ = std::thread([this] { tick(); });
}

SweepProgress::~SweepProgress() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (ticker_.joinable()) ticker_.join();
  std::lock_guard<std::mutex> lock(mutex_);
  if (live_width_ > 0) draw_locked("", false);  // leave no half line behind
}

void SweepProgress::started(std::size_t index, const std::string& label) {
  std::lock_guard<std::mutex> lock(mutex_);
  running_[index] = Running{label, 0, 0};
}

void SweepProgress::step(std::size_t index, long step, long total) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (auto it = running_.find(index); it != running_.end()) {
    it->second.step = step;
    it->second.total = total;
  }
}

void SweepProgress::ended(std::size_t index) {
  std::lock_guard<std::mutex> lock(mutex_);
  running_.erase(index);
}

void SweepProgress::print_line(const std::string& line, std::size_t finished) {
  std::lock_guard<std::mutex> lock(mutex_);
  finished_ = finished;
  if (mode_ == Mode::quiet) return;
  if (live_width_ > 0) draw_locked("", false);
  const std::string out = line + "\n";
  std::fwrite(out.data(), 1, out.size(), stream_);
  std::fflush(stream_);
  last_line_ = Clock::now();
}

std::string SweepProgress::format_line() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return format_locked();
}

std::string SweepProgress::format_locked() const {
  std::string s;
  char buf[160];
  if (rank_ == 0) std::snprintf(buf, sizeof buf, "sweep %zu/%zu done; under way:", finished_, total_);
  else std::snprintf(buf, sizeof buf, "sweep rank %d: under way:", rank_);
  s = buf;
  std::size_t shown = 0;
  for (const auto& [index, r] : running_) {
    (void)index;
    if (mode_ == Mode::live && shown == kLiveCases) {
      std::snprintf(buf, sizeof buf, " (+%zu more)", running_.size() - shown);
      s += buf;
      break;
    }
    if (r.total > 0) std::snprintf(buf, sizeof buf, "%s %s step %ld/%ld", shown ? "," : "", r.label.c_str(), r.step, r.total);
    else std::snprintf(buf, sizeof buf, "%s %s setup", shown ? "," : "", r.label.c_str());
    s += buf;
    ++shown;
  }
  std::snprintf(buf, sizeof buf, "  (%.1f s)", std::chrono::duration<double>(Clock::now() - start_).count());
  return s + buf;
}

void SweepProgress::draw_locked(const std::string& text, bool whole_line) {
  std::string out;
  if (mode_ == Mode::live) {
    out = "\r" + text;
    if (text.size() < live_width_) out.append(live_width_ - text.size(), ' ');
    if (text.empty()) out += '\r';  // cleared: the cursor back at the start of the line
    live_width_ = text.size();
  } else {
    out = text;
  }
  if (whole_line) out += '\n';
  std::fwrite(out.data(), 1, out.size(), stream_);
  std::fflush(stream_);
}

void SweepProgress::tick() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stop_) {
    wake_.wait_for(lock, kRedrawInterval);
    if (stop_ || running_.empty()) continue;
    if (mode_ == Mode::live) {
      draw_locked(format_locked(), false);
    } else if (Clock::now() - last_line_ >= log_interval_) {
      draw_locked(format_locked(), true);
      last_line_ = Clock::now();
    }
  }
}

}  // namespace flapsim::sweep
