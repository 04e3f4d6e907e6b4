#pragma once
/// \file thinned_sample.hpp
/// \brief A sample of at most a fixed number of the values offered to it, for a percentile
/// over a whole run (run.pvsm's colour ranges: the wing's Cp and the wake's |Γ| of every
/// frame). Keeping every value grew with the square of a run's length, since the wake gains
/// a row a step (the 75 mm film wing's case at 16 wingbeats with frames every 4th step: about
/// 2e6 values, 38 MB more than without frames; at 100 wingbeats 8e7). Below the limit it keeps every value, so a run of the usual length gets the same
/// ranges as before; at the limit it drops every second value kept and from then on takes
/// every second (fourth, …) value offered: an even stride through the run, deterministic.

#include <cstddef>
#include <vector>

namespace flapsim::app {

class ThinnedSample {
 public:
  /// \param limit  values kept at most (at least 2)
  explicit ThinnedSample(std::size_t limit = kDefaultLimit) : limit_(limit < 2 ? 2 : limit) {}

  /// 2²⁰ values, 8 MB: a hundred 1000-cell frames before it thins anything.
  static constexpr std::size_t kDefaultLimit = std::size_t{1} << 20;

  /// Offers the values of [first, last).
  template <class It>
  void add(It first, It last) {
    for (; first != last; ++first) {
      if (offered_++ % stride_ == 0) kept_.push_back(*first);
      if (kept_.size() >= limit_) thin();
    }
  }

  /// The values kept (every stride-th offered).
  const std::vector<double>& values() const { return kept_; }
  std::size_t stride() const { return stride_; }

 private:
  void thin() {
    std::size_t j = 0;
    for (std::size_t i = 0; i < kept_.size(); i += 2) kept_[j++] = kept_[i];
    kept_.resize(j);
    stride_ *= 2;
  }

  std::size_t limit_;
  std::size_t stride_ = 1;
  std::size_t offered_ = 0;
  std::vector<double> kept_;
};

}  // namespace flapsim::app
