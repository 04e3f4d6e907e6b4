#include "uvlm/segment_tree.hpp"

#include "uvlm/biot_savart_kernel.hpp"
#include "uvlm/biot_savart_lanes.hpp"
#include "uvlm/kernel_dispatch.hpp"
#include "uvlm/multipole_batch.hpp"

#include <omp.h>

#include <algorithm>
#include <limits>
#include <array>
#include <cmath>
#include <stdexcept>

namespace flapsim::uvlm {

namespace {

using detail::kMaxOrder;
using detail::kTable;
using detail::MultiIndexTable;
using detail::terms_up_to;
constexpr int kLanes = detail::kLanes<double>;
constexpr std::size_t kFlagBlock = 64;  // pieces whose core distance is tested at once

const MultiIndexTable& table() { return kTable; }

/// The batched expansion of the variant in use (kernel_dispatch.hpp).
void (*multipole_batch_variant())(detail::MultipoleBatch&) {
  switch (kernel_isa()) {
    case KernelIsa::Avx512: return detail::multipole_batch_avx512;
    case KernelIsa::Avx2: return detail::multipole_batch_avx2;
    default: return detail::multipole_batch_scalar;
  }
}

/// Interleave the low 20 bits of x, y, z into a 60-bit Morton key.
std::uint64_t spread(std::uint64_t v) {
  v &= 0xFFFFF;
  v = (v | v << 32) & 0x1F00000000FFFFull;
  v = (v | v << 16) & 0x1F0000FF0000FFull;
  v = (v | v << 8) & 0x100F00F00F00F00Full;
  v = (v | v << 4) & 0x10C30C30C30C30C3ull;
  v = (v | v << 2) & 0x1249249249249249ull;
  return v;
}

/// Distance from a segment, in units of its core radius, beyond which the core factor
/// f(h²/r_c²) differs from 1 by less than `tolerance` (vortex_core.hpp).
double core_free_distance(CoreModel model, double tolerance) {
  switch (model) {
    case CoreModel::CutOff: return 1.0;
    case CoreModel::LambOseen: return std::sqrt(std::log(1.0 / tolerance) / detail::kLambOseen);
    case CoreModel::Vatistas: return std::pow(0.5 / tolerance, 0.25);  // 1 − f ≈ 1/(2x²)
  }
  return 1.0;
}

}  // namespace

TreeParameters tree_parameters(double tolerance) {
  if (!(tolerance > 0.0)) throw std::invalid_argument("tree code: tolerance must be > 0");
  // Measured against the direct sum (relative L2 error of the velocities) on the computed
  // free wake of cases/bench_hover.toml after 3 cycles (6289 stretched segments, its 3311
  // nodes) and the far wake of cases/hover_periodic.toml after 20 cycles (40771 segments,
  // at the young wake's 561 nodes), the larger of the two (docs/performance.md):
  // p = 4, θ = 0.45: 3.7e-4; θ = 0.3: 3.5e-5; θ = 0.2: 3.2e-6 (θ = 0.12 below 1e-5: not
  // measured beyond that it is smaller than θ = 0.2).
  if (tolerance >= 1e-3) return {4, 0.45, tolerance};
  if (tolerance >= 1e-4) return {4, 0.3, tolerance};
  if (tolerance >= 1e-5) return {4, 0.2, tolerance};
  return {4, 0.12, tolerance};
}

double SegmentTree::reserved_bytes(std::size_t n, int threads) {
  // The arrays reserve() assigns, in its order.
  const double segments = static_cast<double>(n);
  const double cap = kPiecesPerSegment * segments;
  const double nodes = std::floor(cap / 4) + 64;
  const double padded = cap + nodes * (kLanes - 1);
  const double d = sizeof(double), u32 = sizeof(std::uint32_t), u64 = sizeof(std::uint64_t);
  double bytes =
      10 * segments * d + 13 * cap * d + 10 * padded * d + padded * u32 + 2 * cap * u64 + 3 * cap * u32;
  bytes += nodes * (sizeof(Node) + 3 * terms_up_to(kMaxOrder) * d + u32);
  bytes += std::max(threads, 1) * (2 * segments * u32 + 12 * (segments + kLanes) * d);
  return bytes;
}

void SegmentTree::reserve(std::size_t n) {
  const std::size_t cap = kPiecesPerSegment * n;
  // Nodes: a leaf holds up to kLeafSegments pieces and every internal node ≥ 2 children;
  // a tree of pieces has about one node per 10–20 pieces (measured), so cap/4 + 64 leaves
  // a wide margin. Should a tree need more, build() makes leaves of the nodes it cannot
  // split (larger leaves: slower, not less accurate).
  const std::size_t nodes = cap / 4 + 64;
  for (auto* a : {&wax_, &way_, &waz_, &wbx_, &wby_, &wbz_, &wg_, &wil_, &wrat_, &wsafe2_}) a->assign(n, 0.0);
  for (auto* a : {&qax_, &qay_, &qaz_, &qbx_, &qby_, &qbz_, &sx_, &sy_, &sz_, &tx_, &ty_, &tz_, &sg_})
    a->assign(cap, 0.0);
  const std::size_t padded = cap + nodes * (kLanes - 1);
  for (auto* a : {&pax_, &pay_, &paz_, &pbx_, &pby_, &pbz_, &pg_, &pil_, &prat_, &psafe2_})
    a->assign(padded, 0.0);
  ppar_.assign(padded, 0);
  keys_.assign(2 * cap, 0);
  order_.assign(cap, 0);
  parent_.assign(cap, 0);
  sparent_.assign(cap, 0);
  nodes_.assign(nodes, Node{});
  moments_.assign(nodes * 3 * terms_up_to(kMaxOrder), 0.0);
  stack_.assign(nodes, 0);
  scratch_.assign(static_cast<std::size_t>(std::max(omp_get_max_threads(), 1)), NearScratch{});
  for (NearScratch& t : scratch_) {
    t.stamp.assign(n, 0);
    t.list.assign(n, 0);
    for (auto* a : {&t.ax, &t.ay, &t.az, &t.bx, &t.by, &t.bz, &t.g, &t.neg_g, &t.il, &t.cr, &t.il_cut, &t.one})
      a->assign(n + kLanes, 0.0);
    t.visit = 0;
  }
  size_ = pieces_ = node_count_ = 0;
}

std::size_t SegmentTree::cut_pieces(const SegmentSet& s, double core_distance) {
  const std::size_t n = s.size(), cap = order_.size();
  double total = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double dx = s.bx()[k] - s.ax()[k], dy = s.by()[k] - s.ay()[k], dz = s.bz()[k] - s.az()[k];
    total += std::sqrt(dx * dx + dy * dy + dz * dz);
  }
  // ℓ: asked for, or s_0 · kPieceLengthPerCoreDistance; at least what fits: Σ ⌈L_k/ℓ⌉ ≤
  // Σ (L_k/ℓ + 1) = total/ℓ + n ≤ cap.
  double l = params_.piece_length > 0.0 ? params_.piece_length
                                        : kPieceLengthPerCoreDistance * core_distance * core_.radius;
  if (cap > n) l = std::max(l, total / static_cast<double>(cap - n));
  else l = std::numeric_limits<double>::infinity();
  piece_length_ = l;
  std::size_t m = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double ax = s.ax()[k], ay = s.ay()[k], az = s.az()[k];
    const double dx = s.bx()[k] - ax, dy = s.by()[k] - ay, dz = s.bz()[k] - az;
    const double len = std::sqrt(dx * dx + dy * dy + dz * dz);
    const std::size_t count = std::isfinite(l) && len > l ? static_cast<std::size_t>(std::ceil(len / l)) : 1;
    double px = ax, py = ay, pz = az;  // piece i from A + (i/count)(B − A); the last ends at B exactly
    for (std::size_t i = 0; i < count; ++i, ++m) {
      const double t = static_cast<double>(i + 1) / static_cast<double>(count);
      const double qx = i + 1 == count ? s.bx()[k] : ax + t * dx;
      const double qy = i + 1 == count ? s.by()[k] : ay + t * dy;
      const double qz = i + 1 == count ? s.bz()[k] : az + t * dz;
      qax_[m] = px; qay_[m] = py; qaz_[m] = pz;
      qbx_[m] = qx; qby_[m] = qy; qbz_[m] = qz;
      parent_[m] = static_cast<std::uint32_t>(k);
      px = qx; py = qy; pz = qz;
    }
  }
  return m;
}

