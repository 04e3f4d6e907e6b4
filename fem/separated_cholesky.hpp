#pragma once
/// \file separated_cholesky.hpp
/// \brief A sparse symmetric matrix (positive definite; or any, by LDLᵀ) factorised in two
/// parts and the separator between them, each part on its own thread (docs/fem.md, "Two
/// parts on two threads").
///
/// One level of nested dissection [George & Liu 1981]: a vertex separator S splits the
/// matrix's graph into parts 0 and 1 that share no entry:
///   A = [A₀₀ 0 A₀S; 0 A₁₁ A₁S; AS₀ AS₁ ASS].
/// Each part's principal submatrix with the separator, Bᵢ = [Aᵢᵢ AᵢS; ASᵢ ASS], is
/// factorised by CHOLMOD's supernodal LLᵀ with the separator ordered last (CAMD), so that
/// its last block Lᵢ,SS Lᵢ,SSᵀ = ASS − ASᵢ Aᵢᵢ⁻¹ AᵢS; the separator's Schur complement is
///   C = ASS − Σᵢ ASᵢ Aᵢᵢ⁻¹ AᵢS = L₀,SS L₀,SSᵀ + L₁,SS L₁,SSᵀ − ASS
/// (dense; its Cholesky factor computed here in a fixed order). A solve is block elimination
/// ([Golub & Van Loan 2013], §4.2): each part's forward solve Lᵢ [zᵢ; wᵢ] = [rᵢ; 0] gives
/// ASᵢ Aᵢᵢ⁻¹ rᵢ = −Lᵢ,SS wᵢ; then C x_S = r_S + Σᵢ Lᵢ,SS wᵢ; then each part's backward
/// solve Lᵢᵀ [xᵢ; x_S] = [zᵢ; Lᵢ,SSᵀ x_S].
///
/// For an indefinite matrix (a wrinkling film's tangent) the same with LDLᵀ and no pivoting
/// (SeparatedCholesky(true)): CHOLMOD's simplicial LDLᵀ of each Bᵢ gives Lᵢ,SS Dᵢ,S Lᵢ,SSᵀ,
/// C = Σᵢ Lᵢ,SS Dᵢ,S Lᵢ,SSᵀ − ASS is factorised as L D Lᵀ, and the backward solve takes
/// Lᵢᵀ [xᵢ; x_S] = [Dᵢ⁻¹ zᵢ; Lᵢ,SSᵀ x_S]. It fails only where a pivot vanishes.
///
/// The parts' work is independent and done the same way on one thread or two (the
/// sums over the parts in a fixed order), so the answer is the same bits whatever the
/// thread count. The separator comes from METIS's vertex bisection of the matrix's graph
/// (cholmod_metis_bisector, [Karypis & Kumar 1998]), weighted to balance the parts'
/// operation counts: a deterministic function of the pattern. References: docs/references.md.

#include <Eigen/Core>

#include <memory>
#include <vector>

#include "fem/assembly.hpp"

namespace flapsim::fem {

class SeparatedCholesky {
 public:
  /// \param indefinite  LDLᵀ (CHOLMOD's simplicial LDLᵀ in the parts, dense LDLᵀ of C, no
  ///                    pivoting: any matrix whose pivots do not vanish) instead of LLᵀ
  explicit SeparatedCholesky(bool indefinite = false);
  ~SeparatedCholesky();
  SeparatedCholesky(const SeparatedCholesky&) = delete;
  SeparatedCholesky& operator=(const SeparatedCholesky&) = delete;

  /// \brief Finds the separator of the pattern of A (its lower triangle is read; the
  /// pattern must stay the same for factorize) and analyses both parts.
  /// \return false if the graph gives no useful split (a part empty, or the separator
  /// more than kMaxSeparatorShare of the rows or kMaxSeparatorRows): use one factor.
  bool analyse(const SparseMatrix& a);
  /// \brief Factorises A (the analysed pattern). \return false if a part or the
  /// separator's Schur complement is not positive definite (the matrix is not); for the
  /// LDLᵀ, if a pivot vanishes.
  bool factorize(const SparseMatrix& a);
  /// x = A⁻¹ r (after a successful factorize).
  void solve(const Eigen::VectorXd& r, Eigen::VectorXd& x);

  bool analysed() const { return analysed_; }
  int separator_rows() const;
  int part_rows(int part) const;
  /// Floating-point operations of a part's factorisation (CHOLMOD's count).
  double part_flops(int part) const;
  /// Nonzeros of the two parts' factors and the separator's dense factor.
  double factor_nonzeros() const;

  /// Split only if the separator is at most this share of the rows …
  static constexpr double kMaxSeparatorShare = 0.1;
  /// … and at most this many rows (the dense Schur complement's size).
  static constexpr int kMaxSeparatorRows = 1500;
  /// Bisections tried to balance the parts' operation counts (analyse).
  static constexpr int kBalanceTries = 3;


 private:
  static constexpr int kWeightScale = 100;  ///< a row's weight before balancing
  /// The parts and their analyses for the split `side` (0, 1, or 2: separator, per row);
  /// false if it is no separator or a part cannot be analysed.
  bool build_parts(const SparseMatrix& a, const std::vector<int>& side);
  struct Part;
  std::unique_ptr<Part> parts_[2];
  std::vector<int> separator_;          ///< rows of S (ascending)
  struct SeparatorEntry {
    int row, col, value;  ///< separator rows (row ≥ col in A's order) and A's value index
  };
  std::vector<SeparatorEntry> separator_entries_;  ///< ASS's entries in A's lower triangle
  Eigen::MatrixXd schur_;               ///< C, then its Cholesky factor (lower triangle)
  Eigen::VectorXd separator_rhs_, separator_x_;
  Eigen::VectorXd schur_pivots_;  ///< LDLᵀ: C's D
  bool indefinite_ = false;
  bool analysed_ = false;
};

}  // namespace flapsim::fem
