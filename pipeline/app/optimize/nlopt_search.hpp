#pragma once
/// \file nlopt_search.hpp
/// \brief The search of `flapsim optimize`, done by NLopt (S. G. Johnson, The NLopt
/// nonlinear-optimization package, https://github.com/stevengj/nlopt; Debian
/// libnlopt-cxx-dev). Derivative-free local methods for a bounded problem:
///  - BOBYQA (M. J. D. Powell, "The BOBYQA algorithm for bound constrained optimization
///    without derivatives", Cambridge report DAMTP 2009/NA06): a quadratic model fitted to
///    2n+1 points and refined in a trust region; bounds only. The default without
///    constraints: a smooth objective such as mean lift against a phase is near-quadratic
///    about its optimum, which BOBYQA finds in few evaluations.
///  - COBYLA (M. J. D. Powell, "A direct search optimization method that models the
///    objective and constraint functions by linear interpolation", 1994): linear models of
///    the objective and of each constraint; the default with constraints (BOBYQA takes none).
/// The variables are scaled to [0, 1] over their bounds, so one step and one tolerance,
/// fractions of each range, serve keys of any unit. No random numbers: the same values of
/// the objective give the same points (a rerun that reuses every evaluation retraces the
/// search exactly).

#include <functional>
#include <string>
#include <vector>

namespace flapsim::optimize {

enum class Algorithm { bobyqa, cobyla };

/// "bobyqa", "cobyla".
std::string algorithm_name(Algorithm a);

struct SearchOptions {
  Algorithm algorithm = Algorithm::bobyqa;
  int max_evaluations = 50;  ///< distinct points evaluated at most (a point asked for again is not run again)
  double x_tolerance = 1e-3;    ///< stop when a step changes every variable by less (fraction of its range)
  double initial_step = 0.25;   ///< the first step of each variable (fraction of its range)
};

/// The objective (to maximise) and the constraints' violations (> 0: violated) at a point.
struct PointValue {
  double objective = 0.0;
  std::vector<double> violations;  ///< one per constraint, each scaled to order one
};

/// Evaluates a point, given in the variables' own units. May throw: the search stops and
/// the exception leaves search().
using Evaluate = std::function<PointValue(const std::vector<double>& x)>;

struct SearchResult {
  std::string stop_reason;  ///< why NLopt stopped, in words
  bool max_evaluations_reached = false;
};

/// \brief Runs NLopt from \p start within [\p lo, \p hi] with \p constraints constraints.
/// Each distinct point is evaluated once (NLopt asks for the objective and each constraint
/// separately).
/// \throws what \p evaluate throws; std::runtime_error when NLopt refuses the problem
SearchResult search(const std::vector<double>& lo, const std::vector<double>& hi, const std::vector<double>& start,
                    std::size_t constraints, const SearchOptions& options, const Evaluate& evaluate);

}  // namespace flapsim::optimize