void SegmentTree::build(const SegmentSet& s, const VortexCore& core, const TreeParameters& params) {
  const std::size_t n = s.size();
  if (n > wax_.size()) throw std::length_error("tree code: more segments than reserved");
  if (params.order < 0 || params.order > kMaxOrder || !(params.theta > 0.0 && params.theta < 1.0))
    throw std::invalid_argument("tree code: order must be 0..4 and opening angle in (0, 1)");
  params_ = params;
  core_ = core;
  terms_ = terms_up_to(params.order);
  size_ = n;
  pieces_ = node_count_ = 0;
  if (n == 0) return;

  // The segments as given, with their core distances s_k = s_0 r_c,k.
  const double core_distance = core_free_distance(core.model, 0.1 * params.tolerance);
  const double s0_2 = core_distance * core_distance * core.radius * core.radius;
  for (std::size_t k = 0; k < n; ++k) {
    wax_[k] = s.ax()[k]; way_[k] = s.ay()[k]; waz_[k] = s.az()[k];
    wbx_[k] = s.bx()[k]; wby_[k] = s.by()[k]; wbz_[k] = s.bz()[k];
    wg_[k] = s.gamma()[k];
    wrat_[k] = s.core_ratio2()[k];
    wil_[k] = detail::segment_scale(wax_[k], way_[k], waz_[k], wbx_[k], wby_[k], wbz_[k], wrat_[k]);
    wsafe2_[k] = s0_2 / std::max(wrat_[k], 1e-300);
  }
  const double cut = 1e-6 * core.radius;  // the singular kernel's cut-off δ [m]
  inv_cut2_ = 1.0 / (cut * cut);
  const std::size_t m = cut_pieces(s, core_distance);
  pieces_ = m;

  // Morton keys of the pieces' midpoints, sorted (ties by index: deterministic).
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (std::size_t k = 0; k < m; ++k) {
    const double c[3] = {0.5 * (qax_[k] + qbx_[k]), 0.5 * (qay_[k] + qby_[k]), 0.5 * (qaz_[k] + qbz_[k])};
    for (int i = 0; i < 3; ++i) { lo[i] = std::min(lo[i], c[i]); hi[i] = std::max(hi[i], c[i]); }
  }
  const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-300});
  const double q = 1048575.0 / extent;  // 2^20 − 1 cells per axis
  std::uint64_t* key = keys_.data();
  for (std::size_t k = 0; k < m; ++k) {
    auto cell = [&](double a, double b, int i) {
      return static_cast<std::uint64_t>((0.5 * (a + b) - lo[i]) * q);
    };
    key[k] = spread(cell(qax_[k], qbx_[k], 0)) | spread(cell(qay_[k], qby_[k], 1)) << 1 |
             spread(cell(qaz_[k], qbz_[k], 2)) << 2;
    order_[k] = static_cast<std::uint32_t>(k);
  }
  std::sort(order_.begin(), order_.begin() + m, [key](std::uint32_t i, std::uint32_t j) {
    return key[i] < key[j] || (key[i] == key[j] && i < j);
  });
  std::uint64_t* skey = keys_.data() + m;  // sorted keys
  for (std::size_t k = 0; k < m; ++k) {
    const std::uint32_t o = order_[k];
    skey[k] = key[o];
    sx_[k] = qax_[o]; sy_[k] = qay_[o]; sz_[k] = qaz_[o];
    tx_[k] = qbx_[o]; ty_[k] = qby_[o]; tz_[k] = qbz_[o];
    sparent_[k] = parent_[o];
    sg_[k] = wg_[parent_[o]];
  }
  build_nodes();
}

