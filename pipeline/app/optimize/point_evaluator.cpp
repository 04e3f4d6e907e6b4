#include "pipeline/app/optimize/point_evaluator.hpp"

#include <chrono>
#include <optional>
#include <thread>

#include "pipeline/app/fsi_run.hpp"
#include "pipeline/app/interruption.hpp"
#include "pipeline/app/sweep/kept_series.hpp"
#include "pipeline/app/sweep/summary_reader.hpp"
#include "pipeline/app/sweep/sweep_table.hpp"
#include "pipeline/fsi/numerical_failure.hpp"
#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/folder_lock.hpp"
#include "pipeline/io/output_manifest.hpp"

namespace flapsim::optimize {

namespace {
// The longest wait for another evaluation of the same point to end [s] (a day: a run).
constexpr int kLongestWaitS = 86400;
}  // namespace

sweep::CasePoint point_at(const Problem& problem, const std::vector<double>& x) {
  sweep::CasePoint point;
  for (std::size_t i = 0; i < problem.bounds.size(); ++i) point.push_back({problem.bounds[i].key, x[i]});
  return point;
}

PointEvaluator::PointEvaluator(sweep::SweepInputs inputs, EvaluatorOptions options)
    : inputs_(std::move(inputs)), options_(std::move(options)), host_(sweep::host_name()) {}

sweep::ResolvedCase PointEvaluator::resolve(const sweep::CasePoint& point) const {
  return sweep::resolve_case(inputs_, point);
}

EvaluationOutcome PointEvaluator::evaluate(const sweep::CasePoint& point) const {
  const sweep::ResolvedCase r = resolve(point);
  EvaluationOutcome out;
  Evaluation& e = out.evaluation;
  e.point = point;
  e.inputs_hash = r.inputs_hash;
  e.rank = options_.rank;
  e.host = host_;
  const std::filesystem::path dir = folder(r.inputs_hash);
  const auto kept = [&]() {
    if (options_.force) return false;
    // Asked for its ParaView series, a run without them is run again (kept_series.hpp).
    if (!sweep::has_the_series_asked_for(dir, r.c, options_.vtk_every)) return false;
    auto results = sweep::kept_results(dir / "summary.json", r.inputs_hash);
    if (!results) return false;
    e.results = std::move(*results);
    e.status = "ok";
    e.message = "kept";
    return true;
  };
  if (kept()) return out;
  io::ensure_directory(dir);
  // The folder is locked while the point runs, as a sweep locks each case's folder. Two
  // starts (on two ranks) may ask for the same point at once: the second waits for the
  // first's run and keeps its results.
  std::optional<io::FolderLock> lock;
  for (int waited_s = 0;; ++waited_s) {
    try {
      lock.emplace(dir, "optimize");
      break;
    } catch (const io::OutputError& err) {
      if (std::string(err.what()).find("is writing into this folder now") == std::string::npos ||
          waited_s >= kLongestWaitS)
        throw;
    }
    std::this_thread::sleep_for(std::chrono::seconds(1));
  }
  if (kept()) return out;
  io::remove_stale_temporaries(dir);  // of a killed run of this point
  // An earlier run's files of this point (--force, or a finished point run again for its
  // series): its ParaView series would stay beside the new history, as in a sweep's case.
  io::remove_command_outputs(dir, "run");
  app::RunOptions ro;
  ro.output_dir = dir;
  ro.chain_file = inputs_.chain_file;
  ro.spring_scale = r.spring_scale;
  ro.wing_overrides = r.wing_overrides;
  ro.vtk_every = options_.vtk_every;
  ro.progress = app::ProgressLine::Mode::quiet;  // the optimisation prints a line per evaluation
  // The case's warnings in summary.json, as a sweep's case records them (the report and
  // evaluations.csv show them: evaluation_notes).
  std::vector<std::string> notes;
  ro.warnings = sweep::recorded_warnings(r, notes);
  try {
    e.results = app::run_case(r.c, ro);
    e.status = "ok";
  } catch (const app::Interrupted& err) {
    e.status = "interrupted";
    e.message = err.what();
    out.error = std::current_exception();
  } catch (const NumericalFailure& err) {
    e.status = "failed";
    e.message = err.what();
    out.error = std::current_exception();
  } catch (const std::exception& err) {
    e.status = "error";
    e.message = err.what();
    out.error = std::current_exception();
  }
  if (out.error) {
    // What the run wrote before it stopped (its summary.json says how far it got).
    if (auto partial = sweep::read_summary_results(dir / "summary.json")) e.results = std::move(*partial);
  }
  return out;
}

}  // namespace flapsim::optimize
