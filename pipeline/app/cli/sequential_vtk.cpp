#include "pipeline/app/cli/sequential_vtk.hpp"

#include <cstdlib>

namespace flapsim::cli {

void run_vtk_on_the_calling_thread() {
  setenv("VTK_SMP_BACKEND_IN_USE", "Sequential", /*overwrite=*/0);  // a value the user set is kept
}

}  // namespace flapsim::cli
