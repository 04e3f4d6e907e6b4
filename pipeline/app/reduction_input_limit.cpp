#include "pipeline/app/reduction_input_limit.hpp"

#include <string>

#include "wings/loader/planform_geometry.hpp"

namespace flapsim::app {

InputError reduction_input_error(const wings::Wing& wing, const reduction::ReductionInputLimit& limit) {
  // The clamp is to blame when it holds more than half the span range (the wing file's own
  // warning, wing_file.cpp check_clamp_share), else the mesh.
  const wings::PlanformProperties props = wings::planform_properties(wing.outline);
  const double range = props.span - props.root_y;  // [m]
  const bool clamp = range > 0.0 && (wing.clamp_y - props.root_y) / range > 0.5;
  const std::string what = std::string("the wing cannot be reduced to a beam: ") + limit.what();
  if (clamp) return InputError(wing.source_file, wing.clamp_y_line, "planform.clamp_y", what);
  return InputError(wing.source_file, wing.element_size_line, "mesh.element_size", what);
}

}  // namespace flapsim::app
