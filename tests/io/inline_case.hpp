#pragma once
// Test helper of the io tests: a case file given as text, placed (virtually) in tests/data/
// next to valid_tiny_wing.toml, read as the loader reads a file.

#include <gtest/gtest.h>

#include <string>

#include "pipeline/io/case_file.hpp"
#include "pipeline/io/case_model.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/toml_reader.hpp"

inline flapsim::io::Case case_from_text(const std::string& text) {
  return flapsim::io::read_case(flapsim::wings::parse_toml_string(
      text, std::string(FLAPSIM_SOURCE_DIR) + "/tests/data/inline_case.toml"));
}

/// \brief The InputError that reading \p text as a case throws (a test failure if none).
inline flapsim::InputError error_of(const std::string& text) {
  try {
    case_from_text(text);
  } catch (const flapsim::InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return flapsim::InputError("", 0, "", "");
}
