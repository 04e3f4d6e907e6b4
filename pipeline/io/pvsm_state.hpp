#pragma once
/// \file pvsm_state.hpp
/// \brief A ParaView state file (.pvsm, the XML state ParaView's "File > Load State"
/// reads; no Python needed) for a coupled run: the wing, wake and chain series with
/// chosen colour maps in a 3-D view, and next to it a line chart of the lift over time
/// (ParaView's "Plot Global Variables Over Time" on the field data lift_N, CL, t_over_T
/// of each step) whose time marker follows the animation. Every file is named relative
/// to the state file's folder, so the run folder can be moved or copied whole.
/// Written for ParaView 5.11 (Debian 12); docs/fsi.md, "ParaView".

#include <filesystem>
#include <string>

namespace flapsim::io {

/// What the state shows.
struct RunState {
  bool air = true;          ///< false (vacuum): no wing surface nor wake, only the chain
  std::string wing_pvd = "wing.pvd";    ///< relative to the state file
  std::string wake_pvd = "wake.pvd";
  std::string chain_pvd = "chain.pvd";
  double length_scale = 0.05;  ///< wing length [m], places the camera
  double pressure_range = 1.0;    ///< |Δp| for the wing's colour map [Pa] (grows with the data)
  double circulation_range = 1e-4; ///< |Γ| for the wake's colour map [m²/s]
};

/// \brief The XML text of the state (a <ParaView> document).
std::string run_state_xml(const RunState& state);

/// \brief Writes run_state_xml() to \p path atomically.
/// \throws OutputError
void write_run_state(const std::filesystem::path& path, const RunState& state);

}  // namespace flapsim::io
