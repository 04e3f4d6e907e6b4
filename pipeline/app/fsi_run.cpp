#include "pipeline/app/fsi_run.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "mbd/chain_kinematics.hpp"
#include "mbd/wing_kinematics.hpp"
#include "pipeline/fsi/coupled_step.hpp"
#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/io/fsi_vtk.hpp"
#include "pipeline/fsi/phase_analysis.hpp"
#include "pipeline/fsi/numerical_failure.hpp"
#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/csv_writer.hpp"
#include "pipeline/io/pvd_series.hpp"
#include "pipeline/io/summary_json.hpp"

namespace flapsim::app {

using namespace fsi;
using io::chain_mesh;
using io::wake_mesh;
using io::wing_surface_mesh;

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

// Time series kept in memory for the end-of-run analysis.
struct Series {
  std::vector<double> t, lift, cl, fx, fy, fz;
  std::vector<double> base_phi, base_alpha, tip_phi, tip_alpha, outer_phi, outer_alpha;
  std::vector<int> iterations;
};

std::vector<std::string> history_columns(const io::Case& c, const mbd::ChainModel& chain) {
  std::vector<std::string> cols = {"t_s",          "phi_base_deg", "theta_base_deg", "alpha_base_deg",
                                   "phi_tip_deg",  "theta_tip_deg", "alpha_tip_deg", "Fx_N",
                                   "Fy_N",         "Fz_N",          "lift_N",        "CL",
                                   "coupling_iterations", "coupling_change_rad",
                                   "phi_outer_deg", "theta_outer_deg", "alpha_outer_deg"};
  for (int b = chain.first_jointed_body(); b < chain.num_bodies(); ++b) {
    cols.push_back("bend_" + std::to_string(b + 1) + "_rad");
    cols.push_back("twist_" + std::to_string(b + 1) + "_rad");
  }
  for (const auto& m : c.markers)
    for (const char* axis : {"_x_m", "_y_m", "_z_m"}) cols.push_back(m.name + axis);
  return cols;
}

// Euler angles of a body relative to the chain's undeformed orientation.
EulerAngles body_angles(const io::Case& c, const mbd::ChainModel& chain, const mbd::ChainData& data,
                        int body) {
  const Eigen::Matrix3d r_gs = mbd::rotation_y(c.kinematics.stroke_plane_angle);
  const Eigen::Matrix3d& r_gb = data.bodies[static_cast<std::size_t>(body)].rotation;
  return euler_angles(r_gs.transpose() * r_gb * chain.root_rotation.transpose());
}

// The "outer" body: the one holding the point at 5/6 of the chain's length, the middle
// of the outer third of the span (the third body of the paper's three-body wing). With
// many bodies the last one is a small piece of the rounded tip; this one is a section
// an experimenter's wing-tip marker would follow.
int outer_body(const mbd::ChainModel& chain) {
  const std::vector<double> s = reference_joint_span(chain);
  const double length = s.back() + chain.bodies.back().outboard_joint.norm();
  return host_body(s, s.front() + 5.0 / 6.0 * (length - s.front()));
}

}  // namespace

