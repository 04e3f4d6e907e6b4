#pragma once
/// \file fem_modes_state.hpp
/// \brief fem_modes.pvsm, written by `flapsim modes` next to fem.vtu: a ParaView state
/// (5.11, "File > Load State", no Python) that animates one mode of the wing: fem.vtu
/// through Warp By Vector on the mode's point vector mode_NN, its scale factor swung as
/// sin(2π s) over the animation (s from 0 to 1 in 40 frames: one period, the largest
/// node moving ± kModeViewFraction of the span), coloured by |mode_NN| with a scalar bar,
/// the undeformed wing as a grey outline, and a text naming the mode, its frequency and
/// its kinds (docs/fem.md, "Viewing a mode").

#include <array>
#include <filesystem>
#include <string>

namespace flapsim::io {

/// The mode the state shows.
struct FemModeView {
  std::string vtu = "fem.vtu";  ///< relative to the state file
  int mode = 1;                 ///< 1-based: the point vector mode_NN
  double frequency_hz = 0.0;
  std::string kind, shape_kind;  ///< as in modes.csv
  std::array<double, 6> bounds{-0.05, 0.05, 0.0, 0.05, -0.01, 0.01};  ///< the mesh's (xmin, xmax, …) [m], for the camera
};

/// "mode_NN" of a 1-based mode number (two digits at least).
std::string mode_vector_name(int mode);

/// \brief The XML text of the state (a <ParaView> document).
std::string fem_modes_state_xml(const FemModeView& view);

/// \brief Writes fem_modes_state_xml() to \p path atomically. \throws OutputError
void write_fem_modes_state(const std::filesystem::path& path, const FemModeView& view);

}  // namespace flapsim::io
