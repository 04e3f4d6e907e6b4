#pragma once
/// \file frames_size.hpp
/// \brief The disk space of a run's ParaView frames, known from the case before it starts,
/// and a warning where it is large.
///
/// A run writes a frame of the wing, the wake and the structure every `vtk_every` steps
/// (default 1), and the wake's frame holds the whole wake, which grows by a row a step: the
/// total grows as the square of the run's length. A 48-wingbeat hover of a 60 mm wing at 60
/// steps a wingbeat wrote 2.2 GB, a 300-wingbeat one would write about 86 GB, each with the
/// case's defaults (docs/output_files.md, "Writing cost").

#include <optional>
#include <string>

#include "pipeline/io/case_model.hpp"

namespace flapsim::app {

/// Sizes of a frame's files, LZ4-compressed as io::write_vtp writes them, measured on 4 Dec
/// 2026 (a rigid 60 mm wing at 6 x 10 and 12 x 20 panels, the hawkmoth hover, a film wing's
/// FEM of 387 nodes): the wake's frame 5.4 kB and 53.5 B a ring (4790 and 11 990 rings of
/// two runs; the hawkmoth's 2990 rings within 2 %), the wing's 8.2 kB and 108 B a panel, a
/// chain's 6.5 kB, a FEM's 98 B a node.
inline constexpr double kWakeFrameBytes = 5.4e3;
inline constexpr double kWakeFrameBytesPerRing = 53.5;
inline constexpr double kWingFrameBytes = 8.2e3;
inline constexpr double kWingFrameBytesPerPanel = 108.0;
inline constexpr double kChainFrameBytes = 6.5e3;
inline constexpr double kFemFrameBytesPerNode = 98.0;

/// Frames above this are warned: a long run's defaults fill a disk [B].
inline constexpr double kLargeFramesBytes = 1e9;

/// \brief The ParaView frames a run of the case writes [B]: a frame every \p vtk_every steps
/// from step 0 (0: none), of the wing and the wake (in air; with leading_edge = "shed" the
/// wake's frame holds the sheet's rings too) and of the structure (a chain, or the FEM of
/// \p fem_dofs DOFs, fem::kDofsPerNode a node).
double frames_bytes(const io::Case& c, int vtk_every, int fem_dofs);

/// \brief "" or the warning for the frames of the case's output.vtk_every (frames_bytes) over
/// kLargeFramesBytes, or over \p free_bytes (the space left where the run writes, when
/// known), with the interval that keeps them under kLargeFramesBytes (and, over the free
/// space, under half of it).
std::string frames_size_warning(const io::Case& c, int fem_dofs, std::optional<double> free_bytes);

/// \brief "" or the warning for an output.vtk_every beyond the run's steps: the series then
/// holds step 0 alone (the wing at rest, no load, no wake), which run.pvsm opens on.
std::string frames_interval_warning(const io::Case& c);

}  // namespace flapsim::app
