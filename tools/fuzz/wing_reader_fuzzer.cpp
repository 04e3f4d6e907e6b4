/// \file wing_reader_fuzzer.cpp
/// \brief libFuzzer entry for the wing readers (tools/coverage_fuzz.sh). An input's first
/// byte picks the reader by its two lowest bits: 0 a wing file (wings/loader/wing_file.hpp),
/// 1 or 3 an SVG drawing (wings/loader/svg_drawing.hpp), 2 an outline CSV file
/// (wings/loader/outline_csv.hpp); the rest is the text (reader_outcome.hpp: what counts as a
/// finding).

#include <cstdint>
#include <string>
#include <string_view>

#include "tools/fuzz/reader_outcome.hpp"
#include "wings/loader/outline_csv.hpp"
#include "wings/loader/svg_drawing.hpp"
#include "wings/loader/toml_reader.hpp"
#include "wings/loader/wing_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  namespace w = flapsim::wings;
  flapsim::fuzz::read_or_abort("wing_reader_fuzzer", [&] {
    switch (data[0] & 3) {
      case 0:  // an outline_file it names is looked for beside the working folder's fuzz.toml
        (void)w::read_wing(w::parse_toml_string(text, "fuzz.toml"));
        break;
      case 2:
        (void)w::read_outline_csv(flapsim::fuzz::written("fuzz_outline.csv", text), "planform.outline_file");
        break;
      default: (void)w::parse_svg_drawing(text, "fuzz.svg", "planform.outline_file");
    }
  });
  return 0;
}
