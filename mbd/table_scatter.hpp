#pragma once
/// \file table_scatter.hpp
/// \brief How much of a tabulated signal's acceleration is the scatter of its points.
///
/// A periodic cubic spline passes through every point, so a table's scatter about the smooth
/// motion (measurement noise, or values rounded when printed) becomes curvature between the
/// points, of the order of scatter / spacing². Sampled densely, it dwarfs the motion's own
/// acceleration: eq. 8's sweep and rotation of the rotation-phase paper written as 1000 points
/// rounded to 0.01° give a spline 8–9 times the motion's rms acceleration, and the hover flown
/// with it (cases/hover.toml) 53 % more lift and 3.9 times the aerodynamic power; rounded to
/// 0.1° the run fails at step 17 (docs/case_file.md, "Measured kinematics").

#include <optional>
#include <vector>

namespace flapsim::mbd {

struct TableScatter {
  int harmonics = 0;                 ///< K: the smooth motion is taken as the table's series of K harmonics
  double scatter_rms = 0.0;          ///< rms of the points about that series [the values' unit]
  double spline_acceleration = 0.0;  ///< rms d²/ds² of the spline through the points [unit/cycle²]
  double series_acceleration = 0.0;  ///< rms d²/ds² of the series [unit/cycle²]
  double scatter_share =
      0.0;  ///< rms d²/ds² of the spline through the scatter alone, over spline_acceleration
};

/// A series of N harmonics "leaves the points about as far as K's" when its estimate of the
/// scatter's standard deviation, rms·sqrt(n / (n − 2N − 1)) (the residual's degrees of freedom),
/// is within this factor of K's.
inline constexpr double kSuggestedScatterFactor = 1.1;

/// Fewest points for which the scatter is measured: K = 2 harmonics need 8.
inline constexpr std::size_t kScatterMinPoints = 8;
/// At most this many harmonics are the smooth motion (a wingbeat's angles need fewer; the
/// fit costs O(n K²)).
inline constexpr int kScatterMaxHarmonics = 24;

/// The spline's rms acceleration over the period: d²/ds² is linear between knots, so
/// Simpson's rule per interval is exact.
double spline_rms_acceleration(const std::vector<double>& phases, const std::vector<double>& values);

/// The scatter of a table (phases strictly increasing in [0, 1)) about its least-squares
/// series of K = min(n / 4, kScatterMaxHarmonics) harmonics: n / 4 keeps four points a
/// harmonic, so a motion the table samples well lies within the series and its scatter is
/// what the points add. nullopt below kScatterMinPoints points, for a constant table, or where
/// the points leave the series undetermined.
std::optional<TableScatter> measure_table_scatter(const std::vector<double>& phases,
                                                  const std::vector<double>& values);

/// The fewest harmonics N ≤ scatter.harmonics whose series leaves the table's points about as
/// far as the K of `scatter` (measure_table_scatter of the same table) do: what to fit it with.
int fewest_harmonics_within_scatter(const std::vector<double>& phases, const std::vector<double>& values,
                                    const TableScatter& scatter);

}  // namespace flapsim::mbd
