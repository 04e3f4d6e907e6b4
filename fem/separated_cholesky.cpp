#include "fem/separated_cholesky.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <cholmod.h>
#include <omp.h>

#include "fem/dense_kernels.hpp"
#include "fem/serial_openmp_regions.hpp"

namespace flapsim::fem {

namespace {

// A view of the lower triangle of a compressed column-major matrix as CHOLMOD's (no copy).
cholmod_sparse lower_view(const SparseMatrix& a) {
  cholmod_sparse s{};
  s.nrow = static_cast<size_t>(a.rows());
  s.ncol = static_cast<size_t>(a.cols());
  s.nzmax = static_cast<size_t>(a.nonZeros());
  s.p = const_cast<int*>(a.outerIndexPtr());
  s.i = const_cast<int*>(a.innerIndexPtr());
  s.x = const_cast<double*>(a.valuePtr());
  s.stype = -1;
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}

// The two parts' work on one thread or two: the same calls either way. CHOLMOD's own
// parallel regions (serial_openmp_regions.hpp) run on their calling thread alone: nested
// in this region (one active level), or serialised when there is no region.
template <class Work>
void for_each_part(Work&& work) {
  if (omp_get_max_threads() >= 2 && !omp_in_parallel()) {
    const int levels = omp_get_max_active_levels();
    omp_set_max_active_levels(1);
#pragma omp parallel for num_threads(2) schedule(static, 1)
    for (int part = 0; part < 2; ++part) work(part);
    omp_set_max_active_levels(levels);
  } else {
    const SerialOpenMpRegions cholmod_on_this_thread;
    for (int part = 0; part < 2; ++part) work(part);
  }
}

// Dense Cholesky in place, the lower triangle, column by column: column j less each
// earlier column k times L(j, k), k in order, then divided by its pivot. Each entry's sum
// runs over k in order whatever the vector width (the same bits on every CPU). false: not
// positive definite.
bool dense_cholesky(Eigen::MatrixXd& c) {
  const Eigen::Index n = c.rows();
  for (Eigen::Index j = 0; j < n; ++j) {
    double* cj = c.col(j).data();
    for (Eigen::Index k = 0; k < j; ++k) {
      const double* ck = c.col(k).data();
      const double ljk = ck[j];
      for (Eigen::Index i = j; i < n; ++i) cj[i] -= ck[i] * ljk;
    }
    if (!(cj[j] > 0.0)) return false;
    const double pivot = std::sqrt(cj[j]);
    cj[j] = pivot;
    for (Eigen::Index i = j + 1; i < n; ++i) cj[i] /= pivot;
  }
  return true;
}

// Dense LDLᵀ without pivoting in place: L (unit, below the diagonal) and D (pivots), in the
// order of dense_cholesky. false: a pivot vanished (or is not finite).
bool dense_ldlt(Eigen::MatrixXd& c, Eigen::VectorXd& d) {
  const Eigen::Index n = c.rows();
  d.resize(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    double* cj = c.col(j).data();
    for (Eigen::Index k = 0; k < j; ++k) {
      const double* ck = c.col(k).data();
      const double t = ck[j] * d(k);
      for (Eigen::Index i = j; i < n; ++i) cj[i] -= ck[i] * t;
    }
    if (!std::isfinite(cj[j]) || cj[j] == 0.0) return false;
    d(j) = cj[j];
    cj[j] = 1.0;
    for (Eigen::Index i = j + 1; i < n; ++i) cj[i] /= d(j);
  }
  return true;
}

// x = (L D Lᵀ)⁻¹ b with L the unit lower triangle of l.
void dense_ldlt_solve(const Eigen::MatrixXd& l, const Eigen::VectorXd& d, const Eigen::VectorXd& b,
                      Eigen::VectorXd& x) {
  const Eigen::Index n = l.rows();
  x = b;
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = j + 1; i < n; ++i) x(i) -= l(i, j) * x(j);
  for (Eigen::Index j = 0; j < n; ++j) x(j) /= d(j);
  for (Eigen::Index j = n - 1; j >= 0; --j) {
    double s = x(j);
    for (Eigen::Index i = j + 1; i < n; ++i) s -= l(i, j) * x(i);
    x(j) = s;
  }
}

// x = (L Lᵀ)⁻¹ b with L the lower triangle of l.
void dense_cholesky_solve(const Eigen::MatrixXd& l, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  const Eigen::Index n = l.rows();
  x = b;
  for (Eigen::Index j = 0; j < n; ++j) {  // L y = b, by columns
    x(j) /= l(j, j);
    for (Eigen::Index i = j + 1; i < n; ++i) x(i) -= l(i, j) * x(j);
  }
  for (Eigen::Index j = n - 1; j >= 0; --j) {  // Lᵀ x = y
    double s = x(j);
    for (Eigen::Index i = j + 1; i < n; ++i) s -= l(i, j) * x(i);
    x(j) = s / l(j, j);
  }
}

// v = L w and v = Lᵀ w, L the lower triangle of l.
void lower_times(const Eigen::MatrixXd& l, const Eigen::VectorXd& w, Eigen::VectorXd& v) {
  v.setZero();
  for (Eigen::Index j = 0; j < l.cols(); ++j)
    for (Eigen::Index i = j; i < l.rows(); ++i) v(i) += l(i, j) * w(j);
}
void lower_transposed_times(const Eigen::MatrixXd& l, const Eigen::VectorXd& w, Eigen::VectorXd& v) {
  for (Eigen::Index j = 0; j < l.cols(); ++j) {
    double s = 0.0;
    for (Eigen::Index i = j; i < l.rows(); ++i) s += l(i, j) * w(i);
    v(j) = s;
  }
}

}  // namespace

