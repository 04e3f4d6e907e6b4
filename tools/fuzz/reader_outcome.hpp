#pragma once
/// \file reader_outcome.hpp
/// \brief What the fuzzers of tools/coverage_fuzz.sh accept of a reader: returning, or
/// flapsim::InputError (the documented refusal of bad input). Any other exception aborts
/// (a finding, as a crash or a sanitizer report is).

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>
#include <string_view>

#include "wings/loader/input_error.hpp"

namespace flapsim::fuzz {

/// Runs \p read; aborts, naming \p fuzzer, on an exception other than InputError.
template <class Read>
void read_or_abort(const char* fuzzer, Read&& read) {
  try {
    read();
  } catch (const flapsim::InputError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: an exception other than InputError: %s\n", fuzzer, e.what());
    std::abort();
  }
}

/// \p text written to \p path (in the working folder), for the readers that take a file;
/// returns the path.
inline std::string written(const std::string& path, std::string_view text) {
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(text.data(), static_cast<std::streamsize>(text.size()));
  return path;
}

}  // namespace flapsim::fuzz
