/// \file wing_reader_fuzzer.cpp
/// \brief libFuzzer entry for the wing readers (tools/coverage_fuzz.sh): an input's first
/// byte picks the reader (odd: an SVG drawing, wings/loader/svg_drawing.hpp; even: a wing
/// file, wings/loader/wing_file.hpp), the rest is the text. flapsim::InputError is the
/// documented refusal of bad input; any other exception, a crash or a sanitizer report is a
/// finding.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string_view>

#include "wings/loader/input_error.hpp"
#include "wings/loader/svg_drawing.hpp"
#include "wings/loader/toml_reader.hpp"
#include "wings/loader/wing_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    if (data[0] & 1)
      (void)flapsim::wings::parse_svg_drawing(text, "fuzz.svg", "planform.outline_file");
    else  // an outline_file it names is looked for beside the working folder's fuzz.toml
      (void)flapsim::wings::read_wing(flapsim::wings::parse_toml_string(text, "fuzz.toml"));
  } catch (const flapsim::InputError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "wing_reader_fuzzer: an exception other than InputError: %s\n", e.what());
    std::abort();
  }
  return 0;
}