/// One part with the separator: Bᵢ = [Aᵢᵢ AᵢS; ASᵢ ASS], rows numbered locally (the part's
/// rows ascending, then the separator's), its factor and solve workspace.
struct SeparatedCholesky::Part {
  explicit Part(bool indefinite) {
    cholmod_start(&common);
    common.print = 0;
    // LLᵀ supernodal; LDLᵀ simplicial (CHOLMOD's only LDLᵀ), its factor kept as computed.
    common.supernodal = indefinite ? CHOLMOD_SIMPLICIAL : CHOLMOD_SUPERNODAL;
    common.final_asis = 1;
  }
  ~Part() {
    if (factor != nullptr) cholmod_free_factor(&factor, &common);
    if (matrix != nullptr) cholmod_free_sparse(&matrix, &common);
    for (cholmod_dense** d : {&rhs, &work_y, &work_e, &result})
      if (*d != nullptr) cholmod_free_dense(d, &common);
    cholmod_finish(&common);
  }
  cholmod_common common{};
  cholmod_sparse* matrix = nullptr;   ///< Bᵢ in the factor's order, upper triangle
  cholmod_factor* factor = nullptr;
  std::vector<int> rows;              ///< global row of each local row (part, then separator)
  std::vector<int> row_at;            ///< global row at each of the first nᵢ positions of the factor's order
  std::vector<int> value_from;        ///< A's value index of each of Bᵢ's values
  int part_rows = 0;                  ///< nᵢ
  /// Separator row (0 … |S| − 1) at each of the last |S| positions of the factor's order.
  std::vector<int> separator_at;
  Eigen::MatrixXd lss;                ///< Lᵢ,SS in the factor's order (lower triangle)
  Eigen::MatrixXd lss_square;         ///< Lᵢ,SS Lᵢ,SSᵀ in the factor's order (lower)
  Eigen::MatrixXd lss_product;        ///< Lᵢ,SS Lᵢ,SSᵀ in separator order
  Eigen::VectorXd w, v;               ///< |S| vectors in the factor's order
  Eigen::VectorXd ds;                 ///< LDLᵀ: Dᵢ,S in the factor's order
  Eigen::VectorXd part_pivot_inverse; ///< LDLᵀ: 1 / Dᵢ at the first nᵢ positions
  Eigen::MatrixXd scaled;             ///< LDLᵀ: Lᵢ,SS Dᵢ,S
  cholmod_dense *rhs = nullptr, *work_y = nullptr, *work_e = nullptr, *result = nullptr;
  bool factorised = false;

  // x := op(L) x through CHOLMOD's solve with reused workspace (sys: CHOLMOD_L or CHOLMOD_Lt).
  void apply(int sys, cholmod_dense*& from, cholmod_dense*& to) {
    cholmod_solve2(sys, factor, from, nullptr, &to, nullptr, &work_y, &work_e, &common);
  }
};

