#include "pipeline/app/stage_monitor.hpp"

#include <time.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string_view>
#include <system_error>

namespace flapsim::app {

namespace {

using Clock = std::chrono::steady_clock;
using Display = StageMonitor::Options::Display;

constexpr std::chrono::milliseconds kTick{50};  // how often the watcher looks (signals, progress)

sigset_t interrupt_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

Display resolve(Display d, std::FILE* stream) {
  if (d != Display::automatic) return d;
  if (!stream) return Display::quiet;
  if (const char* q = std::getenv("FLAPSIM_QUIET"); q && std::strcmp(q, "1") == 0) return Display::quiet;
  return ::isatty(::fileno(stream)) ? Display::live : Display::log;
}

const char* signal_name(int s) { return s == SIGINT ? "SIGINT" : s == SIGTERM ? "SIGTERM" : "a signal"; }

/// This process's temporary files in \p dir and its direct subfolders: every name holding
/// ".tmp.<pid>" (atomic_file.hpp's "<name>.tmp.<pid>", the mesh's "mesh.msh.tmp.<pid>.msh").
void remove_temporaries(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  const std::string mark = ".tmp." + std::to_string(static_cast<long>(::getpid()));
  std::error_code ec;
  auto sweep = [&](const fs::path& folder, auto& self, int depth) -> void {
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
      const fs::path p = it->path();
      if (it->is_directory(ec)) {
        if (depth == 0) self(p, self, depth + 1);
      } else if (p.filename().string().find(mark) != std::string::npos) {
        std::error_code ignored;
        fs::remove(p, ignored);
      }
    }
    ec.clear();
  };
  sweep(dir.empty() ? fs::path(".") : dir, sweep, 0);
}

}  // namespace

StageMonitor::StageMonitor(io::OutputFolderClaim& claim, int total_stages, Options options)
    : StageMonitor(claim.command(), total_stages, options) {
  claim_ = &claim;
}

StageMonitor::StageMonitor(std::string command, int total_stages, Options options)
    : claim_(nullptr), command_(std::move(command)), total_(total_stages), options_(options) {
  options_.display = resolve(options_.display, options_.stream);
  start_ = stage_start_ = last_shown_ = Clock::now();
  if (options_.watch_signals) {
    const sigset_t set = interrupt_signals();
    pthread_sigmask(SIG_BLOCK, &set, &old_mask_);
  }
  thread_ = std::thread([this] { watch(); });
}

StageMonitor::~StageMonitor() { done(); }

void StageMonitor::close_logged_stage(Clock::time_point now) {
  // In a log, a stage shown while it ran gets its own time when it ends: the lines above
  // were taken 2 s into it (and every 30 s), "FEM modes (stage 2 of 5): 2 s, 11 s in all",
  // and the log never said how long it took (modes on a fine mesh: 2 s shown for 13.5 s, the
  // last stage's 26 s nowhere).
  if (options_.display != Display::log || !shown_this_stage_ || index_ == 0) return;
  char text[160];
  std::snprintf(text, sizeof text, ": %s (stage %d of %d): done in %.1f s, %.0f s in all\n", name_.c_str(),
                index_, total_, std::chrono::duration<double>(now - stage_start_).count(),
                std::chrono::duration<double>(now - start_).count());
  const std::string line = command_ + text;
  std::fputs(line.c_str(), options_.stream);
  std::fflush(options_.stream);
  shown_this_stage_ = false;
}

void StageMonitor::stage(const std::string& name) {
  const std::lock_guard<std::mutex> lock(mutex_);
  close_logged_stage(Clock::now());
  ++index_;
  name_ = name;
  stage_start_ = Clock::now();
  shown_this_stage_ = false;
}

int StageMonitor::done() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (done_) return late_signal_;
    close_logged_stage(Clock::now());
    done_ = true;
    stop_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
  clear_live_line();
  if (options_.watch_signals) {
    // A signal after the watcher stopped is taken off and returned; then the mask the
    // command started with.
    const sigset_t set = interrupt_signals();
    const timespec now{0, 0};
    for (int s; (s = ::sigtimedwait(&set, nullptr, &now)) > 0;) late_signal_ = s;
    pthread_sigmask(SIG_SETMASK, &old_mask_, nullptr);
  }
  return late_signal_;
}

