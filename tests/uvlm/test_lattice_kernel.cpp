// The lattice kernel (uvlm/lattice_segments.hpp): the same pair terms as the segment kernel
// (biot_savart.hpp) added in another order, so (1) the same bits on every instruction-set
// variant, (2) the segment kernel's result up to the rounding of a sum, (3) the textbook
// formula (Katz & Plotkin eq. 2.68) to the segment kernel's accuracy.
#include "uvlm/biot_savart.hpp"
#include "uvlm/kernel_dispatch.hpp"
#include "uvlm/lattice_segments.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace flapsim::uvlm;

namespace {

// A wavy rows × cols grid of nodes 5 mm apart in x and y (z = ±1 mm waves), circulations of
// either sign, cores of their own ((r_c/r_c,k)² ∈ [0.3, 1]); as a lattice and as a segment
// set (every segment the lattice has), plus target points: every node (on the segments)
// and random points in a box around the grid.
struct Grid {
  std::size_t rows, cols;
  LatticeSegments lattice;
  SegmentSet segments;
  PointSet points;
  Grid(std::size_t rows_, std::size_t cols_, unsigned seed) : rows(rows_), cols(cols_) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> g(-1e-3, 1e-3), ratio(0.3, 1.0), u(-0.01, 0.06);
    const std::size_t n = rows * cols;
    std::vector<double> x(n), y(n), z(n);
    for (std::size_t a = 0; a < n; ++a) {
      const double i = double(a / cols), j = double(a % cols);
      x[a] = 0.005 * j;
      y[a] = 0.005 * i;
      z[a] = 0.001 * std::sin(0.7 * i + 1.3 * j);
    }
    lattice.reserve(n, cols);
    lattice.assign_grid(rows, cols);
    for (std::size_t a = 0; a < n; ++a) lattice.set_node(a, x[a], y[a], z[a]);
    segments.reserve(2 * n);
    for (std::size_t a = 0; a < n; ++a) {
      if (a % cols + 1 < cols) {
        const double ga = g(rng), r = ratio(rng);
        lattice.set_spanwise(a, ga, r);
        segments.push(x[a], y[a], z[a], x[a + 1], y[a + 1], z[a + 1], ga, r);
      }
      if (a + cols < n) {
        const double ga = g(rng), r = ratio(rng);
        lattice.set_streamwise(a, ga, r);
        const std::size_t b = a + cols;
        segments.push(x[b], y[b], z[b], x[a], y[a], z[a], ga, r);
      }
    }
    lattice.finish(true);
    segments.update_single_precision();
    points.reserve(n + 41);
    points.size = n + 41;
    for (std::size_t a = 0; a < n; ++a) points.set(a, {x[a], y[a], z[a]});
    for (std::size_t i = n; i < points.size; ++i) points.set(i, {u(rng), u(rng), 0.2 * u(rng)});
  }
};

struct RestoreIsa {
  KernelIsa isa = kernel_isa();
  ~RestoreIsa() { set_kernel_isa(isa); }
};

PointSet lattice_velocities(const Grid& grid, KernelIsa isa, const VortexCore& core, bool single) {
  set_kernel_isa(isa);
  PointSet p = grid.points;
  p.zero_velocity();
  if (single)
    add_induced_velocity_single(grid.lattice, p.x.data(), p.y.data(), p.z.data(), p.size,
                                p.u.data(), p.v.data(), p.w.data(), core);
  else
    add_induced_velocity(grid.lattice, p.x.data(), p.y.data(), p.z.data(), p.size, p.u.data(),
                         p.v.data(), p.w.data(), core);
  return p;
}

// The grids: one tile of the kernel and a partial one (13 × 11 = 143 nodes, its tiles are
// 64 node indices), a row longer than a tile (3 × 70), a single row (no streamwise segments).
std::vector<Grid> grids() {
  std::vector<Grid> g;
  g.emplace_back(13, 11, 5);
  g.emplace_back(3, 70, 6);
  g.emplace_back(1, 9, 7);
  return g;
}

}  // namespace

