#pragma once
/// \file baseline_math_library.hpp
/// \brief The same results on any x86-64 CPU from the C library's math functions too.
///
/// glibc's libm (exp, log, pow, sin, cos, atan2, …) picks, when a program starts, one of
/// several builds of each function by the CPU's features: one compiled with fused
/// multiply–adds where the CPU has FMA (and AVX2) or FMA4, others without. The FMA builds
/// round differently in the last bit on some arguments, and through the coupling's
/// convergence test such a bit changes a run's history (measured on the flexible hover with
/// the shipped chain: the history.csv of a machine whose libm takes the builds without FMA
/// differs from line 15 on, its mean lift by 3·10⁻⁵; docs/performance.md, "The C library's
/// math functions").
/// flapsim's own kernels give the same bits on every CPU by construction; this makes the
/// C library's functions do the same.

namespace flapsim::cli {

/// Name of the environment variable that marks a process as re-executed already.
inline constexpr const char* kBaselineMathLibraryMark = "FLAPSIM_BASELINE_LIBM";

/// GLIBC_TUNABLES entry that hides FMA and FMA4 from glibc's choice of function builds;
/// the builds it then takes (AVX or SSE2) compute the same IEEE operations in the same
/// order, so they agree to the bit with each other on every x86-64 CPU.
inline constexpr const char* kBaselineMathTunable = "glibc.cpu.hwcaps=-FMA,-FMA4";

/// Unless the process carries kBaselineMathLibraryMark, executes the program again (its
/// own file, /proc/self/exe, with the same argv) with kBaselineMathTunable appended to
/// GLIBC_TUNABLES (a user's own tunables are kept before it) and the mark set: the C
/// library reads its tunables only when a program starts. If that fails, the program goes on as it is and
/// says so on stderr (its results then may differ in their last bits between CPUs).
/// Call first thing in main(); returns only in the re-executed process or on failure.
void run_with_the_baseline_math_library(char** argv);

}  // namespace flapsim::cli
