#include "pipeline/app/optimize/optimize_report.hpp"

#include <cmath>
#include <cstdio>

#include "pipeline/app/after_run_notes.hpp"
#include "pipeline/app/run_results.hpp"
#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/csv_writer.hpp"

namespace flapsim::optimize {

namespace {

std::string number(double v) {
  if (!std::isfinite(v)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string key_of(std::size_t result) { return std::string(app::kRunResults[result].key); }

}  // namespace

std::string optimum_warning_advice(const Evaluation& best) {
  const std::string advice = app::after_run_advice(best.results);
  return advice.empty() ? "The search maximised the result the model gives there, warnings and all." : advice;
}

std::string optimize_report(const std::string& case_file, const Problem& problem, const OptimizeReport& report) {
  std::string md = "# flapsim optimize\n\n";
  md += "- case: `" + case_file + "`\n";
  md += "- maximise: `" + key_of(problem.objective) + "`\n";
  for (const Constraint& c : problem.constraints) md += "- subject to: `" + c.text + "`\n";
  md += "- algorithm: NLopt " + algorithm_name(report.algorithm) + " (docs/optimize.md)\n";
  if (report.starts > 1)
    md += "- starts: " + std::to_string(report.starts) + " (the case's values, then Halton points; docs/optimize.md)\n";
  md += "- ranks: " + std::to_string(report.ranks) + "\n";
  md += "- stopped: " + report.stop_reason + "\n";
  md += "- evaluations: " + std::to_string(report.evaluations.size()) + " (" + std::to_string(report.runs) +
        " run, " + std::to_string(report.evaluations.size() - report.runs) + " kept: evaluated before, by an earlier run or another start), " +
        number(report.wall_s) + " s wall\n\n";

  md += "| key | lower bound | upper bound | start | optimum |\n|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < problem.bounds.size(); ++i) {
    const Bound& b = problem.bounds[i];
    md += "| `" + b.key + "` | " + io::format_number(b.lo) + " | " + io::format_number(b.hi) + " | " +
          sweep::value_label(report.start[i]) + " | " +
          (report.best ? sweep::value_label(report.evaluations[*report.best].point[i].value) : std::string("-")) +
          " |\n";
  }
  md += "\n";

  if (report.best) {
    const Evaluation& best = report.evaluations[*report.best];
    md += "## Optimum\n\n`" + key_of(problem.objective) + "` = " + number(result_value(best, problem.objective)) +
          " at evaluation " + std::to_string(report.numbers[*report.best]) + " (`runs/" + best.inputs_hash +
          "/`)";
    for (const Constraint& c : problem.constraints) md += "; `" + key_of(c.result) + "` = " + number(result_value(best, c.result));
    md += ".\n\n";
    if (const std::string notes = evaluation_notes(best); !notes.empty())
      md += "**The optimum's run was warned**: " + notes +
            " (its `summary.json`; docs/case_file.md, \"Warnings\"). " + optimum_warning_advice(best) +
            "\n\n";
    md += "Run it: `flapsim run " + report.optimum_case.filename().string() +
          (report.optimum_spring_scale != 1.0 ? " --spring-scale " + io::format_number(report.optimum_spring_scale)
                                              : std::string()) +
          " -o DIR` (from this folder).\n\n";
  } else if (problem.constraints.empty()) {
    // Without constraints only failed runs leave no optimum (it said "satisfies the
    // constraints ... Relax the constraint" of a search that had none).
    md +=
        "## No optimum\n\nNo evaluated point completed its run (the status and message of each are in "
        "`evaluations.csv`, the run's own files in `runs/`). No optimum.toml was written.\n\n";
  } else {
    md += "## No optimum\n\nNo evaluated point satisfies the constraints";
    double least = INFINITY;
    std::size_t at = 0;
    for (std::size_t i = 0; i < report.evaluations.size(); ++i) {
      double worst = 0.0;
      for (const Constraint& c : problem.constraints)
        worst = std::max(worst, c.violation(result_value(report.evaluations[i], c.result)));
      if (worst < least) least = worst, at = i;
    }
    if (std::isfinite(least))
      md += "; the nearest, evaluation " + std::to_string(report.numbers[at]) + ", misses by " + number(least);
    md += ". Relax the constraint or widen the bounds. No optimum.toml was written.\n\n";
  }
  if (report.max_evaluations_reached)
    md += "The search stopped at its maximum of evaluations before converging: run the same command with a "
          "larger --max-evaluations to go on (the points evaluated so far are reused).\n\n";

  const bool several = report.starts > 1;
  md += "## Evaluations\n\n| # |";
  if (several) md += " start |";
  for (const Bound& b : problem.bounds) md += " `" + b.key + "` |";
  md += " `" + key_of(problem.objective) + "` |";
  for (const Constraint& c : problem.constraints) md += " `" + key_of(c.result) + "` |";
  md += " status |\n|---|";
  for (std::size_t i = 0; i < problem.bounds.size() + 2 + problem.constraints.size() + (several ? 1 : 0); ++i)
    md += "---|";
  md += "\n";
  for (std::size_t i = 0; i < report.evaluations.size(); ++i) {
    const Evaluation& e = report.evaluations[i];
    // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive, GCC bug 105329)
    // about `" " + std::string&&` once inlined.
    md.append("| ").append(std::to_string(report.numbers[i])).append(" |");
    if (several) md.append(" ").append(std::to_string(report.start_of[i])).append(" |");
    for (const sweep::Assignment& a : e.point) md.append(" ").append(sweep::value_label(a.value)).append(" |");
    // A run that did not complete has no result (its partial means are not one): "—".
    const auto shown = [&](std::size_t key) {
      return e.status == "ok" ? number(result_value(e, key)) : std::string("—");
    };
    md.append(" ").append(shown(problem.objective)).append(" |");
    for (const Constraint& c : problem.constraints) md.append(" ").append(shown(c.result)).append(" |");
    md.append(" ").append(e.status);
    if (e.message == "kept") md.append(" (kept)");
    if (!evaluation_notes(e).empty()) md.append(" (warned)");
    if (report.best && *report.best == i) md.append(" **optimum**");
    md.append(" |\n");
  }
  md += "\nAll results of every evaluation: `evaluations.csv` (\"warned\": its `warnings` column, and the "
        "`peak_tip_bend_deg`, `peak_tip_twist_deg` of a chain beyond 30°); each run's files: "
        "`runs/<inputs hash>/`.\n";
  return md;
}

void write_optimize_report(const std::filesystem::path& dir, const std::string& case_file, const Problem& problem,
                           const OptimizeReport& report) {
  io::write_text_atomically(dir / "report.md", optimize_report(case_file, problem, report));
}

}  // namespace flapsim::optimize
