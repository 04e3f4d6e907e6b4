#pragma once
/// \file reduction_input_limit.hpp
/// \brief A reduction that the wing file's clamp or mesh leaves too little to work with
/// (reduction::ReductionInputLimit) reported as the bad input it is: an InputError of the
/// wing file at clamp_y (when the clamp holds more than half the span range) or at [mesh]
/// element_size, exit status 2. It was a "numerical failure" (exit 3) of `reduce`, `run`
/// and `check` (a 40 mm wing clamped to 39.9 mm; a 10 mm chord meshed at 20 mm).

#include "reduction/reduction_failure.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/wing_model.hpp"

namespace flapsim::app {

/// \brief The InputError of \p wing for \p limit: file, line and key of clamp_y or element_size.
InputError reduction_input_error(const wings::Wing& wing, const reduction::ReductionInputLimit& limit);

/// \brief Runs \p compute (a reduction step of \p wing); a ReductionInputLimit becomes
/// reduction_input_error. Anything else passes unchanged.
template <typename F>
decltype(auto) reduce_wing_input_checked(const wings::Wing& wing, F&& compute) {
  try {
    return compute();
  } catch (const reduction::ReductionInputLimit& e) {
    throw reduction_input_error(wing, e);
  }
}

}  // namespace flapsim::app
