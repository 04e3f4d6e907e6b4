#include "pipeline/app/interruption.hpp"

#include <csignal>

namespace flapsim::app {

namespace {

volatile std::sig_atomic_t g_signal = 0;

extern "C" void record_signal(int signal_number) { g_signal = signal_number; }

const char* signal_name(int s) { return s == SIGINT ? "SIGINT" : s == SIGTERM ? "SIGTERM" : "a signal"; }

}  // namespace

void install_interrupt_handlers() {
  struct sigaction sa {};
  sa.sa_handler = record_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;  // system calls under way (writes) complete
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

int pending_interrupt() { return g_signal; }

void record_interrupt(int signal_number) {
  if (signal_number != 0) g_signal = signal_number;
}

void throw_if_interrupted(const std::string& where) {
  const int s = g_signal;
  if (s != 0) throw Interrupted(s, std::string("interrupted by ") + signal_name(s) + " " + where);
}

}  // namespace flapsim::app
