#pragma once
/// \file toml_preflight.hpp
/// \brief A scan of TOML text before toml++ parses it, refusing the inputs on which
/// toml++ 3.x stops on one of its own assertions instead of reporting a syntax error.
///
/// toml++ 3.x asserts (abort in builds without NDEBUG, an "assume" — undefined
/// behaviour — with NDEBUG on compilers that have one) where a table header's name does
/// not start with a key character ("[=", "[#x]", "[[" at the end of a line, "[[[1]]]";
/// upstream: marzer/tomlplusplus pull request 301) and where an array element starts
/// with a character that ends values ('}' as in "[}", "[1, }", or a Unicode line
/// separator U+0085, U+2028, U+2029). These inputs are all invalid TOML.
///
/// The scan follows the document's structure the way toml++ reads it: it knows whether
/// a line starts a statement (where '[' opens a table header) or continues a value (a
/// multi-line string, an array spread over lines, a string holding brackets). It stops
/// quietly where toml++ reports a syntax error of its own (toml++ reads no further), so
/// it only ever refuses text toml++ would mis-handle.

#include <string>
#include <string_view>

namespace flapsim::wings {

/// Throws InputError(file, line, "", "TOML syntax error: ...") at the first place in
/// `text` where toml++ would stop on an assertion; returns otherwise.
void refuse_toml_the_parser_cannot_read_safely(std::string_view text, const std::string& file);

}  // namespace flapsim::wings
