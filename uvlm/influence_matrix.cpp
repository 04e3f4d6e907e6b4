/// \file influence_matrix.cpp
/// \brief The influence matrix from the lattice's distinct segments (influence_matrix.hpp).

#include "uvlm/influence_matrix.hpp"

#include "uvlm/biot_savart_kernel.hpp"
#include "uvlm/influence_lanes.hpp"
#include "uvlm/kernel_dispatch.hpp"
#include "uvlm/lattice_internal.hpp"

#include <omp.h>

#include <algorithm>
#include <stdexcept>

namespace flapsim::uvlm {

void InfluenceSegments::reserve(int chordwise, int spanwise, int thread_count) {
  const int nc = chordwise, ns = spanwise;
  // Spanwise segments on the nc + 1 ring-node rows, chordwise ones on the ns + 1 columns.
  capacity = static_cast<std::size_t>((nc + 1) * ns + nc * (ns + 1));
  for (auto* a : {&ax, &ay, &az, &bx, &by, &bz, &scale}) a->assign(capacity, 0.0);
  const std::size_t rings = static_cast<std::size_t>(nc) * ns;
  column.assign(rings, 0);
  for (auto& s : side) s.assign(rings, 0);
  threads = std::max(1, thread_count);
  // kRowBlock rows per thread, each padded to a whole cache line.
  scratch.assign(row_stride() * kRowBlock * static_cast<std::size_t>(threads), 0.0);
  size = 0;
  columns = 0;
}

namespace detail {

namespace {

void influence_row_dispatch(const InfluenceRowCall& c) {
  switch (kernel_isa()) {
    case KernelIsa::Scalar: influence_row_scalar(c); break;
    case KernelIsa::Avx2: influence_row_avx2(c); break;
    case KernelIsa::Avx512: influence_row_avx512(c); break;
  }
}

/// The segments and column sides of every ring, or of the last chordwise row's rings.
void collect_segments(const VortexLatticeModel& m, VortexLatticeData& d, bool last_row_only) {
  const int nc = m.chordwise, ns = m.spanwise;
  InfluenceSegments& g = d.influence_segments;
  const double inv_rc2 = 1.0 / (m.bound_core().radius * m.bound_core().radius);
  const double inv_rc2_wake = 1.0 / (m.core.radius * m.core.radius);
  g.size = 0;
  auto push = [&](int from, int to, double inv_core2) {
    const Eigen::Vector3d a = d.ring_nodes.col(from), b = d.ring_nodes.col(to);
    const std::size_t s = g.size++;
    g.ax[s] = a.x(); g.ay[s] = a.y(); g.az[s] = a.z();
    g.bx[s] = b.x(); g.by[s] = b.y(); g.bz[s] = b.z();
    // As SegmentSet::push (its inv_length2, core ratio 1) times 1/r_c²: segment_velocity's scale.
    g.scale[s] = inv_core2 * segment_scale(a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), 1.0);
    return static_cast<int>(s);
  };
  // Rows of chordwise ring index q in [q0, nc): spanwise segments on node rows q0..nc
  // (direction j → j+1; row nc, the trailing-edge vortex, has the wake's core) and
  // chordwise segments of those rows (direction q → q+1). Both with q running fastest, as
  // the columns do (ring q + nc j): the assembly below then reads each side's terms of
  // consecutive columns from consecutive entries of the rows (a segment's term does not
  // depend on where it is stored).
  const int q0 = last_row_only ? nc - 1 : 0, rows = nc - q0;
  std::vector<int>& col = g.column;
  const int span0 = static_cast<int>(g.size);
  for (int j = 0; j < ns; ++j)
    for (int q = q0; q <= nc; ++q) push(m.node(q, j), m.node(q, j + 1), q == nc ? inv_rc2_wake : inv_rc2);
  const int chord0 = static_cast<int>(g.size);
  for (int j = 0; j <= ns; ++j)
    for (int q = q0; q < nc; ++q) push(m.node(q, j), m.node(q + 1, j), inv_rc2);
  auto span = [&](int q, int j) { return span0 + j * (rows + 1) + (q - q0); };
  auto chord = [&](int q, int j) { return chord0 + j * rows + (q - q0); };
  g.columns = 0;
  for (int j = 0; j < ns; ++j)
    for (int q = q0; q < nc; ++q) {
      const int c = g.columns++;
      col[c] = m.panel(q, j);
      g.side[0][c] = span(q, j);       // R(q,j+1) → R(q,j): reversed
      g.side[1][c] = chord(q, j);      // R(q,j) → R(q+1,j)
      g.side[2][c] = span(q + 1, j);   // R(q+1,j) → R(q+1,j+1)
      g.side[3][c] = chord(q, j + 1);  // R(q+1,j+1) → R(q,j+1): reversed
    }
}

}  // namespace

void build_influence(const VortexLatticeModel& m, VortexLatticeData& d, bool last_row_only) {
  const int np = m.panels();
  collect_segments(m, d, last_row_only);
  InfluenceSegments& g = d.influence_segments;
  const std::size_t stride = g.row_stride();
  const std::size_t work = static_cast<std::size_t>(np) * g.size;
  const int threads = (work < kTargetChunkThreshold || omp_in_parallel()) ? 1 : std::min(g.threads, omp_get_max_threads());
  const int *c = g.column.data(), *s0 = g.side[0].data(), *s1 = g.side[1].data(), *s2 = g.side[2].data(),
            *s3 = g.side[3].data();
  constexpr int B = InfluenceSegments::kRowBlock;
  const int blocks = (np + B - 1) / B;
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    // kRowBlock collocation points at a time, so that each column's entries are written
    // as one contiguous run of the column-major matrix, from the terms' segment-major block.
    double* t = g.scratch.data() + stride * B * static_cast<std::size_t>(omp_get_thread_num());
    InfluenceRowCall call{g.size, g.ax.data(), g.ay.data(), g.az.data(), g.bx.data(), g.by.data(), g.bz.data(),
                          g.scale.data(), m.bound_core().model, 0, 0, 0, 0, 0, 0, nullptr, B};
#pragma omp for schedule(static)
    for (int b = 0; b < blocks; ++b) {
      const int i0 = b * B, rows = std::min(B, np - i0);
      for (int r = 0; r < rows; ++r) {
        const int i = i0 + r;
        call.px = d.collocation(0, i); call.py = d.collocation(1, i); call.pz = d.collocation(2, i);
        call.nx = d.normal(0, i); call.ny = d.normal(1, i); call.nz = d.normal(2, i);
        call.out = t + r;
        influence_row_dispatch(call);
      }
      for (int k = 0; k < g.columns; ++k) {
        double* column = &d.influence(i0, c[k]);
        const double *f = t + B * static_cast<std::size_t>(s0[k]), *o = t + B * static_cast<std::size_t>(s1[k]);
        const double *e = t + B * static_cast<std::size_t>(s2[k]), *p = t + B * static_cast<std::size_t>(s3[k]);
        for (int r = 0; r < rows; ++r) {
          double a = 0.0;  // summed as the ring's four sides were before, from zero
          a += -f[r];
          a += o[r];
          a += e[r];
          a += -p[r];
          column[r] = a;
        }
      }
    }
  }
}

}  // namespace detail

}  // namespace flapsim::uvlm
