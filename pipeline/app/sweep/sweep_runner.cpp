#include "pipeline/app/sweep/sweep_runner.hpp"

#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <new>
#include <optional>
#include <set>
#include <thread>

#include "pipeline/app/after_run_notes.hpp"
#include "pipeline/app/fsi_run.hpp"
#include "pipeline/app/interruption.hpp"
#include "pipeline/app/omp_environment.hpp"
#include "pipeline/app/resource_estimate.hpp"
#include "pipeline/app/sweep/earlier_cases.hpp"
#include "pipeline/app/sweep/kept_series.hpp"
#include "pipeline/app/sweep/keys_that_change_nothing.hpp"
#include "pipeline/app/sweep/summary_reader.hpp"
#include "pipeline/app/sweep/sweep_case.hpp"
#include "pipeline/app/sweep/sweep_progress.hpp"
#include "pipeline/fsi/numerical_failure.hpp"
#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/folder_lock.hpp"
#include "pipeline/io/output_manifest.hpp"
#include "wings/loader/input_error.hpp"

namespace flapsim::sweep {

namespace {

using Clock = std::chrono::steady_clock;

// The outcome of a case that an interruption kept from starting.
constexpr const char* kNotRun = "not run";

// The message of a case that ran out of memory (std::bad_alloc).
constexpr const char* kOutOfMemory = "out of memory (the run's arrays did not fit; fewer cases at once: --jobs)";

// Rank 0 checks every case; the others learn whether to go on (and stop as it does).
void share_check(const MpiWorld& world, bool ok) {
  if (!world.active()) return;
  int flag = ok ? 1 : 0;
  MPI_Bcast(&flag, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (!flag && world.rank() != 0)
    throw InputError("", 0, "", "rank 0 found bad input and stopped the sweep (its message says why)");
}

int default_threads(const MpiWorld& world, std::size_t cases) {
  // OMP_NUM_THREADS, when set, is the user's threads per process (as for every command:
  // docs/performance.md); else the machine's cores shared by the ranks on it.
  const int per_rank = app::omp_num_threads_set()
                           ? std::max(1, omp_get_max_threads())
                           : std::max(1, std::max(1, static_cast<int>(std::thread::hardware_concurrency())) /
                                             std::max(1, world.ranks_on_host()));
  // Without MPI, no more threads than cases.
  return world.active() ? per_rank : std::max(1, std::min<int>(per_rank, static_cast<int>(cases)));
}

// The line of a finished case.
std::string finished_line(std::size_t finished, std::size_t total, const SweepRow& r, double wall) {
  const std::string head = "sweep " + std::to_string(finished) + "/" + std::to_string(total) + "  " + describe(r.point);
  char numbers[128];
  if (r.outcome.results.has("mean_CL"))
    std::snprintf(numbers, sizeof numbers, "  mean lift %.5g N  CL %.3f  ", r.outcome.results.number("mean_lift_N"),
                  r.outcome.results.number("mean_CL"));
  else  // in vacuum (or a run that stopped before its first step)
    std::snprintf(numbers, sizeof numbers, "  ");
  const char* status = r.outcome.status == "ok" ? "ok" : r.outcome.status == "interrupted" ? "INTERRUPTED" : "FAILED";
  char tail[64];
  std::snprintf(tail, sizeof tail, "  (rank %d, %.1f s)", r.outcome.rank, wall);
  return head + numbers + status + (r.outcome.message.empty() ? "" : ": ") + r.outcome.message + tail;
}

// Whether a case's error says that its output found no room: an io::OutputError ("cannot
// write '…'") from a write that failed (its message asks "disk full?") or from the system's
// ENOSPC, EDQUOT or EFBIG (the text of strerror). Text, because a remote rank's outcome
// arrives as text.
bool out_of_room(const std::string& message) {
  if (message.rfind("cannot write '", 0) != 0) return false;
  for (const char* cause : {"disk full", "No space left on device", "Disk quota exceeded", "File too large"})
    if (message.find(cause) != std::string::npos) return true;
  return false;
}

}  // namespace

SweepPlan grid_plan(const std::vector<Variation>& variations) {
  SweepPlan plan;
  for (const Variation& v : variations) plan.keys.push_back(v.key);
  plan.points = cartesian_grid(variations);
  return plan;
}

SweepReport run_sweep(const std::string& case_file, const SweepPlan& plan, const SweepOptions& options) {
  const auto start = Clock::now();
  MpiWorld world;
  SweepReport report;
  report.root = world.rank() == 0;
  report.ranks = world.size();
  const std::size_t n = plan.points.size();
  const SweepInputs inputs{case_file, options.chain_file, options.spring_scale, options.wing_file};
  const std::string host = host_name();

  // 1. Rank 0 resolves and checks every case, and finds those an earlier run completed.
  std::vector<ResolvedCase> resolved;
  std::vector<std::size_t> todo;
  std::vector<SweepRow>& rows = report.rows;
  std::optional<io::FolderLock> folder_lock;  // rank 0: no other sweep writes into DIR meanwhile
  if (report.root) {
    try {
      resolved.reserve(n);
      // ~10 ms a case: a large grid checks for seconds to minutes, and SIGTERM (Slurm's 30 s
      // grace) was acted on only once every case was checked (a 100 000-case grid ran on).
      for (std::size_t i = 0; i < n; ++i) {
        app::throw_if_interrupted("while checking case " + std::to_string(i + 1) + " of " +
                                  std::to_string(n) + " before any ran; nothing was written");
        resolved.push_back(resolve_case(inputs, plan.points[i], plan.source(i)));
      }
      refuse_keys_that_change_nothing(inputs, plan, resolved, options.vtk_every);
    } catch (...) {
      share_check(world, false);
      throw;
    }
    try {
      io::ensure_directory(options.output_dir);
      folder_lock.emplace(options.output_dir, "sweep");
    } catch (...) {
      share_check(world, false);
      throw;
    }
    rows.resize(n);
    std::set<std::string> own_folders;
    for (std::size_t i = 0; i < n; ++i) own_folders.insert(case_folder(i, n, plan.points[i]));
    EarlierCases earlier(options.output_dir, std::move(own_folders));  // completed cases under another index (a grid extended)
    const std::map<std::string, RanOn> ran_on = earlier_ran_on(options.output_dir / "sweep.csv");
    for (std::size_t i = 0; i < n; ++i) {
      rows[i].point = plan.points[i];
      rows[i].folder = case_folder(i, n, plan.points[i]);
      std::optional<app::RunResults> kept;
      bool in_own_folder = false;  // kept where it ran, not adopted from another index's folder
      if (!options.force) {
        kept = kept_results(options.output_dir / rows[i].folder / "summary.json", resolved[i].inputs_hash);
        in_own_folder = kept.has_value();
        if (!kept) kept = earlier.adopt(resolved[i].inputs_hash, rows[i].folder);
        // A run asked for its ParaView series (--vtk-every) keeps a case only if the earlier
        // run wrote them (kept_series.hpp): a sweep run again with --vtk-every to get
        // pictures kept every case and wrote none; a FEM sweep's, looked for under
        // chain.pvd, kept none.
        if (kept &&
            !has_the_series_asked_for(options.output_dir / rows[i].folder, resolved[i].c, options.vtk_every))
          kept.reset();
      }
      if (kept) {
        rows[i].done = true;
        std::string message = kept_message(*kept);
        rows[i].outcome = CaseOutcome{"ok", std::move(message), world.rank(), host, std::move(*kept), 0.0};
        // Where it ran, as the earlier table gave its folder (else this rank, which found it kept).
        if (const auto where = ran_on.find(rows[i].folder); in_own_folder && where != ran_on.end()) {
          rows[i].outcome.rank = where->second.rank;
          rows[i].outcome.host = where->second.host;
        }
        ++report.kept;
      } else {
        todo.push_back(i);
      }
    }
    write_sweep_table(options.output_dir / "sweep.csv", plan.keys, rows);
    if (!options.quiet && report.kept > 0)
      std::fprintf(stderr, "sweep: %zu of %zu cases kept from an earlier run (their summary.json matches)\n",
                   report.kept, n);
  }
  share_check(world, true);

  // 2. The cases, over the threads (and ranks), with the progress of those under way.
  SweepProgress progress(n, report.kept, world.rank(),
                         options.quiet ? app::ProgressLine::Mode::quiet : app::ProgressLine::Mode::automatic,
                         options.log_interval);
  report.threads = options.threads > 0 ? options.threads : default_threads(world, todo.size());
  if (report.root && !options.quiet && !todo.empty()) {
    // What the cases to run will take, each as `flapsim run` estimates it (one thread each,
    // as the sweep runs them), the threads of all ranks sharing them.
    double total = 0.0, longest = 0.0;
    for (std::size_t i : todo) {
      total += resolved[i].estimated_seconds;
      longest = std::max(longest, resolved[i].estimated_seconds);
    }
    const int workers = std::max(1, report.threads) * std::max(1, report.ranks);
    std::fprintf(stderr,
                 "sweep: estimate: %zu case%s to run, of the order of %s of one thread's time in all (the "
                 "longest %s), about %s on %d thread%s\n",
                 todo.size(), todo.size() == 1 ? "" : "s", app::seconds_text(total).c_str(),
                 app::seconds_text(longest).c_str(),
                 app::seconds_text(std::max(longest, total / workers)).c_str(), workers,
                 workers == 1 ? "" : "s");
  }
  const RunCase run = [&](std::size_t i) {
    omp_set_num_threads(1);  // the cases fill the cores; no nested parallelism
    CaseOutcome o;
    o.rank = world.rank();
    o.host = host;
    // After SIGINT/SIGTERM no case starts (interruption.hpp); the cases under way finish
    // their step, write summary.json ("interrupted") and end below.
    if (app::pending_interrupt() != 0) {
      o.status = kNotRun;
      return o;
    }
    const auto t0 = Clock::now();
    progress.started(i, case_folder(i, n, plan.points[i]));
    struct Ended {
      SweepProgress& p;
      std::size_t i;
      ~Ended() { p.ended(i); }
    } ended{progress, i};
    // The case's warnings in a few words: its files' (with the point's values), its setup's
    // (setup_warnings.hpp), then what its results say after the run (after_run_notes.hpp).
    std::vector<std::string> notes;
    try {
      // Rank 0 resolved every case; the others resolve the ones they are given.
      std::optional<ResolvedCase> own;
      if (resolved.empty()) own = resolve_case(inputs, plan.points[i], plan.source(i));
      const ResolvedCase& r = own ? *own : resolved[i];
      app::RunOptions ro;
      ro.output_dir = options.output_dir / case_folder(i, n, plan.points[i]);
      // The case's folder is locked while the case runs, as `flapsim run` locks its folder
      // (folder_lock.hpp): a `flapsim run -o DIR/<case>` started meanwhile stops before
      // writing (exit 4), and a case whose folder another command is writing into now is
      // not run (status error, the message says so; the same sweep again runs it).
      io::ensure_directory(ro.output_dir);
      const io::FolderLock case_lock(ro.output_dir, "sweep");
      // Another command's outputs there (a `flapsim reduce -o DIR/<case>`'s summary.json beside
      // its chain.toml) are not the sweep's to replace, as `flapsim run` refuses them (exit 4):
      // the case is not run (status error, the message names them); the others go on.
      io::refuse_clashing_outputs(ro.output_dir, "run");
      io::remove_stale_temporaries(ro.output_dir);  // of a killed run of this case
      // An earlier run's files of this case (a sweep run again, --force, or a finished case
      // run again for its series): its ParaView series would stay beside the new history.
      io::remove_command_outputs(ro.output_dir, "run");
      ro.chain_file = options.chain_file;
      ro.spring_scale = r.spring_scale;
      ro.wing_overrides = r.wing_overrides;
      ro.vtk_every = options.vtk_every;
      ro.progress = app::ProgressLine::Mode::quiet;  // the sweep's own line shows the step
      ro.on_step = [&progress, i](long step, long total) { progress.step(i, step, total); };
      // Recorded in summary.json too: a sweep run again gives them in the row of the case it keeps.
      ro.warnings = recorded_warnings(r, notes);
      o.overhead_s = std::chrono::duration<double>(Clock::now() - t0).count();  // resolving
      o.results = app::run_case(r.c, ro);
      o.status = "ok";
      for (std::string& note : app::after_run_notes(o.results)) notes.push_back(std::move(note));
      o.message = with_notes("", notes);
    } catch (const app::Interrupted& e) {
      o.status = "interrupted";
      // Its summary.json says how far it got; a rerun of the sweep runs it again.
      o.message = with_notes(e.what(), notes);
    } catch (const NumericalFailure& e) {
      o.status = "failed";
      // No results in the table (nan): its summary.json tells how far it got.
      o.message = with_notes(e.what(), notes);
    } catch (const io::OutputError& e) {
      o.status = "error";
      o.message = e.what();  // "cannot write '…'": stops the sweep once recorded (below)
    } catch (const std::bad_alloc&) {
      o.status = "error";
      o.message = kOutOfMemory;  // stops the sweep once recorded (below), as run exits 4
    } catch (const std::exception& e) {
      o.status = "error";
      o.message = e.what();
    } catch (...) {
      o.status = "error";
      o.message = "unknown error";
    }
    return o;
  };
  std::size_t finished = report.kept;
  auto last_write = Clock::now();
  const CaseDone done = [&](std::size_t i, CaseOutcome&& o) {
    if (o.status == kNotRun) return;  // interrupted before it started: not in the table
    rows[i].outcome = std::move(o);
    rows[i].done = true;
    ++finished;
    const auto now = Clock::now();
    if (n <= 1000 || now - last_write > std::chrono::seconds(5) || finished == n) {
      write_sweep_table(options.output_dir / "sweep.csv", plan.keys, rows);
      last_write = now;
    }
    if (!options.quiet)
      progress.print_line(finished_line(finished, n, rows[i], std::chrono::duration<double>(now - start).count()),
                          finished);
    // A case that could not write its files for want of room (a full disk, a quota, a
    // file-size limit): the next cases would fail alike, so the sweep stops (exit status 4)
    // once the case is in the table; the same command resumes it. (A folder that cannot be
    // written is the case's own error: the others go on.)
    // So does a case that ran out of memory (exit status 4, as `flapsim run`).
    if (const CaseOutcome& o = rows[i].outcome; o.status == "error" && (out_of_room(o.message) || o.message == kOutOfMemory))
      throw io::OutputError(options.output_dir / rows[i].folder,
                            std::string(o.message == kOutOfMemory ? "the case ran out of memory" : "the case's output failed") +
                            ", so the sweep stops (no further case starts; sweep.csv "
                            "lists the cases so far; the same command resumes): " + o.message);
  };
  report.stats = schedule_cases(world, todo, report.threads, run, done);
  if (report.root) write_sweep_table(options.output_dir / "sweep.csv", plan.keys, rows);
  report.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  if (const int signal = app::pending_interrupt(); signal != 0) {
    const auto complete = static_cast<std::size_t>(
        std::count_if(rows.begin(), rows.end(), [](const SweepRow& r) { return r.done && r.outcome.status != "interrupted"; }));
    throw app::Interrupted(signal, std::string("sweep interrupted by ") + (signal == SIGINT ? "SIGINT" : "SIGTERM") +
                                       (report.root ? ": " + std::to_string(complete) + " of " + std::to_string(n) +
                                                          " cases finished (" + (options.output_dir / "sweep.csv").string() +
                                                          "); the same command again runs the rest"
                                                    : std::string()));
  }
  return report;
}

}  // namespace flapsim::sweep
