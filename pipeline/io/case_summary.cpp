#include "pipeline/io/case_summary.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "mbd/angle_units.hpp"
#include "wings/loader/toml_reader.hpp"

namespace flapsim::io {

namespace {

template <typename... Args>
std::string line(const char* format, Args... args) {
  char buf[320];
  std::snprintf(buf, sizeof buf, format, args...);
  return std::string(buf) + "\n";
}

/// %g of a number, without a newline.
std::string line_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

}  // namespace

std::optional<double> geometric_angle_of_attack(const mbd::WingKinematics::Angles& a, double frequency_hz) {
  const double dphi = a.sweep.rate;
  if (std::abs(dphi) < 1e-9 + 1e-6 * 2.0 * std::numbers::pi * std::abs(frequency_hz)) return std::nullopt;
  return dphi < 0.0 ? a.rotation.value : std::numbers::pi - a.rotation.value;
}

std::optional<AngleInStream> angle_of_attack_in_stream(const mbd::WingKinematics& kinematics,
                                                       const Eigen::Vector3d& freestream, double radius,
                                                       double t) {
  const mbd::BasePose pose = kinematics.pose(t);
  const Eigen::Vector3d span = pose.rotation.col(1), chord = pose.rotation.col(0),
                        normal = pose.rotation.col(2);
  const Eigen::Vector3d point_velocity = pose.velocity + pose.angular_velocity.cross(radius * span);
  Eigen::Vector3d w = freestream - point_velocity;
  w -= w.dot(span) * span;
  const double scale = freestream.norm() + 2.0 * std::numbers::pi * kinematics.frequency * radius;
  if (!(w.norm() > 1e-9 * scale)) return std::nullopt;
  // The air pushes the wing along its normal toward the side it flows to, (w·n) n: the angle
  // is negative where that push points down.
  const double push_up = w.dot(normal) * normal.z();
  const double side = push_up < 0.0 ? -1.0 : 1.0;
  return AngleInStream{side * std::atan2(std::abs(w.dot(normal)), -w.dot(chord)), w.norm()};
}

std::string describe_case(const Case& c, std::optional<double> stream_radius) {
  std::string s = "case '" + c.name + "' (" + c.file + ")\n";
  if (!c.wing_file.empty()) s += "  wing                   " + c.wing_file + "\n";
  if (!c.chain_file.empty()) s += "  chain                  " + c.chain_file + "\n";
  const auto& k = c.kinematics;
  s += line("  frequency              %10.4g Hz", k.frequency);
  s += line("  rotation phase         %10.4g of the period (< 0: advanced rotation)", k.rotation_phase);
  s += line("  stroke plane angle     %10.4g deg", k.stroke_plane_angle * kRadToDeg);
  // A revolving wing (kinematics.revolution) starts from rest and has no strokes.
  const bool revolving = k.revolution.active();
  if (revolving)
    s += line("  revolution             %10.4g deg/s after a ramp of %g s, from rest",
              k.revolution.rate * kRadToDeg, k.revolution.ramp);
  // A span axis that neither sweeps nor deviates (a plate that heaves or pitches only) has no
  // strokes and no reversals: its geometric angle of attack is undefined throughout.
  const bool span_fixed = !revolving && k.sweep.is_constant() && k.deviation.is_constant();
  s += revolving    ? "  kinematics (AoA: geometric angle of attack; '-' at rest)\n"
       : span_fixed ? "  kinematics (AoA: geometric angle of attack; '-': the span axis does not sweep)\n"
                    : "  kinematics (AoA: geometric angle of attack; '-' at stroke reversal)\n";
  // In a free stream or with a translating pivot the geometric angle is not the one the air
  // meets: the table adds the angle at r2·R with the stream (and the air's speed there).
  const bool in_stream =
      stream_radius && c.air.enabled && (!c.air.freestream.isZero(0.0) || k.pivot_translates());
  if (in_stream)
    s += line(
        "    (in stream: the angle of attack the air meets at r2 = %.4g mm from the pivot, with the\n"
        "     free stream and the pivot's motion, negative where the air pushes the wing down,\n"
        "     and the air's speed there normal to the span)",
        *stream_radius * 1e3);
  s += in_stream
           ? "    phase f*t   sweep phi  deviation theta  rotation alpha   AoA   in stream [deg]  air [m/s]\n"
           : "    phase f*t   sweep phi  deviation theta  rotation alpha   AoA    [deg]\n";
  for (double phase : {0.0, 0.25, 0.5, 0.75}) {
    const auto a = k.angles(phase / k.frequency);
    const auto aoa = geometric_angle_of_attack(a, k.frequency);
    char aoa_text[32];
    if (aoa)
      std::snprintf(aoa_text, sizeof aoa_text, "%7.2f", *aoa * kRadToDeg);
    else
      std::snprintf(aoa_text, sizeof aoa_text, "%7s", "-");
    const char* stroke = revolving    ? (!aoa ? "at rest" : "revolving")
                         : span_fixed ? "no sweep"
                         : !aoa       ? "reversal"
                                      : (a.sweep.rate < 0 ? "downstroke" : "upstroke");
    std::string stream_text;
    if (in_stream) {
      const auto w = angle_of_attack_in_stream(k, c.air.freestream, *stream_radius, phase / k.frequency);
      char buf[48];
      if (w)
        std::snprintf(buf, sizeof buf, "  %9.2f       %9.3g", w->angle * kRadToDeg, w->speed);
      else
        std::snprintf(buf, sizeof buf, "  %9s       %9s", "-", "0");
      stream_text = buf;
    }
    s += line("    %9.2f  %10.2f  %15.2f  %14.2f  %s%s  %s", phase, a.sweep.value * kRadToDeg,
              a.deviation.value * kRadToDeg, a.rotation.value * kRadToDeg, aoa_text, stream_text.c_str(),
              stroke);
  }
  // A table flown as its Fourier series (harmonics = N): how far its points lie from it, so the
  // user can pick the fewest harmonics within the measurement's accuracy.
  for (const auto& named : k.named_signals())
    if (const auto& fit = named.signal->table_fit()) {
      const double unit = named.angle ? kRadToDeg : 1.0;
      s += line(
          "  %-22s %d harmonic%s fitted to %d points: the points %.3g %s (rms) from it, at most %.3g at "
          "phase %.4g",
          named.name, fit->harmonics, fit->harmonics == 1 ? "" : "s", fit->points, fit->residual_rms * unit,
          named.angle ? "deg" : "m", fit->residual_largest * unit, fit->largest_phase);
    }
  if (c.air.enabled)
    s += line("  air                    density %.4g kg/m^3, free stream (%.4g, %.4g, %.4g) m/s",
              c.air.density, c.air.freestream.x(), c.air.freestream.y(), c.air.freestream.z());
  else
    s += "  air                    none (vacuum)\n";
  if (c.structure.kind == Case::Structure::Kind::Rigid)
    s += "  structure              rigid\n";
  else if (c.structure.kind == Case::Structure::Kind::Fem)
    s += line("  structure              the wing's FEM, geometrically nonlinear (element size %s)",
              c.structure.fem_element_size > 0.0
                  ? (std::to_string(c.structure.fem_element_size * 1e3).substr(0, 6) + " mm").c_str()
                  : "of the wing file");
  else
    s += line("  structure              flexible, %d bodies", c.structure.bodies);
  if (!c.structure.gravity.isZero(0.0))
    s += line("  gravity                (%.4g, %.4g, %.4g) m/s^2, ground frame", c.structure.gravity.x(),
              c.structure.gravity.y(), c.structure.gravity.z());
  const auto& n = c.numerics;
  s += line("  time steps             %d per cycle x %d cycles = %lld (dt = %.4g ms)", n.steps_per_cycle,
            n.cycles, static_cast<long long>(n.total_steps()), 1e3 / (k.frequency * n.steps_per_cycle));
  s += line("  panels                 %d chordwise x %d spanwise (%s x %s spacing)", n.chordwise_panels,
            n.spanwise_panels, std::string(wings::choice_name(kSpacingNames, n.chordwise_spacing)).c_str(),
            std::string(wings::choice_name(kSpacingNames, n.spanwise_spacing)).c_str());
  s += line("  loads                  %s, leading edge %s%s%s",
            std::string(wings::choice_name(kLoadMethodNames, n.load_method)).c_str(),
            std::string(wings::choice_name(kLeadingEdgeNames, n.leading_edge)).c_str(),
            n.circulation_rate == CirculationRate::Bdf1 ? ", dGamma/dt first order (bdf1)" : "",
            n.laminar_skin_friction ? ", laminar skin friction" : "");
  if (n.leading_edge == uvlm::LeadingEdge::Shed)
    s += line(
        "  critical LESP          %.4g, sheet's core %.4g mean chords, its rings merged from %s%s",
        n.lesp_critical, n.sheet_core_radius > 0.0 ? n.sheet_core_radius : n.core_radius,
        n.sheet_merge_steps > 0 ? (std::to_string(n.sheet_merge_steps) + " steps old").c_str() : "never",
        n.sheet_merge_steps > 0 && n.sheet_merge_spread_steps > 1
            ? (", each merge spread over " + std::to_string(n.sheet_merge_spread_steps) + " releases").c_str()
            : "");
  s += line("  vortex core            %s, radius %.4g mean chords",
            std::string(wings::choice_name(kCoreModelNames, n.core_model)).c_str(), n.core_radius);
  s += line("  wake                   %s, order %d, %s", n.free_wake ? "free" : "prescribed", n.wake_order,
            n.wake_max_rows > 0 ? (std::to_string(n.wake_max_rows) + " rows kept").c_str()
                                : "all rows kept");
  s += line("  wake cores             %s, near-wing core %.4g mean chords, %s",
            n.core_growth ? ("growing with age (a1 = " + line_number(n.core_growth_a1) +
                             ", nu = " + line_number(n.kinematic_viscosity) + " m^2/s)").c_str()
                          : "constant",
            n.near_wing_core,
            n.frozen_wake_cycles > 0 ? ("frozen after " + line_number(n.frozen_wake_cycles) + " cycles").c_str()
            : n.far_wake_cycles > 0
                ? ("convected by momentum theory after " + line_number(n.far_wake_cycles) + " cycles").c_str()
                : "free throughout");
  s += line("  wake velocity sum      %s",
            n.wake_sum == uvlm::WakeSum::Tree
                ? ("tree code, relative error " + line_number(n.tree_tolerance)).c_str()
                : "direct");
  s += line("  wake sums precision    %s",
            std::string(wings::choice_name(kWakePrecisionNames, n.wake_precision)).c_str());
  s += line("  coupling               %s, at most %d iterations, tolerance %.3g",
            std::string(wings::choice_name(kCouplingMethodNames, n.coupling)).c_str(), n.max_coupling_iterations,
            n.coupling_tolerance);
  if (n.coupling_reuse_steps > 0)
    s += line("  coupling reuse         the secant pairs of the last %d steps (IQN-ILS(q))", n.coupling_reuse_steps);
  if (!n.added_mass) s += line("  added mass             off (the plain partitioned step)");
  if (c.output.vtk_every > 0)
    s += line("  VTK output             every %d steps", c.output.vtk_every);
  else
    s += "  VTK output             none\n";
  s += line("  point loads            %zu", c.loads.size());
  s += line("  markers                %zu", c.markers.size());
  return s;
}

}  // namespace flapsim::io