TEST(LatticeKernel, SegmentCountOfTheGrid) {
  const Grid g(13, 11, 5);
  EXPECT_EQ(g.lattice.segments(), 13u * 10u + 12u * 11u);  // rows (cols − 1) + (rows − 1) cols
  EXPECT_EQ(g.lattice.segments(), g.segments.size());
  LatticeSegments l;
  l.reserve(20, 5);
  l.assign_grid(4, 5);
  EXPECT_THROW(l.set_spanwise(4, 1.0), std::invalid_argument);    // a row's last node
  EXPECT_THROW(l.set_streamwise(15, 1.0), std::invalid_argument);  // the last row
  EXPECT_THROW(l.assign_grid(8, 5), std::length_error);            // beyond the reserved room
}

TEST(LatticeKernel, EveryVariantEqualsTheScalarOneBitForBit) {
  RestoreIsa restore;
  for (const Grid& grid : grids())
    for (CoreModel model : {CoreModel::CutOff, CoreModel::LambOseen, CoreModel::Vatistas})
      for (bool single : {false, true}) {
        const VortexCore core{model, 2e-3};
        const PointSet ref = lattice_velocities(grid, KernelIsa::Scalar, core, single);
        for (KernelIsa isa : supported_kernel_isas()) {
          const PointSet got = lattice_velocities(grid, isa, core, single);
          for (std::size_t i = 0; i < ref.size; ++i) {
            ASSERT_EQ(got.u[i], ref.u[i]) << kernel_isa_name(isa) << " point " << i;
            ASSERT_EQ(got.v[i], ref.v[i]) << kernel_isa_name(isa) << " point " << i;
            ASSERT_EQ(got.w[i], ref.w[i]) << kernel_isa_name(isa) << " point " << i;
          }
        }
      }
}

TEST(LatticeKernel, EqualsTheSegmentKernelUpToTheRoundingOfTheSum) {
  // Each pair's term is the segment kernel's, bit for bit (same operations on the same
  // operands); only the order of the additions differs. The terms t_k are taken from the
  // segment kernel one segment at a time, their sum S in long double; each kernel's sum of
  // n terms in L lanes (at most n/L + L + 1 additions in a chain, each rounding by at most
  // u = ε/2 of the partial sum's size ≤ Σ|t_k|) lies within (n/L + L + 1) u Σ|t_k| of S
  // (Higham, Accuracy and Stability of Numerical Algorithms, 2002, §4.2), plus the final
  // conversion to double.
  RestoreIsa restore;
  for (const Grid& grid : grids())
    for (CoreModel model : {CoreModel::CutOff, CoreModel::LambOseen})
      for (bool single : {false, true}) {
        const VortexCore core{model, 2e-3};
        const PointSet lat = lattice_velocities(grid, kernel_isa(), core, single);
        PointSet seg = grid.points;
        seg.zero_velocity();
        if (single)
          add_induced_velocity_single(grid.segments, seg, core);
        else
          add_induced_velocity(grid.segments, seg, core);
        const std::size_t n = grid.segments.size();
        std::vector<long double> sum(3 * seg.size, 0.0L), size(3 * seg.size, 0.0L);
        SegmentSet one;
        one.reserve(1);
        PointSet t = grid.points;
        for (std::size_t k = 0; k < n; ++k) {
          const SegmentSet& s = grid.segments;
          one.clear();
          one.push(s.ax()[k], s.ay()[k], s.az()[k], s.bx()[k], s.by()[k], s.bz()[k], s.gamma()[k],
                   s.core_ratio2()[k]);
          one.update_single_precision();
          t.zero_velocity();
          if (single)
            add_induced_velocity_single(one, t, core);
          else
            add_induced_velocity(one, t, core);
          for (std::size_t i = 0; i < t.size; ++i)
            for (int c = 0; c < 3; ++c) {
              const double v = c == 0 ? t.u[i] : c == 1 ? t.v[i] : t.w[i];
              sum[3 * i + c] += v;
              size[3 * i + c] += std::abs(v);
            }
        }
        const double L = single ? 16 : 8;
        const double unit = 0.5 * (single ? std::numeric_limits<float>::epsilon()
                                          : std::numeric_limits<double>::epsilon());
        const double chain = double(n) / L + L + 2;
        for (std::size_t i = 0; i < seg.size; ++i)
          for (int c = 0; c < 3; ++c) {
            const double tol = chain * unit * double(size[3 * i + c]) + 1e-300;
            const double l = c == 0 ? lat.u[i] : c == 1 ? lat.v[i] : lat.w[i];
            const double s = c == 0 ? seg.u[i] : c == 1 ? seg.v[i] : seg.w[i];
            ASSERT_LE(std::abs(double(l - sum[3 * i + c])), tol)
                << "lattice " << grid.rows << "x" << grid.cols << " point " << i << " component " << c
                << (single ? " single" : " double");
            ASSERT_LE(std::abs(double(s - sum[3 * i + c])), tol)
                << "segments " << grid.rows << "x" << grid.cols << " point " << i << " component " << c;
          }
      }
}

