#include "pipeline/app/cli/option_checks.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

namespace flapsim::cli {

CLI::Validator whole_number(long lo, long hi) {
  const std::string range = std::to_string(lo) + (hi > lo ? " to " + std::to_string(hi) : std::string());
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        errno = 0;
        char* end = nullptr;
        const long v = std::strtol(text.c_str(), &end, 10);
        if (text.empty() || end == text.c_str() || *end != '\0' || errno != 0 || v < lo || v > hi)
          return "'" + text + "' is not a whole number from " + range;
        return "";
      },
      "INT in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]", "WHOLE_NUMBER");
}

CLI::Validator positive_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (text.empty() || end == text.c_str() || *end != '\0' || !std::isfinite(v) || !(v > 0.0))
          return "'" + text + "' is not a number > 0";
        return "";
      },
      "NUMBER > 0", "POSITIVE_NUMBER");
}

CLI::Validator non_empty_option() {
  return CLI::Validator(
      [](std::string& text) { return text.empty() ? std::string("must not be empty (an unset shell variable?)") : std::string(); },
      "", "NONEMPTY");
}

}  // namespace flapsim::cli