void StageMonitor::watch() {
  const sigset_t set = interrupt_signals();
  for (;;) {
    int s = -1;
    if (options_.watch_signals) {
      const timespec tick{0, std::chrono::duration_cast<std::chrono::nanoseconds>(kTick).count()};
      s = ::sigtimedwait(&set, nullptr, &tick);
    } else {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait_for(lock, kTick, [this] { return stop_; });
    }
    if (s == SIGINT || s == SIGTERM) {
      io::OutputFolderClaim::State found = io::OutputFolderClaim::State::unclaimed;
      std::string record_error;
      try {
        if (claim_) found = claim_->end_if_open("interrupted");
      } catch (const std::exception& e) {
        found = io::OutputFolderClaim::State::open;
        record_error = e.what();
      }
      if (found != io::OutputFolderClaim::State::ended) {
        if (!record_error.empty())
          std::fprintf(stderr, "flapsim: output error: %s\n", record_error.c_str());
        end_interrupted(s, found);
      }
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    if (stop_) return;
    show_progress(Clock::now());
  }
}

void StageMonitor::show_progress(Clock::time_point now) {
  if (options_.display == Display::quiet || index_ == 0) return;
  const bool live = options_.display == Display::live;
  // A live line already up follows the stages at once; otherwise a stage shows after show_after.
  if (!(live && live_width_ > 0) && now - stage_start_ < options_.show_after) return;
  const auto interval = live ? options_.live_interval : options_.log_interval;
  if (shown_this_stage_ && now - last_shown_ < interval) return;
  const double in_stage = std::chrono::duration<double>(now - stage_start_).count();
  const double in_all = std::chrono::duration<double>(now - start_).count();
  char tail[96];
  std::snprintf(tail, sizeof(tail), " (stage %d of %d): %.0f s, %.0f s in all", index_, total_, in_stage, in_all);
  std::string line = command_;
  line.append(": ").append(name_).append(tail);
  if (live) {
    std::string out("\r");
    out.append(line);
    if (line.size() < live_width_) out.append(live_width_ - line.size(), ' ');
    live_width_ = line.size();
    std::fputs(out.c_str(), options_.stream);
  } else {
    line.push_back('\n');
    std::fputs(line.c_str(), options_.stream);
  }
  std::fflush(options_.stream);
  last_shown_ = now;
  shown_this_stage_ = true;
}

void StageMonitor::clear_live_line() {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (live_width_ == 0) return;
  std::string out("\r");
  out.append(live_width_, ' ');
  out.push_back('\r');
  std::fputs(out.c_str(), options_.stream);
  std::fflush(options_.stream);
  live_width_ = 0;
}

void StageMonitor::end_interrupted(int signal_number, io::OutputFolderClaim::State found) {
  clear_live_line();
  std::string stage;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (index_ == 0)
      stage = " before its first stage";
    else
      stage.append(" during ").append(name_).append(" (stage ").append(std::to_string(index_)).append(" of ")
          .append(std::to_string(total_)).append(")");
  }
  if (!options_.scratch_file.empty()) {
    std::error_code ignored;
    std::filesystem::remove(options_.scratch_file, ignored);
  }
  std::string manifest;
  if (claim_) {
    remove_temporaries(claim_->dir());
    manifest = (claim_->dir() / io::kManifestName).string();
  }
  std::fflush(stdout);
  std::fprintf(stderr, "flapsim: %s interrupted by %s%s; %s\n", command_.c_str(), signal_name(signal_number),
               stage.c_str(),
               found == io::OutputFolderClaim::State::open
                   ? (manifest + " records it as \"interrupted\"; the files written before stay valid").c_str()
                   : "nothing was written");
  std::fflush(stderr);
  std::_Exit(128 + signal_number);  // at once: the stage under way cannot stop, its threads end with the process
}

}  // namespace flapsim::app