SeparatedCholesky::SeparatedCholesky(bool indefinite) : indefinite_(indefinite) {}
SeparatedCholesky::~SeparatedCholesky() = default;

int SeparatedCholesky::separator_rows() const { return static_cast<int>(separator_.size()); }
int SeparatedCholesky::part_rows(int part) const {
  return parts_[part] != nullptr ? parts_[part]->part_rows : 0;
}

double SeparatedCholesky::part_flops(int part) const {
  return parts_[part] != nullptr && parts_[part]->factor != nullptr ? parts_[part]->common.fl : 0.0;
}

double SeparatedCholesky::factor_nonzeros() const {
  double nz = 0.5 * static_cast<double>(separator_.size()) * static_cast<double>(separator_.size() + 1);
  for (const auto& p : parts_)
    if (p != nullptr && p->factor != nullptr) nz += static_cast<double>(p->common.lnz);
  return nz;
}

bool SeparatedCholesky::analyse(const SparseMatrix& a) {
  analysed_ = false;
  const int n = static_cast<int>(a.rows());
  if (n < 2 || !a.isCompressed()) return false;
  // The separator: METIS's vertex bisection of the graph of A (its full pattern without
  // the diagonal), balancing the rows' weights. A part's factorisation costs more than its
  // share of the rows says (the fill depends on its shape), so the rows of the part that
  // took more operations are weighted by the ratio and the graph is bisected again, up to
  // kBalanceTries times; the split whose larger part costs least is kept.
  cholmod_common common{};
  cholmod_start(&common);
  common.print = 0;
  cholmod_sparse view = lower_view(a);
  cholmod_sparse* graph = cholmod_copy(&view, 0, -1, &common);
  std::vector<int> weight(static_cast<size_t>(n), kWeightScale), side(static_cast<size_t>(n), 0), best;
  double best_cost = 0.0;
  for (int attempt = 0; attempt < kBalanceTries && graph != nullptr; ++attempt) {
    const long s = cholmod_metis_bisector(graph, weight.data(), nullptr, side.data(), &common);
    if (s <= 0 || common.status != CHOLMOD_OK || !build_parts(a, side)) break;
    const double cost = std::max(part_flops(0), part_flops(1));
    if (best.empty() || cost < best_cost) {
      best = side;
      best_cost = cost;
    }
    const double mean = 0.5 * (part_flops(0) + part_flops(1));
    for (int g = 0; g < n; ++g) {
      const int k = side[static_cast<size_t>(g)];
      if (k < 2)
        weight[static_cast<size_t>(g)] = std::max(
            1, static_cast<int>(std::lround(weight[static_cast<size_t>(g)] * part_flops(k) / mean)));
    }
  }
  if (graph != nullptr) cholmod_free_sparse(&graph, &common);
  cholmod_finish(&common);
  if (best.empty()) return false;
  if (best != side && !build_parts(a, best)) return false;
  analysed_ = true;
  return true;
}

