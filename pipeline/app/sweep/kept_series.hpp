#pragma once
/// \file kept_series.hpp
/// \brief Whether a finished run kept by a sweep or an optimisation (found by its inputs
/// hash: summary_reader.hpp, earlier_cases.hpp) has the ParaView series the command now asks
/// for. The inputs hash leaves out output.vtk_every and the command's --vtk-every, which
/// decide only which files a run writes (io::input_hash), so a run found by its hash may
/// have been run without series: asked for them (--vtk-every N > 0), the command keeps it
/// only if its folder holds the structure's series (every run with frames writes it:
/// chain.pvd, or fem.pvd for kind = "fem"), and runs it again otherwise. A run with series
/// is kept when none are asked for; the interval of its series is not compared.

#include <filesystem>

#include "pipeline/io/case_model.hpp"

namespace flapsim::sweep {

/// \brief Whether \p run_folder, a finished run of \p c, has the series a run with
/// \p vtk_every writes (always true for 0: none asked for).
bool has_the_series_asked_for(const std::filesystem::path& run_folder, const io::Case& c, int vtk_every);

}  // namespace flapsim::sweep
