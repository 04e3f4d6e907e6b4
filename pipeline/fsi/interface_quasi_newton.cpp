#include "pipeline/fsi/interface_quasi_newton.hpp"

#include <Eigen/QR>

#include <algorithm>
#include <stdexcept>

namespace flapsim::fsi {

InterfaceQuasiNewton::InterfaceQuasiNewton(int max_columns, int reuse_steps)
    : max_columns_(std::max(1, max_columns)), reuse_steps_(std::max(0, reuse_steps)) {
  column_step_.assign(static_cast<std::size_t>(max_columns_), 0);
}

void InterfaceQuasiNewton::start_step() {
  ++step_;
  has_previous_ = false;
  // Pairs are newest first: drop from the end those older than the reuse window.
  while (columns_ > 0 && column_step_[static_cast<std::size_t>(columns_ - 1)] < step_ - reuse_steps_) --columns_;
}

void InterfaceQuasiNewton::drop_column(int j) {
  for (int k = j; k + 1 < columns_; ++k) {
    v_.col(k) = v_.col(k + 1);
    w_.col(k) = w_.col(k + 1);
    column_step_[static_cast<std::size_t>(k)] = column_step_[static_cast<std::size_t>(k + 1)];
  }
  --columns_;
  ++filtered_;
}

bool InterfaceQuasiNewton::filtered_update(const Eigen::VectorXd& r, Eigen::VectorXd& c) {
  // Modified Gram–Schmidt from the newest pair: V = Q R with the dropped pairs left out.
  const Eigen::Index n = v_.rows();
  if (q_.rows() != n || q_.cols() != max_columns_) {
    q_.resize(n, max_columns_);
    r_.resize(max_columns_, max_columns_);
  }
  int j = 0;
  while (j < columns_) {
    q_.col(j) = v_.col(j);
    const double length = q_.col(j).norm();
    r_.col(j).head(j).setZero();
    for (int i = 0; i < j; ++i) {
      r_(i, j) = q_.col(i).dot(q_.col(j));
      q_.col(j) -= r_(i, j) * q_.col(i);
    }
    const double rest = q_.col(j).norm();
    if (!(rest > kReuseFilterLimit * length)) {
      drop_column(j);
      continue;
    }
    r_(j, j) = rest;
    q_.col(j) /= rest;
    ++j;
  }
  if (columns_ == 0) return false;
  qtr_.noalias() = q_.leftCols(columns_).transpose() * r;
  c = -r_.topLeftCorner(columns_, columns_).triangularView<Eigen::Upper>().solve(qtr_);
  return c.allFinite();
}

bool InterfaceQuasiNewton::next(const Eigen::VectorXd& r, const Eigen::VectorXd& output,
                                Eigen::VectorXd& next) {
  if (has_previous_) {
    if (previous_r_.size() != r.size() || previous_output_.size() != output.size())
      throw std::invalid_argument("InterfaceQuasiNewton: the sizes changed within a step");
    if (v_.rows() != r.size() || w_.rows() != output.size() || v_.cols() != max_columns_) {
      v_.resize(r.size(), max_columns_);
      w_.resize(output.size(), max_columns_);
      columns_ = 0;
    }
    // Newest column first; the oldest falls off when the store is full.
    const int keep = std::min(columns_, max_columns_ - 1);
    for (int j = keep; j > 0; --j) {
      v_.col(j) = v_.col(j - 1);
      w_.col(j) = w_.col(j - 1);
      column_step_[static_cast<std::size_t>(j)] = column_step_[static_cast<std::size_t>(j - 1)];
    }
    v_.col(0) = r - previous_r_;
    w_.col(0) = output - previous_output_;
    column_step_[0] = step_;
    columns_ = keep + 1;
  } else {
    if (columns_ > 0 && (v_.rows() != r.size() || w_.rows() != output.size()))
      columns_ = 0;  // the earlier steps' pairs are of another size
    first_norm_ = r.norm();
  }
  if (r.norm() > first_norm_ && columns_ > 0 && column_step_[static_cast<std::size_t>(columns_ - 1)] < step_) {
    // The step's residual grew: the earlier steps' pairs (the oldest ones, at the end) go.
    while (columns_ > 0 && column_step_[static_cast<std::size_t>(columns_ - 1)] < step_) --columns_;
    ++stale_drops_;
  }
  previous_r_ = r;
  previous_output_ = output;
  has_previous_ = true;
  if (columns_ == 0) return false;
  if (reuse_steps_ > 0) {
    if (!filtered_update(r, coefficients_)) return false;
    next = output + w_.leftCols(columns_) * coefficients_;
    return true;
  }
  // Least squares by a rank-revealing QR: columns that add nothing (a sub-iteration that
  // repeated an earlier direction) get no weight instead of a huge one.
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(v_.leftCols(columns_));
  const Eigen::VectorXd c = qr.solve(-r);
  if (!c.allFinite()) return false;
  next = output + w_.leftCols(columns_) * c;
  return true;
}

}  // namespace flapsim::fsi
