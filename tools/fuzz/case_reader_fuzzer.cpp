/// \file case_reader_fuzzer.cpp
/// \brief libFuzzer entry for the case readers (tools/coverage_fuzz.sh). An input's first
/// byte picks the reader by its two lowest bits: 0 a case file (pipeline/io/case_file.hpp),
/// 1 or 3 a chain file (pipeline/io/chain_file.hpp), 2 a kinematics CSV file
/// (pipeline/io/kinematics_csv.hpp; its column "sweep_deg", fitted when the byte's bit 2 is
/// set); the rest is the text (reader_outcome.hpp: what counts as a finding).

#include <cstdint>
#include <string>
#include <string_view>

#include "pipeline/io/case_file.hpp"
#include "pipeline/io/chain_file.hpp"
#include "pipeline/io/kinematics_csv.hpp"
#include "tools/fuzz/reader_outcome.hpp"
#include "wings/loader/toml_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  flapsim::fuzz::read_or_abort("case_reader_fuzzer", [&] {
    switch (data[0] & 3) {
      case 0: (void)flapsim::io::read_case(flapsim::wings::parse_toml_string(text, "fuzz_case.toml")); break;
      case 2:
        (void)flapsim::io::read_kinematics_csv(flapsim::fuzz::written("fuzz_kinematics.csv", text),
                                               "sweep_deg", 26.1, "kinematics.sweep", (data[0] & 4) != 0);
        break;
      default: (void)flapsim::io::parse_chain_text(text, "fuzz_chain.toml");
    }
  });
  return 0;
}
