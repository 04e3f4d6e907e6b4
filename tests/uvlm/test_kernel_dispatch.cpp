// The Biot–Savart kernel variants (scalar, AVX2, AVX-512): every variant this CPU runs
// gives the same velocities, bit for bit, as the baseline x86-64 one (the design of
// uvlm/kernel_dispatch.hpp: same operations in the same order whatever the vector width),
// and the baseline agrees with the textbook segment formula.
#include "uvlm/biot_savart.hpp"
#include "uvlm/biot_savart_kernel.hpp"
#include "uvlm/kernel_dispatch.hpp"
#include "uvlm/vortex_lattice.hpp"

#include "wing_cases.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <array>
#include <limits>
#include <random>
#include <vector>

using namespace flapsim::uvlm;

namespace {

struct Problem {
  SegmentSet s;
  PointSet p;
};

// 1003 segments (not a multiple of the 8 or 16 lanes, so the padded tail block is used)
// and 41 points in a 5 cm box with circulations of either sign.
Problem random_problem() {
  Problem q;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 0.05), g(-1e-3, 1e-3);
  q.s.reserve(1003);
  for (int k = 0; k < 1003; ++k) q.s.push(u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), g(rng));
  q.s.update_single_precision();
  q.p.reserve(41);
  q.p.size = 41;
  for (int i = 0; i < 41; ++i) q.p.set(i, {u(rng), u(rng), u(rng)});
  return q;
}

PointSet velocities(Problem& q, KernelIsa isa, const VortexCore& core, bool single) {
  set_kernel_isa(isa);
  q.p.zero_velocity();
  if (single)
    add_induced_velocity_single(q.s, q.p, core);
  else
    add_induced_velocity(q.s, q.p, core);
  return q.p;
}

struct RestoreIsa {
  KernelIsa isa = kernel_isa();
  ~RestoreIsa() { set_kernel_isa(isa); }
};

}  // namespace

TEST(KernelDispatch, DefaultIsTheWidestVariantTheCpuRuns) {
  const auto isas = supported_kernel_isas();
  ASSERT_FALSE(isas.empty());
  EXPECT_EQ(isas.front(), KernelIsa::Scalar);  // baseline x86-64 runs everywhere
  EXPECT_EQ(kernel_isa(), isas.back());
  if (!kernel_isa_supported(KernelIsa::Avx512)) {
    EXPECT_THROW(set_kernel_isa(KernelIsa::Avx512), std::invalid_argument);
  }
  std::printf("kernel variants on this CPU:");
  for (KernelIsa isa : isas) std::printf(" %s", std::string(kernel_isa_name(isa)).c_str());
  std::printf("\n");
}

TEST(KernelDispatch, EveryVariantEqualsTheScalarOneBitForBit) {
  RestoreIsa restore;
  Problem q = random_problem();
  for (CoreModel model : {CoreModel::CutOff, CoreModel::LambOseen, CoreModel::Vatistas})
    for (bool single : {false, true}) {
      const VortexCore core{model, 2e-3};
      const PointSet ref = velocities(q, KernelIsa::Scalar, core, single);
      for (KernelIsa isa : supported_kernel_isas()) {
        const PointSet got = velocities(q, isa, core, single);
        for (std::size_t i = 0; i < ref.size; ++i) {
          EXPECT_EQ(got.u[i], ref.u[i]) << kernel_isa_name(isa) << " point " << i;
          EXPECT_EQ(got.v[i], ref.v[i]) << kernel_isa_name(isa) << " point " << i;
          EXPECT_EQ(got.w[i], ref.w[i]) << kernel_isa_name(isa) << " point " << i;
        }
      }
    }
}