bool SeparatedCholesky::build_parts(const SparseMatrix& a, const std::vector<int>& side) {
  const int n = static_cast<int>(a.rows());
  for (auto& p : parts_) p = std::make_unique<Part>(indefinite_);
  separator_.clear();
  std::vector<int> local(static_cast<size_t>(n), -1);  // local index within its part (or S)
  int count[3] = {0, 0, 0};
  for (int g = 0; g < n; ++g) {
    const int k = side[static_cast<size_t>(g)];
    local[static_cast<size_t>(g)] = count[k]++;
    if (k == 2) separator_.push_back(g);
  }
  const int ns = count[2];
  if (count[0] == 0 || count[1] == 0 || ns > kMaxSeparatorRows ||
      ns > kMaxSeparatorShare * static_cast<double>(n))
    return false;
  // Each part's Bᵢ (lower triangle in local numbering), with the map from A's values.
  // An entry between the two parts means S is no separator: no split.
  separator_entries_.clear();
  for (int part = 0; part < 2; ++part) {
    Part& p = *parts_[part];
    p.part_rows = count[part];
    const int nb = count[part] + ns;
    p.rows.assign(static_cast<size_t>(nb), 0);
    for (int g = 0; g < n; ++g) {
      const int k = side[static_cast<size_t>(g)];
      if (k == part) p.rows[static_cast<size_t>(local[static_cast<size_t>(g)])] = g;
      if (k == 2) p.rows[static_cast<size_t>(count[part] + local[static_cast<size_t>(g)])] = g;
    }
    auto local_of = [&](int g) {
      const int k = side[static_cast<size_t>(g)];
      return k == part ? local[static_cast<size_t>(g)]
             : k == 2  ? count[part] + local[static_cast<size_t>(g)]
                       : -1;
    };
    struct Entry {
      int col, row, value;
    };
    std::vector<Entry> entries;
    for (int j = 0; j < n; ++j)
      for (int q = a.outerIndexPtr()[j]; q < a.outerIndexPtr()[j + 1]; ++q) {
        const int i = a.innerIndexPtr()[q];
        if (i < j) continue;  // the lower triangle
        const int si = side[static_cast<size_t>(i)], sj = side[static_cast<size_t>(j)];
        if ((si == 0 && sj == 1) || (si == 1 && sj == 0)) return false;
        const int li = local_of(i), lj = local_of(j);
        if (li < 0 || lj < 0) continue;
        entries.push_back(Entry{std::min(li, lj), std::max(li, lj), q});
        if (part == 0 && si == 2 && sj == 2)
          separator_entries_.push_back(SeparatorEntry{local[static_cast<size_t>(i)], local[static_cast<size_t>(j)], q});
      }
    // The order: CAMD with the separator last. Bᵢ is then stored in that order, as the
    // upper triangle CHOLMOD's supernodal factorisation reads in place (no permuted copy at
    // each factorisation), and analysed in its natural order without postordering (which
    // could move separator columns before part columns).
    auto compressed = [&](cholmod_sparse*& m, int stype) {
      std::sort(entries.begin(), entries.end(),
                [](const Entry& x, const Entry& y) { return x.col != y.col ? x.col < y.col : x.row < y.row; });
      m = cholmod_allocate_sparse(static_cast<size_t>(nb), static_cast<size_t>(nb), entries.size(), 1, 1, stype,
                                  CHOLMOD_REAL, &p.common);
      if (m == nullptr) return false;
      int* cp = static_cast<int*>(m->p);
      int* ri = static_cast<int*>(m->i);
      std::fill(cp, cp + nb + 1, 0);
      p.value_from.resize(entries.size());
      for (std::size_t e = 0; e < entries.size(); ++e) {
        ++cp[entries[e].col + 1];
        ri[e] = entries[e].row;
        p.value_from[e] = entries[e].value;
      }
      for (int j = 0; j < nb; ++j) cp[j + 1] += cp[j];
      return true;
    };
    if (!compressed(p.matrix, -1)) return false;
    std::vector<int> member(static_cast<size_t>(nb), 0), order(static_cast<size_t>(nb));
    for (int l = count[part]; l < nb; ++l) member[static_cast<size_t>(l)] = 1;
    if (!cholmod_camd(p.matrix, nullptr, 0, member.data(), order.data(), &p.common)) return false;
    cholmod_free_sparse(&p.matrix, &p.common);
    std::vector<int> position(static_cast<size_t>(nb));
    for (int k = 0; k < nb; ++k) position[static_cast<size_t>(order[static_cast<size_t>(k)])] = k;
    for (Entry& e : entries) {
      const int pr = position[static_cast<size_t>(e.row)], pc = position[static_cast<size_t>(e.col)];
      e = Entry{std::max(pr, pc), std::min(pr, pc), e.value};  // upper: row ≤ column
    }
    if (!compressed(p.matrix, 1)) return false;
    p.common.nmethods = 1;
    p.common.method[0].ordering = CHOLMOD_NATURAL;
    p.common.postorder = 0;
    p.factor = cholmod_analyze(p.matrix, &p.common);
    if (p.factor == nullptr || p.common.status != CHOLMOD_OK) return false;
    const int* perm = static_cast<const int*>(p.factor->Perm);
    for (int k = 0; k < nb; ++k)
      if (perm[k] != k) return false;  // the order is not the one given
    p.row_at.resize(static_cast<size_t>(count[part]));
    for (int k = 0; k < count[part]; ++k) {
      const int l = order[static_cast<size_t>(k)];
      if (l >= count[part]) return false;  // the separator is not last
      p.row_at[static_cast<size_t>(k)] = p.rows[static_cast<size_t>(l)];
    }
    p.separator_at.assign(static_cast<size_t>(ns), 0);
    for (int k = 0; k < ns; ++k) p.separator_at[static_cast<size_t>(k)] = order[static_cast<size_t>(count[part] + k)] - count[part];
    p.lss.setZero(ns, ns);
    p.lss_square.setZero(ns, ns);
    p.lss_product.setZero(ns, ns);
    p.w.setZero(ns);
    p.v.setZero(ns);
    if (indefinite_) {
      p.ds.setZero(ns);
      p.scaled.setZero(ns, ns);
      p.part_pivot_inverse.setZero(count[part]);
    }
    p.rhs = cholmod_zeros(static_cast<size_t>(nb), 1, CHOLMOD_REAL, &p.common);
    if (p.rhs == nullptr) return false;
  }
  schur_.setZero(ns, ns);
  separator_rhs_.setZero(ns);
  separator_x_.setZero(ns);
  return true;
}

