#pragma once
/// \file gmsh_module_loader.hpp
/// \brief Loads libflapsim_gmsh.so (fem/gmsh_boundary.hpp) on first use, with dlopen.
/// Where it looks, in order:
///   1. next to the running program (the folder of /proc/self/exe): `build/` holds both
///      `flapsim` and the module, and an installed flapsim has it in the same folder;
///   2. the build tree that compiled this code (for the test and benchmark programs in
///      `build/tests/*` and `build/bench`).
/// If neither exists (or it is from another build), throws std::runtime_error naming the
/// file it looked for; the command exits with status 4 (docs/architecture.md).

#include "fem/gmsh_boundary.hpp"

namespace flapsim::fem {

/// The module's mesh function; loads the module on the first call (thread-safe).
MeshWithGmshFn& gmsh_mesher();

}  // namespace flapsim::fem
