#include "pipeline/fsi/stop_request.hpp"

#include <utility>

namespace flapsim::fsi {

namespace {
thread_local StopCheck t_check;
}  // namespace

ScopedStopCheck::ScopedStopCheck(StopCheck check) : previous_(std::exchange(t_check, std::move(check))) {}

ScopedStopCheck::~ScopedStopCheck() { t_check = std::move(previous_); }

void check_stop() {
  if (t_check) t_check();
}

}  // namespace flapsim::fsi
