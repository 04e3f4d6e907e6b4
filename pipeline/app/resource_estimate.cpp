#include "pipeline/app/resource_estimate.hpp"

#include <omp.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "pipeline/app/frames_size.hpp"
#include "pipeline/app/run_history.hpp"
#include "uvlm/leading_edge_sheet.hpp"
#include "uvlm/segment_tree.hpp"
#include "uvlm/vortex_lattice.hpp"
#include "wings/loader/input_error.hpp"

namespace flapsim::app {

std::string seconds_text(double s) {
  char buf[32];
  if (s >= 86400.0) std::snprintf(buf, sizeof buf, "%.2g days", s / 86400.0);
  else if (s >= 3600.0) std::snprintf(buf, sizeof buf, "%.2g h", s / 3600.0);
  else if (s >= 60.0) std::snprintf(buf, sizeof buf, "%.2g min", s / 60.0);
  else std::snprintf(buf, sizeof buf, "%.2g s", s);
  return buf;
}

namespace {

// Σ f(r) for the integers r = from … to (none if to < from), f a polynomial of degree at
// most 2 there: fitted through f(from), f(from + 1), f(from + 2) (Newton's forward
// differences) and summed with Σ C(j, 1) = m(m−1)/2, Σ C(j, 2) = m(m−1)(m−2)/6, j = 0 … m−1.
template <typename F>
double sum_quadratic(F f, double from, double to) {
  const double m = to - from + 1.0;
  if (!(m >= 1.0)) return 0.0;
  const double f0 = f(from), d1 = f(from + 1.0) - f0, d2 = f(from + 2.0) - 2.0 * f(from + 1.0) + f0;
  return f0 * m + d1 * m * (m - 1.0) / 2.0 + d2 * m * (m - 1.0) * (m - 2.0) / 6.0;
}

}  // namespace

std::string bytes_text(double b) {
  char buf[32];
  if (b >= 1e9)
    std::snprintf(buf, sizeof buf, "%.3g GB", b / 1e9);
  else if (b >= 1e6)
    std::snprintf(buf, sizeof buf, "%.3g MB", b / 1e6);
  else
    std::snprintf(buf, sizeof buf, "%.3g kB", b / 1e3);
  return buf;
}

double nominal_interactions_per_second(uvlm::KernelIsa isa, bool single_precision) {
  switch (isa) {
    case uvlm::KernelIsa::Scalar: return single_precision ? 4.2e8 / 2 : 1.9e8 / 2;
    case uvlm::KernelIsa::Avx2: return single_precision ? 9.7e8 / 2 : 4.3e8 / 2;
    case uvlm::KernelIsa::Avx512: return single_precision ? 1.2e9 / 2 : 5.4e8 / 2;
  }
  return 1.9e8 / 2;
}

double tree_pairs_per_target(double segments, double tolerance) {
  const double theta = uvlm::tree_parameters(tolerance).theta;
  const double at_reference = theta >= 0.45  ? 2330.0
                              : theta >= 0.3 ? 5040.0
                              : theta >= 0.2 ? 9020.0
                                             : 18900.0;
  return at_reference * std::log2(std::max(segments, 2.0)) / std::log2(kTreeReferenceSegments);
}

double lattice_factorisations(double solves, double cycles, bool iterative) {
  return iterative ? std::min(solves, 4.0 + 4.0 * cycles) : solves;
}

double fem_memory_bytes(double dofs) {
  return dofs > 0.0 ? 30.0 * dofs * std::log2(std::max(dofs, 2.0)) * 12.0 + 40.0 * dofs * 8.0 : 0.0;
}

RunEstimate estimate_run(const io::Case& c, int bodies, int fem_dofs, int reduced_fem_dofs) {
  RunEstimate e;
  const auto& n = c.numerics;
  e.steps = n.total_steps();
  const double steps = static_cast<double>(e.steps);
  const double nc = n.chordwise_panels, ns = n.spanwise_panels;
  const double panels = nc * ns;
  // Mean coupling iterations per step: a few (docs/fsi.md, "Added mass in the coupling":
  // a chain with the added mass 2.9–4.4 measured (the hawkmoth hover 2.9–3.3 at 100 steps a
  // cycle, 4.4 at 40), the hawkmoth's FEM 3.97, 4 taken; without it and with sub-steps
  // (which leave it out) 5; a film wing's FEM, which drops it, 6–8); the cap bounds it.
  const bool added_mass = (bodies > 1 || fem_dofs > 0) && n.added_mass && n.structure_substeps == 1;
  const double typical = added_mass ? 4.0 : 5.0;
  const double iterations = std::min(typical, static_cast<double>(n.max_coupling_iterations));

  double memory = 64e6;  // the program, libraries, VTK and the wing: a fixed allowance [B]
  memory += steps * static_cast<double>(sizeof(StepSample));
  if (c.air.enabled) {
    // Each step's strip lifts (RunRecorder, span_loads.csv): ns doubles.
    memory += steps * static_cast<double>(sizeof(double)) * ns;
    // Wake storage for rows = wake capacity + 1 (vortex_lattice.cpp): per node the
    // position and the AB2 velocity (6 doubles), per ring a circulation, per segment
    // two end points, a circulation and a core (8 doubles).
    const double rows = (n.wake_max_rows > 0 ? std::min<double>(n.wake_max_rows, steps) : steps) + 1.0;
    e.wake_panels = static_cast<std::int64_t>((rows - 1.0) * ns);
    const double wake_nodes = (rows + 1.0) * (ns + 1.0);
    const double wake_segments = (rows + 1.0) * ns + rows * (ns + 1.0);
    // A shed leading edge (numerics.leading_edge = "shed") adds its vortex sheet: up to a
    // node row a step (it gains one at nearly every step of a flapping wing: 99 of the
    // first 100 of the rigid hover, docs/performance.md), as the wake, and its segments are
    // summed with the wake's, in the same precision (uvlm/leading_edge_sheet.hpp): stored for
    // a ring a step (uvlm::sheet_ring_capacity, fsi_setup.cpp; not shortened by
    // wake_max_rows), and in the sums, merged from sheet_merge_steps steps old,
    // uvlm::merged_sheet_rings(r) rings where the wake has r rows (r without merging).
    const bool shed = n.leading_edge == uvlm::LeadingEdge::Shed;
    const int merge = shed ? n.sheet_merge_steps : 0, spread = n.sheet_merge_spread_steps;
    memory += wake_nodes * 6 * 8 + rows * ns * 8 + wake_segments * 8 * 8;
    double summed_segments = wake_segments;
    if (shed) {  // the same per ring, its rings' node rows and one more (the release row)
      const double rings = uvlm::sheet_ring_capacity(steps);
      const double sheet_segments = (rings + 1.0) * ns + rings * (ns + 1.0);
      memory += (rings + 1.0) * (ns + 1.0) * 6 * 8 + rings * ns * 8 + sheet_segments * 8 * 8;
      summed_segments += sheet_segments;
    }
    // The tree code's storage, reserved for every segment the wake (and sheet) can hold
    // (vortex_lattice.cpp): about 2.6 kB a segment, 40 times the segment's own. Until 2 Dec
    // 2026 it was not counted: a 200-cycle hover with the tree estimated at 82 MB held 495 MB
    // after 6 s, and a run under `ulimit -v` that check passed stopped out of memory.
    if (n.wake_sum == uvlm::WakeSum::Tree)
      memory +=
          uvlm::SegmentTree::reserved_bytes(static_cast<std::size_t>(summed_segments), omp_get_max_threads());
    e.lattice_bytes = 2.0 * panels * panels * 8;  // influence matrix and its LU
    memory += e.lattice_bytes;
    // Interactions: at step k the wake has r = min(k, max_rows) rows; the wake's nodes move
    // by their induced velocity (every segment at each node) only in the rows younger than
    // far_wake_cycles or frozen_wake_cycles (the older rows move as a whole or stand:
    // docs/uvlm.md, "Far wake"), and every collocation point sees every segment once per
    // lattice solve: one per step for a rigid wing, a few coupling iterations for a chain.
    const double max_rows = n.wake_max_rows > 0 ? n.wake_max_rows : steps;
    const double old_after_cycles = n.far_wake_cycles > 0.0 ? n.far_wake_cycles : n.frozen_wake_cycles;
    const double free_rows = old_after_cycles > 0.0
                                 ? std::max(1.0, std::floor(old_after_cycles * n.steps_per_cycle))
                                 : std::numeric_limits<double>::infinity();
    const double solves = bodies > 1 || fem_dofs > 0 ? iterations : 1.0;
    const double bound_segments = (nc + 1) * ns + nc * (ns + 1);
    auto ring_segments = [&](double rings) { return (rings + 1) * ns + rings * (ns + 1); };
    // A far wake summed by the tree code (model.far_wake_by_tree): its rows since the last
    // build are summed directly, at least far_tree_rebuild_steps / 2 of them on average (here;
    // the more of a longer interval with the tree's builds, below); the rest cost each target
    // tree_pairs_per_target.
    const bool far_tree = n.far_wake_cycles > 0.0 && n.wake_sum == uvlm::WakeSum::Tree;
    // A truncated wake (wake_max_rows) drops rows at every step: its far tree is rebuilt at
    // every step (uvlm/wake.cpp).
    const bool truncated = n.wake_max_rows > 0;
    const double rebuild = truncated ? 1.0 : uvlm::VortexLatticeModel{}.far_tree_rebuild_steps;
    const double direct_rows =
        far_tree ? free_rows + std::floor(0.5 * rebuild) : std::numeric_limits<double>::infinity();
    auto targets_at = [&](double r) {
      const double young = std::min(r, free_rows);
      double moving_rows = young + 1;
      if (shed) moving_rows += uvlm::merged_sheet_rings(merge, young, spread) + 1;
      return (n.free_wake ? moving_rows * (ns + 1) : 0.0) + solves * panels;
    };
    auto step_cost = [&](double r) {
      const double young = std::min(r, free_rows);
      double segs = ring_segments(std::min(r, direct_rows)), moving_rows = young + 1;
      if (shed) {
        segs += ring_segments(uvlm::merged_sheet_rings(merge, r, spread));
        moving_rows += uvlm::merged_sheet_rings(merge, young, spread) + 1;
      }
      const double moving_nodes = n.free_wake ? moving_rows * (ns + 1) : 0.0;
      return (moving_nodes + solves * panels) * (segs + bound_segments);
    };
    // Sum over steps, in closed form per part, where the count is quadratic in r: the wake
    // growing with its nodes all moving, growing beyond the moving rows, and the merged
    // sheet's parts (merged_sheet_rings: r up to 3M + K − 1, constant to 16M + K − 1, linear
    // beyond; K the releases a merge is spread over); then a wake of max_rows.
    const double growing = std::min(steps, max_rows);
    const double moving = std::min(growing, free_rows);
    const double apart = merge > 0 ? spread - 1.0 : 0.0;
    double ends[] = {moving, growing, 3.0 * merge + apart,
                     static_cast<double>(uvlm::kSheetMergeMaxRows) * merge + apart, std::floor(direct_rows)};
    std::sort(std::begin(ends), std::end(ends));
    double sum = 0.0, from = 1.0;
    for (double end : ends) {
      if (end < from || end > growing) continue;
      sum += sum_quadratic(step_cost, from, end);
      from = end + 1.0;
    }
    sum += std::max(0.0, steps - growing) * step_cost(max_rows);
    e.interactions = sum;
    // The tree's rows at step k: m = min(k, max_rows) − direct_rows, of N(m) = ring_segments(m)
    // segments, seen by T = targets_at(k) points (constant once the far wake exists). Its
    // evaluations: Σ log₂ N(m) over m = 1 … M in closed form: with N(m) = s (m + a), s = 2 ns +
    // 1, a = ns / s, it is M log₂ s + (lnΓ(M + 1 + a) − lnΓ(1 + a)) / ln 2. Its builds, every
    // k(N) = max(k₀, c √N) steps (uvlm::far_tree_rebuild_interval, c = √(2κ / (s T')), κ the
    // build's pairs a segment, T' the young wake's nodes and the panels the interval is chosen
    // for; k₀ = far_tree_rebuild_steps): κ N / k a step, and the rows that joined since, beyond
    // the k₀/2 counted in the interactions, T s (k − k₀)/2 a step: for N ≤ N₀ = (k₀/c)² κ N/k₀,
    // above it A √N − B with A = κ/c + T s c/2, B = T s k₀/2; Σ √N(m) by the midpoint rule,
    // √s (2/3) [(m + a)^{3/2}] from m − 1/2 to m + 1/2.
    if (far_tree && std::floor(direct_rows) < growing) {
      const double s = 2.0 * ns + 1.0, a = ns / s, first = std::floor(direct_rows);
      const double grown = growing - first,
                   kept = std::max(0.0, steps - growing);  // steps of m growing, held
      auto log2_sum = [&](double M) {
        return M * std::log2(s) + (std::lgamma(M + 1.0 + a) - std::lgamma(1.0 + a)) / std::log(2.0);
      };
      const double per_log2 = tree_pairs_per_target(2.0, n.tree_tolerance);  // τ(N) = per_log2 · log₂ N
      const double logs = log2_sum(grown) + kept * std::log2(ring_segments(grown));
      const double T = targets_at(growing), kappa = kTreeBuildPairsPerSegment;
      const double young_nodes = n.free_wake ? (free_rows + 1.0) * (ns + 1.0) : 0.0;
      const double c2 = n.core_growth || truncated ? 0.0 : 2.0 * kappa / (s * (young_nodes + panels));  // c²
      // m up to m0 (N ≤ N₀ = k₀²/c²): rebuilt every k₀ steps.
      const double m0 =
          c2 > 0.0 ? std::clamp(std::floor((rebuild * rebuild / c2 - ns) / s), 0.0, grown) : grown;
      auto rebuild_cost = [&](double N) {  // a step's build and rows since the build [pairs]
        if (!(c2 > 0.0) || N * c2 <= rebuild * rebuild) return kappa * N / rebuild;
        const double c = std::sqrt(c2);
        return (kappa / c + T * s * c / 2.0) * std::sqrt(N) - T * s * rebuild / 2.0;
      };
      double builds = kappa / rebuild * (s * m0 * (m0 + 1.0) / 2.0 + ns * m0);
      if (m0 < grown) {
        const double c = std::sqrt(c2);
        auto root_integral = [&](double x) { return std::sqrt(s) * (2.0 / 3.0) * std::pow(x + a, 1.5); };
        const double roots =
            root_integral(grown + 0.5) - root_integral(m0 + 0.5);  // Σ √N(m), m = m0+1 … grown
        builds += (kappa / c + T * s * c / 2.0) * roots - T * s * rebuild / 2.0 * (grown - m0);
      }
      builds += kept * rebuild_cost(ring_segments(grown));
      e.tree_pairs = T * per_log2 * logs + builds;
    }
    // The LU factorisations of the influence matrix, (2/3) n³ each (Golub & Van Loan,
    // "Matrix Computations", §3.2): a lattice of 3200 panels took 25 s for 8 of them, which
    // the interactions' 0.56 s did not say (until 3 Dec).
    uvlm::VortexLatticeModel lattice;
    lattice.leading_edge = n.leading_edge;
    const bool iterative = lattice.iterative(static_cast<int>(panels)) && !n.steady;
    e.lattice_flops = lattice_factorisations(steps * solves, static_cast<double>(n.cycles), iterative) *
                      (2.0 / 3.0) * panels * panels * panels;
  }
  // The chain: 2 dofs per joint (bending, torsion); dense LU of the Newton matrix per
  // Newton iteration (~3) per coupling iteration.
  const double dofs = 2.0 * std::max(bodies, 1);
  memory += 8.0 * dofs * dofs * 8;
  e.structure_flops = bodies > 1 ? steps * iterations * 3.0 * (2.0 / 3.0) * dofs * dofs * dofs : 0.0;
  if (fem_dofs > 0) {
    // The FEM: its sparse factor (about 30 n log₂ n entries of 8 B plus indices, the same
    // nested-dissection count) and the measured CPU time of a step (resource_estimate.hpp).
    const double n_fem = fem_dofs;
    e.fem_dofs = fem_dofs;
    memory += kFemStructureMemoryFactor * fem_memory_bytes(n_fem) + kMesherBytes;
    const double per_cycle = std::max(1.0, static_cast<double>(n.steps_per_cycle)) / 100.0;
    const double newton = std::pow(per_cycle, -kFemStepsPerCycleExponent);
    const double coupling = c.air.enabled ? kFemCouplingStepShare : 0.0;  // in vacuum nothing to couple
    e.fem_seconds = steps * (newton + coupling) * kFemSecondsPerStep1000 * std::pow(n_fem / 1000.0, kFemDofsExponent);
  }
  e.memory_bytes = memory;
  e.frames_bytes = frames_bytes(c, c.output.vtk_every, fem_dofs);
  e.setup_memory_bytes = fem_memory_bytes(reduced_fem_dofs);
  e.isa = uvlm::kernel_isa();
  e.interactions_per_second =
      nominal_interactions_per_second(e.isa, c.numerics.wake_precision == io::WakePrecision::Single);
  e.seconds = e.interactions / e.interactions_per_second +
              e.tree_pairs / nominal_interactions_per_second(e.isa, false) +
              e.structure_flops / kFlopsPerSecond + e.lattice_flops / kLatticeFlopsPerSecond + e.fem_seconds;
  return e;
}

std::string describe(const RunEstimate& e) {
  char buf[768];
  const std::string isa(uvlm::kernel_isa_name(e.isa));
  const std::string structure = e.fem_dofs > 0 ? "FEM solves (" + std::to_string(e.fem_dofs) + " DOFs) ~" + seconds_text(e.fem_seconds)
                                                    : [&] {
                                                        char f[48];
                                                        std::snprintf(f, sizeof f, "%.2g chain flop", e.structure_flops);
                                                        return std::string(f);
                                                      }();
  std::string memory = bytes_text(e.memory_bytes);
  // The setup's reduction of the wing comes first and may need more (the hawkmoth: 155 MB
  // before a run of 64 MB; the estimate said 64 MB of a process that peaked at 153 MB).
  if (e.setup_memory_bytes > 0.0)
    memory +=
        " (and ~" + bytes_text(e.setup_memory_bytes) + " before it, for the wing's FEM reduced in the setup)";
  if (e.frames_bytes > 0.0) memory += ", ParaView frames ~" + bytes_text(e.frames_bytes) + " on disk";
  char tree[96] = "";
  if (e.tree_pairs > 0.0)
    std::snprintf(tree, sizeof tree, " (and the far wake's tree code, as long as %.2g direct pairs)",
                  e.tree_pairs);
  std::snprintf(buf, sizeof buf,
                "estimate: %lld steps, up to %lld wake panels, memory ~%s, %.2g Biot-Savart interactions%s, "
                "%.2g lattice LU flop, %s, time of the order of %s (one thread, %s kernel at a nominal %.2g "
                "interactions/s)",
                static_cast<long long>(e.steps), static_cast<long long>(e.wake_panels), memory.c_str(),
                e.interactions, tree, e.lattice_flops, structure.c_str(), seconds_text(e.seconds).c_str(),
                isa.c_str(), e.interactions_per_second);
  return buf;
}

double usable_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  double bytes = pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 1e18;
  struct rlimit lim {};
  if (::getrlimit(RLIMIT_AS, &lim) == 0 && lim.rlim_cur != RLIM_INFINITY)
    bytes = std::min(bytes, static_cast<double>(lim.rlim_cur));
  return bytes;
}

