#include "pipeline/app/optimize/optimize_problem.hpp"

#include <cmath>
#include <limits>

#include "pipeline/app/run_results.hpp"
#include "pipeline/app/sweep/sweep_values.hpp"
#include "wings/loader/input_error.hpp"

namespace flapsim::optimize {

namespace {

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

// A finite number filling the whole text, or nothing.
bool read_number(const std::string& text, double& value) {
  const std::string s = trimmed(text);
  if (s.empty()) return false;
  std::size_t used = 0;
  try {
    value = std::stod(s, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == s.size() && std::isfinite(value);
}

bool usable(const app::ResultDefinition& d) {
  // The wall time differs from run to run: an optimum of it would not be reproducible.
  return (d.kind == app::ResultKind::number || d.kind == app::ResultKind::integer) && d.key != "wall_time_s";
}

}  // namespace

double Constraint::violation(double value) const {
  if (!std::isfinite(value)) return std::numeric_limits<double>::infinity();
  return at_least ? limit - value : value - limit;
}

Bound parse_bound(const std::string& text) {
  const auto bad = [&text](const std::string& why) -> InputError {
    return InputError("", 0, "--vary", "'" + text + "': " + why);
  };
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw bad("expected KEY=LO:HI, e.g. kinematics.rotation_phase=-0.25:0.15");
  Bound b;
  b.key = trimmed(text.substr(0, eq));
  const std::string range = text.substr(eq + 1);
  const auto colon = range.find(':');
  if (b.key.empty() || colon == std::string::npos || range.find(':', colon + 1) != std::string::npos)
    throw bad("expected KEY=LO:HI (two bounds), e.g. kinematics.rotation_phase=-0.25:0.15");
  // A text key's words (numerics.leading_edge=none:shed): no number lies between them.
  if (sweep::is_word_value(trimmed(range.substr(0, colon))) &&
      sweep::is_word_value(trimmed(range.substr(colon + 1))))
    throw bad(
        "optimize searches a number between two bounds, and a word is the value of a text key: compare "
        "words with a sweep (flapsim sweep CASE.toml --vary " +
        b.key + "=" + trimmed(range.substr(0, colon)) + "," + trimmed(range.substr(colon + 1)) + ")");
  if (!read_number(range.substr(0, colon), b.lo)) throw bad("the lower bound is not a finite number");
  if (!read_number(range.substr(colon + 1), b.hi)) throw bad("the upper bound is not a finite number");
  if (!(b.lo < b.hi)) throw bad("the lower bound must be below the upper bound (LO < HI)");
  return b;
}

std::string usable_results() {
  std::string s;
  for (const app::ResultDefinition& d : app::kRunResults)
    if (usable(d)) s += (s.empty() ? "" : ", ") + std::string(d.key);
  return s;
}

std::size_t parse_result(const std::string& name, const std::string& option) {
  for (std::size_t i = 0; i < app::kRunResults.size(); ++i) {
    const app::ResultDefinition& d = app::kRunResults[i];
    if (d.key != name) continue;
    if (usable(d)) return i;
    throw InputError("", 0, option,
                     "'" + name + "' cannot be optimised (" +
                         (d.key == "wall_time_s" ? std::string("it differs from run to run")
                                                 : std::string("not a number")) +
                         "); one of: " + usable_results());
  }
  throw InputError("", 0, option, "'" + name + "' is not a result of a run; one of: " + usable_results());
}

Constraint parse_constraint(const std::string& text) {
  Constraint c;
  c.text = text;
  auto op = text.find(">=");
  c.at_least = true;
  if (op == std::string::npos) {
    op = text.find("<=");
    c.at_least = false;
  }
  if (op == std::string::npos) {
    // `--constraint mean_lift_N>=0.002` unquoted: the shell takes '>' for a redirection, writes
    // a file named '=0.002' and passes the name alone.
    const bool name_alone = text.find_first_of("<>= ") == std::string::npos && !text.empty();
    throw InputError("", 0, "--constraint",
                     "'" + text + "': expected RESULT>=X or RESULT<=X, e.g. mean_lift_N>=0.0125" +
                         (name_alone ? std::string("; quote it, --constraint '") + text +
                                           ">=X': unquoted, the shell reads '>' as a redirection (and "
                                           "writes a file named '=X' in the current folder)"
                                     : std::string()));
  }
  c.result = parse_result(trimmed(text.substr(0, op)), "--constraint");
  if (!read_number(text.substr(op + 2), c.limit))
    throw InputError("", 0, "--constraint", "'" + text + "': the limit is not a finite number");
  return c;
}

}  // namespace flapsim::optimize
