#pragma once
/// \file reduction_failure.hpp
/// \brief A wing that cannot be reduced with the options given (a section with too few
/// FEM nodes, a singular compliance). The message is meant for the user: positions in
/// mm from the pivot, joints and bodies numbered from 1 as in the chain file. The
/// command line turns it into exit status 3 (a numerical failure, README "Exit status").

#include <stdexcept>
#include <string>

namespace flapsim::reduction {

class ReductionFailure : public std::runtime_error {
 public:
  explicit ReductionFailure(const std::string& what) : std::runtime_error(what) {}
};

/// \brief A wing whose clamp or mesh leaves too little free to reduce: the clamp reaching the
/// loaded tip zone, too few free nodes to load, no beam cell outside the tip zone. The
/// wing file is at fault, not the numerics: the commands report it as bad input (exit 2)
/// naming clamp_y or [mesh] element_size (pipeline/app/reduction_input_limit.hpp).
class ReductionInputLimit : public ReductionFailure {
 public:
  explicit ReductionInputLimit(const std::string& what) : ReductionFailure(what) {}
};

}  // namespace flapsim::reduction