void refuse_if_it_cannot_fit(const RunEstimate& e, const io::Case& c) {
  const double usable = usable_memory_bytes();
  if (e.memory_bytes <= usable) return;
  const std::string need = "the run needs about " + bytes_text(e.memory_bytes) + " of memory, more than the " +
                           bytes_text(usable) + " this machine offers (" + describe(e) + ")";
  // The lattice's dense matrices grow with the square of its panels, whatever the run's
  // length: a 400 x 400 lattice needs 410 GB for 2 cycles (before, the message blamed the
  // cycles and the wake).
  if (e.lattice_bytes > 0.5 * e.memory_bytes) {
    const auto& n = c.numerics;
    const std::string key =
        n.spanwise_panels >= n.chordwise_panels ? "numerics.spanwise_panels" : "numerics.chordwise_panels";
    throw InputError(c.file, c.line_of(key), key,
                     need + "; of it the lattice of " + std::to_string(n.chordwise_panels) + " x " +
                         std::to_string(n.spanwise_panels) + " panels needs " + bytes_text(e.lattice_bytes) +
                         " (its influence matrix and LU, 2 x panels^2 numbers): use fewer panels "
                         "(numerics.chordwise_panels, numerics.spanwise_panels)");
  }
  throw InputError(c.file, c.line_of("numerics.cycles"), "numerics.cycles",
                   need + "; shorten it (numerics.cycles, numerics.steps_per_cycle) or bound the wake "
                          "(numerics.wake_max_rows)");
}

}  // namespace flapsim::app