void SegmentTree::build_nodes() {
  const std::size_t m = pieces_;
  const std::uint64_t* skey = keys_.data() + m;
  // Octree: split a range at the highest octal digit where its first and last keys
  // differ (every internal node has ≥ 2 children); a range becomes a leaf when it is
  // small enough, or when the reserved nodes would not hold its children.
  nodes_[0] = Node{};
  nodes_[0].seg_begin = 0;
  nodes_[0].seg_end = static_cast<std::uint32_t>(m);
  node_count_ = 1;
  std::size_t top = 0;
  stack_[top++] = 0;
  std::uint32_t padded = 0;
  while (top > 0) {
    const std::uint32_t id = stack_[--top];
    const std::uint32_t b = nodes_[id].seg_begin, e = nodes_[id].seg_end;
    const std::uint64_t diff = skey[b] ^ skey[e - 1];
    const bool full = node_count_ + 8 > nodes_.size();
    if (e - b <= static_cast<std::uint32_t>(kLeafSegments) || diff == 0 || full) {
      Node& leaf = nodes_[id];
      leaf.child_count = 0;
      leaf.begin = padded;
      leaf.count = (e - b + kLanes - 1) / kLanes * kLanes;
      for (std::uint32_t k = 0; k < leaf.count; ++k) {
        const std::uint32_t p = padded + k;
        if (b + k < e) {
          const std::uint32_t g = b + k;
          pax_[p] = sx_[g]; pay_[p] = sy_[g]; paz_[p] = sz_[g];
          pbx_[p] = tx_[g]; pby_[p] = ty_[g]; pbz_[p] = tz_[g];
          pg_[p] = sg_[g];
          prat_[p] = 1.0;
          pil_[p] = detail::segment_scale(sx_[g], sy_[g], sz_[g], tx_[g], ty_[g], tz_[g], 1.0);
          ppar_[p] = sparent_[g];
          psafe2_[p] = wsafe2_[sparent_[g]];
        } else {  // padding: no circulation, zero length, never near
          pax_[p] = pay_[p] = paz_[p] = pbx_[p] = pby_[p] = pbz_[p] = pg_[p] = pil_[p] = prat_[p] = 0.0;
          ppar_[p] = 0;
          psafe2_[p] = -1.0;
        }
      }
      padded += leaf.count;
      continue;
    }
    const int shift = (63 - __builtin_clzll(diff)) / 3 * 3;
    const std::uint32_t first = static_cast<std::uint32_t>(node_count_);
    std::uint32_t start = b;
    while (start < e) {
      const std::uint64_t digit = (skey[start] >> shift) & 7;
      std::uint32_t stop = start + 1;
      while (stop < e && ((skey[stop] >> shift) & 7) == digit) ++stop;
      Node child{};
      child.seg_begin = start;
      child.seg_end = stop;
      nodes_[node_count_++] = child;
      start = stop;
    }
    nodes_[id].first_child = first;
    nodes_[id].child_count = static_cast<std::uint32_t>(node_count_) - first;
    for (std::uint32_t c = nodes_[id].child_count; c-- > 0;) stack_[top++] = first + c;
  }

  // Geometry of each node: centre of the bounding box of its piece ends, radius, and the
  // largest core distance of its pieces' segments.
  for (std::size_t id = 0; id < node_count_; ++id) {
    Node& nd = nodes_[id];
    double l[3] = {1e300, 1e300, 1e300}, h[3] = {-1e300, -1e300, -1e300}, safe2 = 0.0;
    for (std::uint32_t k = nd.seg_begin; k < nd.seg_end; ++k) {
      const double p[6] = {sx_[k], sy_[k], sz_[k], tx_[k], ty_[k], tz_[k]};
      for (int i = 0; i < 3; ++i) {
        l[i] = std::min({l[i], p[i], p[i + 3]});
        h[i] = std::max({h[i], p[i], p[i + 3]});
      }
      safe2 = std::max(safe2, wsafe2_[sparent_[k]]);
    }
    nd.cx = 0.5 * (l[0] + h[0]); nd.cy = 0.5 * (l[1] + h[1]); nd.cz = 0.5 * (l[2] + h[2]);
    double r2 = 0;
    for (std::uint32_t k = nd.seg_begin; k < nd.seg_end; ++k) {
      const double da = (sx_[k] - nd.cx) * (sx_[k] - nd.cx) + (sy_[k] - nd.cy) * (sy_[k] - nd.cy) + (sz_[k] - nd.cz) * (sz_[k] - nd.cz);
      const double db = (tx_[k] - nd.cx) * (tx_[k] - nd.cx) + (ty_[k] - nd.cy) * (ty_[k] - nd.cy) + (tz_[k] - nd.cz) * (tz_[k] - nd.cz);
      r2 = std::max({r2, da, db});
    }
    nd.radius = std::sqrt(r2);
    nd.safe_distance = std::sqrt(safe2);
  }
  // Moments: leaves from their pieces, parents from their children (children have
  // larger indices than their parent).
  for (std::size_t id = node_count_; id-- > 0;) compute_moments(id);
}

