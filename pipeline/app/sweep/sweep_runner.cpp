#include "pipeline/app/sweep/sweep_runner.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <thread>

#include "pipeline/app/fsi_run.hpp"
#include "pipeline/fsi/numerical_failure.hpp"
#include "pipeline/io/atomic_file.hpp"
#include "pipeline/io/csv_writer.hpp"

namespace flapsim::sweep {

namespace {

void write_table(const std::filesystem::path& path, const std::string& key,
                 const std::vector<SweepRow>& rows, const std::vector<bool>& done) {
  std::vector<std::string> header{key};
  for (std::size_t i : app::sweep_results()) header.emplace_back(app::kRunResults[i].key);
  header.insert(header.end(), {"folder", "status"});
  std::vector<std::vector<std::string>> cells;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!done[i]) continue;
    const SweepRow& r = rows[i];
    std::vector<std::string> row{io::format_number(r.value)};
    for (std::string& cell : app::sweep_cells(r.results)) row.push_back(std::move(cell));
    row.push_back(r.folder);
    row.push_back(r.status);
    cells.push_back(std::move(row));
  }
  io::write_csv(path, header, cells);
}

}  // namespace

std::vector<SweepRow> run_sweep(const std::string& case_file, const Variation& variation,
                                const SweepOptions& options) {
  const std::size_t n = variation.values.size();
  std::vector<io::Case> cases;
  cases.reserve(n);
  for (double v : variation.values) cases.push_back(load_case_with(case_file, variation.key, v));

  io::ensure_directory(options.output_dir);
  std::vector<SweepRow> rows(n);
  std::vector<bool> done(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    rows[i].value = variation.values[i];
    char name[96];
    std::snprintf(name, sizeof name, "%02zu_%s", i, value_label(variation.values[i]).c_str());
    rows[i].folder = name;
  }
  const int threads = std::max(
      1, std::min<int>(static_cast<int>(n), options.threads > 0
                                               ? options.threads
                                               : static_cast<int>(std::thread::hardware_concurrency())));
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  std::size_t finished = 0;
  const auto start = std::chrono::steady_clock::now();
  std::exception_ptr fatal;

  auto worker = [&] {
    omp_set_num_threads(1);  // the cases fill the cores; no nested parallelism
    for (;;) {
      const std::size_t i = next.fetch_add(1);
      if (i >= n) return;
      app::RunOptions ro;
      ro.output_dir = options.output_dir / rows[i].folder;
      ro.chain_file = options.chain_file;
      ro.spring_scale = options.spring_scale;
      ro.vtk_every = options.vtk_every;
      ro.progress = app::ProgressLine::Mode::quiet;
      SweepRow r = rows[i];
      try {
        r.results = app::run_case(cases[i], ro);
        r.status = "ok";
      } catch (const NumericalFailure& e) {
        r.status = std::string("failed: ") + e.what();
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!fatal) fatal = std::current_exception();
        next = n;  // stop handing out cases
        return;
      }
      std::lock_guard<std::mutex> lock(mutex);
      rows[i] = r;
      done[i] = true;
      ++finished;
      write_table(options.output_dir / "sweep.csv", variation.key, rows, done);
      if (!options.quiet) {
        const double wall =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "sweep %zu/%zu  %s = %s  mean lift %.5g N  CL %.3f  %s  (%.1f s)\n",
                     finished, n, variation.key.c_str(), value_label(r.value).c_str(),
                     r.results.number("mean_lift_N"), r.results.number("mean_CL"),
                     r.status == "ok" ? "ok" : "FAILED", wall);
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  if (fatal) std::rethrow_exception(fatal);
  return rows;
}

}  // namespace flapsim::sweep
