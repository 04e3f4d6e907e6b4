#pragma once
/// \file start_points.hpp
/// \brief The starts of a multi-start `flapsim optimize` (--starts N): start 1 is the
/// case's own values (clamped into the bounds); start k > 1 is point k − 1 of the Halton
/// sequence (J. H. Halton, "On the efficiency of certain quasi-random sequences of points
/// in evaluating multi-dimensional integrals", Numer. Math. 2, 1960), one prime base per
/// key (2, 3, 5, …), scaled into the bounds: spread evenly over the box, no random numbers,
/// the same on every machine and rank count.

#include <cstddef>
#include <vector>

namespace flapsim::optimize {

/// \brief The radical inverse of \p index in \p base: its digits mirrored about the point,
/// e.g. 1, 2, 3 in base 2 give 0.5, 0.25, 0.75.
double radical_inverse(std::size_t index, unsigned base);

/// \brief \p count starts in [lo, hi]: \p first, then Halton points 1, 2, ….
/// At most 20 keys (the first 20 primes).
std::vector<std::vector<double>> start_points(const std::vector<double>& first, const std::vector<double>& lo,
                                              const std::vector<double>& hi, std::size_t count);

}  // namespace flapsim::optimize
