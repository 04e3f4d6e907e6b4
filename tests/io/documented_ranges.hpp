#pragma once
/// \file documented_ranges.hpp
/// \brief What a loaded wing, case or chain may hold (docs/wing_file.md, docs/case_file.md,
/// docs/multibody.md): the fuzzers' test of a mutant that loaded ("" or the value outside
/// its range), shared by tests/io/test_fuzz_loaders.cpp and tests/app/test_fuzz_sweep_arguments.cpp.

#include <cmath>
#include <string>

#include "mbd/chain_model.hpp"
#include "pipeline/io/case_file.hpp"
#include "pipeline/io/case_model.hpp"
#include "wings/loader/mesh_budget.hpp"
#include "wings/loader/wing_file.hpp"

namespace flapsim::test {

namespace w = flapsim::wings;
namespace io = flapsim::io;

// --- documented ranges of what loaded ----------------------------------------------------------

inline bool normal_or_zero(double v) { return v == 0.0 || std::fpclassify(v) == FP_NORMAL; }
inline bool positive(double v) { return v > 0.0 && std::fpclassify(v) == FP_NORMAL; }

inline std::string wing_out_of_range(const w::Wing& wing) {
  if (!positive(wing.span)) return "span";
  if (wing.outline.size() < 3) return "outline size";
  for (const auto& p : wing.outline)
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !normal_or_zero(p.x()) || !normal_or_zero(p.y()))
      return "outline point";
  if (!positive(wing.membrane.thickness)) return "membrane.thickness";
  const auto material_ok = [](const w::Material& m) {
    return positive(m.youngs_modulus) && positive(m.density) && m.poisson_ratio > -1.0 && m.poisson_ratio < 0.5;
  };
  if (!material_ok(wing.membrane.material)) return "membrane material";
  if (!(wing.membrane.nonstructural_mass_per_area >= 0.0) || !std::isfinite(wing.membrane.nonstructural_mass_per_area))
    return "nonstructural_mass_per_area";
  for (const auto& v : wing.veins) {
    if (v.points.size() < 2) return "vein points";
    if (!material_ok(v.material)) return "vein material";
    for (const auto* s : {&v.root_section, &v.tip_section}) {
      if (s->shape == w::Section::Shape::HollowCircle &&
          (!positive(s->outer_diameter) || !positive(s->wall) || s->wall > 0.5 * s->outer_diameter * (1 + 1e-12)))
        return "vein section";
      if (s->shape == w::Section::Shape::Rectangle && (!positive(s->width) || !positive(s->height)))
        return "vein section";
    }
  }
  if (!positive(wing.mesh.element_size) || !positive(wing.mesh.vein_element_size)) return "mesh sizes";
  if (w::estimated_mesh_elements(wing) > w::kMaxMeshElements) return "mesh budget";
  return "";
}

inline std::string case_out_of_range(const io::Case& c) {
  const auto& n = c.numerics;
  if (!positive(c.kinematics.frequency) || c.kinematics.frequency > io::kMaxFrequencyHz) return "frequency_hz";
  if (!(std::abs(c.kinematics.rotation_phase) <= 1.0)) return "rotation_phase";
  if (n.steps_per_cycle < 4 || n.cycles < 1 || n.total_steps() > io::kMaxTotalSteps) return "steps";
  if (n.chordwise_panels < 1 || n.chordwise_panels > 1000 || n.spanwise_panels < 1 || n.spanwise_panels > 1000)
    return "panels";
  if (!(n.core_radius > 0.0 && n.core_radius <= 1.0) || !positive(n.core_radius)) return "core_radius";
  if (!(n.coupling_tolerance > 0.0 && n.coupling_tolerance < 1.0) || !positive(n.coupling_tolerance))
    return "coupling_tolerance";
  if (n.wake_max_rows < 0 || n.max_coupling_iterations < 1) return "wake/coupling counts";
  if (c.air.enabled && !positive(c.air.density)) return "air.density";
  if (!c.air.freestream.allFinite()) return "air.freestream";
  if (c.name.empty() || io::folder_name_of(c.name) != c.name) return "name";
  if (c.structure.bodies < 1 || c.structure.bodies > 1000) return "structure.bodies";
  if (c.output.vtk_every < 0) return "vtk_every";
  return "";
}

inline std::string chain_out_of_range(const flapsim::mbd::ChainModel& chain) {
  if (chain.bodies.empty() || chain.joints.size() != chain.bodies.size()) return "bodies";
  for (const auto& b : chain.bodies) {
    if (!positive(b.length) || !positive(b.mass)) return "length or mass";
    if (!b.inertia.allFinite() || !b.center_of_mass.allFinite() || !b.outboard_joint.allFinite()) return "finite";
  }
  for (const auto& j : chain.joints)
    for (double v : {j.bend_stiffness, j.twist_stiffness, j.bend_damping, j.twist_damping})
      if (!(v >= 0.0) || !std::isfinite(v) || !normal_or_zero(v)) return "joint springs";
  return "";
}

}  // namespace flapsim::test
