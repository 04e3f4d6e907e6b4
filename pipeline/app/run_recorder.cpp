#include "pipeline/app/run_recorder.hpp"

#include <exception>
#include <filesystem>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "mbd/chain_kinematics.hpp"
#include "pipeline/app/low_reynolds_warning.hpp"
#include "pipeline/app/span_loads.hpp"
#include "pipeline/app/step_zigzag.hpp"
#include "pipeline/fsi/cycle_statistics.hpp"
#include "pipeline/fsi/fem_structure.hpp"
#include "pipeline/fsi/phase_analysis.hpp"
#include "pipeline/fsi/wing_attachment.hpp"
#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/fem_run_vtk.hpp"
#include "pipeline/io/fsi_vtk.hpp"
#include "pipeline/io/pvsm_state.hpp"
#include "pipeline/io/vtk_writers.hpp"
#include "wings/loader/toml_reader.hpp"

namespace flapsim::app {

namespace {

// A path as a user names it: one under the current folder relative to it (run --wing's
// wing reaches the case as an absolute path), any other as it is.
std::string as_named(const std::string& path) {
  std::error_code ec;
  const std::filesystem::path here = std::filesystem::current_path(ec);
  const std::filesystem::path p(path);
  if (ec || !p.is_absolute()) return path;
  const std::filesystem::path relative = p.lexically_relative(here);
  return relative.empty() || *relative.begin() == ".." ? path : relative.generic_string();
}

// A series recorded at every step, from t = 0: t = 0 has no loads, its value is the first
// step's (the time series' 0 itself: RunRecorder::times_from_zero).
std::vector<double> from_zero(std::vector<double> x) {
  x.insert(x.begin(), x.empty() ? 0.0 : x.front());
  return x;
}

const std::filesystem::path& existing_directory(const std::filesystem::path& dir) {
  io::ensure_directory(dir);
  return dir;
}

// One quantity of every sample, as a time series.
template <typename Get>
std::vector<double> series(const std::vector<StepSample>& samples, Get get) {
  std::vector<double> x;
  x.reserve(samples.size());
  for (const StepSample& s : samples) x.push_back(get(s));
  return x;
}

// The structure's frame: the FEM's deformed mesh (fem.pvd) or the chain's bodies (chain.pvd).
io::PolyDataMesh structure_frame(const FsiSetup& setup, const fsi::FsiData& data, double t) {
  if (setup.fem_structure) {
    const fsi::FemStructureModel& m = *setup.fem_structure;
    const auto& fem = dynamic_cast<const fsi::FemStructureData&>(*data.structure);
    const mbd::BasePose p = m.base_motion(t);
    return io::fem_frame_mesh(m.structural.mesh, fem.trial_positions(), p.rotation, p.position, t);
  }
  const fsi::ChainStructureData& chain = fsi::chain_structure(*data.structure);
  io::PolyDataMesh mesh = io::chain_mesh(setup.chain(), chain.chain, t);
  Eigen::VectorXd q;
  data.structure->joint_angles(q);
  io::add_joint_fields(mesh, setup.chain(), chain.chain, q);
  return mesh;
}

std::string structure_series(const FsiSetup& setup) { return setup.fem_structure ? "fem" : "chain"; }

// The values of a cell scalar of \p mesh, or nullptr.
const Eigen::VectorXd* cell_scalar(const io::PolyDataMesh& mesh, const std::string& name) {
  for (const io::ScalarField& f : mesh.cell_data.scalars)
    if (f.name == name) return &f.values;
  return nullptr;
}

}  // namespace

RunRecorder::RunRecorder(const io::Case& c, const FsiSetup& setup, const std::filesystem::path& output_dir,
                         int vtk_every, double spring_scale, std::chrono::steady_clock::time_point started)
    : case_(c),
      setup_(setup),
      dir_(existing_directory(output_dir)),
      vtk_every_(vtk_every),
      started_(started),
      outer_body_(fsi::outer_body(setup.chain())),
      history_(dir_ / "history.csv", history_header(c, setup.chain()), kHistoryPublishEvery,
               kHistoryMaxPublishInterval),
      row_(history_.columns().size()) {
  const fsi::FsiModel& model = setup.model;
  if (model.air) dynamic_pressure_ = setup.reference.dynamic_pressure_area(model.density) / setup.reference.area;
  tip_path_.name = "tip";
  for (const auto& m : c.markers) marker_paths_.push_back(io::Trajectory{m.name, {}, {}});
  RunResults& r = results_;
  r.set("case", c.name);
  if (!c.wing_file.empty()) r.set("wing_file", as_named(c.wing_file));
  r.set("structure", setup.structure_source);
  r.set("air", model.air);
  r.set("frequency_hz", c.kinematics.frequency);
  r.set("rotation_phase", c.kinematics.rotation_phase);
  r.set("steps_per_cycle", setup.steps_per_cycle);
  r.set("cycles", c.numerics.cycles);
  r.set("dt_s", setup.dt);
  r.set("structure_kind", std::string(wings::choice_name(io::kStructureKindNames, c.structure.kind)));
  r.set("bodies", setup.chain().num_bodies());
  if (setup.fem_structure) r.set("fem_nodes", setup.fem_structure->structural.mesh.num_nodes());
  r.set("spring_scale", spring_scale);
  if (model.air) {
    r.set("reference_area_m2", setup.reference.area);
    r.set("reference_speed_m_s", setup.reference.speed);
    r.set("reference_kind", setup.reference.kind_name());
    r.set("flapping_speed_m_s", setup.reference.flapping_speed);
    r.set("free_stream_speed_m_s", setup.reference.free_stream_speed);
    r.set("load_method", std::string(wings::choice_name(io::kLoadMethodNames, c.numerics.load_method)));
    r.set("leading_edge", std::string(wings::choice_name(io::kLeadingEdgeNames, c.numerics.leading_edge)));
    r.set("r2", setup.reference.r2);
    r.set("reynolds_number", reynolds_number(c, setup));
  }
}

void RunRecorder::begin() {
  if (vtk_every_ <= 0) return;
  if (setup_.model.air) {
    wing_pvd_.emplace(dir_ / "wing.pvd");
    wake_pvd_.emplace(dir_ / "wake.pvd");
  }
  chain_pvd_.emplace(dir_ / (structure_series(setup_) + ".pvd"));
  series_published_ = std::chrono::steady_clock::now();
  io::ensure_directory(dir_ / "vtk");
  write_state();
}

const StepSample& RunRecorder::measure(const fsi::FsiData& data) {
  measured_ = sample_step(setup_.model, data, case_.kinematics, setup_.reference);
  measured_step_ = data.step;
  return *measured_;
}

void RunRecorder::record(const fsi::FsiData& data) {
  if (!measured_ || measured_step_ != data.step) measure(data);
  samples_.push_back(std::move(*measured_));
  measured_.reset();
  if (setup_.model.air && data.lattice)
    append_strip_lifts(setup_.model.lattice, data.lattice->loads, setup_.reference.lift_direction,
                       strip_lift_);
  history_row(samples_.back(), case_, data, row_);
  history_.append(std::span<const double>(row_.data(), row_.size()));
  // The markers' positions are the row's last columns (run_history.hpp).
  const std::size_t marker_columns = 3 * marker_paths_.size();
  record_paths(samples_.back().time, samples_.back().tip_position,
               std::span<const double>(row_.data() + row_.size() - marker_columns, marker_columns));
  if (vtk_every_ > 0 && data.step % vtk_every_ == 0) write_series(data, data.step);
}

void RunRecorder::record_initial(const fsi::FsiData& data) {
  std::vector<double> markers;
  if (!case_.markers.empty()) {  // markers ride on a chain's bodies (the case reader's rule)
    const fsi::ChainStructureData& cd = fsi::chain_structure(*data.structure);
    for (const auto& m : case_.markers) {
      const Eigen::Vector3d p = mbd::point_position(cd.chain, m.body - 1, m.point);
      markers.insert(markers.end(), {p.x(), p.y(), p.z()});
    }
  }
  record_paths(data.time(), data.structure->readout().tip_position, markers);
  if (vtk_every_ > 0) write_series(data, 0);
}

void RunRecorder::record_paths(double t, const Eigen::Vector3d& tip, std::span<const double> markers) {
  tip_path_.times.push_back(t);
  tip_path_.points.push_back(tip);
  for (std::size_t k = 0; k < marker_paths_.size(); ++k) {
    marker_paths_[k].times.push_back(t);
    marker_paths_[k].points.emplace_back(markers[3 * k], markers[3 * k + 1], markers[3 * k + 2]);
  }
}

void RunRecorder::write_paths() const {
  io::write_vtp(dir_ / "tip_path.vtp", io::trajectory_mesh(tip_path_, setup_.period));
  for (std::size_t k = 0; k < marker_paths_.size(); ++k)
    io::write_vtp(dir_ / ("marker_" + std::to_string(k + 1) + "_path.vtp"),
                  io::trajectory_mesh(marker_paths_[k], setup_.period));
}

void RunRecorder::write_series(const fsi::FsiData& data, long step) {
  const fsi::FsiModel& model = setup_.model;
  const double t = data.time();
  io::StepValues values;
  values.step = step;
  values.t_over_T = t / setup_.period;
  if (step > 0) {
    const StepSample& last = samples_.back();
    values.lift = last.lift;
    values.cl = last.cl;
    values.drag = last.drag;
    values.cd = last.cd;
    values.power = last.power;
    values.drive_power = last.drive_power;
  }
  if (model.air) {
    // Step 0 is the pose before the first solve: the lattice placed on the chain, no loads.
    io::PolyDataMesh wing;
    if (step == 0) {
      Eigen::Matrix3Xd nodes(3, model.lattice.nodes()), velocities(3, model.lattice.nodes());
      data.structure->surface(nodes, velocities);
      wing = io::wing_surface_mesh(model.lattice, nodes, velocities, t);
    } else {
      wing = io::wing_surface_mesh(model.lattice, *data.lattice, t);
    }
    model.structure->rigid_surface(t, rigid_nodes_);
    io::add_wing_reference_fields(wing, dynamic_pressure_, rigid_nodes_);
    io::add_step_values(wing, values);
    record_for_state(wing, step);
    const auto wf = io::PvdSeries::step_file_name("vtk/wing", step, "vtp");
    io::write_vtp(dir_ / wf, wing, io::Flush::deferred);
    wing_pvd_->append(t, dir_ / wf);
    io::PolyDataMesh wake = io::wake_mesh(model.lattice, *data.lattice, t);
    if (const Eigen::VectorXd* gamma = cell_scalar(wake, "circulation_m2_s"))
      circulation_values_.add(gamma->begin(), gamma->end());
    io::add_step_values(wake, values);
    const auto kf = io::PvdSeries::step_file_name("vtk/wake", step, "vtp");
    io::write_vtp(dir_ / kf, wake, io::Flush::deferred);
    wake_pvd_->append(t, dir_ / kf);
  }
  io::PolyDataMesh chain = structure_frame(setup_, data, t);
  io::add_step_values(chain, values);
  if (!model.air) record_for_state(chain, step);
  const auto cf = io::PvdSeries::step_file_name("vtk/" + structure_series(setup_), step, "vtp");
  io::write_vtp(dir_ / cf, chain, io::Flush::deferred);
  chain_pvd_->append(t, dir_ / cf);
  frame_times_.push_back(t);
  publish_series(false);
}

void RunRecorder::record_for_state(const io::PolyDataMesh& frame, long step) {
  frame_fields_.clear();
  for (const auto& [name, value] : frame.field_data.numbers) frame_fields_.push_back(name);
  camera_.add_frame(frame);
  if (step == 0) return;  // no loads before the first solve
  for (const io::VectorField& f : frame.point_data.vectors)  // a FEM's surface in vacuum
    if (f.name == "displacement_m") {
      const Eigen::VectorXd magnitude = f.values.colwise().norm().transpose();
      displacement_values_.add(magnitude.begin(), magnitude.end());
    }
  const Eigen::VectorXd* values = cell_scalar(frame, "Cp");
  wing_field_ = values ? "Cp" : "pressure_jump_Pa";
  if (!values) values = cell_scalar(frame, wing_field_);
  if (values) wing_values_.add(values->begin(), values->end());
}

void RunRecorder::publish_series(bool now) {
  if (!chain_pvd_ || chain_pvd_->unpublished() == 0) return;
  const auto clock = std::chrono::steady_clock::now();
  if (!now && clock - series_published_ < kSeriesPublishInterval) return;
  io::sync_file_system(dir_);  // the frames first: a .pvd lists only frames on disk
  for (auto* series : {&wing_pvd_, &wake_pvd_, &chain_pvd_})
    if (*series) (*series)->publish();
  series_published_ = clock;
}

void RunRecorder::write_state() const {
  io::RunState state;
  state.air = setup_.model.air;
  state.chain_pvd = structure_series(setup_) + ".pvd";
  state.structure_mesh = static_cast<bool>(setup_.fem_structure);
  double length = 0.0;
  for (const auto& b : setup_.chain().bodies) length += b.length;
  if (length > 0.0) state.length_scale = length;
  // Robust colour ranges: a percentile of |value| over the frames (the extreme is one
  // frame's leading-edge peak; with it the rest of the wing looked grey).
  std::vector<double> wing = wing_values_.values(), gamma = circulation_values_.values();
  const double wing_range = io::magnitude_percentile(wing, io::kStateColourPercentile);
  const double gamma_range = io::magnitude_percentile(gamma, io::kStateColourPercentile);
  state.wing_field = wing_field_;
  if (wing_range > 0.0) state.wing_range = wing_range;
  if (gamma_range > 0.0) state.circulation_range = gamma_range;
  std::vector<double> displacement = displacement_values_.values();
  if (const double d = io::magnitude_percentile(displacement, io::kStateColourPercentile); d > 0.0)
    state.displacement_range = d;
  if (!frame_fields_.empty()) state.frame_fields = frame_fields_;
  state.bounds = camera_.bounds();
  state.front = camera_.best(io::state_box(state), static_cast<double>(io::kStateViewWidth) / io::kStateViewHeight);
  state.start_time = io::state_start_time(frame_times_, setup_.period);
  io::write_run_state(dir_ / "run.pvsm", state);
}

// The results of the samples: means over the last complete cycle (or whatever was run,
// if less than one cycle), rotation phases and lags, coupling statistics.
void RunRecorder::analyse(const fsi::FsiData& data) {
  RunResults& r = results_;
  const double period = setup_.period;
  // A step measured and then refused (its force diverged) is not one completed: the results
  // end at the step before.
  const bool refused = measured_ && measured_step_ == data.step && !samples_.empty();
  const auto [t_begin, t_end] = mean_window();
  const std::vector<double> t = series(samples_, [](const StepSample& s) { return s.time; });
  const std::vector<double> t_from_zero = times_from_zero();
  const auto mean = [&](std::vector<double> x) { return last_cycle_mean(std::move(x)); };
  r.set("steps", data.step - (refused ? 1 : 0));
  r.set("time_s", t_end);
  // Counted in steps: (t_end − t_begin) / T is 1 only to round-off, and complete runs (20 Hz,
  // 1 or 5 cycles of 24 steps) gave 0.9999999999999998 and a report saying they had ended
  // within their first cycle.
  const long steps_per_cycle = case_.numerics.steps_per_cycle;
  const long recorded = static_cast<long>(samples_.size());
  r.set("mean_window_cycles",
        static_cast<double>(std::min(recorded, steps_per_cycle)) / static_cast<double>(steps_per_cycle));
  r.set("mean_lift_N", mean(series(samples_, [](const StepSample& s) { return s.lift; })));
  r.set("mean_Fx_N", mean(series(samples_, [](const StepSample& s) { return s.force.x(); })));
  r.set("mean_Fy_N", mean(series(samples_, [](const StepSample& s) { return s.force.y(); })));
  r.set("mean_Fz_N", mean(series(samples_, [](const StepSample& s) { return s.force.z(); })));
  if (setup_.model.air) {  // in vacuum no reference speed: no coefficients
    r.set("mean_CL", mean(series(samples_, [](const StepSample& s) { return s.cl; })));
    r.set("mean_drag_N", mean(series(samples_, [](const StepSample& s) { return s.drag; })));
    r.set("mean_CD", mean(series(samples_, [](const StepSample& s) { return s.cd; })));
    const LiftReference& ref = setup_.reference;
    if (ref.kind == LiftReference::Kind::FreeStream && ref.flapping_speed > 0.0) {
      const double ratio = ref.free_stream_speed / ref.flapping_speed;
      const double scale = ratio * ratio;
      r.set("mean_CL_on_flapping_speed", r.number("mean_CL") * scale);
      r.set("mean_CD_on_flapping_speed", r.number("mean_CD") * scale);
    }
    r.set("mean_side_N", mean(series(samples_, [](const StepSample& s) { return s.side; })));
    r.set("mean_Mx_base_Nm", mean(series(samples_, [](const StepSample& s) { return s.moment.x(); })));
    r.set("mean_My_base_Nm", mean(series(samples_, [](const StepSample& s) { return s.moment.y(); })));
    r.set("mean_Mz_base_Nm", mean(series(samples_, [](const StepSample& s) { return s.moment.z(); })));
    const double power = mean(series(samples_, [](const StepSample& s) { return s.power; }));
    r.set("mean_power_W", power);
    // The largest step-to-step change of C_L after the start (its first two steps carry the
    // impulse of a wing started in air): the mark of a shed sheet come apart (run_results.hpp).
    const LiftJump jump = largest_recorded_jump(3);
    if (jump.step > 0) {
      r.set("largest_CL_jump", jump.size);
      r.set("largest_CL_jump_step", jump.step);
    }
    r.set("mean_CP", mean(series(samples_, [](const StepSample& s) { return s.cp; })));
    r.set("lift_per_power_N_W", power != 0.0 ? r.number("mean_lift_N") / power
                                             : std::numeric_limits<double>::quiet_NaN());
    // Over the whole cycles from the second on (a flow that does not repeat: its result); at
    // least three of them, for a standard deviation that means something (the 3-cycle hovers
    // of `make run` report their last cycle alone).
    // From numerics.settled_from_cycle (default 2), as long as 3 whole cycles are left.
    const int from = case_.numerics.settled_from_cycle;
    if (fsi::whole_cycles(period, t_end) - from + 1 >= 3) {
      const fsi::CycleStatistics cl = fsi::cycle_statistics(
          t_from_zero, from_zero(series(samples_, [](const StepSample& s) { return s.cl; })), period, t_end,
          from);
      const fsi::CycleStatistics lift = fsi::cycle_statistics(
          t_from_zero, from_zero(series(samples_, [](const StepSample& s) { return s.lift; })), period, t_end,
          from);
      r.set("settled_cycles", static_cast<int>(cl.cycle_means.size()));
      r.set("settled_from_cycle", from);
      r.set("settled_mean_lift_N", lift.mean);
      r.set("settled_mean_CL", cl.mean);
      r.set("settled_CL_standard_error", cl.standard_error);
      r.set("cycle_CL_deviation", cl.deviation);
      r.set("cycle_CL_lag_correlation", cl.lag_one_correlation);
      r.set("settled_CL_drift", cl.drift);
    }
  }

  r.set("mean_drive_power_W", mean(series(samples_, [](const StepSample& s) { return s.drive_power; })));
  {
    double peak_power = -std::numeric_limits<double>::infinity(), peak_moment = 0.0;
    for (const StepSample& s : samples_)
      if (s.time >= t_begin - 1e-12 * (t_end - t_begin)) {
        peak_power = std::max(peak_power, s.drive_power);
        peak_moment = std::max(peak_moment, s.drive_moment.norm());
      }
    if (std::isfinite(peak_power)) r.set("peak_drive_power_W", peak_power);
    r.set("peak_drive_moment_Nm", peak_moment);
  }
  const auto base_phi = series(samples_, [](const StepSample& s) { return s.base.sweep.value; });
  const auto base_alpha = series(samples_, [](const StepSample& s) { return s.base.rotation.value; });
  const auto tip_phi = series(samples_, [](const StepSample& s) { return s.tip.sweep; });
  const auto tip_alpha = series(samples_, [](const StepSample& s) { return s.tip.rotation; });
  const auto outer_phi = series(samples_, [](const StepSample& s) { return s.outer.sweep; });
  const auto outer_alpha = series(samples_, [](const StepSample& s) { return s.outer.rotation; });
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double right_angle = 0.5 * std::numbers::pi;
  r.set("base_rotation_phase", fsi::rotation_phase(t, base_phi, base_alpha, period, t_begin, t_end).value_or(nan));
  r.set("tip_rotation_phase", fsi::rotation_phase(t, tip_phi, tip_alpha, period, t_begin, t_end).value_or(nan));
  r.set("tip_rotation_lag",
        fsi::crossing_lag(t, tip_alpha, base_alpha, right_angle, period, t_begin, t_end).value_or(nan));
  const double phi_mean = fsi::window_mean(t, base_phi, t_begin, t_end);
  r.set("tip_sweep_lag", fsi::crossing_lag(t, tip_phi, base_phi, phi_mean, period, t_begin, t_end).value_or(nan));
  if (!setup_.fem_structure) r.set("outer_body", outer_body_ + 1);  // the FEM's: the band at 5/6 R
  r.set("outer_rotation_phase",
        fsi::rotation_phase(t, outer_phi, outer_alpha, period, t_begin, t_end).value_or(nan));
  r.set("outer_rotation_lag",
        fsi::crossing_lag(t, outer_alpha, base_alpha, right_angle, period, t_begin, t_end).value_or(nan));

  if (setup_.model.structure->num_dofs() > 0) {
    const TipDeflection peak = peak_tip_deflection();
    r.set("peak_tip_bend_deg", peak.bend_deg);
    r.set("peak_tip_twist_deg", peak.twist_deg);
    // A motion at the step's rate (step_zigzag.hpp): the larger of the bend's and the twist's.
    const StepZigzag bend =
        largest_step_zigzag(series(samples_, [](const StepSample& s) { return s.tip_bend; }));
    const StepZigzag twist =
        largest_step_zigzag(series(samples_, [](const StepSample& s) { return s.tip_twist; }));
    const StepZigzag& zigzag = twist.amplitude > bend.amplitude ? twist : bend;
    r.set("largest_tip_zigzag_deg", zigzag.amplitude * 180.0 / std::numbers::pi);
    if (zigzag.step > 0) r.set("largest_tip_zigzag_step", zigzag.step);
  }

  double iterations = 0.0;
  int max_iterations = 0;
  for (const StepSample& s : samples_) {
    iterations += s.coupling_iterations;
    max_iterations = std::max(max_iterations, s.coupling_iterations);
  }
  r.set("mean_coupling_iterations", samples_.empty() ? 0.0 : iterations / samples_.size());
  r.set("max_coupling_iterations", max_iterations);
  r.set("coupling_tolerance_rad", setup_.model.coupling.tolerance);
  r.set("coupling_method", setup_.model.coupling.method == fsi::CouplingMethod::InterfaceQuasiNewton
                               ? std::string("iqn_ils") : std::string("aitken"));
  if (setup_.model.coupling.reuse_steps > 0) r.set("coupling_reuse_steps", setup_.model.coupling.reuse_steps);
  if (data.structure->split_steps() > 0) {
    r.set("split_structural_steps", data.structure->split_steps());
    r.set("max_structural_pieces", data.structure->max_step_pieces());
  }
  if (data.structure->restarted_steps() > 0)
    r.set("restarted_structural_steps", data.structure->restarted_steps());
  if (data.stall_retries > 0) r.set("stalled_steps_retried", data.stall_retries);
  if (setup_.model.air) r.set("wake_panels", data.lattice->wake_panels());
}

LiftJump RunRecorder::largest_recorded_jump(long first_step) const {
  LiftJump largest;
  for (std::size_t k = static_cast<std::size_t>(std::max(first_step - 1, 1L)); k < samples_.size(); ++k) {
    const double change = std::abs(samples_[k].cl - samples_[k - 1].cl);
    if (change > largest.size) largest = {change, static_cast<long>(k) + 1};
  }
  return largest;
}

LiftJump RunRecorder::largest_lift_jump() const {
  LiftJump largest = largest_recorded_jump(2);
  if (measured_ && !samples_.empty()) {  // the step that failed after it was measured
    const double change = std::abs(measured_->cl - samples_.back().cl);
    if (change > largest.size) largest = {change, static_cast<long>(samples_.size()) + 1};
  }
  return largest;
}

RunRecorder::TipDeflection RunRecorder::peak_tip_deflection() const {
  double bend = 0.0, twist = 0.0;
  for (const StepSample& s : samples_) {
    bend = std::max(bend, std::abs(s.tip_bend));
    twist = std::max(twist, std::abs(s.tip_twist));
  }
  return {bend * 180.0 / std::numbers::pi, twist * 180.0 / std::numbers::pi};
}

std::pair<double, double> RunRecorder::mean_window() const {
  // The results end at the last step recorded: a step that failed (a structure that did
  // not converge, a diverged force) had moved the structure's clock on, and time_s said
  // 0.3625 s after 28 steps of 0.0125 s, the means' window shifted by that step.
  const double t_end = samples_.empty() ? 0.0 : samples_.back().time;
  return {std::max(0.0, t_end - setup_.period), t_end};
}

std::vector<double> RunRecorder::times_from_zero() const {
  std::vector<double> t{0.0};
  for (const StepSample& s : samples_) t.push_back(s.time);
  return t;
}

double RunRecorder::last_cycle_mean(std::vector<double> per_step) const {
  const auto [t_begin, t_end] = mean_window();
  return fsi::window_mean(times_from_zero(), from_zero(std::move(per_step)), t_begin, t_end);
}

void RunRecorder::write_span_loads() const {
  if (!setup_.grid || samples_.empty()) return;
  const std::size_t strips = static_cast<std::size_t>(setup_.model.lattice.spanwise);
  if (strip_lift_.size() != strips * samples_.size()) return;  // in vacuum: none
  std::vector<double> mean(strips), per_step(samples_.size());
  for (std::size_t j = 0; j < strips; ++j) {
    for (std::size_t k = 0; k < samples_.size(); ++k) per_step[k] = strip_lift_[k * strips + j];
    mean[j] = last_cycle_mean(per_step);
  }
  app::write_span_loads(dir_ / "span_loads.csv", span_strips(*setup_.grid), mean);
}

RunResults RunRecorder::finish(const fsi::FsiData& data, const std::string& status, const std::string& error) {
  // history.csv that cannot be completed (a full disk, a file-size limit) keeps its last
  // published rows; summary.json, small, still says the run failed and why, then the
  // output error goes on to the caller (exit status 4).
  std::exception_ptr history_failure;
  std::string final_status = status, final_error = error;
  try {
    history_.close();
  } catch (const io::OutputError& e) {
    history_failure = std::current_exception();
    final_status = "failed";
    if (final_error.empty()) final_error = std::string("output error: ") + e.what();
  }
  try {
    publish_series(true);  // the frames written since the last publication
    if (vtk_every_ > 0) write_paths();
  } catch (const io::OutputError& e) {
    if (!history_failure) history_failure = std::current_exception();
    final_status = "failed";
    if (final_error.empty()) final_error = std::string("output error: ") + e.what();
  }
  try {
    write_span_loads();
  } catch (const io::OutputError& e) {
    if (!history_failure) history_failure = std::current_exception();
    final_status = "failed";
    if (final_error.empty()) final_error = std::string("output error: ") + e.what();
  }
  if (!final_error.empty()) results_.set("error", final_error);
  results_.set("status", final_status);
  analyse(data);
  results_.set("wall_time_s",
               std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count());
  summary_json(results_).write(dir_ / "summary.json");
  if (history_failure) std::rethrow_exception(history_failure);
  if (vtk_every_ > 0) write_state();  // colour ranges of the whole run
  return results_;
}

}  // namespace flapsim::app
