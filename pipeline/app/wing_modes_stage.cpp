#include "pipeline/app/wing_modes_stage.hpp"

#include <chrono>
#include <iostream>
#include <exception>
#include <limits>
#include <memory>
#include <optional>
#include <thread>

#include "fem/load_cases.hpp"
#include "fem/static_solver.hpp"
#include "pipeline/app/numerical_stage.hpp"
#include "pipeline/fsi/numerical_failure.hpp"
#include "reduction/chain_lumping.hpp"
#include "reduction/reduction_failure.hpp"
#include "reduction/station_mode_kind.hpp"
#include "wings/loader/input_error.hpp"

namespace flapsim::app {

namespace {

class StageClock {
 public:
  explicit StageClock(std::vector<std::pair<std::string, double>>& out) : out_(out) {}
  void lap(const char* name) {
    const auto now = std::chrono::steady_clock::now();
    out_.emplace_back(name, std::chrono::duration<double>(now - last_).count());
    last_ = now;
  }

 private:
  std::vector<std::pair<std::string, double>>& out_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace

WingModesStage compute_wing_modes(const wings::Wing& wing, int num_modes, int bodies, int threads,
                                  const std::function<void(const std::string&)>& stage) {
  auto begin = [&](const char* name) {
    if (stage) stage(name);
  };
  WingModesStage out;
  StageClock clock(out.stage_seconds);
  begin("mesh and FEM matrices");
  fem::WingFem& f = out.fem;
  numerical_stage("FEM", [&] {
    f.model = fem::wing_structural_model(wing, fem::mesh_wing(wing));
    clock.lap("mesh");
    f.system = fem::assemble(f.model, threads);
    f.root_clamp = fem::root_clamp(f.model.mesh, wing.clamp_y);
    if (f.root_clamp.num_free() == f.root_clamp.num_dofs())
      throw InputError(wing.source_file, 0, "planform.clamp_y",
                       "no mesh node lies at or below clamp_y = " + std::to_string(wing.clamp_y * 1e3) +
                           " mm: the root would be free");
    clock.lap("assembly");
  });
  const fem::Mesh& mesh = f.model.mesh;
  // The eigen-solve (its own factorisation of K − σM, σ = 0, then Lanczos) on this thread;
  // on a second one the static side, which needs only K: one factorisation of the clamped
  // K shared by the four tip load cases and the reduction's load cases, then the chain
  // whose stations name the modes. Each side's numbers are those of the sequential order.
  begin(threads > 1 ? "FEM modes and static load cases" : "FEM modes");
  std::shared_ptr<const fem::StaticSolver> factor;
  std::optional<reduction::LumpedChain> chain;
  double factor_s = 0, statics_s = 0, chain_s = 0;
  auto static_side = [&] {
    auto t = std::chrono::steady_clock::now();
    auto lap = [&t](double& into) {
      const auto now = std::chrono::steady_clock::now();
      into = std::chrono::duration<double>(now - t).count();
      t = now;
    };
    factor = numerical_stage("FEM static load cases",
                             [&] { return std::make_shared<const fem::StaticSolver>(f.system.stiffness, f.root_clamp); });
    lap(factor_s);
    out.statics = numerical_stage("FEM static load cases", [&] {
      std::vector<io::StaticResult> r;
      for (auto& lc : fem::tip_load_cases(mesh, fem::tip_station(mesh))) {
        Eigen::VectorXd u = factor->solve(lc.loads);
        if (!u.allFinite()) throw NumericalFailure("FEM static load case '" + lc.name + "': non-finite displacements");
        r.push_back({std::move(lc), std::move(u)});
      }
      return r;
    });
    lap(statics_s);
    // The chain of `flapsim reduce --bodies N` (default analysis options); a wing that cannot
    // be reduced to N bodies keeps the modes' shape classification (with a warning).
    numerical_stage("mode names", [&] {
      try {
        const reduction::ClampedWingAnalysis analysis(mesh, f.system, f.root_clamp, {}, factor);
        chain = reduction::lump_into_chain(analysis, bodies);
      } catch (const reduction::ReductionFailure& e) {
        std::cerr << "warning: modes named by their shape, not by the stations of a " << bodies
                  << "-body chain: " << e.what() << "\n";
      }
    });
    lap(chain_s);
  };
  double eigen_s = 0;
  auto eigen_side = [&] {
    const auto t = std::chrono::steady_clock::now();
    out.modes = numerical_stage("FEM modes", [&] { return fem::wing_modes(f, num_modes); });
    eigen_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  if (threads > 1) {
    std::exception_ptr failed;
    std::thread worker([&] {
      try {
        static_side();
      } catch (...) {
        failed = std::current_exception();
      }
    });
    try {
      eigen_side();
    } catch (...) {
      worker.join();
      throw;
    }
    worker.join();
    if (failed) std::rethrow_exception(failed);
  } else {
    eigen_side();
    begin("static load cases");
    static_side();
  }
  clock.lap(threads > 1 ? "eigen-solve | statics (wall)" : "eigen-solve + statics (wall)");
  out.stage_seconds.emplace_back("eigen-solve", eigen_s);
  out.stage_seconds.emplace_back("factorisation", factor_s);
  out.stage_seconds.emplace_back("static load cases", statics_s);
  out.stage_seconds.emplace_back("reduction chain", chain_s);
  begin("mode names");
  for (const fem::ModeKind k : out.modes.kinds)
    out.labels.push_back({fem::to_string(k), std::numeric_limits<double>::quiet_NaN(), fem::to_string(k)});
  if (chain) {
    const auto measures = numerical_stage(
        "mode names", [&] { return reduction::classify_modes_by_stations(*chain, out.modes.modes.shapes); });
    for (std::size_t i = 0; i < out.labels.size(); ++i) {
      out.labels[i].kind = reduction::to_string(measures[i].kind);
      out.labels[i].beam_share = measures[i].beam_share;
    }
  }
  clock.lap("mode names");
  return out;
}

}  // namespace flapsim::app
