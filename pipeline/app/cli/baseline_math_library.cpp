#include "pipeline/app/cli/baseline_math_library.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace flapsim::cli {

void run_with_the_baseline_math_library(char** argv) {
  if (std::getenv(kBaselineMathLibraryMark) != nullptr) return;
  const char* earlier = std::getenv("GLIBC_TUNABLES");
  std::string tunables = earlier != nullptr && *earlier != '\0' ? std::string(earlier) + ":" : std::string();
  tunables += kBaselineMathTunable;  // last: it decides glibc.cpu.hwcaps
  if (setenv("GLIBC_TUNABLES", tunables.c_str(), 1) != 0 || setenv(kBaselineMathLibraryMark, "1", 1) != 0) {
    std::fprintf(stderr, "flapsim: warning: could not set GLIBC_TUNABLES (%s): the C library's math functions "
                 "keep their builds for this CPU, and results may differ in their last bits from another "
                 "CPU's (docs/performance.md, \"The C library's math functions\")\n", std::strerror(errno));
    return;
  }
  // The program's own path rather than /proc/self/exe, so that ps and top name it flapsim.
  char self[4096];
  const ssize_t length = readlink("/proc/self/exe", self, sizeof self - 1);
  if (length > 0) {
    self[length] = '\0';
    execv(self, argv);  // returns if the file is gone (replaced by a build since it started)
  }
  execv("/proc/self/exe", argv);
  const int failure = errno;  // execv returns only when it failed
  if (earlier != nullptr) setenv("GLIBC_TUNABLES", earlier, 1); else unsetenv("GLIBC_TUNABLES");
  std::fprintf(stderr, "flapsim: warning: could not start again with the C library's baseline math functions "
               "(/proc/self/exe: %s): results may differ in their last bits from another CPU's "
               "(docs/performance.md, \"The C library's math functions\")\n", std::strerror(failure));
}

}  // namespace flapsim::cli
