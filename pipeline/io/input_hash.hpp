#pragma once
/// \file input_hash.hpp
/// \brief A fingerprint of everything a run's results depend on: the resolved case
/// (every field of io::Case after defaults, overrides and unit conversion, but
/// output.vtk_every, which decides only which files are written, and its name), the wing it
/// flaps (every field of wings::Wing: outline, veins, membrane, mesh sizes; not its or its
/// veins' names; the clamp line only where the wing's FEM is built: kind = "fem", or a
/// flexible wing without a chain file), the chain file's bytes and the joint-spring factor. Two runs with
/// equal hashes read the same inputs (and may differ only in the files they write); a sweep re-run skips a
/// case whose summary.json carries the hash of its inputs, and an optimisation a point whose run folder does
/// (docs/sweeps.md, "Resuming a sweep"; a run kept where ParaView series are asked for must also have them).
///
/// The hash is FNV-1a 64 (Fowler, Noll, Vo; public-domain reference at
/// http://www.isthe.com/chongo/tech/comp/fnv/) of a canonical text: one `name=value` line
/// per field in a fixed order, numbers in shortest round-trip form (the same double
/// gives the same text on any machine), periodic signals as their value and first two
/// phase derivatives at 64 phases s = k/64. File paths are not part of it (moving a
/// study does not change its hash); the chain file enters by its content.

#include <cstdint>
#include <string>
#include <string_view>

#include "pipeline/io/case_model.hpp"
#include "wings/loader/wing_model.hpp"

namespace flapsim::io {

/// \brief FNV-1a 64 of \p bytes (offset basis 14695981039346656037, prime 1099511628211).
std::uint64_t fnv1a_64(std::string_view bytes);

/// \brief The canonical text the hash is taken of (for tests and for diagnosing a
/// hash that changed).
/// \param chain_file   the chain file the run uses instead of the case's ("" = the case's)
/// \param spring_scale the joint-spring factor of the run
std::string canonical_inputs(const Case& c, const wings::Wing* wing, const std::string& chain_file,
                             double spring_scale);

/// \brief The hash of canonical_inputs() as 16 lower-case hex digits.
/// \throws flapsim::InputError if the chain file cannot be read
std::string input_hash(const Case& c, const wings::Wing* wing, const std::string& chain_file,
                       double spring_scale);

}  // namespace flapsim::io
