#pragma once
/// \file optimize_problem.hpp
/// \brief What `flapsim optimize` is asked (docs/optimize.md): the varied keys with their
/// bounds (`--vary KEY=LO:HI`, the keys `flapsim sweep --vary` takes: a numeric case key,
/// `wing.<key>` or `spring_scale`), the result to maximise (`--maximize RESULT`) and the
/// constraints on results (`--constraint RESULT>=X`, `RESULT<=X`). Results are named by
/// their key in the one results definition (pipeline/app/run_results.hpp), so every
/// number of summary.json can be an objective or a constraint.

#include <cstddef>
#include <string>
#include <vector>

namespace flapsim::optimize {

/// One varied key and its bounds (LO < HI, both finite, in the key's own unit).
struct Bound {
  std::string key;
  double lo = 0.0;
  double hi = 0.0;
};

/// A constraint on a result: `result >= limit` (at_least) or `result <= limit`.
struct Constraint {
  std::size_t result = 0;  ///< index into app::kRunResults
  bool at_least = true;
  double limit = 0.0;
  std::string text;  ///< as given, e.g. "mean_lift_N>=0.0125"

  /// How far a value is from satisfying it (> 0: violated; NaN counts as violated).
  double violation(double value) const;
};

struct Problem {
  std::vector<Bound> bounds;
  std::size_t objective = 0;  ///< index into app::kRunResults (maximised)
  std::vector<Constraint> constraints;
};

/// \brief Parses `KEY=LO:HI`.
/// \throws flapsim::InputError (key "--vary") on bad syntax, a bound that is not a finite
///         number, LO >= HI
Bound parse_bound(const std::string& text);

/// \brief The index in app::kRunResults of a result usable as an objective or constraint:
/// a number or integer a run computes (not an input echoed back, not the wall time, which
/// differs from run to run).
/// \param option the option named in the error ("--maximize", "--constraint")
/// \throws flapsim::InputError naming the option and listing the usable results
std::size_t parse_result(const std::string& name, const std::string& option);

/// \brief Parses `RESULT>=X` or `RESULT<=X`.
/// \throws flapsim::InputError (key "--constraint") on bad syntax, an unknown result or a
///         limit that is not a finite number
Constraint parse_constraint(const std::string& text);

/// \brief The results usable as objectives, comma-separated (for messages and --help).
std::string usable_results();

}  // namespace flapsim::optimize
