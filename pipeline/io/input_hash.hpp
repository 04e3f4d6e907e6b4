#pragma once
/// \file input_hash.hpp
/// \brief A stable hash of everything a run reads: the case file (with the overrides of a
/// sweep applied), the wing file it names, the wing's outline CSV and the chain file (the
/// case's, or one given on the command line). Two runs with the same hash read the same
/// values, whatever the files' key order, comments, whitespace, number spelling or folder;
/// a sweep can skip a case whose folder already holds the results of the same inputs.
///
/// Hash: FNV-1a, 64 bits (Fowler, Noll and Vo; offset basis 14695981039346656037, prime
/// 1099511628211, http://www.isthe.com/chongo/tech/comp/fnv/) over a canonical
/// serialisation: each TOML file as wings::TomlTable::canonical_text(), the CSV as its
/// bytes, each part introduced by its role ("case", "wing", "outline", "chain").
/// Not a cryptographic hash: it detects changed inputs, not forged ones.

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace flapsim::io {

inline constexpr std::uint64_t kFnv1a64Offset = 14695981039346656037ull;
inline constexpr std::uint64_t kFnv1a64Prime = 1099511628211ull;

/// FNV-1a 64 of \p bytes, continuing from \p hash (the offset basis for a new hash).
constexpr std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t hash = kFnv1a64Offset) {
  for (unsigned char c : bytes) {
    hash ^= c;
    hash *= kFnv1a64Prime;
  }
  return hash;
}

/// The hash as 16 lower-case hex digits.
std::string hash_hex(std::uint64_t hash);

/// The canonical serialisation the hash is computed over (for inspection and tests).
/// \param case_file   the case file
/// \param overrides   sweep overrides {"kinematics.rotation_phase", "-0.1"} (TOML values)
/// \param chain_file  a chain file replacing the case's ("" = the case's own, if any)
/// \throws flapsim::InputError if a file cannot be read or parsed
std::string canonical_inputs(const std::string& case_file,
                             const std::vector<std::pair<std::string, std::string>>& overrides = {},
                             const std::string& chain_file = "");

/// fnv1a64(canonical_inputs(...)).
std::uint64_t input_hash(const std::string& case_file,
                         const std::vector<std::pair<std::string, std::string>>& overrides = {},
                         const std::string& chain_file = "");

}  // namespace flapsim::io