TEST(KernelDispatch, EveryVariantMatchesTheTextbookSegmentFormula) {
  // Katz & Plotkin eq. 2.68: v = Γ/(4π) (r1×r2)/|r1×r2|² · r0·(r1/|r1| − r2/|r2|), times the
  // Lamb–Oseen factor 1 − exp(−1.25643 h²/r_c²), h the distance from the point to the
  // segment (vortex_core.hpp), evaluated here with std::exp and the projection parameter,
  // independently of the kernel's polynomial exp and its r1·r2 test.
  RestoreIsa restore;
  Problem q = random_problem();
  const VortexCore core{CoreModel::LambOseen, 2e-3};
  for (KernelIsa isa : supported_kernel_isas()) {
    for (bool single : {false, true}) {
      const PointSet got = velocities(q, isa, core, single);
      for (std::size_t i = 0; i < got.size; ++i) {
        const Eigen::Vector3d p = q.p.position(i);
        Eigen::Vector3d ref = Eigen::Vector3d::Zero();
        double scale = 0;  // Σ|contributions|, the size the rounding errors scale with
        for (std::size_t k = 0; k < q.s.size(); ++k) {
          const Eigen::Vector3d a(q.s.ax()[k], q.s.ay()[k], q.s.az()[k]);
          const Eigen::Vector3d b(q.s.bx()[k], q.s.by()[k], q.s.bz()[k]);
          const Eigen::Vector3d r0 = b - a, r1 = p - a, r2 = p - b, c = r1.cross(r2);
          const double t = r1.dot(r0) / r0.squaredNorm();  // projection of P on the line, 0 at A
          const double h2 = t < 0 ? r1.squaredNorm() : t > 1 ? r2.squaredNorm() : c.squaredNorm() / r0.squaredNorm();
          const double f = 1 - std::exp(-1.25643 * h2 / (core.radius * core.radius));
          const Eigen::Vector3d v = q.s.gamma()[k] / (4 * M_PI) * c / c.squaredNorm() *
                                    r0.dot(r1.normalized() - r2.normalized()) * f;
          ref += v;
          scale += v.norm();
        }
        // Double: the kernel's exp is accurate to 1e-12; single: float rounding (~1e-7)
        // amplified near the segment's line (r1·r2 ≈ |r1||r2|).
        const double tol = single ? 1e-4 * scale : 1e-11 * scale;
        EXPECT_NEAR((got.velocity(i) - ref).norm(), 0.0, tol)
            << kernel_isa_name(isa) << (single ? " single" : " double") << " point " << i;
      }
    }
  }
}

TEST(KernelDispatch, PolynomialExpAgreesWithStdExp) {
  // The kernels' e^(−y) (biot_savart_kernel.hpp: (e^(−y/64))^64, degree-10 Taylor polynomial)
  // against the C library on the whole range it is used on, y = 1.25643 h²/r_c² ∈ [0, 40].
  // What the Lamb–Oseen factor 1 − e^(−y) needs is its absolute error: below 128 ulp of 1
  // (2.8e-14) in double — measured 1.1e-14, the polynomial's rounding amplified 64× by the
  // six squarings; the truncation is below 1.2e-19 — and 64 ulp of 1 (7.6e-6) in float
  // (measured 2.3e-6; (e^(−y/32))^32, degree 6).
  // Relative to e^(−y) itself, 5e-14 for y ≤ 10 (measured 2.1e-14).
  using flapsim::uvlm::detail::exp_neg;
  double worst = 0, worst_single = 0, worst_relative = 0;
  for (int i = 0; i <= 40000; ++i) {
    const double y = 40.0 * i / 40000;
    const double e = std::exp(-y);
    worst = std::max(worst, std::abs(exp_neg(y) - e));
    if (y <= 10) worst_relative = std::max(worst_relative, std::abs(exp_neg(y) - e) / e);
    const float yf = static_cast<float>(y);
    worst_single = std::max(worst_single, std::abs(double(exp_neg(yf)) - std::exp(-double(yf))));
  }
  EXPECT_LT(worst, 128 * std::numeric_limits<double>::epsilon());
  EXPECT_LT(worst_relative, 5e-14);
  EXPECT_LT(worst_single, 64 * double(std::numeric_limits<float>::epsilon()));
  // Beyond x = kLambOseenUnity the factor is 1 exactly (so a block of segments that far
  // from the point may skip the exponential without changing a bit): e^(−1.25643·30) =
  // 4.3e-17 is less than half the spacing of doubles below 1 (2^-54 = 5.6e-17).
  using flapsim::uvlm::detail::kLambOseen;
  using flapsim::uvlm::detail::kLambOseenUnity;
  EXPECT_EQ(1.0 - exp_neg(kLambOseen * kLambOseenUnity<double>), 1.0);
  EXPECT_LT(1.0 - exp_neg(kLambOseen * 0.95 * kLambOseenUnity<double>), 1.0);  // not 1 below it
  // Float: from x = 14, e^(−17.6) = 2.3e-8 < 2^-25 = 3.0e-8.
  EXPECT_EQ(1.0f - exp_neg(float(kLambOseen) * kLambOseenUnity<float>), 1.0f);
  EXPECT_LT(1.0f - exp_neg(float(kLambOseen) * 0.9f * kLambOseenUnity<float>), 1.0f);
}

