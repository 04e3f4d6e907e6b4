#pragma once
/// \file checked_integer.hpp
/// \brief Integer arithmetic that reports overflow instead of wrapping (counts read
/// from input files: steps_per_cycle × cycles, panels, bodies). Built on the GCC/Clang
/// builtins __builtin_mul_overflow / __builtin_add_overflow, which compute the exact
/// result and say whether it fits the result type.

#include <cstdint>
#include <optional>

namespace flapsim::wings {

/// a × b, or nullopt if the exact product does not fit an int64.
inline std::optional<std::int64_t> checked_multiply(std::int64_t a, std::int64_t b) {
  std::int64_t r = 0;
  if (__builtin_mul_overflow(a, b, &r)) return std::nullopt;
  return r;
}

/// a + b, or nullopt if the exact sum does not fit an int64.
inline std::optional<std::int64_t> checked_add(std::int64_t a, std::int64_t b) {
  std::int64_t r = 0;
  if (__builtin_add_overflow(a, b, &r)) return std::nullopt;
  return r;
}

/// v as an int, or nullopt if it does not fit.
inline std::optional<int> checked_narrow(std::int64_t v) {
  int r = 0;
  if (__builtin_mul_overflow(v, 1, &r)) return std::nullopt;
  return r;
}

}  // namespace flapsim::wings
