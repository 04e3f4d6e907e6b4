#include "pipeline/app/fsi_run.hpp"

#include <chrono>
#include <cstdio>
#include <functional>
#include <string>

#include "pipeline/app/diverged_force.hpp"
#include "pipeline/app/flexibility_warnings.hpp"
#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/app/interruption.hpp"
#include "pipeline/app/numerical_stage.hpp"
#include "pipeline/app/released_chain_failure.hpp"
#include "pipeline/app/run_recorder.hpp"
#include "pipeline/fsi/coupled_step.hpp"
#include "pipeline/fsi/numerical_failure.hpp"
#include "pipeline/fsi/stop_request.hpp"
#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/input_hash.hpp"

namespace flapsim::app {

namespace {

// The time loop: from the initial state, `steps` coupled steps of dt; after each step
// (before the wake is shed, so the outputs show the wake the step's loads came from)
// the recorder and the progress line.
void time_loop(const FsiSetup& setup, fsi::FsiData& data, RunRecorder& recorder, ProgressLine& progress,
               const std::function<void(long, long)>& on_step) {
  const fsi::FsiModel& model = setup.model;
  // The force beyond which the lattice has diverged (diverged_force.hpp).
  const double duration = static_cast<double>(setup.steps) * setup.dt;  // [s]
  const double force_limit =
      model.air && setup.grid
          ? diverged_force_limit(
                model.density,
                fastest_wing_point_speed(model.base(), setup.period, setup.grid->nodes, model.free_stream,
                                         400, duration),
                setup.reference.area,
                fastest_wing_point_acceleration(model.base(), setup.period, setup.grid->nodes, 400, duration),
                setup.reference.mean_chord)
          : 0.0;
  fsi::initialize(model, data, 0.0);
  recorder.record_initial(data);
  // A coupled step that lasts says how far its coupling has come: the lattice solves so far
  // and the structure's last change against the tolerance (a light film's first step in
  // air took minutes with nothing but the seconds shown). Asked only when the line is drawn.
  const std::function<std::string()> coupling_so_far = [&]() -> std::string {
    if (!model.air || model.structure->num_dofs() == 0 || data.step_solves == 0) return "";
    char text[128];
    std::snprintf(text, sizeof text, "%d lattice solves, structure change %.2g rad (tolerance %.2g)%s",
                  data.step_solves, data.step_change, model.coupling.tolerance,
                  data.structure->split_steps() > 0
                      ? (", halved=" + std::to_string(data.structure->split_steps())).c_str()
                      : "");
    return text;
  };
  // SIGINT/SIGTERM within a step (one of a film's FEM can take minutes): the step is left
  // between two of its solves and the outputs end at the step before (stop_request.hpp).
  // A step that lasts shows that it is under way on the progress line.
  const fsi::ScopedStopCheck stop_within_step([&] {
    if (pending_interrupt() != 0)
      throw_if_interrupted("during step " + std::to_string(data.step + 1) + " of " + std::to_string(setup.steps) +
                           (data.step > 0 ? " (the step dropped: the outputs end at step " + std::to_string(data.step) + ")"
                                          : std::string(" (the step dropped: no step done)")));
    progress.step_under_way(coupling_so_far);
  });
  for (long n = 0; n < setup.steps; ++n) {
    fsi::coupled_step(model, data, setup.dt);
    // From the second step on: the first carries a start's impulse (diverged_force.hpp). A
    // step whose force diverged is in no output: the outputs end at the step before.
    const StepSample& measured = recorder.measure(data);
    if (force_limit > 0.0 && n > 0)
      throw_if_force_diverged(measured.force, force_limit, data.step - 1, data.time());
    recorder.record(data);
    fsi::shed_wake(model, data);
    // Chain solves split in halves so far (step halving, mbd/generalized_alpha.hpp): shown once there are any.
    char split[48] = "";
    if (data.structure->split_steps() > 0)
      std::snprintf(split, sizeof split, "%shalved=%ld", model.air ? "  " : "", data.structure->split_steps());
    if (model.air) {
      char extra[144];
      std::snprintf(extra, sizeof extra, "CL=%.3f  iterations=%d%s", recorder.last().cl, data.last_iterations, split);
      progress.update(data.step, data.time(), extra);
    } else {
      progress.update(data.step, data.time(), split);
    }
    if (on_step) on_step(data.step, static_cast<long>(setup.steps));
    // SIGINT/SIGTERM: the step is complete and recorded; stop here (interruption.hpp).
    // After the last step the run is complete: it ends as such.
    if (n + 1 < setup.steps) throw_if_interrupted("after step " + std::to_string(data.step) + " of " + std::to_string(setup.steps));
  }
}

}  // namespace

RunResults run_case(const io::Case& c, const RunOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  // 1. Setup: structure, lattice, attachment, base motion, references.
  // A chain file and a spring scale act on a flexible wing's chain only; for another kind
  // they are unused (warned by the commands) and no part of the run's inputs or summary.
  const bool chain_used = c.structure.kind == io::Case::Structure::Kind::Flexible;
  const std::string chain_file = chain_used ? options.chain_file : std::string();
  const double spring_scale = chain_used ? options.spring_scale : 1.0;
  const FsiSetup setup = numerical_stage("run setup", [&] {
    return build_fsi_setup(c, SetupOptions{chain_file, spring_scale, options.wing_overrides});
  });
  if (options.before_start) options.before_start(setup);
  // 2. The recorder: the output folder, history.csv, the series.
  RunRecorder recorder(c, setup, options.output_dir, options.vtk_every.value_or(c.output.vtk_every),
                       spring_scale, started);
  recorder.set_inputs_hash(io::input_hash(c, setup.wing ? &*setup.wing : nullptr, chain_file, spring_scale));
  if (options.warnings) recorder.set_warnings(options.warnings(setup));
  fsi::FsiData data(setup.model);
  ProgressLine progress(setup.steps, stderr, options.progress);
  // 3. The time loop; a numerical failure still leaves a complete summary.json.
  try {
    recorder.begin();
    time_loop(setup, data, recorder, progress, options.on_step);
  } catch (const NumericalFailure& e) {
    // A chain that had swung beyond small rotations, or a FEM wing that had swung far: say
    // so with the failure (the joint, the angles), as the failure is then the wing's motion
    // rather than the solver's.
    const RunRecorder::TipDeflection tip = recorder.peak_tip_deflection();
    Eigen::VectorXd last_q;
    data.structure->joint_angles(last_q);
    std::string why = large_motion_at_failure(setup, last_q, tip.bend_deg, tip.twist_deg) +
                      fem_motion_at_failure(c, tip.bend_deg, tip.twist_deg, e.in_structure());
    const std::string released = released_chain_at_failure(c, e.step());
    if (!released.empty()) why += (why.empty() ? "" : ". ") + released;
    // A leading-edge sheet that came apart: the loads' jumps it leaves, and what to change.
    const std::string lattice =
        diverged_lattice_advice(c.numerics, recorder.largest_lift_jump(), recorder.recorded_steps());
    if (!lattice.empty()) why += (why.empty() ? "" : ". ") + lattice;
    if (why.empty()) {
      recorder.finish(data, "failed", e.what());
      throw;
    }
    const NumericalFailure explained(e.reason() + ". " + why, e.step(), e.time(), e.in_structure());
    recorder.finish(data, "failed", explained.what());
    throw explained;
  } catch (const Interrupted& e) {
    recorder.finish(data, "interrupted", e.what());
    throw;
  } catch (const io::OutputError& e) {
    // A file could not be written (a full disk, a file-size limit): summary.json still says
    // how far the run got, if it can be written; the output error stands either way.
    try {
      recorder.finish(data, "failed", std::string("output error: ") + e.what());
    } catch (const std::exception&) {
    }
    throw;
  }
  const RunResults results = recorder.finish(data, "ok");
  char extra[96];
  if (results.has("mean_CL"))
    std::snprintf(extra, sizeof extra, "mean lift %.4g N, mean CL %.3f", results.number("mean_lift_N"),
                  results.number("mean_CL"));
  else
    std::snprintf(extra, sizeof extra, "in vacuum, no lift");
  progress.finish(extra);
  return results;
}

}  // namespace flapsim::app
