#include "pipeline/app/sweep/kept_series.hpp"

#include <system_error>

namespace flapsim::sweep {

bool has_the_series_asked_for(const std::filesystem::path& run_folder, const io::Case& c, int vtk_every) {
  if (vtk_every <= 0) return true;
  // The structure's series (run_recorder.cpp): the FEM's deformed mesh, or the chain's bodies.
  const char* series = c.structure.kind == io::Case::Structure::Kind::Fem ? "fem.pvd" : "chain.pvd";
  std::error_code ec;
  return std::filesystem::exists(run_folder / series, ec);
}

}  // namespace flapsim::sweep
