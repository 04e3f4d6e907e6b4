#pragma once
/// \file resource_estimate.hpp
/// \brief What a run will cost, known from the case before it starts: memory (the wake,
/// the lattice's influence matrix, the per-step samples, the chain's matrices), Biot–Savart
/// interactions and an order-of-magnitude time. `flapsim check` prints it for a case;
/// `flapsim run` prints it before a long run and refuses a run whose memory cannot fit
/// (docs/case_file.md, "Size of a run").
///
/// The memory model counts the arrays a run allocates (uvlm/vortex_lattice.cpp: wake
/// nodes, wake circulations and AB2 velocities, wake segments; the dense influence matrix
/// and its LU; one StepSample per step for the end-of-run analysis; dense chain matrices).
/// Interactions: every wake node sees every bound and wake segment (free wake), and every
/// collocation point sees every wake segment per coupling iteration; a far wake summed by
/// the tree code costs each of them about log N (tree_pairs_per_target). The time divides
/// them by a nominal single-thread throughput of the kernel variant the CPU runs; it is an
/// order of magnitude, not a measurement.

#include <cstdint>
#include <string>

#include "pipeline/io/case_model.hpp"
#include "uvlm/kernel_dispatch.hpp"
#include "uvlm/segment_tree.hpp"

namespace flapsim::app {

struct RunEstimate {
  std::int64_t steps = 0;          ///< time steps
  std::int64_t wake_panels = 0;    ///< largest wake [panels]
  double memory_bytes = 0.0;       ///< peak memory of the run's arrays [B]
  double frames_bytes = 0.0;       ///< the ParaView frames of output.vtk_every on disk (frames_size.hpp) [B]
  /// The FEM of a wing reduced in the setup (its matrices, factor and modes), freed before the
  /// run, 0 if none [B]: shown beside memory_bytes, not refused (the setup has run by the time
  /// it is known). The hawkmoth's, 27,618 DOFs: 155 MB, where the run's arrays are 64 MB
  /// (measured peak of `run cases/hover_flexible.toml` without a chain file: 153 MB; with one, 25 MB).
  double setup_memory_bytes = 0.0;
  double lattice_bytes = 0.0;      ///< of it, the lattice's influence matrix and its LU [B]
  double interactions = 0.0;       ///< Biot–Savart segment-point evaluations of the whole run
  /// The far wake summed by the tree code (wake_sum = "tree" with far_wake_cycles): its
  /// evaluations at the targets and its builds, counted as the direct double-precision pairs
  /// that take as long (tree_pairs_per_target, kTreeBuildPairsPerSegment); 0 without it
  double tree_pairs = 0.0;
  double structure_flops = 0.0;    ///< dense chain solves of the whole run [flop]
  double lattice_flops = 0.0;      ///< the lattice's LU factorisations of the whole run [flop]
  std::int64_t fem_dofs = 0;       ///< DOFs of the FEM structure (kind = "fem"; 0 for a chain)
  double fem_seconds = 0.0;        ///< the FEM structure's solves of the whole run (kind = "fem") [s]
  double interactions_per_second = 0.0;  ///< the nominal throughput the time assumes [1/s]
  uvlm::KernelIsa isa = uvlm::KernelIsa::Scalar;  ///< the kernel variant it assumes
  double seconds = 0.0;            ///< order of magnitude of the wall time, one thread [s]
};

/// A time in two significant digits and its unit: "44 s", "2.7 h", "1.1 days".
std::string seconds_text(double seconds);

/// Nominal single-thread throughput of the direct Biot–Savart sums [interactions/s] with the
/// kernel variant `isa` in single or double precision (the case's numerics.wake_precision):
/// half the throughput measured on the development machine (docs/performance.md, "Measured",
/// 6000 segments × 3300 points, per CPU second: scalar 1.9e8 and 4.2e8, AVX2 4.3e8 and 9.7e8,
/// AVX-512 5.4e8 and 1.2e9 in double and single precision), the other half a margin for
/// slower CPUs and the work besides the sums.
double nominal_interactions_per_second(uvlm::KernelIsa isa, bool single_precision);
/// The far wake by the tree code (uvlm/segment_tree.hpp): one target's evaluation costs
/// about as much as this many direct double-precision pairs at kTreeReferenceSegments
/// segments, growing as log N with the far wake's N segments (a Barnes–Hut tree: the nodes a
/// target accepts double with each level). Measured with bench_wake_tree's
/// BM_PeriodicFarWake (the 20-cycle far wake of cases/hover_periodic.toml, 40 771 segments, at
/// the young wake's 649 nodes; 1 thread, FLAPSIM_KERNEL=avx2, 2-core AMD EPYC, 4 Dec 2026):
/// 6.2, 13.4 and 24.0 µs a target at tolerances 1e-3, 1e-4 and 1e-5 (θ = 0.45, 0.3, 0.2), a
/// direct double pair 2.66 ns: 2330, 5040 and 9020 pairs. Below 1e-5 (θ = 0.12, not
/// measured) the 1e-4 → 1e-5 growth, θ^−1.44, carried on: 18 900.
double tree_pairs_per_target(double segments, double tolerance);
inline constexpr double kTreeReferenceSegments = 40771.0;
/// A build of the far wake's tree as long as this many direct double pairs a segment
/// (uvlm::SegmentTree::kBuildPairsPerSegment, measured); it is built every
/// uvlm::far_tree_rebuild_interval steps.
inline constexpr double kTreeBuildPairsPerSegment = uvlm::SegmentTree::kBuildPairsPerSegment;
/// Nominal throughput of the chain's dense solves [flop/s].
inline constexpr double kFlopsPerSecond = 1e9;
/// Nominal throughput of the lattice's LU factorisation (Eigen's PartialPivLU of the dense
/// influence matrix, (2/3) n³ flop for n panels) [flop/s]: half of the 7.3e9 measured in the
/// portable build (a hover of 3200 panels, 12 steps, 8 factorisations: 25 s on one thread of
/// a 2-core AMD EPYC, 3 Dec 2026), the other half a margin as for the interactions.
inline constexpr double kLatticeFlopsPerSecond = 3.5e9;
/// The lattice's factorisations in a run of `solves` lattice solves over `cycles` cycles:
/// every solve's with the direct solve (the matrix changes at every step of a moving wing),
/// about 4 a cycle and 4 more with the iterative one, which keeps an earlier factorisation
/// as its preconditioner (model.iterative: at least 150 panels; the hawkmoth hover at 1200
/// panels: 8 in 12 steps, 5 in 50 and in 100 steps of a cycle; 13 in 3 cycles of 24 steps at
/// 192 panels).
double lattice_factorisations(double solves, double cycles, bool iterative);
/// Runs estimated above this are "long": flapsim run prints the estimate first [s].
inline constexpr double kLongRunSeconds = 10.0;
/// Runs estimated above this print their estimate even with run -q [s].
inline constexpr double kVeryLongRunSeconds = 3600.0;

/// One-thread CPU time of one time step of the FEM structure in vacuum at 1000 DOFs and 100
/// steps per cycle [s]: all its Newton iterations (assembly, the kept factorisation's renewals,
/// the solves), scaled by (DOFs/1000)^kFemDofsExponent and
/// (steps per cycle/100)^−kFemStepsPerCycleExponent. Fitted (geometric mean of measured/model)
/// to ten runs of the hawkmoth FEM at 4038–52 626 DOFs, 100 and 400 steps a cycle, in vacuum
/// and in air (docs/fsi.md, "Cost estimate of a FEM run", the runs of 1 Dec on a 2-core AMD
/// EPYC with AVX-512, CI's CPU family): every estimate within 0.87–1.23 of the run's CPU time.
/// The constants of 29 Nov (2.7e-3 s, n^1.5, 0.30, 0.70; a 2-core Intel Xeon) were 0.74–1.64
/// times these runs (the hawkmoth FEM hover, 27 618 DOFs: 2.3 times).
inline constexpr double kFemSecondsPerStep1000 = 3.49e-3;
/// The factorisation of a 2-D mesh's matrix under a fill-reducing ordering grows as n^1.5
/// asymptotically (George & Liu 1981, nested dissection); at these sizes flapsim's dense
/// supernodal kernels gain more on the larger supernodes of finer meshes, and the measured
/// runs in vacuum at 400 steps a cycle grow as n^1.28 (least squares in log DOFs, 4038–52 626
/// DOFs; 1.27 on 29 Nov, 1.41 and 1.51 before the kernels): the measured slope, rounded.
inline constexpr double kFemDofsExponent = 1.3;
/// A smaller step turns the wing less, and its Newton solve needs fewer iterations and new
/// matrices: in vacuum a step at 400 steps a cycle costs 0.641 and 0.585 times one at 100
/// (4038 and 9030 DOFs, measured 1 Dec), 4^−0.321 and 4^−0.387 (mean 0.35).
inline constexpr double kFemStepsPerCycleExponent = 0.35;
/// A step coupled with the lattice (air) adds its sub-iterations' solves, warm-started and
/// loose (docs/fsi.md, "One coupled step"), and those do not shrink with the step: measured
/// (air − vacuum) at the same mesh and step, in units of a vacuum step at 100 steps a cycle,
/// 0.403, 0.310 (100 steps a cycle, 4038 and 9030 DOFs) and 0.520 (400 steps, 4038 DOFs),
/// geometric mean 0.40 (1 Dec). So an air step costs 1.4 vacuum steps at 100 steps a cycle
/// (not the ~5 of its sub-iterations).
inline constexpr double kFemCouplingStepShare = 0.40;

/// \param bodies    bodies of the chain the run will use (the case's structure.bodies)
/// \param fem_dofs  DOFs of the FEM structure (kind = "fem"; 0 for a chain)
/// \param reduced_fem_dofs  DOFs of the wing's FEM reduced in the setup (FsiSetup::reduced_fem_dofs)
RunEstimate estimate_run(const io::Case& c, int bodies, int fem_dofs = 0, int reduced_fem_dofs = 0);

/// Memory of a FEM of \p dofs DOFs: its sparse factor (about 30 n log2 n entries of 8 B plus
/// indices, nested dissection) and 40 n numbers of matrices and vectors [B]. The linear FEM
/// of a reduction in the setup: the hawkmoth's, 27 618 DOFs, 156 MB, a measured peak of 153 MB.
double fem_memory_bytes(double dofs);

/// The FEM as the structure (kind = "fem", geometrically nonlinear) holds more than the
/// linear FEM: the tangent matrix, the kept factorisation and the one that renews it, the
/// generalised-α state. Its peak over fem_memory_bytes, fitted (least squares of the slope)
/// on four runs of a 60 mm swept film wing at 2322, 7518, 26 880 and 53 490 DOFs (peaks of
/// 92, 138, 348 and 630 MB, 100 steps in air; 4 Dec 2026, 2-core AMD EPYC): 1.7; before, the
/// estimate took 1, and said 74, 102, 215 and 384 MB (the hawkmoth FEM hover: 220 MB for a
/// peak of 367 MB).
inline constexpr double kFemStructureMemoryFactor = 1.7;
/// The mesher (gmsh and OpenCASCADE, loaded to mesh the wing in the run's setup) beyond the
/// fixed allowance [B]: the same four runs' intercept.
inline constexpr double kMesherBytes = 15e6;

/// "64.8 MB", "2.2 GB", "386 kB": a size for a message.
std::string bytes_text(double bytes);

/// One line: "estimate: N steps, up to W wake panels, memory ~X, ~Y interactions, ~T".
std::string describe(const RunEstimate& e);

/// Memory this process may use [B]: the physical memory, or less if an address-space
/// limit (ulimit -v) is set.
double usable_memory_bytes();

/// \throws flapsim::InputError if the run's memory exceeds usable_memory_bytes(), naming
///         both and the keys that shrink the run: the panel counts (key
///         numerics.spanwise_panels or chordwise_panels, the larger) when the lattice's
///         matrices are most of it, else the length of the run (key numerics.cycles)
void refuse_if_it_cannot_fit(const RunEstimate& e, const io::Case& c);

}  // namespace flapsim::app
