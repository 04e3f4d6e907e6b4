#include "pipeline/app/reduction_input_limit.hpp"

#include <string>

#include "wings/loader/planform_geometry.hpp"

namespace flapsim::app {

InputError reduction_input_error(const wings::Wing& wing, const reduction::ReductionInputLimit& limit) {
  // The clamp is to blame when it holds most of the span range (the wing file's own warning,
  // wing_file.cpp check_clamp_share), else the mesh.
  const bool clamp = wings::clamp_span_share(wings::planform_properties(wing.outline), wing.clamp_y) >
                     wings::kClampHoldsMost;
  const std::string what = std::string("the wing cannot be reduced to a beam: ") + limit.what();
  if (clamp) return InputError(wing.source_file, wing.clamp_y_line, "planform.clamp_y", what);
  return InputError(wing.source_file, wing.element_size_line, "mesh.element_size", what);
}

}  // namespace flapsim::app
