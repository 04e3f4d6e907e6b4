#include "uvlm/biot_savart.hpp"

#include "uvlm/biot_savart_kernel.hpp"

#include <stdexcept>

namespace flapsim::uvlm {

void SegmentSet::reserve(std::size_t capacity) {
  for (auto* a : {&ax_, &ay_, &az_, &bx_, &by_, &bz_, &gamma_, &inv_len2_}) a->assign(capacity, 0.0);
  size_ = 0;
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
constexpr std::size_t kParallelThreshold = 20000;

template <CoreModel M>
void add_velocity_impl(const SegmentSet& s, const double* x, const double* y, const double* z,
                       std::size_t n, double* u, double* v, double* w, double inv_rc2) {
  const std::size_t ns = s.size();
  const double* __restrict ax = s.ax();
  const double* __restrict ay = s.ay();
  const double* __restrict az = s.az();
  const double* __restrict bx = s.bx();
  const double* __restrict by = s.by();
  const double* __restrict bz = s.bz();
  const double* __restrict g = s.gamma();
  const double* __restrict il = s.inv_length2();
  const long nt = static_cast<long>(n);
#pragma omp parallel for schedule(static) if (n * ns > kParallelThreshold)
  for (long i = 0; i < nt; ++i) {
    const double px = x[i], py = y[i], pz = z[i];
    double su = 0.0, sv = 0.0, sw = 0.0;
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
      add_velocity_impl<CoreModel::CutOff>(segments, x, y, z, n, u, v, w, inv_rc2);
      break;
    case CoreModel::LambOseen:
      add_velocity_impl<CoreModel::LambOseen>(segments, x, y, z, n, u, v, w, inv_rc2);
      break;
    case CoreModel::Vatistas:
      add_velocity_impl<CoreModel::Vatistas>(segments, x, y, z, n, u, v, w, inv_rc2);
      break;
  }
}

}  // namespace flapsim::uvlm
