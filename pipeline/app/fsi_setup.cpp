#include "pipeline/app/fsi_setup.hpp"

#include "pipeline/app/lattice_surface.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "mbd/wing_kinematics.hpp"
#include "pipeline/app/fem_structure_setup.hpp"
#include "pipeline/app/structure_source.hpp"
#include "reduction/linear_chain.hpp"
#include "uvlm/leading_edge_sheet.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/planform_geometry.hpp"
#include "wings/loader/wing_file.hpp"
#include "wings/loader/wing_mass_properties.hpp"

namespace flapsim::app {

using fsi::ExternalLoads;
using fsi::FsiModel;
using io::Case;

mbd::ChainModel make_rigid_chain(const wings::Wing& wing) {
  const wings::PlanformProperties p = wings::planform_properties(wing.outline);
  const wings::WingInertia w = wings::estimate_wing_inertia(wing);
  mbd::ChainBody body;
  body.length = p.span;
  if (w.mass > 1e-12) {
    body.mass = w.mass;
    body.center_of_mass = Eigen::Vector3d(w.center_of_mass.x(), w.center_of_mass.y(), 0.0);
    body.inertia = w.inertia;
  } else {  // a massless wing: a token mass at the outline's centroid
    body.mass = 1e-12;
    body.center_of_mass = Eigen::Vector3d(p.centroid.x(), p.centroid.y(), 0.0);
  }
  body.outboard_joint = Eigen::Vector3d(0.0, p.span, 0.0);
  mbd::ChainModel chain;
  chain.bodies = {body};
  chain.joints = {mbd::ChainJoint{}};
  chain.root = mbd::RootAttachment::rigid;
  return chain;
}

Eigen::Vector3d span_point_velocity(const mbd::WingKinematics& kinematics, double radius, double t) {
  const mbd::BasePose pose = kinematics.pose(t);
  return pose.velocity + pose.angular_velocity.cross(pose.rotation * Eigen::Vector3d(0.0, radius, 0.0));
}

double mean_speed_at_radius(const mbd::WingKinematics& kinematics, double radius, int samples) {
  const double period = 1.0 / kinematics.frequency;
  // A revolving wing: the period after its ramp (the steady revolution the coefficients of
  // revolving-wing experiments refer to); a flapping wing: the first period.
  const double start = kinematics.revolution.active() ? kinematics.revolution.ramp : 0.0;
  double sum = 0.0;
  for (int i = 0; i < samples; ++i)
    sum += span_point_velocity(kinematics, radius, start + period * i / samples).norm();
  return sum / samples;
}

double stroke_disk_area(const mbd::WingKinematics& kinematics, double span, int samples) {
  // A revolving wing sweeps the whole circle.
  if (kinematics.revolution.active()) return std::numbers::pi * span * span;
  const double period = 1.0 / kinematics.frequency;
  std::vector<Eigen::Vector3d> axis(static_cast<std::size_t>(samples));
  for (int i = 0; i < samples; ++i)
    axis[i] = kinematics.pose(period * i / samples).rotation * Eigen::Vector3d::UnitY();
  double stroke = 0.0;  // Φ [rad]
  for (int i = 0; i < samples; ++i)
    for (int j = i + 1; j < samples; ++j)
      stroke = std::max(stroke, std::atan2(axis[i].cross(axis[j]).norm(), axis[i].dot(axis[j])));
  return 0.5 * stroke * span * span;
}

namespace {

uvlm::VortexLatticeModel lattice_model(const Case& c, double mean_chord, double span, std::int64_t steps) {
  uvlm::VortexLatticeModel m;
  m.chordwise = c.numerics.chordwise_panels;
  m.spanwise = c.numerics.spanwise_panels;
  m.core.model = c.numerics.core_model;
  m.core.radius = c.numerics.core_radius * mean_chord;
  m.wake_model = c.numerics.free_wake ? uvlm::WakeModel::Free : uvlm::WakeModel::Prescribed;
  m.wake_integrator = c.numerics.wake_order == 2 ? uvlm::WakeIntegrator::AdamsBashforth2
                                                 : uvlm::WakeIntegrator::Euler;
  m.load_method = c.numerics.load_method;
  m.leading_edge = c.numerics.leading_edge;
  m.lesp_critical = c.numerics.lesp_critical;
  m.sheet_merge_steps = c.numerics.sheet_merge_steps;
  m.sheet_merge_spread_steps = c.numerics.sheet_merge_spread_steps;
  if (c.numerics.leading_edge == uvlm::LeadingEdge::Shed) m.sheet_core_radius = c.numerics.sheet_core_radius * mean_chord;
  m.single_precision_wake = c.numerics.wake_precision == io::WakePrecision::Single;
  m.first_order_circulation_rate = c.numerics.circulation_rate == io::CirculationRate::Bdf1;
  m.max_wake_rows = c.numerics.wake_max_rows;
  m.wake_capacity = c.numerics.wake_max_rows > 0 ? c.numerics.wake_max_rows : static_cast<int>(steps);  // <= 1e8
  // A shed leading edge's sheet is not shortened with the wake (wake_max_rows).
  if (c.numerics.leading_edge == uvlm::LeadingEdge::Shed)
    m.sheet_capacity = uvlm::sheet_ring_capacity(static_cast<double>(steps));
  m.core_growth.enabled = c.numerics.core_growth;
  m.core_growth.squire_a1 = c.numerics.core_growth_a1;
  m.core_growth.kinematic_viscosity = c.numerics.kinematic_viscosity;
  m.skin_friction_viscosity = c.numerics.laminar_skin_friction ? c.numerics.kinematic_viscosity : 0.0;
  m.near_wing_core = c.numerics.near_wing_core * mean_chord;
  // The wake younger than a quarter cycle is summed anew at every solve of a step, the
  // older one may be held within it (uvlm/old_wake_hold.hpp; docs/fsi.md, "One coupled step").
  m.young_wake_rows = std::max(1, c.numerics.steps_per_cycle / 4);
  m.frozen_wake_age = c.numerics.frozen_wake_cycles / c.kinematics.frequency;
  m.far_wake_age = c.numerics.far_wake_cycles / c.kinematics.frequency;
  if (m.far_wake_age > 0.0) {
    m.far_wake_disk_area = stroke_disk_area(c.kinematics, span);
    // A wing whose span axis keeps one direction (a constant sweep angle and no deviation:
    // it pitches or plunges only) sweeps no disk: momentum theory's induced velocity
    // sqrt(T/(2 rho A)) has no area to act on. Refused as bad input rather than given a
    // made-up area (docs/case_file.md, far_wake_cycles).
    if (!(m.far_wake_disk_area > 0.0))
      throw InputError(c.file, c.line_of("numerics.far_wake_cycles"), "numerics.far_wake_cycles",
                       "the convected far wake needs the disk the wing's span sweeps (momentum theory), and this "
                       "wing's span axis keeps one direction over the cycle (no sweep or deviation motion: stroke "
                       "angle 0): set far_wake_cycles = 0 (or give the wing a sweep motion)");
  }
  m.wake_sum = c.numerics.wake_sum;
  m.tree_tolerance = c.numerics.tree_tolerance;
  if (c.numerics.steady) {  // the straight wake of the steady lattice: one row, 10⁴ mean chords
    m.steady_wake_length = 1e4 * mean_chord;
    m.wake_capacity = 1;
    m.max_wake_rows = 0;
    m.far_wake_age = m.frozen_wake_age = 0.0;
  }
  return m;
}

ExternalLoads point_loads(const Case& c) {
  if (c.loads.empty()) return {};
  const std::vector<io::PointLoad> loads = c.loads;
  const double f = c.kinematics.frequency;
  return [loads, f](double t, mbd::Loads& out) {
    const double s = f * t;
    for (const auto& l : loads) {
      Eigen::Vector3d force, moment;
      for (int i = 0; i < 3; ++i) {
        force(i) = l.force[i].at_phase(s).value;
        moment(i) = l.moment[i].at_phase(s).value;
      }
      out.add_force(l.body - 1, l.point, force, l.frame);
      out.add_moment(l.body - 1, moment, l.frame);
    }
  };
}

}  // namespace

std::optional<wings::Wing> load_case_wing(const Case& c,
                                          const std::vector<std::pair<std::string, std::string>>& overrides) {
  if (c.wing_file.empty()) {
    if (!overrides.empty())
      throw InputError(c.file, 0, "wing." + overrides.front().first,
                       "the case names no wing file whose key could be set");
    return std::nullopt;
  }
  if (overrides.empty()) return wings::load_wing_file(c.wing_file);
  wings::TomlTable root = wings::parse_toml_file(c.wing_file);
  root.apply_overrides(overrides);
  return wings::read_wing(root);
}

void check_lattice_can_follow(const Case& c, const wings::Wing& wing) {
  // An outline with a gap along the chord (a slot): the lattice would cover it and give the
  // lift of a wing that is not there (wings::LatticeGap, docs/wing_file.md).
  if (!c.air.enabled || !(wing.lattice_gap.area_share > 0.0)) return;
  const wings::LatticeGap& g = wing.lattice_gap;
  throw InputError(g.file, g.line, g.key,
                   g.description + ". The lattice cannot follow this outline, so this case cannot run in air. "
                   "To run it anyway with the gap covered: a wing file with the gap closed for the case and "
                   "the chain of this wing from 'flapsim reduce' (the FEM follows the outline) with --chain "
                   "(docs/wing_file.md, \"Outlines the vortex lattice cannot follow\")");
}

std::string soft_chain_warning(const Case& c, const FsiSetup& setup) {
  const mbd::ChainModel& chain = setup.chain();
  if (c.structure.kind != Case::Structure::Kind::Flexible || chain.num_dofs() == 0) return "";
  if (!c.kinematics.oscillates()) return "";  // a wing that only revolves: no wingbeat drives it
  double f1 = 0.0;
  bool bending = false;
  try {
    const std::vector<reduction::ChainMode> modes = reduction::LinearChain(chain).modes();
    if (modes.empty()) return "";
    f1 = modes.front().frequency_hz;
    bending = modes.front().is_bending();
  } catch (const std::exception&) {
    return "";  // a chain bent at rest: no linear modes about a straight shape
  }
  const double f = c.kinematics.frequency;
  if (!(f1 < f)) return "";
  char text[800];
  std::snprintf(text, sizeof text,
                "the chain's first natural frequency, %.3g Hz (%s), is below the wingbeat frequency %.3g Hz: "
                "the wing is driven above its first resonance and will bend further than its linear joint "
                "springs represent; such runs usually stop with a numerical failure. Run the wing's own "
                "FEM, geometrically nonlinear (structure.kind = \"fem\"), stiffen the wing (a thicker "
                "membrane, veins), lower frequency_hz, or scale the springs (--spring-scale; frequencies "
                "scale by its square root)",
                f1, bending ? "bending" : "torsion", f);
  return text;
}

FsiSetup build_fsi_setup(const Case& c, const SetupOptions& options) {
  FsiSetup s;
  s.period = 1.0 / c.kinematics.frequency;
  s.steps_per_cycle = c.numerics.steps_per_cycle;
  s.steps = c.numerics.total_steps();
  if (s.steps > io::kMaxTotalSteps)
    throw InputError(c.file, c.line_of("numerics.cycles"), "numerics.cycles",
                     std::to_string(s.steps) + " time steps, more than the maximum " + std::to_string(io::kMaxTotalSteps));
  s.dt = s.period / s.steps_per_cycle;
  s.wing = load_case_wing(c, options.wing_overrides);
  if (c.air.enabled && !s.wing)
    throw InputError(c.file, c.line_of("wing"), "wing",
                     "a run in air needs the wing's outline for the vortex lattice: name a wing "
                     "file, or set air = \"none\" for a vacuum run of the chain");
  if (s.wing) check_lattice_can_follow(c, *s.wing);

  FsiModel& m = s.model;
  auto chain_structure = std::make_shared<fsi::ChainStructureModel>();
  fsi::ChainStructureModel& cs = *chain_structure;
  StructureChoice structure = choose_structure(c, options.chain_file, s.wing ? &*s.wing : nullptr);
  cs.chain = std::move(structure.chain);
  s.structure_source = structure.description;
  s.chain_file = structure.chain_file;
  s.chain_fem = std::move(structure.chain_fem);
  s.reduced_fem_dofs = structure.reduced_fem_dofs;
  s.spring_scale = options.spring_scale;
  if (!(options.spring_scale > 0.0) || !std::isfinite(options.spring_scale))
    throw InputError("", 0, "--spring-scale", "must be a positive number");
  if (options.spring_scale != 1.0 && cs.chain.num_dofs() > 0) {
    cs.chain.scale_stiffness(options.spring_scale);
    char buf[64];
    std::snprintf(buf, sizeof buf, ", springs x %g", options.spring_scale);
    s.structure_source += buf;
  }
  if (c.structure.kind == Case::Structure::Kind::Flexible && cs.chain.num_bodies() != c.structure.bodies)
    s.structure_source += " (" + std::to_string(cs.chain.num_bodies()) + " bodies; the case says " +
                          std::to_string(c.structure.bodies) + ")";
  for (std::size_t i = 0; i < c.loads.size(); ++i)
    if (const auto& l = c.loads[i]; l.body > cs.chain.num_bodies())
      throw InputError(c.file, c.line_of("loads." + std::to_string(i + 1) + ".body"), "loads.body",
                       "body " + std::to_string(l.body) + " is outside the chain of " +
                           std::to_string(cs.chain.num_bodies()) + " bodies");
  for (std::size_t i = 0; i < c.markers.size(); ++i)
    if (const auto& mk = c.markers[i]; mk.body > cs.chain.num_bodies())
      throw InputError(c.file, c.line_of("markers." + std::to_string(i + 1) + ".body"), "markers.body",
                       "marker '" + mk.name + "' on body " + std::to_string(mk.body) +
                           " is outside the chain of " + std::to_string(cs.chain.num_bodies()) + " bodies");

  cs.chain.gravity = c.structure.gravity;
  cs.integrator.rho_infinity = c.numerics.rho_infinity;
  cs.integrator.substeps = c.numerics.structure_substeps;
  const int n = cs.chain.num_dofs();
  auto initial = [&](const std::vector<double>& values, int line, const char* key) {
    if (values.empty()) return Eigen::VectorXd();
    if (static_cast<int>(values.size()) != n)
      throw InputError(c.file, line, std::string("structure.") + key,
                       "expected " + std::to_string(n) + " values (bend and twist of each of the " +
                           std::to_string(n / 2) + " joints " + std::to_string(cs.chain.first_jointed_body() + 1) +
                           " ... " + std::to_string(cs.chain.num_bodies()) + "), found " +
                           std::to_string(values.size()));
    return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(values.data(), n));
  };
  cs.initial_q = initial(c.structure.initial_angles, c.structure.initial_angles_line, "initial_angles_deg");
  cs.initial_v = initial(c.structure.initial_rates, c.structure.initial_rates_line, "initial_rates_deg_per_s");
  cs.base_motion = mbd::make_base_motion(c.kinematics);
  cs.external_loads = point_loads(c);
  m.frequency = c.kinematics.frequency;
  m.coupling.method = c.numerics.coupling == io::CouplingMethod::InterfaceQuasiNewton
                          ? fsi::CouplingMethod::InterfaceQuasiNewton
                          : fsi::CouplingMethod::Aitken;
  m.coupling.max_iterations = c.numerics.max_coupling_iterations;
  m.coupling.reuse_steps = c.numerics.coupling_reuse_steps;
  m.coupling.tolerance = c.numerics.coupling_tolerance;
  m.coupling.added_mass = c.numerics.added_mass;
  m.air = c.air.enabled;
  m.density = c.air.density;
  m.free_stream = c.air.freestream;

