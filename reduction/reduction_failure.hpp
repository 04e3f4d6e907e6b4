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

}  // namespace flapsim::reduction