void SegmentTree::compute_moments(std::size_t id) {
  const MultiIndexTable& T = table();
  const Node& nd = nodes_[id];
  double* Q = moments_.data() + id * 3 * terms_;
  for (int t = 0; t < 3 * terms_; ++t) Q[t] = 0.0;
  const int p = params_.order;
  if (nd.child_count == 0) {
    // Q_n = Σ Γ (B − A) ∫₀¹ (y(s) − c)^n ds, 3-point Gauss–Legendre (exact to degree 5).
    static const double gs[3] = {0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6)};
    static const double gw[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
    for (std::uint32_t k = nd.seg_begin; k < nd.seg_end; ++k) {
      const double lx = tx_[k] - sx_[k], ly = ty_[k] - sy_[k], lz = tz_[k] - sz_[k];
      for (int g = 0; g < 3; ++g) {
        const double d[3] = {sx_[k] + gs[g] * lx - nd.cx, sy_[k] + gs[g] * ly - nd.cy,
                             sz_[k] + gs[g] * lz - nd.cz};
        double pw[3][kMaxOrder + 1];
        for (int i = 0; i < 3; ++i) {
          pw[i][0] = 1.0;
          for (int e = 1; e <= p; ++e) pw[i][e] = pw[i][e - 1] * d[i];
        }
        const double w = gw[g] * sg_[k];
        for (int t = 0; t < terms_; ++t) {
          const double m = w * pw[0][T.a[t]] * pw[1][T.b[t]] * pw[2][T.c[t]];
          Q[3 * t] += m * lx;
          Q[3 * t + 1] += m * ly;
          Q[3 * t + 2] += m * lz;
        }
      }
    }
    return;
  }
  // Translation of each child's moments to this centre:
  // Q_n = Σ_{m ≤ n} C(n, m) d^(n − m) Q_m(child), d = c_child − c.
  for (std::uint32_t c = 0; c < nd.child_count; ++c) {
    const std::size_t cid = nd.first_child + c;
    const Node& ch = nodes_[cid];
    const double* Qc = moments_.data() + cid * 3 * terms_;
    const double d[3] = {ch.cx - nd.cx, ch.cy - nd.cy, ch.cz - nd.cz};
    double pw[3][kMaxOrder + 1];
    for (int i = 0; i < 3; ++i) {
      pw[i][0] = 1.0;
      for (int e = 1; e <= p; ++e) pw[i][e] = pw[i][e - 1] * d[i];
    }
    for (int t = 0; t < terms_; ++t) {
      const int a = T.a[t], b = T.b[t], cc = T.c[t];
      for (int i = 0; i <= a; ++i)
        for (int j = 0; j <= b; ++j)
          for (int k = 0; k <= cc; ++k) {
            const int m = T.index[i][j][k];
            const double f = T.binomial[a][i] * T.binomial[b][j] * T.binomial[cc][k] *
                             pw[0][a - i] * pw[1][b - j] * pw[2][cc - k];
            Q[3 * t] += f * Qc[3 * m];
            Q[3 * t + 1] += f * Qc[3 * m + 1];
            Q[3 * t + 2] += f * Qc[3 * m + 2];
          }
    }
  }
}