  if (m.air) {
    const wings::PlanformProperties p = wings::planform_properties(s.wing->outline);
    uvlm::PlanformGridOptions g;
    g.chordwise = c.numerics.chordwise_panels;
    g.spanwise = c.numerics.spanwise_panels;
    g.chordwise_spacing = c.numerics.chordwise_spacing;
    g.spanwise_spacing = c.numerics.spanwise_spacing;
    s.grid = uvlm::make_planform_grid(s.wing->outline, g);
    shape_lattice_surface(*s.wing, *s.grid);  // [surface]: twist, camber, dihedral (lattice-only)
    m.lattice = lattice_model(c, p.mean_chord, p.span, s.steps);
    cs.attachment = fsi::attach_wing(cs.chain, s.grid->nodes, g.chordwise, g.spanwise);
    s.reference.area = p.area;
    s.reference.span = p.span;
    s.reference.mean_chord = p.mean_chord;
    s.reference.r2 = p.r2;
    LiftReference& ref = s.reference;
    ref.flapping_speed = mean_speed_at_radius(c.kinematics, p.r2 * p.span);
    ref.free_stream_speed = c.air.freestream.norm();
    if (ref.free_stream_speed > 0.0) {
      ref.kind = LiftReference::Kind::FreeStream;
      ref.speed = ref.free_stream_speed;
      ref.drag_direction = c.air.freestream / ref.free_stream_speed;
      const Eigen::Vector3d up = Eigen::Vector3d::UnitZ() - ref.drag_direction.z() * ref.drag_direction;
      if (up.norm() < 1e-9)
        throw InputError(
            c.file, c.line_of("air.freestream"), "air.freestream",
            "a vertical free stream leaves lift and drag undefined (lift is normal to it, "
            "in the vertical plane through it); for a climb or a descent give the stream a "
            "horizontal part and read the vertical force, summary.json's mean_Fz_N (docs/case_file.md, "
            "[air])");
      ref.lift_direction = up.normalized();
    } else {
      ref.kind = LiftReference::Kind::Flapping;
      ref.speed = ref.flapping_speed;
    }
    // Kinematics whose speed overflows (a sweep amplitude of 1e300 degrees: `check` passed it
    // with a Mach warning, `run` stopped at its first step with exit 3) are bad input.
    if (!std::isfinite(ref.flapping_speed)) {
      const auto t = c.line_of("kinematics.sweep");
      throw InputError(
          c.file, t, "kinematics",
          "the span axis's speed at r2 R is not finite: an angle's amplitude or a rate overflows "
          "(sweep, deviation, rotation in degrees, a translation in metres)");
    }
    // A span axis that does not move (a wing that only pitches about it) moves by round-off
    // (2e-17 m/s, CL 8e32): compared with the speed of a span turning a radian a period.
    const double turning_span_speed = 2.0 * std::numbers::pi * c.kinematics.frequency * p.span;  // [m/s]
    if (!(ref.speed > 1e-9 * turning_span_speed)) {
      char text[400];
      std::snprintf(text, sizeof text,
                    "neither a free stream nor a moving span: the point at r2 R on the span axis moves at "
                    "%.3g m/s over a cycle (a wing that only pitches about its span axis), no reference "
                    "speed for the coefficients; give the case a free stream, a sweep or a deviation",
                    ref.speed);
      throw InputError(c.file, c.line_of("air.freestream"), "air.freestream", text);
    }
  }
  if (c.structure.kind == Case::Structure::Kind::Fem) {
    // The FEM's shell is the flat planform and the lattice rides on it: a shaped lattice
    // surface would sit off the shell it is attached to (docs/uvlm.md, "Twist, camber and dihedral").
    if (s.wing && !s.wing->surface.flat())
      throw InputError(s.wing->source_file, s.wing->surface.line, "surface",
                       "twist, camber and dihedral shape the vortex lattice only; structure.kind = \"fem\" "
                       "runs the flat FEM of the planform: use kind = \"rigid\" or \"flexible\" (the chain), "
                       "or remove [surface]");
    const double span = wings::planform_properties(s.wing->outline).span;
    s.fem_structure = make_fem_structure(c, *s.wing, cs.base_motion,
                                         s.grid ? s.grid->nodes : Eigen::Matrix3Xd(3, 0), span);
    const fem::Mesh& mesh = s.fem_structure->structural.mesh;
    s.structure_source += " (" + std::to_string(mesh.num_nodes()) + " nodes, " +
                          std::to_string(mesh.triangles.size()) + " triangles, " +
                          std::to_string(mesh.beams.size()) + " vein elements)";
    m.structure = s.fem_structure;
  } else {
    m.structure = chain_structure;
  }
  s.chain_structure = std::move(chain_structure);
  return s;
}

}  // namespace flapsim::app
