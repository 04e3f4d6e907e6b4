#pragma once
/// \file bounds_check.hpp
/// \brief The start and the bounds of `flapsim optimize`, checked before anything is
/// written or run (docs/optimize.md, "How it searches"): the start, and each key at either
/// bound and at an inner value that is no whole number (1/π of the way; the other keys at
/// the start), are resolved and checked as a sweep's cases are; then a key that changes
/// nothing at those points is refused as a sweep refuses it
/// (sweep/keys_that_change_nothing.hpp): a mesh size a FEM case's own key sets,
/// output.vtk_every (the optimisation's --vtk-every sets it), a key whose points all have
/// the same inputs hash.

#include <vector>

#include "pipeline/app/optimize/optimize_problem.hpp"
#include "pipeline/app/optimize/point_evaluator.hpp"

namespace flapsim::optimize {

/// \brief Checks the start and the bounds of \p problem.
/// \param start     the start, one value per bound
/// \param vtk_every the optimisation's --vtk-every (every run's ParaView interval)
/// \throws flapsim::InputError: a point that does not resolve (a key the case does not have,
///         a bound that makes an invalid case, an integer key) named '--vary'; a key that
///         changes nothing named by the key at the case file, its message starting
///         "--vary KEY=LO:HI"
void check_start_and_bounds(const PointEvaluator& evaluator, const Problem& problem,
                            const std::vector<double>& start, int vtk_every);

}  // namespace flapsim::optimize
