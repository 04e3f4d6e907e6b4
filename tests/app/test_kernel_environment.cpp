// FLAPSIM_KERNEL chooses a narrower Biot–Savart kernel to measure what a CPU without the
// wider units gets (docs/performance.md). A value it cannot choose is ignored, and was
// ignored silently: a benchmark run "with FLAPSIM_KERNEL=AVX2" (upper case) measured the
// AVX-512 kernels. Every command now warns of it; a value it honours gives no warning.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace {

// stderr of `FLAPSIM_KERNEL=VALUE flapsim check <flat plate>`; the exit status must be 0.
std::string check_with_kernel(const flapsim::test::ScratchDir& dir, const std::string& value) {
  const std::string cmd = "FLAPSIM_KERNEL='" + value + "' '" + std::string(FLAPSIM_BINARY) + "' check '" +
                          std::string(FLAPSIM_SOURCE_DIR) + "/wings/flat_plate.toml' > /dev/null 2> '" +
                          (dir / "err.txt").string() + "'";
  const int status = std::system(cmd.c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << value;
  return flapsim::test::read_text(dir / "err.txt");
}

TEST(KernelEnvironment, AValueItCannotChooseIsWarnedAndOneItHonoursIsNot) {
  const flapsim::test::ScratchDir dir("kernel_environment");
  for (const char* wrong : {"AVX2", "avx-2", "bogus"}) {
    const std::string err = check_with_kernel(dir, wrong);
    EXPECT_NE(err.find(std::string("FLAPSIM_KERNEL='") + wrong + "' is not one of scalar, avx2, avx512"),
              std::string::npos)
        << err;
  }
  // scalar (SSE2) runs on every x86-64 CPU.
  EXPECT_EQ(check_with_kernel(dir, "scalar").find("FLAPSIM_KERNEL"), std::string::npos);
}

}  // namespace
