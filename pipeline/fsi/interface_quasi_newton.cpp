#include "pipeline/fsi/interface_quasi_newton.hpp"

#include <Eigen/QR>

#include <algorithm>
#include <stdexcept>

namespace flapsim::fsi {

InterfaceQuasiNewton::InterfaceQuasiNewton(int max_columns) : max_columns_(std::max(1, max_columns)) {}

void InterfaceQuasiNewton::start_step() {
  columns_ = 0;
  has_previous_ = false;
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
    }
    v_.col(0) = r - previous_r_;
    w_.col(0) = output - previous_output_;
    columns_ = keep + 1;
  }
  previous_r_ = r;
  previous_output_ = output;
  has_previous_ = true;
  if (columns_ == 0) return false;
  // Least squares by a rank-revealing QR: columns that add nothing (a sub-iteration that
  // repeated an earlier direction) get no weight instead of a huge one.
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(v_.leftCols(columns_));
  const Eigen::VectorXd c = qr.solve(-r);
  if (!c.allFinite()) return false;
  next = output + w_.leftCols(columns_) * c;
  return true;
}

}  // namespace flapsim::fsi
