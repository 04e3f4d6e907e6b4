#pragma once
/// \file periodic_signal.hpp
/// \brief A periodic angle signal of the stroke phase s = f·t (in cycles, period 1):
/// a harmonic series or smoothly interpolated tabulated data, each with exact
/// first and second derivatives.

#include <optional>
#include <vector>

namespace flapsim::mbd {

/// Value and derivatives of a signal. When returned by PeriodicSignal::at_phase the
/// derivatives are per cycle (d/ds, d²/ds²); WingKinematics turns them into per second.
struct AngleSample {
  double value = 0.0;         ///< [rad]
  double rate = 0.0;          ///< [rad/cycle] or [rad/s]
  double acceleration = 0.0;  ///< [rad/cycle²] or [rad/s²]
};

class PeriodicSignal {
 public:
  /// Zero signal.
  PeriodicSignal();

  /// value(s) = mean + Σ_n cos_coeffs[n-1]·cos(2πns) + sin_coeffs[n-1]·sin(2πns).
  /// \param mean        [rad]
  /// \param cos_coeffs  [rad], n = 1, 2, …
  /// \param sin_coeffs  [rad], n = 1, 2, … (may differ in length from cos_coeffs)
  static PeriodicSignal harmonic(double mean, std::vector<double> cos_coeffs,
                                 std::vector<double> sin_coeffs);

  /// Periodic cubic spline (C², period 1) through (phases[i], values[i]).
  /// \param phases  strictly increasing, within [0, 1); at least 3 points
  /// \param values  [rad]
  /// \throws std::invalid_argument on bad tables (callers turn it into InputError)
  static PeriodicSignal tabulated(std::vector<double> phases, std::vector<double> values);

  /// How far a table's points lie from the series fitted to them (fitted()).
  struct TableFit {
    int points = 0;                 ///< the table's points (its closing phase 1 dropped)
    int harmonics = 0;              ///< N
    double residual_rms = 0.0;      ///< [the signal's unit]
    double residual_largest = 0.0;  ///< [the signal's unit]
    double largest_phase = 0.0;     ///< the phase of that point [cycles]
  };

  /// The least-squares series of `harmonics` harmonics through a table (mbd/fourier_fit.hpp):
  /// a harmonic signal that remembers its fit (table_fit()).
  /// \throws std::invalid_argument as fit_fourier_series
  static PeriodicSignal fitted(const std::vector<double>& phases, const std::vector<double>& values,
                               int harmonics);

  /// The fit a signal made by fitted() came from; empty for any other.
  const std::optional<TableFit>& table_fit() const { return table_fit_; }

  /// Value, d/ds and d²/ds² at phase s [cycles] (any real s; period 1).
  AngleSample at_phase(double s) const;

  /// Whether the signal is the same at every phase (no harmonic, or a table of equal values).
  bool is_constant() const;

  /// The highest harmonic n with a non-zero coefficient of a harmonic series (0 for none and
  /// for a table): a step resolves it only with more than 2n steps per cycle.
  int highest_harmonic() const;

 private:
  bool tabulated_ = false;
  double mean_ = 0.0;
  std::vector<double> cos_, sin_;
  std::vector<double> phases_, values_, second_derivs_;  // spline knots, values, y''
  std::optional<TableFit> table_fit_;
};

}  // namespace flapsim::mbd
