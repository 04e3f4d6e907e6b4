#include "pipeline/fsi/coupled_step.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "pipeline/fsi/numerical_failure.hpp"
#include "pipeline/fsi/panel_load_response.hpp"
#include "pipeline/fsi/stop_request.hpp"
#include "uvlm/leading_edge_side.hpp"
#include "uvlm/old_wake_hold.hpp"

namespace flapsim::fsi {

FsiData::FsiData(const FsiModel& model)
    : structure(model.structure->make_data()),
      aitken(model.coupling.first_relaxation),
      quasi_newton(std::min(model.structure->num_dofs(), kMaxQuasiNewtonPairs), model.coupling.reuse_steps) {
  if (model.air) {
    lattice.emplace(model.lattice);
    // A structure that moves within a step may hold the older wake's sums (sub_iterate).
    lattice->old_wake_apart = model.coupling.old_wake_hold_after > 0 && model.structure->num_dofs() > 0;
    added_mass_scratch.emplace(model.lattice);
    for (Eigen::Matrix3Xd& f : earlier_forces) f.setZero(3, model.lattice.panels());
    nodes.setZero(3, model.lattice.nodes());
    node_velocities.setZero(3, model.lattice.nodes());
  }
  residual.setZero(structure->interface_size());
}

namespace {

// A number of a message in 3 significant digits ("1e-06", "2.35e-07"): std::to_string's six
// decimals printed a change of 2e-7 rad and a tolerance of 1e-9 alike as 0.000000.
std::string significant(double v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3g", v);
  return text;
}

// The lattice solved on the structure's current pose at time t (loads in data.lattice).
void solve_air(const FsiModel& model, FsiData& data, double dt, long step, double t) {
  data.structure->surface(data.nodes, data.node_velocities);
  if (!data.nodes.allFinite() || !data.node_velocities.allFinite())
    throw NumericalFailure("deformed wing surface is not finite", step, t);
  uvlm::VortexLatticeData& lat = *data.lattice;
  uvlm::solve(model.lattice, lat, data.nodes, data.node_velocities, model.free_stream, dt,
              model.density);
  if (!lat.loads.force.allFinite() || !lat.gamma.allFinite())
    throw NumericalFailure("aerodynamic loads are not finite", step, t);
}

// The structure's loads = its external loads at t + the lattice's panel loads (at the
// current pose).
void assemble_loads(const FsiModel& model, FsiData& data, double t) {
  data.structure->set_external_loads(t);
  if (model.air) data.structure->add_panel_loads(data.lattice->loads);
}

// Whether the step's first lattice solve linearises the air's added mass anew
// (CouplingSettings::added_mass_every): at the first three steps, every
// added_mass_every-th step and a step after one that took more than added_mass_stale
// solves (the held linearisation may no longer fit the wing's shape).
bool added_mass_due(const FsiModel& model, const FsiData& data, long step) {
  const CouplingSettings& c = model.coupling;
  return step < 3 || step % std::max(1, c.added_mass_every) == 0 || data.last_iterations > c.added_mass_stale;
}

// Sub-iterations from the iterate (steps 1–3 of the file comment) until the structure stops
// changing or k reaches k + limit; k counts the step's lattice solves, delta the last change.
bool sub_iterate(const FsiModel& model, FsiData& data, double dt, long step, double t1,
                 CouplingMethod method, int limit, int& k, double& delta) {
  StructureData& s = *data.structure;
  const int last = k + limit;
  bool first = k == 0;
  const double tol = model.coupling.tolerance;
  double accuracy = 1.0;  // of the last solve, in multiples of the structure's tolerance
  bool hold_released = false;
  while (k < last) {
    check_stop();  // a program that wants to stop need not wait for the step's end (stop_request.hpp)
    // 1. lattice on the iterate
    if (!first) s.pose_iterate();
    if (k == model.coupling.edge_side_hold_after) uvlm::hold_leading_edge_sides(model.lattice, *data.lattice);
    // The older wake's sums held from the first solve, the hold_after-th or a later one,
    // after a small change, and for good summed anew once it grows again
    // (uvlm/old_wake_hold.hpp).
    const int hold_after = model.coupling.old_wake_hold_after;
    const bool small_change = delta <= model.coupling.old_wake_hold_change * tol;
    if (hold_after > 0 && k >= hold_after && small_change && !hold_released && !data.lattice->old_wake_held)
      uvlm::hold_old_wake_sums(model.lattice, *data.lattice);
    else if (hold_after > 0 && k > hold_after && !small_change && data.lattice->old_wake_held) {
      uvlm::sum_old_wake_anew(*data.lattice);
      hold_released = true;
    }
    // (first of the step: the structure's pose is already the predictor's = the iterate)
    solve_air(model, data, dt, step, t1);
    ++k;
    ++data.step_solves;
    if (k == 1 && model.coupling.added_mass) {  // the air's added mass
      PanelLoadResponse response(model.lattice, *data.lattice, *data.added_mass_scratch);
      if (added_mass_due(model, data, step)) {
        // Its right-hand sides by the factors of this solve's matrix (not GMRES from an
        // earlier one's), which then precondition the next solves (uvlm/vortex_lattice.hpp).
        uvlm::factorise_current_matrix(*data.lattice);
        s.linearise_panel_loads(response);
      } else {
        s.refresh_panel_load_response(response);
      }
    }
    // 2. the structure's step with these loads, to 1 % of the last change (file comment)
    assemble_loads(model, data, t1);
    accuracy = s.set_solve_accuracy(
        model.coupling.loose_intermediate_solves ? std::max(1.0, (first ? data.first_change : delta) / tol) : 1.0);
    s.solve(dt);
    first = false;
    // 3. converged?
    delta = s.change(model.frequency);
    if (!std::isfinite(delta)) throw NumericalFailure("coupling produced a non-finite structure state", step, t1);
    data.step_change = delta;
    if (k == 1) data.first_change = delta;
    if (delta <= tol && accuracy > 1.0 && s.solved_accuracy() > 1.0) {
      // Converged on an intermediate answer: the same loads at full accuracy (not needed
      // when the answer asked for loosely passed the structure's full test all the same).
      s.set_solve_accuracy(1.0);
      s.solve(dt);
      ++data.accuracy_solves;
      accuracy = 1.0;
      delta = s.change(model.frequency);
      if (!std::isfinite(delta)) throw NumericalFailure("coupling produced a non-finite structure state", step, t1);
    }
    if (delta <= tol) return true;
    s.residual(data.residual);
    bool updated = false;
    if (method == CouplingMethod::InterfaceQuasiNewton) {
      s.trial_vector(data.stacked_trial);
      updated = data.quasi_newton.next(data.residual, data.stacked_trial, data.stacked_next);
      if (updated) s.set_iterate(data.stacked_next);
    }
    if (!updated) s.relax(data.aitken.next(data.residual));
  }
  return false;
}

// The predictor's panel loads (CouplingSettings::predictor_order): the last accepted
// step's forces F₀ extrapolated through the earlier ones, 2F₀ − F₁ or 3F₀ − 3F₁ + F₂, at
// F₀'s points; then F₀ joins the earlier forces.
const uvlm::PanelLoads& predicted_loads(const FsiModel& model, FsiData& data) {
  const uvlm::PanelLoads& last = data.lattice->loads;
  const int order = std::min(model.coupling.predictor_order, data.earlier_count);
  data.predicted_loads = last;
  Eigen::Matrix3Xd* f = data.earlier_forces;
  if (order == 1) data.predicted_loads.force = 2.0 * last.force - f[0];
  if (order >= 2) data.predicted_loads.force = 3.0 * last.force - 3.0 * f[0] + f[1];
  f[1] = f[0];
  f[0] = last.force;
  data.earlier_count = std::min(data.earlier_count + 1, 2);
  return data.predicted_loads;
}

}  // namespace

void initialize(const FsiModel& model, FsiData& data, double t0) {
  try {
    data.structure->initialize(t0);
  } catch (const StructureFailure& e) {
    throw NumericalFailure("the initial state (t = " + std::to_string(t0) + " s): " + e.what(), -1, 0.0,
                           /*in_structure=*/true);
  }
  data.step = 0;
  data.last_iterations = 0;
  data.total_iterations = 0;
  data.last_change = 0.0;
  data.earlier_count = 0;
}

void coupled_step(const FsiModel& model, FsiData& data, double dt) {
  StructureData& s = *data.structure;
  const double t1 = s.time() + dt;
  const long step = data.step;
  data.step_solves = 0;
  data.step_change = 0.0;
  try {
    if (model.structure->num_dofs() == 0) {
      // Rigid wing: the pose is prescribed; one lattice solve, nothing to iterate.
      s.prescribe(t1);
      data.last_iterations = 0;
      if (model.air) {
        solve_air(model, data, dt, step, t1);
        data.last_iterations = 1;
      }
      // The loads on the wing at t1 (prescribed and aerodynamic): they move nothing, but the
      // drive moment and power the base supplies include them (ω·M + v·F at the pivot).
      assemble_loads(model, data, t1);
      data.last_change = 0.0;
    } else if (!model.air) {
      s.set_external_loads(t1);
      s.set_solve_accuracy(1.0);
      s.solve(dt);
      s.accept();
      data.last_iterations = 0;
      data.last_change = 0.0;
    } else {
      // 0. predictor: the previous steps' aerodynamic loads extrapolated to this one,
      // transferred at the accepted pose of the last step (the structure's current pose).
      const auto predict = [&](const uvlm::PanelLoads* loads, double accuracy) {
        s.set_external_loads(t1);
        if (loads != nullptr) s.add_panel_loads(*loads);
        s.set_solve_accuracy(accuracy);
        s.solve(dt);
        s.start_iterate();
        data.aitken.start_step();
        data.quasi_newton.start_step();
      };
      predict(step > 0 ? &predicted_loads(model, data) : nullptr,
              model.coupling.loose_intermediate_solves ? std::max(1.0, data.first_change / model.coupling.tolerance)
                                                       : 1.0);
      int k = 0;
      double delta = 0.0;
      bool converged = sub_iterate(model, data, dt, step, t1, model.coupling.method,
                                   model.coupling.max_iterations, k, delta);
      // A stalled coupling, once more from the predictor with a finer structure
      // (StructureData::refine_after_stall; docs/fsi.md, "A stalled coupling, tried again").
      int retry = 0;
      for (; !converged && retry < kStallRetries && s.refine_after_stall(); ++retry) {
        uvlm::release_leading_edge_sides(*data.lattice);  // the stalled iterates' sides and sums
        uvlm::sum_old_wake_anew(*data.lattice);
        predict(step > 0 ? &data.predicted_loads : nullptr, 1.0);
        int again = 0;  // the retry's lattice solves (the step's count goes on below)
        converged = sub_iterate(model, data, dt, step, t1, model.coupling.method, model.coupling.max_iterations,
                                again, delta);
        k += again;
      }
      if (retry > 0) ++data.stall_retries;  // a step, however often it was tried again
      data.last_iterations = k;
      data.last_change = delta;
      if (!converged)
        throw NumericalFailure("strong coupling did not converge in " + std::to_string(k) +
                                   " sub-iterations (structure change " + significant(delta) +
                                   " rad, tolerance " + significant(model.coupling.tolerance) + ")" +
                                   (retry > 0 ? "; tried " + std::to_string(retry + 1) +
                                                    " times, the structure finer each time, at most " +
                                                    std::to_string(model.coupling.max_iterations) +
                                                    " a try (numerics.max_coupling_iterations)"
                                              : std::string()) +
                                   (model.coupling.method == CouplingMethod::Aitken
                                        ? std::string("; a light wing may converge with numerics.coupling = "
                                                      "\"iqn_ils\" (docs/fsi.md, \"Coupling\")")
                                        : std::string()),
                               step, t1);
      // 4. accept the structure's answer; its pose is that answer's (solve()).
      s.accept();
    }
  } catch (const StructureFailure& e) {
    throw NumericalFailure(e.what(), step, t1, /*in_structure=*/true);
  } catch (const std::length_error& e) {
    throw NumericalFailure(e.what(), step, t1);
  }
  data.step = step + 1;
  data.total_iterations += data.last_iterations;
}

void shed_wake(const FsiModel& model, FsiData& data) {
  if (!model.air) return;
  try {
    uvlm::advance(model.lattice, *data.lattice);
  } catch (const std::length_error& e) {
    throw NumericalFailure(e.what(), data.step - 1, data.time());
  }
}

}  // namespace flapsim::fsi
