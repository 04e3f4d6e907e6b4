#include "pipeline/app/sweep/case_scheduler.hpp"

#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <mutex>
#include <string>
#include <thread>

namespace flapsim::sweep {

namespace {

using Clock = std::chrono::steady_clock;
constexpr int kRequestTag = 1401;  // worker -> rank 0: previous outcome (or nothing), wants a case
constexpr int kReplyTag = 1402;    // rank 0 -> worker: index of the next case, or -1

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// The shared list of rank 0 and the outcomes' way into `done`.
class CaseList {
 public:
  CaseList(const std::vector<std::size_t>& todo, const CaseDone& done) : todo_(todo), done_(done) {}

  long take() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (fatal_ || next_ >= todo_.size()) return -1;
    return static_cast<long>(todo_[next_++]);
  }

  void finish(std::size_t index, CaseOutcome&& outcome) {
    std::lock_guard<std::mutex> lock(mutex_);
    stats_.cases += 1;
    stats_.overhead_s += outcome.overhead_s;
    stats_.max_overhead_s = std::max(stats_.max_overhead_s, outcome.overhead_s);
    if (fatal_) return;
    try {
      done_(index, std::move(outcome));
    } catch (...) {
      fatal_ = std::current_exception();
    }
  }

  ScheduleStats stats() const { return stats_; }
  void rethrow() const {
    if (fatal_) std::rethrow_exception(fatal_);
  }

 private:
  const std::vector<std::size_t>& todo_;
  const CaseDone& done_;
  std::mutex mutex_;
  std::size_t next_ = 0;
  std::exception_ptr fatal_;
  ScheduleStats stats_;
};

// A worker thread: asks `next` for a case until it gets -1, runs each, hands its outcome
// (with the time spent outside the run) to `report` before asking again.
template <typename Next, typename Report>
void work(const RunCase& run, Next next, Report report) {
  auto idle_since = Clock::now();
  for (;;) {
    const long index = next();
    if (index < 0) return;
    const auto started = Clock::now();
    CaseOutcome outcome = run(static_cast<std::size_t>(index));
    // Overhead: before the run (previous report, request, table) plus after it until now.
    outcome.overhead_s += seconds(started - idle_since);
    idle_since = Clock::now();
    report(static_cast<std::size_t>(index), std::move(outcome), idle_since);
  }
}

// Starts `threads` local worker threads taking their cases from `list`.
std::vector<std::thread> start_local_workers(CaseList& list, int threads, const RunCase& run) {
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([&list, &run] {
      work(
          run, [&list] { return list.take(); },
          [&list](std::size_t i, CaseOutcome&& o, Clock::time_point since) {
            o.overhead_s += seconds(Clock::now() - since);
            list.finish(i, std::move(o));
          });
    });
  return pool;
}

ScheduleStats local_threads(const std::vector<std::size_t>& todo, int threads, const RunCase& run,
                            const CaseDone& done) {
  CaseList list(todo, done);
  std::vector<std::thread> pool = start_local_workers(list, threads, run);
  for (auto& t : pool) t.join();
  list.rethrow();
  return list.stats();
}

ScheduleStats master(const std::vector<std::size_t>& todo, int threads, int remote_threads,
                     const RunCase& run, const CaseDone& done) {
  CaseList list(todo, done);
  std::vector<std::thread> pool = start_local_workers(list, threads, run);
  std::string buffer;
  for (int active = remote_threads; active > 0;) {
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kRequestTag, MPI_COMM_WORLD, &flag, &status);
    if (!flag) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      continue;
    }
    int bytes = 0;
    MPI_Get_count(&status, MPI_CHAR, &bytes);
    buffer.assign(static_cast<std::size_t>(bytes), '\0');
    MPI_Recv(buffer.data(), bytes, MPI_CHAR, status.MPI_SOURCE, kRequestTag, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    if (bytes > 0) {
      std::size_t index = 0;
      CaseOutcome outcome;
      try {
        outcome = decode_outcome(buffer, index);
      } catch (const std::exception& e) {
        // Cannot happen between two copies of this program; if it does, the other ranks
        // would wait forever: end the whole job.
        std::fprintf(stderr, "flapsim sweep: %s (from rank %d)\n", e.what(), status.MPI_SOURCE);
        MPI_Abort(MPI_COMM_WORLD, 1);
      }
      list.finish(index, std::move(outcome));
    }
    long next = list.take();
    MPI_Send(&next, 1, MPI_LONG, status.MPI_SOURCE, kReplyTag, MPI_COMM_WORLD);
    if (next < 0) --active;
  }
  for (auto& t : pool) t.join();
  list.rethrow();
  return list.stats();
}

ScheduleStats worker(int threads, const RunCase& run) {
  std::mutex mpi;  // MPI_THREAD_SERIALIZED: one thread in MPI at a time
  std::mutex stats_mutex;
  ScheduleStats stats;
  auto body = [&] {
    std::string pending;  // the encoded outcome of this thread's previous case
    work(
        run,
        [&] {
          long next = -1;
          std::lock_guard<std::mutex> lock(mpi);
          MPI_Send(pending.data(), static_cast<int>(pending.size()), MPI_CHAR, 0, kRequestTag,
                   MPI_COMM_WORLD);
          MPI_Recv(&next, 1, MPI_LONG, 0, kReplyTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
          pending.clear();
          return next;
        },
        [&](std::size_t i, CaseOutcome&& o, Clock::time_point) {
          // The time until the next case starts (sending this outcome with the next
          // request) is counted as overhead of the next case, not of this one.
          {
            std::lock_guard<std::mutex> lock(stats_mutex);
            stats.cases += 1;
            stats.overhead_s += o.overhead_s;
            stats.max_overhead_s = std::max(stats.max_overhead_s, o.overhead_s);
          }
          pending = encode_outcome(i, o);
        });
  };
  if (threads == 1) {
    body();  // on the main thread: right also when MPI allows only the main thread in it
    return stats;
  }
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(body);
  for (auto& t : pool) t.join();
  return stats;
}

}  // namespace

ScheduleStats schedule_cases(const MpiWorld& world, const std::vector<std::size_t>& todo, int threads,
                             const RunCase& run, const CaseDone& done) {
  threads = std::max(1, threads);
  if (!world.active() || world.size() == 1) return local_threads(todo, threads, run, done);
  if (!world.serialized_threads()) threads = 1;  // only the main thread may call MPI (see MpiWorld)
  // Rank 0 learns how many worker threads the others run (it answers each one's last request with -1).
  std::vector<int> counts(static_cast<std::size_t>(world.size()), 0);
  MPI_Gather(&threads, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (world.rank() != 0) return worker(threads, run);
  int remote = 0;
  for (std::size_t r = 1; r < counts.size(); ++r) remote += counts[r];
  return master(todo, threads, remote, run, done);
}

}  // namespace flapsim::sweep