bool SeparatedCholesky::factorize(const SparseMatrix& a) {
  if (!analysed_) return false;
  const double* values = a.valuePtr();
  const int ns = separator_rows();
  for_each_part([&](int part) {
    Part& p = *parts_[part];
    double* bx = static_cast<double*>(p.matrix->x);
    for (std::size_t e = 0; e < p.value_from.size(); ++e) bx[e] = values[p.value_from[e]];
    p.factorised = cholmod_factorize(p.matrix, p.factor, &p.common) && p.common.status == CHOLMOD_OK &&
                   p.factor->minor == p.factor->n;
    if (!p.factorised) return;
    const int first = p.part_rows;
    if (indefinite_) {
      // Simplicial LDLᵀ: column j holds D(j) first, then L's entries below the unit diagonal.
      const int* lp = static_cast<const int*>(p.factor->p);
      const int* li = static_cast<const int*>(p.factor->i);
      const int* lnz = static_cast<const int*>(p.factor->nz);
      const double* lx = static_cast<const double*>(p.factor->x);
      p.lss.setZero();
      for (int j = 0; j < first + ns; ++j) {
        const double d = lx[lp[j]];
        if (!std::isfinite(d) || d == 0.0) {
          p.factorised = false;
          return;
        }
        if (j < first) {
          p.part_pivot_inverse(j) = 1.0 / d;
          continue;
        }
        p.ds(j - first) = d;
        p.lss(j - first, j - first) = 1.0;
        for (int q = lp[j] + 1; q < lp[j] + lnz[j]; ++q) p.lss(li[q] - first, j - first) = lx[q];
      }
      // Lᵢ,SS Dᵢ,S Lᵢ,SSᵀ (the factorisation's dense kernel), in separator order.
      for (int l = 0; l < ns; ++l) p.scaled.col(l) = p.lss.col(l) * p.ds(l);
      dense::gemm(ns, ns, ns, 1.0, p.scaled.data(), ns, p.lss.data(), 1, ns, 0.0, p.lss_square.data(), ns);
      for (int c = 0; c < ns; ++c)
        for (int b = c; b < ns; ++b) {
          const int sb = p.separator_at[static_cast<size_t>(b)], sc = p.separator_at[static_cast<size_t>(c)];
          p.lss_product(sb, sc) = p.lss_product(sc, sb) = p.lss_square(b, c);
        }
      return;
    }
    // Lᵢ,SS from the supernodes holding the last |S| columns (rows in the factor's order).
    const int* super = static_cast<const int*>(p.factor->super);
    const int* pi = static_cast<const int*>(p.factor->pi);
    const int* px = static_cast<const int*>(p.factor->px);
    const int* srow = static_cast<const int*>(p.factor->s);
    const double* lx = static_cast<const double*>(p.factor->x);
    p.lss.setZero();
    for (std::size_t sn = 0; sn < p.factor->nsuper; ++sn) {
      const int k1 = super[sn], k2 = super[sn + 1];
      if (k2 <= first) continue;
      const int nrow = pi[sn + 1] - pi[sn];
      for (int j = std::max(k1, first); j < k2; ++j)
        for (int r = 0; r < nrow; ++r) {
          const int i = srow[pi[sn] + r];
          if (i >= j) p.lss(i - first, j - first) = lx[px[sn] + (j - k1) * nrow + r];
        }
    }
    // Lᵢ,SS Lᵢ,SSᵀ (lower triangle, the dense kernel of the factorisation: the same bits on
    // every CPU), put in separator order.
    dense::syrk_lower(ns, ns, 1.0, p.lss.data(), ns, 0.0, p.lss_square.data(), ns);
    for (int c = 0; c < ns; ++c)
      for (int b = c; b < ns; ++b) {
        const int sb = p.separator_at[static_cast<size_t>(b)], sc = p.separator_at[static_cast<size_t>(c)];
        p.lss_product(sb, sc) = p.lss_product(sc, sb) = p.lss_square(b, c);
      }
  });
  if (!parts_[0]->factorised || !parts_[1]->factorised) return false;
  // C = L₀,SS L₀,SSᵀ + L₁,SS L₁,SSᵀ − ASS, and its Cholesky factor (lower triangle).
  schur_ = parts_[0]->lss_product + parts_[1]->lss_product;
  for (const SeparatorEntry& e : separator_entries_) {
    schur_(e.row, e.col) -= values[e.value];
    if (e.row != e.col) schur_(e.col, e.row) -= values[e.value];
  }
  return indefinite_ ? dense_ldlt(schur_, schur_pivots_) : dense_cholesky(schur_);
}

