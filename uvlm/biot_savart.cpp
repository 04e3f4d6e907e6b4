#include "uvlm/biot_savart.hpp"

#include "uvlm/biot_savart_kernel.hpp"
#include "uvlm/biot_savart_lanes.hpp"
#include "uvlm/kernel_dispatch.hpp"

#include <stdexcept>

namespace flapsim::uvlm {

void SegmentSet::reserve(std::size_t capacity) {
  for (auto* a : {&ax_, &ay_, &az_, &bx_, &by_, &bz_, &gamma_, &inv_len2_, &core_ratio2_}) a->assign(capacity, 0.0);
  for (auto& a : single_) a.assign(capacity, 0.0f);
  size_ = 0;
}

void SegmentSet::update_single_precision() {
  const std::vector<double>* src[9] = {&ax_, &ay_, &az_, &bx_, &by_, &bz_, &gamma_, &inv_len2_, &core_ratio2_};
  for (int a = 0; a < 9; ++a)
    for (std::size_t k = 0; k < size_; ++k) single_[a][k] = static_cast<float>((*src[a])[k]);
}

void SegmentSet::push(double ax, double ay, double az, double bx, double by, double bz,
                      double gamma, double core_ratio2) {
  if (size_ >= ax_.size()) throw std::length_error("SegmentSet: capacity exceeded");
  ax_[size_] = ax; ay_[size_] = ay; az_[size_] = az;
  bx_[size_] = bx; by_[size_] = by; bz_[size_] = bz;
  gamma_[size_] = gamma;
  inv_len2_[size_] = detail::segment_scale(ax, ay, az, bx, by, bz, core_ratio2);
  core_ratio2_[size_] = core_ratio2;
  ++size_;
}

void PointSet::reserve(std::size_t capacity) {
  for (auto* a : {&x, &y, &z, &u, &v, &w}) a->assign(capacity, 0.0);
  size = 0;
}

void PointSet::zero_velocity() {
  for (std::size_t i = 0; i < size; ++i) u[i] = v[i] = w[i] = 0.0;
}

namespace {

template <class T>
void dispatch(const detail::KernelCall<T>& c) {
  switch (kernel_isa()) {
    case KernelIsa::Scalar: detail::sum_scalar(c); break;
    case KernelIsa::Avx2: detail::sum_avx2(c); break;
    case KernelIsa::Avx512: detail::sum_avx512(c); break;
  }
}

}  // namespace

void detail::point_range_dispatch(const detail::PointRangeCall& c) {
  switch (kernel_isa()) {
    case KernelIsa::Scalar: detail::point_range_scalar(c); break;
    case KernelIsa::Avx2: detail::point_range_avx2(c); break;
    case KernelIsa::Avx512: detail::point_range_avx512(c); break;
  }
}

Eigen::Vector3d segment_velocity(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double gamma,
                                 const Eigen::Vector3d& p, const VortexCore& core) {
  SegmentSet s;
  s.reserve(1);
  s.push(a, b, gamma);
  double u = 0, v = 0, w = 0;
  add_induced_velocity(s, &p.x(), &p.y(), &p.z(), 1, &u, &v, &w, core);
  return {u, v, w};
}

Eigen::Vector3d segment_velocity(const SegmentSet& segments, std::size_t k, const Eigen::Vector3d& p,
                                 const VortexCore& core) {
  if (!(core.radius > 0.0)) throw std::invalid_argument("vortex core radius must be > 0");
  if (k >= segments.size()) throw std::out_of_range("segment_velocity: no such segment");
  const SegmentSet& s = segments;
  double u = 0, v = 0, w = 0;
  detail::KernelCall<double> c{1, s.ax() + k, s.ay() + k, s.az() + k, s.bx() + k, s.by() + k, s.bz() + k,
                               s.gamma() + k, s.inv_length2() + k, s.core_ratio2() + k,
                               1.0 / (core.radius * core.radius), core.model, 1, &p.x(), &p.y(), &p.z(),
                               &u, &v, &w};
  dispatch(c);
  return {u, v, w};
}

void add_induced_velocity(const SegmentSet& segments, PointSet& points, const VortexCore& core) {
  add_induced_velocity(segments, points.x.data(), points.y.data(), points.z.data(), points.size,
                       points.u.data(), points.v.data(), points.w.data(), core);
}

void add_induced_velocity(const SegmentSet& segments, const double* x, const double* y,
                          const double* z, std::size_t n, double* u, double* v, double* w,
                          const VortexCore& core) {
  if (!(core.radius > 0.0)) throw std::invalid_argument("vortex core radius must be > 0");
  if (segments.size() == 0 || n == 0) return;
  const SegmentSet& s = segments;
  detail::KernelCall<double> c{s.size(), s.ax(), s.ay(), s.az(), s.bx(), s.by(), s.bz(),
                               s.gamma(), s.inv_length2(), s.core_ratio2(),
                               1.0 / (core.radius * core.radius),
                               core.model, n, x, y, z, u, v, w};
  dispatch(c);
}

void add_induced_velocity_single(const SegmentSet& segments, PointSet& points, const VortexCore& core) {
  add_induced_velocity_single(segments, points.x.data(), points.y.data(), points.z.data(),
                              points.size, points.u.data(), points.v.data(), points.w.data(), core);
}

void add_induced_velocity_single(const SegmentSet& segments, const double* x, const double* y,
                                 const double* z, std::size_t n, double* u, double* v, double* w,
                                 const VortexCore& core) {
  if (!(core.radius > 0.0)) throw std::invalid_argument("vortex core radius must be > 0");
  if (segments.size() == 0 || n == 0) return;
  const SegmentSet& s = segments;
  detail::KernelCall<float> c{s.size(), s.single(0), s.single(1), s.single(2), s.single(3),
                              s.single(4), s.single(5), s.single(6), s.single(7), s.single(8),
                              static_cast<float>(1.0 / (core.radius * core.radius)), core.model,
                              n, x, y, z, u, v, w};
  dispatch(c);
}

}  // namespace flapsim::uvlm