void SegmentTree::add_core_corrections(NearScratch& t, std::size_t count, double x, double y,
                                       double z, double* su, double* sv, double* sw) const {
  // The listed segments packed into whole blocks of lanes (padding: Γ = 0, zero length),
  // then v_core − v_singular of each: the core kernel with Γ, the singular one with −Γ.
  std::size_t c = 0;
  for (; c < count; ++c) {
    const std::uint32_t k = t.list[c];
    t.ax[c] = wax_[k]; t.ay[c] = way_[k]; t.az[c] = waz_[k];
    t.bx[c] = wbx_[k]; t.by[c] = wby_[k]; t.bz[c] = wbz_[k];
    t.g[c] = wg_[k]; t.neg_g[c] = -wg_[k];
    t.il[c] = wil_[k]; t.cr[c] = wrat_[k];
    t.il_cut[c] = wrat_[k] > 0.0 ? wil_[k] / wrat_[k] : 0.0;  // 1/|B − A|²
    t.one[c] = 1.0;
  }
  for (; c % kLanes != 0; ++c) {
    t.ax[c] = t.ay[c] = t.az[c] = t.bx[c] = t.by[c] = t.bz[c] = 0.0;
    t.g[c] = t.neg_g[c] = t.il[c] = t.cr[c] = t.il_cut[c] = t.one[c] = 0.0;
  }
  detail::PointRangeCall call{c,      t.ax.data(), t.ay.data(), t.az.data(), t.bx.data(), t.by.data(),
                              t.bz.data(), t.g.data(), t.il.data(), t.cr.data(),
                              1.0 / (core_.radius * core_.radius), core_.model, x, y, z, su, sv, sw};
  detail::point_range_dispatch(call);
  call.gamma = t.neg_g.data();
  call.inv_length2 = t.il_cut.data();
  call.core_ratio2 = t.one.data();
  call.inv_rc2 = inv_cut2_;
  call.model = CoreModel::CutOff;
  detail::point_range_dispatch(call);
}

