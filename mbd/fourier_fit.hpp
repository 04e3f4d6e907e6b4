#pragma once
/// \file fourier_fit.hpp
/// \brief The least-squares Fourier series of a periodic table: a measured wingbeat's angles
/// as mean + Σ_{n≤N} a_n cos 2πns + b_n sin 2πns, without the point-to-point scatter that a
/// spline through the points turns into accelerations (docs/case_file.md, "Kinematics").

#include <vector>

namespace flapsim::mbd {

/// A series fitted to a table, and how far the table's points lie from it.
struct FourierFit {
  double mean = 0.0;               ///< [the values' unit]
  std::vector<double> cos_coeffs;  ///< a_n, n = 1 … N
  std::vector<double> sin_coeffs;  ///< b_n, n = 1 … N
  double residual_rms = 0.0;       ///< rms of value − series over the points
  double residual_largest = 0.0;   ///< largest |value − series|
  double largest_phase = 0.0;      ///< the phase of that point [cycles]
};

/// The series of `harmonics` harmonics nearest to (phases[i], values[i]) in least squares:
/// the normal equations of the 2N + 1 coefficients, accumulated point by point (O(n N²),
/// no n × (2N + 1) matrix: a measured table may have 10⁵ points), solved by LDLᵀ.
/// Evenly spaced points make the normal matrix diagonal (n/2, n for the mean).
/// \param phases  [cycles], any real (taken modulo 1); as many as values
/// \throws std::invalid_argument if harmonics < 0, there are fewer than 2N + 1 points, or the
///         points leave the series undetermined (all within a part of the cycle too short
///         for N harmonics: the normal matrix's reciprocal condition number below 1e-12)
FourierFit fit_fourier_series(const std::vector<double>& phases, const std::vector<double>& values,
                              int harmonics);

/// The series' value at phase s [cycles].
double fourier_series_value(const FourierFit& fit, double s);

}  // namespace flapsim::mbd
