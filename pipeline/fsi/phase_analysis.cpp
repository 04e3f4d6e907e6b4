#include "pipeline/fsi/phase_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pipeline/fsi/wing_attachment.hpp"

namespace flapsim::fsi {

mbd::StrokeAngles body_angles(const mbd::ChainModel& chain, const mbd::ChainData& data,
                        double stroke_plane_angle, int body) {
  const Eigen::Matrix3d r_gs = mbd::rotation_y(stroke_plane_angle);
  const Eigen::Matrix3d& r_gb = data.bodies[static_cast<std::size_t>(body)].rotation;
  return mbd::stroke_angles(r_gs.transpose() * r_gb * chain.root_rotation.transpose());
}

int outer_body(const mbd::ChainModel& chain) {
  const std::vector<double> s = reference_joint_span(chain);
  const double length = s.back() + chain.bodies.back().outboard_joint.norm();
  return host_body(s, s.front() + 5.0 / 6.0 * (length - s.front()));
}

std::vector<double> crossing_times(const std::vector<double>& t, const std::vector<double>& x,
                                   double level, int direction) {
  std::vector<double> out;
  const std::size_t n = std::min(t.size(), x.size());
  for (std::size_t i = 1; i < n; ++i) {
    const double a = x[i - 1] - level, b = x[i] - level;
    const bool rising = a < 0.0 && b >= 0.0;
    const bool falling = a > 0.0 && b <= 0.0;
    if ((rising && direction >= 0) || (falling && direction <= 0))
      out.push_back(t[i - 1] + (t[i] - t[i - 1]) * a / (a - b));
  }
  return out;
}

double window_mean(const std::vector<double>& t, const std::vector<double>& x, double t0,
                   double t1) {
  double integral = 0.0, span = 0.0;
  const std::size_t n = std::min(t.size(), x.size());
  const double eps = 1e-9 * std::max(std::abs(t1 - t0), 1e-300);
  for (std::size_t i = 1; i < n; ++i) {
    if (t[i - 1] < t0 - eps || t[i] > t1 + eps) continue;
    const double h = t[i] - t[i - 1];
    integral += 0.5 * h * (x[i] + x[i - 1]);
    span += h;
  }
  return span > 0.0 ? integral / span : std::numeric_limits<double>::quiet_NaN();
}

namespace {

constexpr double kPi = 3.14159265358979323846;

double wrap_half(double f) {
  f -= std::round(f);
  if (f <= -0.5) f += 1.0;
  return f;
}

// Times of the local extrema (sign +1 maxima, −1 minima) in [t0, t1], refined by a
// parabola through the three samples around each.
std::vector<double> extremum_times(const std::vector<double>& t, const std::vector<double>& x,
                                   int sign, double t0, double t1) {
  std::vector<double> out;
  const std::size_t n = std::min(t.size(), x.size());
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double a = sign * x[i - 1], b = sign * x[i], c = sign * x[i + 1];
    if (!(b >= a && b > c)) continue;
    const double h0 = t[i] - t[i - 1], h1 = t[i + 1] - t[i];
    // Vertex of the parabola b + βx + γx² through (−h0, a), (0, b), (h1, c).
    const double d0 = (b - a) / h0, d1 = (c - b) / h1;
    const double gamma = (d1 - d0) / (h0 + h1);
    const double beta = d0 + gamma * h0;
    double dt = gamma < 0.0 ? -beta / (2.0 * gamma) : 0.0;
    dt = std::clamp(dt, -h0, h1);
    const double te = t[i] + dt;
    if (te >= t0 && te <= t1) out.push_back(te);
  }
  return out;
}

// The shift (c − t_ref)/period of the candidate nearest t_ref in time: the crossing of the
// same cycle. NaN if there is none within half a period. (The shift used to be wrapped to
// (−½, ½] before the nearest was chosen, so a crossing of another cycle, a whole period
// away, could be taken when the lag drifts from cycle to cycle.)
double nearest_shift(const std::vector<double>& candidates, double t_ref, double period) {
  double best = std::numeric_limits<double>::quiet_NaN();
  for (double c : candidates) {
    const double f = (c - t_ref) / period;
    if (!(std::abs(f) >= std::abs(best))) best = f;
  }
  return std::abs(best) <= 0.5 ? best : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

std::optional<double> crossing_lag(const std::vector<double>& t, const std::vector<double>& x,
                                   const std::vector<double>& reference, double level,
                                   double period, double t0, double t1) {
  double sum = 0.0;
  int count = 0;
  for (int dir : {+1, -1}) {
    const auto cx = crossing_times(t, x, level, dir);
    for (double tr : crossing_times(t, reference, level, dir)) {
      if (tr < t0 || tr > t1) continue;
      const double f = nearest_shift(cx, tr, period);
      if (std::isfinite(f)) {
        sum += f;
        ++count;
      }
    }
  }
  if (count == 0) return std::nullopt;
  return sum / count;
}

std::optional<double> rotation_phase(const std::vector<double>& t, const std::vector<double>& sweep,
                                     const std::vector<double>& alpha, double period, double t0,
                                     double t1) {
  constexpr double kRightAngle = 0.5 * 3.14159265358979323846;
  const auto maxima = extremum_times(t, sweep, +1, t0 - period, t1 + period);
  const auto minima = extremum_times(t, sweep, -1, t0 - period, t1 + period);
  // The reversal of a crossing is the largest maximum (smallest minimum) of φ within half
  // a period of it: a deforming tip's φ wiggles, and its small local extrema are not
  // stroke reversals.
  const auto reversal_near = [&](double tc, int sign) {
    const auto& candidates = sign > 0 ? maxima : minima;
    // A crossing just before the last sample has its reversal at the series' end, where no
    // extremum can be seen (no sample after it): then the reversal a period before or after
    // stands for it (the cycle repeats). Before, such a crossing was dropped and the phase was
    // the other half-stroke's alone (mean rotation 80°: 0.0457 for δψ = 0.01).
    for (const double shift : {0.0, -period, period}) {
      double best_t = std::numeric_limits<double>::quiet_NaN(), best_v = -1e300;
      for (double te : candidates) {
        if (std::abs(te + shift - tc) > 0.5 * period) continue;
        // φ at te by linear interpolation of the samples (the parabola's vertex is close).
        const auto it = std::lower_bound(t.begin(), t.end(), te);
        const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(it - t.begin()), t.size() - 1);
        const double v = sign * sweep[i];
        if (v > best_v) {
          best_v = v;
          best_t = te + shift;
        }
      }
      if (std::isfinite(best_t)) return best_t;
    }
    return std::numeric_limits<double>::quiet_NaN();
  };
  // The phases are points on a circle (−½ and ½ are the same timing): their mean is the
  // direction of Σ (cos 2πf, sin 2πf). A linear mean of a rotation phase of ½, whose
  // crossings find the reversal half a period before or after by a sample's round-off, gave
  // 0 for ±½ (the tip at 0.0 where the base read −0.5).
  double sum_cos = 0.0, sum_sin = 0.0;
  int count = 0;
  for (int dir : {-1, +1}) {
    for (double tc : crossing_times(t, alpha, kRightAngle, dir)) {
      if (tc < t0 || tc > t1) continue;
      const double tr = reversal_near(tc, dir < 0 ? +1 : -1);
      const double f = std::isfinite(tr) ? wrap_half((tr - tc) / period)
                                         : std::numeric_limits<double>::quiet_NaN();
      if (std::isfinite(f)) {
        sum_cos += std::cos(2.0 * kPi * -f);
        sum_sin += std::sin(2.0 * kPi * -f);
        ++count;
      }
    }
  }
  if (count == 0) return std::nullopt;
  return wrap_half(std::atan2(sum_sin, sum_cos) / (2.0 * kPi));
}

}  // namespace flapsim::fsi
