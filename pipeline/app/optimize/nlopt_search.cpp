#include "pipeline/app/optimize/nlopt_search.hpp"

#include <nlopt.h>

#include <algorithm>
#include <exception>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>

namespace flapsim::optimize {

namespace {

// What the C callbacks share: the scaling, the values of the points seen, the first error,
// and the number of distinct points the search may evaluate.
struct Context {
  std::vector<double> lo{}, hi{};
  const Evaluate* evaluate = nullptr;
  std::map<std::vector<double>, PointValue> seen{};  // by the point in its own units
  std::exception_ptr error{};
  nlopt_opt opt = nullptr;
  std::size_t max_points = 0;
  bool max_points_reached = false;  // NLopt asked for a new point past max_points: stopped
};

std::vector<double> unscale(const Context& c, const double* u) {
  std::vector<double> x(c.lo.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = std::clamp(c.lo[i] + u[i] * (c.hi[i] - c.lo[i]), c.lo[i], c.hi[i]);
  return x;
}

const PointValue* value_at(Context& c, const double* u) {
  if (c.error) return nullptr;
  const std::vector<double> x = unscale(c, u);
  if (const auto it = c.seen.find(x); it != c.seen.end()) return &it->second;
  // --max-evaluations counts the runs: NLopt's own count takes in the points it asks for
  // again (served from `seen`), so that 14 evaluations could list 12 runs.
  if (c.seen.size() >= c.max_points) {
    c.max_points_reached = true;
    nlopt_force_stop(c.opt);
    return nullptr;
  }
  try {
    return &c.seen.emplace(x, (*c.evaluate)(x)).first->second;
  } catch (...) {
    c.error = std::current_exception();
    nlopt_force_stop(c.opt);
    return nullptr;
  }
}

double objective(unsigned, const double* u, double*, void* data) {
  const PointValue* v = value_at(*static_cast<Context*>(data), u);
  return v ? v->objective : 0.0;
}

struct ConstraintData {
  Context* context;
  std::size_t index;
};

double constraint(unsigned, const double* u, double*, void* data) {
  const auto* d = static_cast<ConstraintData*>(data);
  const PointValue* v = value_at(*d->context, u);
  return v && d->index < v->violations.size() ? v->violations[d->index] : 0.0;
}

void check(nlopt_result r, const char* what) {
  if (r < 0) throw std::runtime_error(std::string("NLopt refused the ") + what + ": " + nlopt_result_to_string(r));
}

std::string reason(nlopt_result r) {
  switch (r) {
    case NLOPT_SUCCESS: return "success";
    case NLOPT_STOPVAL_REACHED: return "the objective reached its stop value";
    case NLOPT_FTOL_REACHED: return "the objective changed by less than its tolerance";
    case NLOPT_XTOL_REACHED: return "the step fell below the x tolerance (converged)";
    case NLOPT_MAXEVAL_REACHED: return "the maximum number of evaluations was reached";
    case NLOPT_MAXTIME_REACHED: return "the time limit was reached";
    case NLOPT_ROUNDOFF_LIMITED: return "round-off limited further progress";
    default: return nlopt_result_to_string(r);
  }
}

}  // namespace

std::string algorithm_name(Algorithm a) { return a == Algorithm::bobyqa ? "bobyqa" : "cobyla"; }

SearchResult search(const std::vector<double>& lo, const std::vector<double>& hi, const std::vector<double>& start,
                    std::size_t constraints, const SearchOptions& options, const Evaluate& evaluate) {
  const auto n = static_cast<unsigned>(lo.size());
  Context c{.lo = lo,
            .hi = hi,
            .evaluate = &evaluate,
            .max_points = static_cast<std::size_t>(std::max(options.max_evaluations, 0))};
  std::unique_ptr<nlopt_opt_s, decltype(&nlopt_destroy)> opt(
      nlopt_create(options.algorithm == Algorithm::bobyqa ? NLOPT_LN_BOBYQA : NLOPT_LN_COBYLA, n), &nlopt_destroy);
  if (!opt) throw std::runtime_error("NLopt could not create the optimiser");
  c.opt = opt.get();
  nlopt_srand(20260101);  // no algorithm used here draws random numbers; fixed all the same
  const std::vector<double> zeros(n, 0.0), ones(n, 1.0), xtol(n, options.x_tolerance),
      step(n, options.initial_step);
  check(nlopt_set_lower_bounds(c.opt, zeros.data()), "bounds");
  check(nlopt_set_upper_bounds(c.opt, ones.data()), "bounds");
  check(nlopt_set_max_objective(c.opt, objective, &c), "objective");
  std::vector<ConstraintData> data(constraints);
  for (std::size_t i = 0; i < constraints; ++i) {
    data[i] = {&c, i};
    check(nlopt_add_inequality_constraint(c.opt, constraint, &data[i], 0.0), "constraint");
  }
  check(nlopt_set_xtol_abs(c.opt, xtol.data()), "x tolerance");
  // NLopt's cap counts its asks, repeats included: a bound well above the distinct points'
  // (max_points above), so that only a search that asks for old points over and over meets it.
  const int asks = options.max_evaluations > (std::numeric_limits<int>::max() - 1000) / 10
                       ? std::numeric_limits<int>::max()
                       : 10 * options.max_evaluations + 1000;
  check(nlopt_set_maxeval(c.opt, asks), "maximum of evaluations");
  check(nlopt_set_initial_step(c.opt, step.data()), "initial step");
  std::vector<double> u(n);
  for (unsigned i = 0; i < n; ++i) u[i] = std::clamp((start[i] - lo[i]) / (hi[i] - lo[i]), 0.0, 1.0);
  double best = 0.0;
  const nlopt_result r = nlopt_optimize(c.opt, u.data(), &best);
  if (c.error) std::rethrow_exception(c.error);
  if (r == NLOPT_FORCED_STOP && c.max_points_reached) return {reason(NLOPT_MAXEVAL_REACHED), true};
  if (r < 0 && r != NLOPT_ROUNDOFF_LIMITED) throw std::runtime_error(std::string("NLopt stopped: ") + nlopt_result_to_string(r));
  return {reason(r), r == NLOPT_MAXEVAL_REACHED};
}

}  // namespace flapsim::optimize
