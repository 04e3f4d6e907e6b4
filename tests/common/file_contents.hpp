#pragma once
/// \file
/// \brief Everything written so far to a FILE* (a tmpfile() standing in for stderr in tests).

#include <cstdio>
#include <string>

namespace flapsim::test {

/// Flushes f, rewinds it and returns all it holds.
inline std::string file_contents(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string s;
  for (int c; (c = std::fgetc(f)) != EOF;) s += static_cast<char>(c);
  return s;
}

}  // namespace flapsim::test
