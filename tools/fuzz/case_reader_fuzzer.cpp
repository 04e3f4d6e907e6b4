/// \file case_reader_fuzzer.cpp
/// \brief libFuzzer entry for the case and chain readers (tools/coverage_fuzz.sh): an
/// input's first byte picks the reader (odd: a chain file, pipeline/io/chain_file.hpp; even:
/// a case file, pipeline/io/case_file.hpp), the rest is the text. flapsim::InputError is the
/// documented refusal of bad input; any other exception, a crash or a sanitizer report is a
/// finding.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string_view>

#include "pipeline/io/case_file.hpp"
#include "pipeline/io/chain_file.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/toml_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    if (data[0] & 1)
      (void)flapsim::io::parse_chain_text(text, "fuzz_chain.toml");
    else
      (void)flapsim::io::read_case(flapsim::wings::parse_toml_string(text, "fuzz_case.toml"));
  } catch (const flapsim::InputError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "case_reader_fuzzer: an exception other than InputError: %s\n", e.what());
    std::abort();
  }
  return 0;
}