namespace {

// Velocity induced at p by the segment a→b (circulation 1) by Katz & Plotkin eq. 2.68,
// v = (r1×r2)/(4π|r1×r2|²) · r0·(r1/|r1| − r2/|r2|), times the core factor f (1 for the
// singular kernel, 1 − exp(−1.25643 h²/r_c²) for Lamb–Oseen, h by the projection
// parameter), all in long double (x87: 64-bit significand, 2^-64 = 5.4e-20).
using Vec = std::array<long double, 3>;
Vec textbook_velocity(const Vec& a, const Vec& b, const Vec& p, long double rc, bool lamb_oseen) {
  const Vec r0{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const Vec r1{p[0] - a[0], p[1] - a[1], p[2] - a[2]};
  const Vec r2{p[0] - b[0], p[1] - b[1], p[2] - b[2]};
  auto dot = [](const Vec& x, const Vec& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  const Vec c{r1[1] * r2[2] - r1[2] * r2[1], r1[2] * r2[0] - r1[0] * r2[2], r1[0] * r2[1] - r1[1] * r2[0]};
  const long double n1 = std::sqrt(dot(r1, r1)), n2 = std::sqrt(dot(r2, r2)), c2 = dot(c, c);
  long double f = 1;
  if (lamb_oseen) {
    const long double t = dot(r1, r0) / dot(r0, r0);
    const long double h2 = t < 0 ? dot(r1, r1) : t > 1 ? dot(r2, r2) : c2 / dot(r0, r0);
    f = 1 - std::exp(-1.25643L * h2 / (rc * rc));
  }
  const long double k = (dot(r0, r1) / n1 - dot(r0, r2) / n2) / (4 * 3.14159265358979323846264338327950288L * c2) * f;
  return {k * c[0], k * c[1], k * c[2]};
}

long double sin_angle(const Vec& a, const Vec& b, const Vec& p) {
  const Vec r1{p[0] - a[0], p[1] - a[1], p[2] - a[2]}, r2{p[0] - b[0], p[1] - b[1], p[2] - b[2]};
  const Vec c{r1[1] * r2[2] - r1[2] * r2[1], r1[2] * r2[0] - r1[0] * r2[2], r1[0] * r2[1] - r1[1] * r2[0]};
  auto norm = [](const Vec& x) { return std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]); };
  return norm(c) / (norm(r1) * norm(r2));
}

}  // namespace

