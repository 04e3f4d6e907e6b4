#pragma once
/// \file multipole_expansion.hpp
/// \brief The tables of the tree code's Cartesian multipole expansion (segment_tree.hpp):
/// multi-indices n = (a, b, c) up to |n| = p + 1 ≤ 5 in graded order, their neighbours
/// n ± e_i, n − 2e_i, the factors (−1)^|n|/(n! 4π) and binomial coefficients, all
/// compile-time constants; and the batched evaluation of expansions (multipole_batch.hpp).

#include "uvlm/biot_savart_kernel.hpp"

namespace flapsim::uvlm::detail {

inline constexpr int kMaxOrder = 4;                 // p ≤ 4
inline constexpr int kMaxDerivative = kMaxOrder + 1;  // ∂ⁿφ up to |n| = p + 1
constexpr int terms_up_to(int q) { return (q + 1) * (q + 2) * (q + 3) / 6; }
inline constexpr int kMaxTerms = terms_up_to(kMaxDerivative);  // 56

/// Multi-indices n = (a, b, c) in graded order (|n| = 0, 1, 2, …) and their neighbours.
struct MultiIndexTable {
  int a[kMaxTerms]{}, b[kMaxTerms]{}, c[kMaxTerms]{}, order[kMaxTerms]{};
  int minus[kMaxTerms][3]{};   // index of n − e_i (−1 if n_i = 0)
  int minus2[kMaxTerms][3]{};  // index of n − 2e_i (−1 if n_i < 2)
  int plus[kMaxTerms][3]{};    // index of n + e_i (−1 beyond kMaxDerivative)
  int index[kMaxDerivative + 1][kMaxDerivative + 1][kMaxDerivative + 1]{};
  double factor[kMaxTerms]{};  // (−1)^|n| / (n! 4π)
  double binomial[kMaxDerivative + 1][kMaxDerivative + 1]{};
  constexpr MultiIndexTable() {
    int t = 0;
    for (auto& x : index)
      for (auto& y : x)
        for (int& z : y) z = -1;
    for (int m = 0; m <= kMaxDerivative; ++m)
      for (int i = m; i >= 0; --i)
        for (int j = m - i; j >= 0; --j) {
          a[t] = i; b[t] = j; c[t] = m - i - j; order[t] = m;
          index[i][j][m - i - j] = t++;
        }
    auto idx = [&](int i, int j, int k) constexpr {
      return (i < 0 || j < 0 || k < 0 || i + j + k > kMaxDerivative) ? -1 : index[i][j][k];
    };
    auto fact = [](int n) constexpr { double f = 1; for (int i = 2; i <= n; ++i) f *= i; return f; };
    for (t = 0; t < kMaxTerms; ++t) {
      const int i = a[t], j = b[t], k = c[t];
      minus[t][0] = idx(i - 1, j, k); minus[t][1] = idx(i, j - 1, k); minus[t][2] = idx(i, j, k - 1);
      minus2[t][0] = idx(i - 2, j, k); minus2[t][1] = idx(i, j - 2, k); minus2[t][2] = idx(i, j, k - 2);
      plus[t][0] = idx(i + 1, j, k); plus[t][1] = idx(i, j + 1, k); plus[t][2] = idx(i, j, k + 1);
      factor[t] = ((order[t] % 2) ? -1.0 : 1.0) / (fact(i) * fact(j) * fact(k)) * detail::kInvFourPi;
    }
    for (int n = 0; n <= kMaxDerivative; ++n)
      for (int k = 0; k <= n; ++k) binomial[n][k] = fact(n) / (fact(k) * fact(n - k));
  }
};

// A compile-time constant, so the expansion below, unrolled for each order, reads no table.
inline constexpr MultiIndexTable kTable{};

/// (2m − 1)/m and (m − 1)/m of the derivative recurrence, m = 1 … kMaxDerivative.
inline constexpr double kRecurrence1[kMaxDerivative + 1] = {0.0, 1.0, 3.0 / 2.0, 5.0 / 3.0, 7.0 / 4.0, 9.0 / 5.0};
inline constexpr double kRecurrence2[kMaxDerivative + 1] = {0.0, 0.0, 1.0 / 2.0, 2.0 / 3.0, 3.0 / 4.0, 4.0 / 5.0};

}  // namespace flapsim::uvlm::detail
