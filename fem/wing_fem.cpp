#include "fem/wing_fem.hpp"

#include "wings/loader/input_error.hpp"

namespace flapsim::fem {

WingFem build_wing_fem(const wings::Wing& wing, const MeshOptions& options) {
  WingFem fem;
  fem.model = wing_structural_model(wing, mesh_wing(wing, options));
  fem.system = assemble(fem.model);
  fem.root_clamp = root_clamp(fem.model.mesh, wing.clamp_y);
  if (fem.root_clamp.num_free() == fem.root_clamp.num_dofs())
    throw InputError(wing.source_file, 0, "planform.clamp_y",
                     "no mesh node lies at or below clamp_y = " + std::to_string(wing.clamp_y * 1e3) +
                         " mm: the root would be free");
  return fem;
}

WingModes wing_modes(const WingFem& fem, int num_modes, bool clamped) {
  ModalOptions opt;
  opt.num_modes = num_modes;
  WingModes out;
  const Constraints c = clamped ? fem.root_clamp : Constraints(fem.model.mesh.num_dofs());
  out.modes = solve_modes(fem.system.stiffness, fem.system.mass, c, opt);
  out.kinds = classify_modes(fem.model.mesh, fem.system, out.modes.shapes, out.modes.frequencies_hz,
                             clamped ? 0.0 : 1e-4);
  return out;
}

}  // namespace flapsim::fem