void SeparatedCholesky::solve(const Eigen::VectorXd& r, Eigen::VectorXd& x) {
  const int ns = separator_rows();
  x.resize(r.size());
  // Forward: Lᵢ [zᵢ; wᵢ] = Pᵢ [rᵢ; 0]; the separator's right-hand side gains Lᵢ,SS wᵢ.
  for_each_part([&](int part) {
    Part& p = *parts_[part];
    double* b = static_cast<double*>(p.rhs->x);
    for (int k = 0; k < p.part_rows; ++k) b[k] = r(p.row_at[static_cast<size_t>(k)]);
    std::fill(b + p.part_rows, b + p.part_rows + ns, 0.0);
    p.apply(CHOLMOD_L, p.rhs, p.result);
    const double* y = static_cast<const double*>(p.result->x);
    for (int k = 0; k < ns; ++k) p.w(k) = y[p.part_rows + k];
    lower_times(p.lss, p.w, p.v);
  });
  for (int k = 0; k < ns; ++k) separator_rhs_(k) = r(separator_[static_cast<size_t>(k)]);
  for (const auto& p : parts_)
    for (int k = 0; k < ns; ++k) separator_rhs_(p->separator_at[static_cast<size_t>(k)]) += p->v(k);
  if (indefinite_)
    dense_ldlt_solve(schur_, schur_pivots_, separator_rhs_, separator_x_);
  else
    dense_cholesky_solve(schur_, separator_rhs_, separator_x_);
  for (int k = 0; k < ns; ++k) x(separator_[static_cast<size_t>(k)]) = separator_x_(k);
  // Backward: Lᵢᵀ [xᵢ; x_S] = [zᵢ; Lᵢ,SSᵀ x_S], then Pᵢᵀ.
  for_each_part([&](int part) {
    Part& p = *parts_[part];
    for (int k = 0; k < ns; ++k) p.w(k) = separator_x_(p.separator_at[static_cast<size_t>(k)]);
    lower_transposed_times(p.lss, p.w, p.v);
    double* y = static_cast<double*>(p.result->x);
    if (indefinite_)  // Lᵢᵀ [xᵢ; x_S] = [Dᵢ⁻¹ zᵢ; Lᵢ,SSᵀ x_S]
      for (int k = 0; k < p.part_rows; ++k) y[k] *= p.part_pivot_inverse(k);
    for (int k = 0; k < ns; ++k) y[p.part_rows + k] = p.v(k);
    p.apply(CHOLMOD_Lt, p.result, p.rhs);
    const double* b = static_cast<const double*>(p.rhs->x);
    for (int k = 0; k < p.part_rows; ++k) x(p.row_at[static_cast<size_t>(k)]) = b[k];
  });
}

}  // namespace flapsim::fem
