#pragma once
/// \file biot_savart.hpp
/// \brief Velocity induced by straight vortex segments: a structure-of-arrays segment
/// set and the O(targets × segments) kernel, vectorised over segments and parallel
/// (OpenMP) over target points. This sum is the cost of a free-wake run.

#include "uvlm/vortex_core.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace flapsim::uvlm {

/// Straight vortex segments A→B with circulation Γ, stored as separate arrays so the
/// kernel's loop over segments is contiguous and vectorises. Storage is reserved once
/// (`reserve`); `clear` and `push` never allocate while within the reserved capacity.
class SegmentSet {
 public:
  /// Allocate room for `capacity` segments.
  void reserve(std::size_t capacity);
  void clear() { size_ = 0; }
  /// Keep the first n segments (n ≤ size()): drop those pushed after them.
  void truncate(std::size_t n) { size_ = n < size_ ? n : size_; }
  /// Append A→B with circulation gamma [m²/s]. Throws std::length_error beyond capacity.
  /// \param core_ratio2  (r_c / r_c,k)²: this segment's core r_c,k relative to the core r_c
  ///                     the sum is called with (1: the same core; < 1: a larger core,
  ///                     e.g. grown with age, core_growth.hpp)
  void push(double ax, double ay, double az, double bx, double by, double bz, double gamma,
            double core_ratio2 = 1.0);
  void push(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double gamma) {
    push(a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), gamma);
  }
  std::size_t size() const { return size_; }
  std::size_t capacity() const { return ax_.size(); }

  // Segment arrays (first size() entries valid) [m], [m²/s].
  const double* ax() const { return ax_.data(); }
  const double* ay() const { return ay_.data(); }
  const double* az() const { return az_.data(); }
  const double* bx() const { return bx_.data(); }
  const double* by() const { return by_.data(); }
  const double* bz() const { return bz_.data(); }
  const double* gamma() const { return gamma_.data(); }
  /// (r_c/r_c,k)²/|B − A|² [1/m²] per segment (0 for zero length), so the kernel needs no
  /// division for it: the kernel's x = h²/r_c,k² = |r1×r2|² · inv_length2 / r_c².
  const double* inv_length2() const { return inv_len2_.data(); }
  /// (r_c/r_c,k)² per segment, as pushed (1 unless the segment has its own core).
  const double* core_ratio2() const { return core_ratio2_.data(); }

  /// Copy the segments into the single-precision arrays that
  /// add_induced_velocity_single reads (no allocation).
  void update_single_precision();
  /// Single-precision copies, in the order ax, ay, az, bx, by, bz, gamma, inv_length2,
  /// core_ratio2.
  const float* single(int array) const { return single_[array].data(); }

 private:
  std::vector<double> ax_, ay_, az_, bx_, by_, bz_, gamma_, inv_len2_, core_ratio2_;
  std::vector<float> single_[9];
  std::size_t size_ = 0;
};

/// Target points and their velocities in structure-of-arrays form.
struct PointSet {
  std::vector<double> x, y, z;  ///< positions [m]
  std::vector<double> u, v, w;  ///< velocities [m/s]
  std::size_t size = 0;         ///< points in use (≤ capacity)
  void reserve(std::size_t capacity);
  void set(std::size_t i, const Eigen::Vector3d& p) { x[i] = p.x(); y[i] = p.y(); z[i] = p.z(); }
  Eigen::Vector3d position(std::size_t i) const { return {x[i], y[i], z[i]}; }
  Eigen::Vector3d velocity(std::size_t i) const { return {u[i], v[i], w[i]}; }
  /// Set u = v = w = 0 for the points in use.
  void zero_velocity();
};

/// Velocity [m/s] induced at p by one segment a→b of circulation gamma (regularised).
Eigen::Vector3d segment_velocity(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double gamma,
                                 const Eigen::Vector3d& p, const VortexCore& core);

/// Velocity [m/s] induced at p by segment k of `segments` alone, by the kernel of the sums
/// below (the same arithmetic; no allocation): what a sum over the set holds of that segment.
Eigen::Vector3d segment_velocity(const SegmentSet& segments, std::size_t k, const Eigen::Vector3d& p,
                                 const VortexCore& core);

/// Add the velocity induced by every segment of `segments` to each point of `points`
/// (points.u/v/w += …). Parallel over points (OpenMP), vectorised over segments.
/// \param core  regularisation; core.radius > 0 [m]
void add_induced_velocity(const SegmentSet& segments, PointSet& points, const VortexCore& core);

/// Raw-array form of add_induced_velocity for n points at (x, y, z) [m], adding to (u, v, w) [m/s].
void add_induced_velocity(const SegmentSet& segments, const double* x, const double* y,
                          const double* z, std::size_t n, double* u, double* v, double* w,
                          const VortexCore& core);

/// Single-precision form of add_induced_velocity (about twice the throughput), for the
/// free-wake convection where a relative error of about 1e-6 in the velocity is far below
/// the time-integration error. Reads the copies made by segments.update_single_precision().
void add_induced_velocity_single(const SegmentSet& segments, PointSet& points, const VortexCore& core);

/// Raw-array form of add_induced_velocity_single.
void add_induced_velocity_single(const SegmentSet& segments, const double* x, const double* y,
                                 const double* z, std::size_t n, double* u, double* v, double* w,
                                 const VortexCore& core);

}  // namespace flapsim::uvlm
