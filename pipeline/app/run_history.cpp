#include "pipeline/app/run_history.hpp"

#include <cmath>
#include <numbers>

#include "mbd/angle_units.hpp"
#include "mbd/chain_energy.hpp"
#include "mbd/chain_kinematics.hpp"

namespace flapsim::app {

namespace {

// The columns every run writes. A column is a name (unit as a suffix), a description and
// how it is computed from the step's sample.
constexpr HistoryColumn kColumns[] = {
    {"t_s", "time", [](const StepSample& s) { return s.time; }},
    {"phi_base_deg", "base sweep angle φ (prescribed)",
     [](const StepSample& s) { return s.base.sweep.value * kRadToDeg; }},
    {"theta_base_deg", "base deviation angle θ (prescribed)",
     [](const StepSample& s) { return s.base.deviation.value * kRadToDeg; }},
    {"alpha_base_deg", "base rotation angle α (prescribed)",
     [](const StepSample& s) { return s.base.rotation.value * kRadToDeg; }},
    {"phi_tip_deg", "sweep angle of the last body", [](const StepSample& s) { return s.tip.sweep * kRadToDeg; }},
    {"theta_tip_deg", "deviation angle of the last body",
     [](const StepSample& s) { return s.tip.deviation * kRadToDeg; }},
    {"alpha_tip_deg", "rotation angle of the last body",
     [](const StepSample& s) { return s.tip.rotation * kRadToDeg; }},
    {"Fx_N", "aerodynamic force, ground x", [](const StepSample& s) { return s.force.x(); }},
    {"Fy_N", "aerodynamic force, ground y", [](const StepSample& s) { return s.force.y(); }},
    {"Fz_N", "aerodynamic force, ground z", [](const StepSample& s) { return s.force.z(); }},
    {"lift_N", "lift: the aerodynamic force along the lift direction (+z_G in hover; normal to U∞ in a free stream)",
     [](const StepSample& s) { return s.lift; }},
    {"drag_N", "drag: the force along the air's motion past the wing (U∞; in hover against the horizontal motion at r2·R); negative = thrust",
     [](const StepSample& s) { return s.drag; }},
    {"side_N", "side force: along drag direction × lift direction", [](const StepSample& s) { return s.side; }},
    {"Mx_base_Nm", "aerodynamic moment about the pivot, ground x", [](const StepSample& s) { return s.moment.x(); }},
    {"My_base_Nm", "aerodynamic moment about the pivot, ground y", [](const StepSample& s) { return s.moment.y(); }},
    {"Mz_base_Nm", "aerodynamic moment about the pivot, ground z", [](const StepSample& s) { return s.moment.z(); }},
    {"power_W", "aerodynamic power −Σ F·v over the panels (what the wing spends on the air)",
     [](const StepSample& s) { return s.power; }},
    {"Mx_drive_Nm", "moment the base exerts on the wing about the pivot (inertial + aerodynamic + gravity), ground x",
     [](const StepSample& s) { return s.drive_moment.x(); }},
    {"My_drive_Nm", "moment the base exerts on the wing about the pivot, ground y",
     [](const StepSample& s) { return s.drive_moment.y(); }},
    {"Mz_drive_Nm", "moment the base exerts on the wing about the pivot, ground z",
     [](const StepSample& s) { return s.drive_moment.z(); }},
    {"drive_power_W", "power the base supplies to the wing, ω·M + v·F at the pivot (inertial plus aerodynamic)",
     [](const StepSample& s) { return s.drive_power; }},
    {"CL", "lift coefficient L / (½ ρ U_ref² S)", [](const StepSample& s) { return s.cl; }},
    {"CD", "drag coefficient D / (½ ρ U_ref² S)", [](const StepSample& s) { return s.cd; }},
    {"CP", "power coefficient P / (½ ρ U_ref³ S)", [](const StepSample& s) { return s.cp; }},
    {"coupling_iterations", "lattice solves of the step",
     [](const StepSample& s) { return static_cast<double>(s.coupling_iterations); }},
    {"coupling_change_rad", "structure change at the end of the step's sub-iterations",
     [](const StepSample& s) { return s.coupling_change; }},
    {"phi_outer_deg", "sweep angle of the outer body", [](const StepSample& s) { return s.outer.sweep * kRadToDeg; }},
    {"theta_outer_deg", "deviation angle of the outer body",
     [](const StepSample& s) { return s.outer.deviation * kRadToDeg; }},
    {"alpha_outer_deg", "rotation angle of the outer body",
     [](const StepSample& s) { return s.outer.rotation * kRadToDeg; }},
    {"tip_bend_deg", "the tip's bend relative to the base: the chain's last body or the FEM's tip section, in the wing frame, Rx(bend) Ry(twist) (docs/fsi.md, \"The FEM as the structure\")",
     [](const StepSample& s) { return s.tip_bend * kRadToDeg; }},
    {"tip_twist_deg", "the tip's twist relative to the base (> 0 nose-down, the chain's joint convention)",
     [](const StepSample& s) { return s.tip_twist * kRadToDeg; }},
};

// A section's stroke angles read from its rotation lie in (−π, π]; the prescribed base's
// keep counting (a revolving wing's sweep passes 360°, a rotation's mean plus amplitude
// may pass 180°). Each is moved by the whole turns that bring it nearest the base's, so a
// rigid wing's tip reads the base's angles and a flexible one's its lag, with no ±360° jumps
// (until 2 Dec 2026 a revolving wing's phi_tip_deg read 9, 99, −171, 0 where phi_base_deg
// read 9, 459, 909, 2160).
mbd::StrokeAngles turned_as_the_base(mbd::StrokeAngles a, const mbd::WingKinematics::Angles& base) {
  constexpr double kTurn = 2.0 * std::numbers::pi;
  a.sweep += kTurn * std::round((base.sweep.value - a.sweep) / kTurn);
  a.rotation += kTurn * std::round((base.rotation.value - a.rotation) / kTurn);
  return a;
}

}  // namespace

std::span<const HistoryColumn> history_columns() { return kColumns; }

StepSample sample_step(const fsi::FsiModel& model, const fsi::FsiData& data,
                       const mbd::WingKinematics& kinematics, const LiftReference& reference) {
  // The structure's outputs: its sections' angles, the tip's deflection, the base's
  // reaction (alike for every structure: fsi::StructureReadout).
  const fsi::StructureReadout out = data.structure->readout();
  StepSample s;
  s.time = data.time();
  s.base = kinematics.angles(s.time);
  const Eigen::Matrix3d r_sg = mbd::rotation_y(kinematics.stroke_plane_angle).transpose();
  s.tip = turned_as_the_base(mbd::stroke_angles(r_sg * out.tip_rotation), s.base);
  s.outer = turned_as_the_base(mbd::stroke_angles(r_sg * out.outer_rotation), s.base);
  s.tip_bend = out.tip_bend;
  s.tip_twist = out.tip_twist;
  s.tip_position = out.tip_position;
  if (model.air) {
    const uvlm::PanelLoads& loads = data.lattice->loads;
    s.force = loads.total_force;
    s.moment = uvlm::moment_about(loads, kinematics.pose(s.time).position);
    s.power = loads.power;
    const Eigen::Vector3d up = reference.lift_direction;
    Eigen::Vector3d along = reference.drag_direction;
    if (reference.kind == LiftReference::Kind::Flapping) {
      // Hover: against the wing's horizontal motion (normal to the lift direction) at r2·R.
      // At a stroke reversal that motion stops and the direction is undefined: a step that
      // falls on it (sweep = A cos 2πft at t = T/2, T) had |v| ~ 1e-16 m/s of either sign
      // from round-off, and its drag ±|F_horizontal| (a mean drag 1.8 % off with the
      // frequency changed). Below 1e-9 of the reference speed the step's drag and side force
      // are 0, the mean of the two half strokes' limits there.
      const Eigen::Vector3d v = span_point_velocity(kinematics, reference.r2 * reference.span, s.time);
      const Eigen::Vector3d horizontal = v - v.dot(up) * up;
      along = horizontal.norm() > kReversalSpeedFraction * reference.speed
                  ? Eigen::Vector3d(-horizontal.normalized())
                  : Eigen::Vector3d::Zero();
    }
    s.lift = s.force.dot(up);
    s.drag = s.force.dot(along);
    s.side = s.force.dot(along.cross(up));
    const double qs = reference.dynamic_pressure_area(model.density);
    s.cl = s.lift / qs;
    s.cd = s.drag / qs;
    s.cp = s.power / (qs * reference.speed);
  }
  s.drive_moment = out.drive_moment;
  s.drive_power = out.drive_power;
  s.coupling_iterations = data.last_iterations;
  s.coupling_change = data.last_change;
  return s;
}

std::vector<std::string> history_header(const io::Case& c, const mbd::ChainModel& chain) {
  std::vector<std::string> cols;
  for (const HistoryColumn& col : kColumns) cols.emplace_back(col.name);
  for (int b = chain.first_jointed_body(); b < chain.num_bodies(); ++b) {
    cols.push_back("bend_" + std::to_string(b + 1) + "_rad");
    cols.push_back("twist_" + std::to_string(b + 1) + "_rad");
  }
  for (const auto& m : c.markers)
    for (const char* axis : {"_x_m", "_y_m", "_z_m"}) cols.push_back(m.name + axis);
  return cols;
}

void history_row(const StepSample& sample, const io::Case& c, const fsi::FsiData& data,
                 std::vector<double>& row) {
  std::size_t i = 0;
  for (const HistoryColumn& col : kColumns) row[i++] = col.value(sample);
  Eigen::VectorXd q;
  data.structure->joint_angles(q);
  for (Eigen::Index k = 0; k < q.size(); ++k) row[i++] = q(k);
  if (c.markers.empty()) return;
  // Markers ride on a chain's bodies (the case reader refuses them for the FEM).
  const fsi::ChainStructureData& cd = fsi::chain_structure(*data.structure);
  for (const auto& m : c.markers) {
    const Eigen::Vector3d p = mbd::point_position(cd.chain, m.body - 1, m.point);
    for (int a = 0; a < 3; ++a) row[i++] = p(a);
  }
}

}  // namespace flapsim::app
