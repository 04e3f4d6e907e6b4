#include "uvlm/biot_savart.hpp"

#include "uvlm/biot_savart_kernel.hpp"

#include <stdexcept>

namespace flapsim::uvlm {

void SegmentSet::reserve(std::size_t capacity) {
  for (auto* a : {&ax_, &ay_, &az_, &bx_, &by_, &bz_, &gamma_, &inv_len2_}) a->assign(capacity, 0.0);
  for (auto& a : single_) a.assign(capacity, 0.0f);
  size_ = 0;
}

void SegmentSet::update_single_precision() {
  const std::vector<double>* src[8] = {&ax_, &ay_, &az_, &bx_, &by_, &bz_, &gamma_, &inv_len2_};
  for (int a = 0; a < 8; ++a)
    for (std::size_t k = 0; k < size_; ++k) single_[a][k] = static_cast<float>((*src[a])[k]);
}

void SegmentSet::push(double ax, double ay, double az, double bx, double by, double bz,
                      double gamma) {
  if (size_ >= ax_.size()) throw std::length_error("SegmentSet: capacity exceeded");
  ax_[size_] = ax; ay_[size_] = ay; az_[size_] = az;
  bx_[size_] = bx; by_[size_] = by; bz_[size_] = bz;
  gamma_[size_] = gamma;
  inv_len2_[size_] = detail::segment_scale(ax, ay, az, bx, by, bz, 1.0);
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

// Cost below which threads are not worth starting (point–segment interactions).
constexpr std::size_t kParallelThreshold = 100000;

/// T: the precision of the evaluation; the segment arrays are in that precision.
template <CoreModel M, class T>
void add_velocity_impl(std::size_t ns, const T* __restrict ax, const T* __restrict ay,
                       const T* __restrict az, const T* __restrict bx, const T* __restrict by,
                       const T* __restrict bz, const T* __restrict g, const T* __restrict il,
                       const double* x, const double* y, const double* z, std::size_t n, double* u,
                       double* v, double* w, T inv_rc2) {
  const long nt = static_cast<long>(n);
#pragma omp parallel for schedule(static) if (n * ns > kParallelThreshold)
  for (long i = 0; i < nt; ++i) {
    const T px = static_cast<T>(x[i]), py = static_cast<T>(y[i]), pz = static_cast<T>(z[i]);
    T su = 0, sv = 0, sw = 0;
#pragma omp simd reduction(+ : su, sv, sw)
    for (std::size_t k = 0; k < ns; ++k) {
      detail::segment_velocity<M>(px, py, pz, ax[k], ay[k], az[k], bx[k], by[k], bz[k], g[k],
                                  inv_rc2 * il[k], su, sv, sw);
    }
    u[i] += su;
    v[i] += sv;
    w[i] += sw;
  }
}

template <CoreModel M>
void add_double(const SegmentSet& s, const double* x, const double* y, const double* z,
                std::size_t n, double* u, double* v, double* w, double inv_rc2) {
  add_velocity_impl<M, double>(s.size(), s.ax(), s.ay(), s.az(), s.bx(), s.by(), s.bz(), s.gamma(),
                               s.inv_length2(), x, y, z, n, u, v, w, inv_rc2);
}

template <CoreModel M>
void add_single(const SegmentSet& s, PointSet& p, float inv_rc2) {
  add_velocity_impl<M, float>(s.size(), s.single(0), s.single(1), s.single(2), s.single(3),
                              s.single(4), s.single(5), s.single(6), s.single(7), p.x.data(),
                              p.y.data(), p.z.data(), p.size, p.u.data(), p.v.data(), p.w.data(),
                              inv_rc2);
}

}  // namespace

Eigen::Vector3d segment_velocity(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double gamma,
                                 const Eigen::Vector3d& p, const VortexCore& core) {
  SegmentSet s;
  s.reserve(1);
  s.push(a, b, gamma);
  double u = 0, v = 0, w = 0;
  add_induced_velocity(s, &p.x(), &p.y(), &p.z(), 1, &u, &v, &w, core);
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
  const double inv_rc2 = 1.0 / (core.radius * core.radius);
  switch (core.model) {
    case CoreModel::CutOff:
      add_double<CoreModel::CutOff>(segments, x, y, z, n, u, v, w, inv_rc2);
      break;
    case CoreModel::LambOseen:
      add_double<CoreModel::LambOseen>(segments, x, y, z, n, u, v, w, inv_rc2);
      break;
    case CoreModel::Vatistas:
      add_double<CoreModel::Vatistas>(segments, x, y, z, n, u, v, w, inv_rc2);
      break;
  }
}

void add_induced_velocity_single(const SegmentSet& segments, PointSet& points, const VortexCore& core) {
  if (!(core.radius > 0.0)) throw std::invalid_argument("vortex core radius must be > 0");
  const float inv_rc2 = static_cast<float>(1.0 / (core.radius * core.radius));
  switch (core.model) {
    case CoreModel::CutOff: add_single<CoreModel::CutOff>(segments, points, inv_rc2); break;
    case CoreModel::LambOseen: add_single<CoreModel::LambOseen>(segments, points, inv_rc2); break;
    case CoreModel::Vatistas: add_single<CoreModel::Vatistas>(segments, points, inv_rc2); break;
  }
}

}  // namespace flapsim::uvlm