TEST(KernelDispatch, EachPairIsWithinItsRoundingBoundOfTheExactFormula) {
  // One segment at a time against 64 points (so each velocity is one pair's, not a sum that
  // could hide errors), 300 random segments in a 5 cm box, points anywhere in it: the
  // double kernel of every variant against the long-double textbook formula above.
  // Errors relative to |v|/sin θ (θ between r1 and r2, see below; sin θ = 1 beside the
  // segment). Singular kernel (cut-off, points outside the core): the kernel's ~40
  // roundings of 2^-53 = 1.1e-16 each bound its relative error by ~4.4e-15 if they all
  // added up; tolerance 1e-14 (measured 8.1e-16). Lamb–Oseen: plus the factor's absolute error, below
  // 2.8e-14 (PolynomialExpAgreesWithStdExp), i.e. relative 2.8e-14/f; only pairs with
  // x = h²/r_c² ≥ 1 (f ≥ 0.72) are taken, where that is ≤ 3.9e-14: tolerance 1e-14 + 2.8e-14/f
  // (measured 1.6e-15).
  RestoreIsa restore;
  std::uniform_real_distribution<double> u(0.0, 0.05);
  const double rc = 2e-3;
  PointSet p;
  p.reserve(64);
  p.size = 64;
  for (KernelIsa isa : supported_kernel_isas()) {
    set_kernel_isa(isa);
    std::mt19937 rng(23);  // the same pairs for every variant
    double worst_singular = 0, worst_lamb_oseen = 0;
    for (int k = 0; k < 300; ++k) {
      const Vec a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)};
      SegmentSet s;
      s.reserve(1);
      s.push(double(a[0]), double(a[1]), double(a[2]), double(b[0]), double(b[1]), double(b[2]), 1.0);
      for (int i = 0; i < 64; ++i) p.set(i, {u(rng), u(rng), u(rng)});
      for (bool lamb_oseen : {false, true}) {
        p.zero_velocity();
        add_induced_velocity(s, p, {lamb_oseen ? CoreModel::LambOseen : CoreModel::CutOff, rc});
        for (int i = 0; i < 64; ++i) {
          const Vec q{p.x[i], p.y[i], p.z[i]};
          const Vec ref = textbook_velocity(a, b, q, rc, lamb_oseen);
          // Error relative to |v|/sin θ, θ the angle between r1 and r2: r1×r2 loses digits in
          // proportion to 1/sin θ (near the segment's line beyond its ends, where v → 0).
          const long double size = std::sqrt(ref[0] * ref[0] + ref[1] * ref[1] + ref[2] * ref[2]) / sin_angle(a, b, q);
          const long double du = p.u[i] - ref[0], dv = p.v[i] - ref[1], dw = p.w[i] - ref[2];
          const double rel = double(std::sqrt(du * du + dv * dv + dw * dw) / size);
          const Vec r0{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
          // h²/r_c² as in textbook_velocity, for choosing the pairs
          const Vec r1{q[0] - a[0], q[1] - a[1], q[2] - a[2]};
          const long double t = (r1[0] * r0[0] + r1[1] * r0[1] + r1[2] * r0[2]) /
                                (r0[0] * r0[0] + r0[1] * r0[1] + r0[2] * r0[2]);
          const long double tc = std::clamp(t, 0.0L, 1.0L);
          const long double hx = r1[0] - tc * r0[0], hy = r1[1] - tc * r0[1], hz = r1[2] - tc * r0[2];
          const double x = double((hx * hx + hy * hy + hz * hz) / (rc * rc));
          if (x < 1) continue;
          if (lamb_oseen) {
            const double f = 1 - std::exp(-1.25643 * x);
            EXPECT_LT(rel, 1e-14 + 2.8e-14 / f) << kernel_isa_name(isa) << " segment " << k << " point " << i;
            worst_lamb_oseen = std::max(worst_lamb_oseen, rel);
          } else {
            EXPECT_LT(rel, 1e-14) << kernel_isa_name(isa) << " segment " << k << " point " << i;
            worst_singular = std::max(worst_singular, rel);
          }
        }
      }
    }
    std::printf("%s double: worst relative error against the exact formula %.2g (singular), %.2g (Lamb-Oseen, x >= 1)\n",
                std::string(kernel_isa_name(isa)).c_str(), worst_singular, worst_lamb_oseen);
  }
}

TEST(KernelDispatch, AFreeWakeRunGivesTheSameLiftWithEveryVariant) {
  // A rectangular wing (AR 4, 4 × 8 panels, α = 5°) started impulsively, free wake, 40
  // steps, with double- and single-precision wake sums: every kernel variant this CPU runs
  // gives the same CL history, bit for bit (so FLAPSIM_KERNEL=scalar, avx2 and the default
  // give the same numbers; kernel_dispatch.hpp).
  RestoreIsa restore;
  flapsim::uvlm::testing::RectangularWing w;
  w.chordwise = 4;
  w.spanwise = 8;
  w.wake_core = 0.05;
  const int steps = 40;
  const Eigen::Matrix3Xd nodes = w.grid().nodes, zero = Eigen::Matrix3Xd::Zero(3, nodes.cols());
  const double step = 0.25 * w.chord / w.speed;
  auto history = [&](KernelIsa isa, bool single) {
    set_kernel_isa(isa);
    VortexLatticeModel m = w.model(steps, WakeModel::Free);
    m.single_precision_wake = single;
    VortexLatticeData d(m);
    std::vector<double> cl;
    for (int k = 0; k < steps; ++k) {
      solve(m, d, nodes, zero, w.free_stream(), step, w.rho);
      cl.push_back(w.lift_coefficient(d.loads));
      advance(m, d);
    }
    return cl;
  };
  for (bool single : {false, true}) {
    const std::vector<double> ref = history(KernelIsa::Scalar, single);
    EXPECT_GT(*std::max_element(ref.begin(), ref.end()), 0.3);  // a lifting run (CL → 0.75)
    for (KernelIsa isa : supported_kernel_isas())
      EXPECT_EQ(history(isa, single), ref) << kernel_isa_name(isa) << (single ? " single" : " double");
  }
}
