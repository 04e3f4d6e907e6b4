// What the flapsim program loads at start (docs/performance.md, "Start-up"): gmsh and its
// ~90 libraries only when a wing is meshed, through the module libflapsim_gmsh.so.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "common/run_flapsim.hpp"

namespace fs = std::filesystem;

namespace {

// The shared libraries the dynamic loader maps when the program starts (what ldd prints).
std::string libraries_loaded_at_start() {
  const fs::path out = fs::temp_directory_path() / ("flapsim_startup_" + std::to_string(getpid()) + ".txt");
  const std::string cmd =
      "LD_TRACE_LOADED_OBJECTS=1 '" + std::string(FLAPSIM_BINARY) + "' > '" + out.string() + "' 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0);
  const std::string text = flapsim::test::read_text(out);
  fs::remove(out);
  return text;
}

}  // namespace

TEST(StartUp, TheProgramLoadsNeitherGmshNorOpenCascade) {
  const std::string libs = libraries_loaded_at_start();
  EXPECT_NE(libs.find("libgomp"), std::string::npos) << libs;  // the listing works
  EXPECT_NE(libs.find("libflapsim_omp_wait_policy.so"), std::string::npos) << libs;
  EXPECT_EQ(libs.find("libgmsh"), std::string::npos) << libs;
  EXPECT_EQ(libs.find("libTKernel"), std::string::npos) << libs;  // OpenCASCADE's core
  EXPECT_EQ(libs.find("libflapsim_gmsh"), std::string::npos) << libs;
  // ... which is built next to the program, where it is looked for first (meshing through
  // it is what the mesh, modes and reduce tests do).
  EXPECT_TRUE(fs::exists(fs::path(FLAPSIM_BINARY).parent_path() / "libflapsim_gmsh.so"));
}
