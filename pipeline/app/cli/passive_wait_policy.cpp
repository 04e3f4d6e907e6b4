// libflapsim_omp_wait_policy.so: sets OMP_WAIT_POLICY=passive, unless the environment
// already has an OMP_WAIT_POLICY, before the GNU OpenMP runtime reads it
// (docs/performance.md, "OpenMP wait policy").
//
// libgomp reads the variable once, in its library constructor. Shared libraries are
// initialised dependencies first; among libraries that do not depend on each other, the
// GNU dynamic loader initialises the later one in the program's DT_NEEDED list first.
// This library depends on the C library only and is linked right after libgomp
// (pipeline/app/CMakeLists.txt), so its constructor runs after the C library has set up
// the environment and before libgomp's. (The program's own DT_PREINIT_ARRAY functions run
// earlier still, but the C library's initialisation, which comes after them, resets
// `environ` to the process's original environment, so a variable set there is lost.)
// tests/app/test_threads_option.cpp checks the effect (GOMP_SPINCOUNT 0).
#include <cstdlib>

namespace {

__attribute__((constructor)) void use_passive_omp_wait_policy() {
  setenv("OMP_WAIT_POLICY", "passive", /*overwrite=*/0);  // a value the user set is kept
}

}  // namespace