RunSummary run_case(const io::Case& c, const RunOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  FsiSetup setup = build_fsi_setup(c, SetupOptions{options.chain_file, options.spring_scale});
  const FsiModel& model = setup.model;
  const int vtk_every = options.vtk_every.value_or(c.output.vtk_every);
  const auto& dir = options.output_dir;
  io::ensure_directory(dir);

  FsiData data(model);
  RunSummary summary;
  summary.structure = setup.structure_source;
  const double qs = model.air ? setup.reference.dynamic_pressure_area(model.density) : 0.0;

  io::CsvTimeSeriesWriter history(dir / "history.csv", history_columns(c, model.chain), 20);
  std::optional<io::PvdSeries> wing_pvd, wake_pvd, chain_pvd;
  if (vtk_every > 0) {
    if (model.air) {
      wing_pvd.emplace(dir / "wing.pvd");
      wake_pvd.emplace(dir / "wake.pvd");
    }
    chain_pvd.emplace(dir / "chain.pvd");
    io::ensure_directory(dir / "vtk");
  }
  Series series;
  const int outer_index = outer_body(model.chain);
  std::vector<double> row(history.columns().size());
  app::ProgressLine progress(setup.steps, stderr, options.progress);

  io::SummaryJson json;
  json.set("case", c.name);
  json.set("structure", setup.structure_source);
  json.set("air", model.air);
  json.set("frequency_hz", c.kinematics.frequency);
  json.set("rotation_phase", c.kinematics.rotation_phase);
  json.set("steps_per_cycle", setup.steps_per_cycle);
  json.set("cycles", c.numerics.cycles);
  json.set("dt_s", setup.dt);
  json.set("bodies", model.chain.num_bodies());
  json.set("spring_scale", options.spring_scale);
  if (model.air) {
    json.set("reference_area_m2", setup.reference.area);
    json.set("reference_speed_m_s", setup.reference.speed);
    json.set("r2", setup.reference.r2);
  }

  auto record = [&](long step) {
    const double t = data.state.time;
    const auto base = c.kinematics.angles(t);
    const EulerAngles tip = body_angles(c, model.chain, data.chain, model.chain.num_bodies() - 1);
    const EulerAngles outer = body_angles(c, model.chain, data.chain, outer_index);
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    if (model.air) force = data.lattice->loads.total_force;
    const double lift = force.z();
    const double cl = qs > 0.0 ? lift / qs : 0.0;
    std::size_t i = 0;
    for (double v : {t, base.sweep.value * kDeg, base.deviation.value * kDeg, base.rotation.value * kDeg,
                     tip.sweep * kDeg, tip.deviation * kDeg, tip.rotation * kDeg, force.x(), force.y(),
                     force.z(), lift, cl, double(data.last_iterations), data.last_change,
                     outer.sweep * kDeg, outer.deviation * kDeg, outer.rotation * kDeg})
      row[i++] = v;
    for (int k = 0; k < data.state.q.size(); ++k) row[i++] = data.state.q(k);
    for (const auto& m : c.markers) {
      const Eigen::Vector3d p = mbd::point_position(data.chain, m.body - 1, m.point);
      for (int a = 0; a < 3; ++a) row[i++] = p(a);
    }
    history.append(std::span<const double>(row.data(), row.size()));
    series.t.push_back(t);
    series.lift.push_back(lift);
    series.cl.push_back(cl);
    series.fx.push_back(force.x());
    series.fy.push_back(force.y());
    series.fz.push_back(force.z());
    series.base_phi.push_back(base.sweep.value);
    series.base_alpha.push_back(base.rotation.value);
    series.tip_phi.push_back(tip.sweep);
    series.tip_alpha.push_back(tip.rotation);
    series.outer_phi.push_back(outer.sweep);
    series.outer_alpha.push_back(outer.rotation);
    series.iterations.push_back(data.last_iterations);

    if (vtk_every > 0 && step % vtk_every == 0) {
      if (model.air) {
        const auto wf = io::PvdSeries::step_file_name("vtk/wing", step, "vtp");
        io::write_vtp(dir / wf, wing_surface_mesh(model.lattice, *data.lattice, t));
        wing_pvd->add(t, dir / wf);
        const auto kf = io::PvdSeries::step_file_name("vtk/wake", step, "vtp");
        io::write_vtp(dir / kf, wake_mesh(model.lattice, *data.lattice, t));
        wake_pvd->add(t, dir / kf);
      }
      const auto cf = io::PvdSeries::step_file_name("vtk/chain", step, "vtp");
      io::write_vtp(dir / cf, chain_mesh(model.chain, data.chain, t));
      chain_pvd->add(t, dir / cf);
    }
  };

  auto finish_summary = [&](const std::string& status) {
    summary.steps = data.step;
    summary.wall_time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    // Last complete cycle (or whatever was run, if less than one cycle).
    const double t_end = data.state.time;
    const double t_begin = std::max(0.0, t_end - setup.period);
    const auto mean = [&](const std::vector<double>& x) {
      std::vector<double> tt = series.t, xx = x;
      tt.insert(tt.begin(), 0.0);  // the series start at the first step; t = 0 has no loads
      xx.insert(xx.begin(), xx.empty() ? 0.0 : xx.front());
      return window_mean(tt, xx, t_begin, t_end);
    };
    summary.mean_lift = mean(series.lift);
    summary.mean_cl = mean(series.cl);
    const auto bp = rotation_phase(series.t, series.base_phi, series.base_alpha, setup.period, t_begin, t_end);
    const auto tp = rotation_phase(series.t, series.tip_phi, series.tip_alpha, setup.period, t_begin, t_end);
    const auto lag = crossing_lag(series.t, series.tip_alpha, series.base_alpha, 0.5 * std::numbers::pi,
                                  setup.period, t_begin, t_end);
    const double phi_mean = window_mean(series.t, series.base_phi, t_begin, t_end);
    const auto sweep_lag = crossing_lag(series.t, series.tip_phi, series.base_phi, phi_mean,
                                        setup.period, t_begin, t_end);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    summary.base_rotation_phase = bp.value_or(nan);
    summary.tip_rotation_phase = tp.value_or(nan);
    summary.tip_rotation_lag = lag.value_or(nan);
    summary.tip_sweep_lag = sweep_lag.value_or(nan);
    summary.outer_rotation_phase =
        rotation_phase(series.t, series.outer_phi, series.outer_alpha, setup.period, t_begin, t_end).value_or(nan);
    summary.outer_rotation_lag = crossing_lag(series.t, series.outer_alpha, series.base_alpha, 0.5 * std::numbers::pi,
                                              setup.period, t_begin, t_end)
                                     .value_or(nan);
    double it_sum = 0.0;
    int it_max = 0;
    for (int it : series.iterations) {
      it_sum += it;
      it_max = std::max(it_max, it);
    }
    summary.mean_coupling_iterations = series.iterations.empty() ? 0.0 : it_sum / series.iterations.size();
    summary.max_coupling_iterations = it_max;

    json.set("status", status);
    json.set("steps", summary.steps);
    json.set("time_s", t_end);
    json.set("mean_lift_N", summary.mean_lift);
    json.set("mean_CL", summary.mean_cl);
    json.set("mean_Fx_N", mean(series.fx));
    json.set("mean_Fy_N", mean(series.fy));
    json.set("mean_Fz_N", mean(series.fz));
    json.set("base_rotation_phase", summary.base_rotation_phase);
    json.set("tip_rotation_phase", summary.tip_rotation_phase);
    json.set("tip_rotation_lag", summary.tip_rotation_lag);
    json.set("tip_sweep_lag", summary.tip_sweep_lag);
    json.set("outer_body", outer_index + 1);
    json.set("outer_rotation_phase", summary.outer_rotation_phase);
    json.set("outer_rotation_lag", summary.outer_rotation_lag);
    json.set("mean_coupling_iterations", summary.mean_coupling_iterations);
    json.set("max_coupling_iterations", summary.max_coupling_iterations);
    json.set("coupling_tolerance_rad", model.coupling.tolerance);
    if (model.air) json.set("wake_panels", data.lattice->wake_panels());
    json.set("wall_time_s", summary.wall_time_s);
    json.write(dir / "summary.json");
  };

  try {
    initialize(model, data, 0.0);
    for (long n = 0; n < setup.steps; ++n) {
      coupled_step(model, data, setup.dt);
      record(data.step);
      shed_wake(model, data);
      if (model.air) {
        char extra[96];
        std::snprintf(extra, sizeof extra, "CL=%.3f  iterations=%d", series.cl.back(), data.last_iterations);
        progress.update(data.step, data.state.time, extra);
      } else {
        progress.update(data.step, data.state.time);
      }
    }
  } catch (const NumericalFailure& e) {
    json.set("error", e.what());
    history.close();
    finish_summary("failed");
    throw;
  }
  history.close();
  finish_summary("ok");
  char extra[96];
  std::snprintf(extra, sizeof extra, "mean lift %.4g N, mean CL %.3f", summary.mean_lift, summary.mean_cl);
  progress.finish(extra);
  return summary;
}

}  // namespace flapsim::app
