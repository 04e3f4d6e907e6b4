#include "uvlm/lattice_segments.hpp"

#include "uvlm/biot_savart_kernel.hpp"
#include "uvlm/kernel_dispatch.hpp"
#include "uvlm/lattice_lanes.hpp"

#include <stdexcept>
#include <string>

namespace flapsim::uvlm {

namespace {

constexpr std::size_t kPad = detail::kLanes<float>;  // span is a multiple of every variant's lanes

std::size_t round_up(std::size_t n) { return (n + kPad - 1) / kPad * kPad; }

}  // namespace

void LatticeSegments::reserve(std::size_t nodes, std::size_t cols) {
  const std::size_t n = round_up(nodes) + cols + 1 + kPad;
  for (auto& a : double_) a.assign(n, 0.0);
  for (auto& a : single_) a.assign(n, 0.0f);
  rows_ = cols_ = span_ = 0;
}

void LatticeSegments::assign_grid(std::size_t rows, std::size_t cols) {
  const std::size_t span = round_up(rows * cols);
  if (span + cols + 1 + kPad > double_[X].size())
    throw std::length_error("LatticeSegments: a grid of " + std::to_string(rows) + " x " +
                            std::to_string(cols) + " nodes exceeds the reserved room");
  rows_ = rows;
  cols_ = cols;
  span_ = rows * cols == 0 ? 0 : span;
  for (Array a : {SpanGamma, StreamGamma})
    std::fill(double_[a].begin(), double_[a].begin() + static_cast<long>(span_), 0.0);
  for (Array a : {SpanCoreRatio2, StreamCoreRatio2})
    std::fill(double_[a].begin(), double_[a].begin() + static_cast<long>(span_), 1.0);
}

std::size_t LatticeSegments::segments() const {
  if (rows_ == 0 || cols_ == 0) return 0;
  return rows_ * (cols_ - 1) + (rows_ - 1) * cols_;
}

void LatticeSegments::set_node(std::size_t a, double x, double y, double z) {
  double_[X][a] = x;
  double_[Y][a] = y;
  double_[Z][a] = z;
}

void LatticeSegments::set_spanwise(std::size_t a, double gamma, double core_ratio2) {
  if (a >= nodes() || a % cols_ + 1 >= cols_)
    throw std::invalid_argument("LatticeSegments: no spanwise segment at node " + std::to_string(a));
  double_[SpanGamma][a] = gamma;
  double_[SpanCoreRatio2][a] = core_ratio2;
}

void LatticeSegments::set_streamwise(std::size_t a, double gamma, double core_ratio2) {
  if (a + cols_ >= nodes())
    throw std::invalid_argument("LatticeSegments: no streamwise segment at node " + std::to_string(a));
  double_[StreamGamma][a] = gamma;
  double_[StreamCoreRatio2][a] = core_ratio2;
}

void LatticeSegments::finish(bool single) {
  const std::size_t n = nodes();
  if (n == 0) return;
  const std::size_t end = span_ + cols_ + 1 + kPad;
  for (std::size_t a = n; a < end; ++a) set_node(a, double_[X][n - 1], double_[Y][n - 1], double_[Z][n - 1]);
  const double *x = double_[X].data(), *y = double_[Y].data(), *z = double_[Z].data();
  for (std::size_t a = 0; a < span_; ++a) {
    // As SegmentSet::push: spanwise A = a, B = a + 1; streamwise A = a + cols, B = a.
    const std::size_t b = a + 1, c = a + cols_;
    double_[SpanInvLength2][a] =
        detail::segment_scale(x[a], y[a], z[a], x[b], y[b], z[b], double_[SpanCoreRatio2][a]);
    double_[StreamInvLength2][a] =
        detail::segment_scale(x[c], y[c], z[c], x[a], y[a], z[a], double_[StreamCoreRatio2][a]);
  }
  if (single)
    for (int k = 0; k < kArrays; ++k) {
      const std::size_t m = k <= Z ? end : span_;
      for (std::size_t a = 0; a < m; ++a) single_[k][a] = static_cast<float>(double_[k][a]);
    }
}

namespace {

template <class T>
void dispatch(const detail::LatticeCall<T>& c) {
  switch (kernel_isa()) {
    case KernelIsa::Scalar: detail::lattice_sum_scalar(c); break;
    case KernelIsa::Avx2: detail::lattice_sum_avx2(c); break;
    case KernelIsa::Avx512: detail::lattice_sum_avx512(c); break;
  }
}

template <class T, class Get>
void sum(const LatticeSegments& l, Get get, const double* x, const double* y, const double* z,
         std::size_t n, double* u, double* v, double* w, const VortexCore& core) {
  if (!(core.radius > 0.0)) throw std::invalid_argument("vortex core radius must be > 0");
  if (l.span() == 0 || n == 0) return;
  using L = LatticeSegments;
  detail::LatticeCall<T> c{l.cols(), l.span(),
                           get(L::X), get(L::Y), get(L::Z),
                           get(L::SpanGamma), get(L::SpanInvLength2), get(L::SpanCoreRatio2),
                           get(L::StreamGamma), get(L::StreamInvLength2), get(L::StreamCoreRatio2),
                           static_cast<T>(1.0 / (core.radius * core.radius)), core.model,
                           n, x, y, z, u, v, w};
  dispatch(c);
}

}  // namespace

void add_induced_velocity(const LatticeSegments& lattice, const double* x, const double* y,
                          const double* z, std::size_t n, double* u, double* v, double* w,
                          const VortexCore& core) {
  sum<double>(lattice, [&](LatticeSegments::Array a) { return lattice.data(a); }, x, y, z, n, u, v, w, core);
}

void add_induced_velocity_single(const LatticeSegments& lattice, const double* x,
                                 const double* y, const double* z, std::size_t n, double* u,
                                 double* v, double* w, const VortexCore& core) {
  sum<float>(lattice, [&](LatticeSegments::Array a) { return lattice.single(a); }, x, y, z, n, u, v, w, core);
}

}  // namespace flapsim::uvlm