TEST(LatticeKernel, MatchesTheTextbookFormulaInDoublePrecision) {
  // Katz & Plotkin eq. 2.68, v = Γ/(4π) (r1×r2)/|r1×r2|² · r0·(r1/|r1| − r2/|r2|), summed in
  // long double over the 13 × 11 grid, at the random points more than 3 core radii from
  // every segment (the singular kernel there; cut-off model): the lattice kernel's sum
  // within 1e-14 of Σ|v_k| / sin θ_k (θ_k between r1 and r2: r1×r2 loses digits as
  // sin θ → 0; the segment kernel's per-pair bound, test_kernel_dispatch.cpp) and within
  // 1e-14 of Σ|v_k| (about 50 roundings of 2^-53 = 1.1e-16 if they all added up); worst
  // measured printed.
  const Grid grid(13, 11, 5);
  const double rc = 2e-3;
  PointSet p = grid.points;
  p.zero_velocity();
  add_induced_velocity(grid.lattice, p.x.data(), p.y.data(), p.z.data(), p.size, p.u.data(),
                       p.v.data(), p.w.data(), {CoreModel::CutOff, rc});
  using Vec = std::array<long double, 3>;
  auto dot = [](const Vec& x, const Vec& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  const SegmentSet& s = grid.segments;
  double worst = 0, worst_plain = 0;
  int tested = 0;
  for (std::size_t i = grid.rows * grid.cols; i < p.size; ++i) {
    const Vec q{p.x[i], p.y[i], p.z[i]};
    Vec ref{0, 0, 0};
    long double size = 0, plain = 0, closest = 1;
    for (std::size_t k = 0; k < s.size(); ++k) {
      const Vec a{s.ax()[k], s.ay()[k], s.az()[k]}, b{s.bx()[k], s.by()[k], s.bz()[k]};
      const Vec r0{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
      const Vec r1{q[0] - a[0], q[1] - a[1], q[2] - a[2]}, r2{q[0] - b[0], q[1] - b[1], q[2] - b[2]};
      const Vec c{r1[1] * r2[2] - r1[2] * r2[1], r1[2] * r2[0] - r1[0] * r2[2], r1[0] * r2[1] - r1[1] * r2[0]};
      const long double n1 = std::sqrt(dot(r1, r1)), n2 = std::sqrt(dot(r2, r2)), c2 = dot(c, c);
      const long double t = std::clamp(dot(r1, r0) / dot(r0, r0), 0.0L, 1.0L);
      const Vec h{r1[0] - t * r0[0], r1[1] - t * r0[1], r1[2] - t * r0[2]};
      closest = std::min(closest, std::sqrt(dot(h, h)));
      const long double kk = s.gamma()[k] * (dot(r0, r1) / n1 - dot(r0, r2) / n2) /
                             (4 * 3.14159265358979323846264338327950288L * c2);
      for (int m = 0; m < 3; ++m) ref[m] += kk * c[m];
      size += std::abs(kk) * n1 * n2;  // |v_k| / sin θ_k = |k| |r1×r2| / (|r1×r2| / (|r1||r2|))
      plain += std::abs(kk) * std::sqrt(c2);  // |v_k|
    }
    if (closest < 3 * rc) continue;
    ++tested;
    const long double du = p.u[i] - ref[0], dv = p.v[i] - ref[1], dw = p.w[i] - ref[2];
    const double rel = double(std::sqrt(du * du + dv * dv + dw * dw) / size);
    const double rel_plain = double(std::sqrt(du * du + dv * dv + dw * dw) / plain);
    EXPECT_LT(rel, 1e-14) << "point " << i;
    EXPECT_LT(rel_plain, 1e-14) << "point " << i;
    worst = std::max(worst, rel);
    worst_plain = std::max(worst_plain, rel_plain);
  }
  EXPECT_GT(tested, 10);
  std::printf("lattice kernel, double: %d points, worst error %.2g of sum |v_k| / sin theta_k, %.2g of sum |v_k|\n",
              tested, worst, worst_plain);
}