void SegmentTree::add_induced_velocity(const double* x, const double* y, const double* z,
                                       std::size_t n, double* u, double* v, double* w) const {
  last_multipoles_ = last_direct_ = last_corrections_ = 0;
  if (size_ == 0 || n == 0) return;
  const double theta2 = params_.theta * params_.theta;
  std::size_t multipoles = 0, direct = 0, corrections = 0;
  const long nt = static_cast<long>(n);
  const int team = std::min(omp_get_max_threads(), static_cast<int>(scratch_.size()));
  void (*const expansions)(detail::MultipoleBatch&) = multipole_batch_variant();
#pragma omp parallel num_threads(team) reduction(+ : multipoles, direct, corrections)
  {
    NearScratch& t = scratch_[static_cast<std::size_t>(omp_get_thread_num())];
#pragma omp for schedule(dynamic, 16)
    for (long i = 0; i < nt; ++i) {
      alignas(64) double su[kLanes] = {}, sv[kLanes] = {}, sw[kLanes] = {};
      double mu = 0.0, mv = 0.0, mw = 0.0;
      const double px = x[i], py = y[i], pz = z[i];
      std::uint32_t stack[8 * 64];
      int top = 0;
      stack[top++] = 0;
      // A new stamp for this target (all stamps cleared when the counter wraps).
      if (++t.visit == 0) {
        std::fill(t.stamp.begin(), t.stamp.end(), 0u);
        t.visit = 1;
      }
      std::size_t near = 0;
      // Accepted nodes are evaluated kMultipoleBatch at a time and added in the order
      // they were accepted.
      detail::MultipoleBatch batch;
      batch.order = params_.order;
      batch.count = 0;
      auto flush = [&] {
        if (batch.count == 0) return;
        expansions(batch);
        for (int j = 0; j < batch.count; ++j) {
          mu += batch.u[j];
          mv += batch.v[j];
          mw += batch.w[j];
        }
        batch.count = 0;
      };
      detail::PointRangeCall call{0,       nullptr, nullptr, nullptr,   nullptr,          nullptr, nullptr,
                                  nullptr, nullptr, nullptr, inv_cut2_, CoreModel::CutOff, px,     py,
                                  pz,      su,      sv,      sw};
      while (top > 0) {
        const Node& nd = nodes_[stack[--top]];
        const double dx = px - nd.cx, dy = py - nd.cy, dz = pz - nd.cz;
        // |R| θ > b and |R| − b > core distance, squared (no square root per node visited).
        const double r2 = dx * dx + dy * dy + dz * dz, reach = nd.radius + nd.safe_distance;
        if (r2 * theta2 > nd.radius * nd.radius && r2 > reach * reach) {
          const int j = batch.count++;
          batch.moments[j] = moments_.data() + (&nd - nodes_.data()) * 3 * terms_;
          batch.rx[j] = dx;
          batch.ry[j] = dy;
          batch.rz[j] = dz;
          if (batch.count == detail::kMultipoleBatch) flush();
          ++multipoles;
        } else if (nd.child_count == 0) {
          const std::size_t b = nd.begin;
          call.count = nd.count;
          call.ax = pax_.data() + b; call.ay = pay_.data() + b; call.az = paz_.data() + b;
          call.bx = pbx_.data() + b; call.by = pby_.data() + b; call.bz = pbz_.data() + b;
          call.gamma = pg_.data() + b; call.inv_length2 = pil_.data() + b;
          call.core_ratio2 = prat_.data() + b;
          detail::point_range_dispatch(call);
          direct += nd.count;
          if (r2 <= reach * reach) {
            // Pieces within their segment's core distance: list the segment once. The
            // distances in a vector loop, the (few) hits afterwards.
            for (std::size_t k0 = b; k0 < b + nd.count; k0 += kFlagBlock) {
              const std::size_t len = std::min<std::size_t>(kFlagBlock, b + nd.count - k0);
              alignas(64) double hit[kFlagBlock];
#pragma omp simd
              for (std::size_t j = 0; j < len; ++j) {
                const std::size_t k = k0 + j;
                const double ex = pbx_[k] - pax_[k], ey = pby_[k] - pay_[k], ez = pbz_[k] - paz_[k];
                const double rx = px - pax_[k], ry = py - pay_[k], rz = pz - paz_[k];
                double s = (rx * ex + ry * ey + rz * ez) * pil_[k];
                s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
                const double hx = rx - s * ex, hy = ry - s * ey, hz = rz - s * ez;
                hit[j] = psafe2_[k] - (hx * hx + hy * hy + hz * hz);
              }
              for (std::size_t j = 0; j < len; ++j) {
                if (!(hit[j] > 0.0)) continue;
                const std::uint32_t seg = ppar_[k0 + j];
                if (t.stamp[seg] != t.visit) {
                  t.stamp[seg] = t.visit;
                  t.list[near++] = seg;
                }
              }
            }
          }
        } else {
          for (std::uint32_t c = nd.child_count; c-- > 0;) stack[top++] = nd.first_child + c;
        }
      }
      flush();
      if (near > 0) add_core_corrections(t, near, px, py, pz, su, sv, sw);
      corrections += near;
      double tu = 0, tv = 0, tw = 0;
      for (int l = 0; l < kLanes; ++l) {
        tu += su[l];
        tv += sv[l];
        tw += sw[l];
      }
      u[i] += tu + mu;
      v[i] += tv + mv;
      w[i] += tw + mw;
    }
  }
  last_multipoles_ = multipoles;
  last_direct_ = direct;
  last_corrections_ = corrections;
}

}  // namespace flapsim::uvlm
