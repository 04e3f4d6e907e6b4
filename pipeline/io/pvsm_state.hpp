#pragma once
/// \file pvsm_state.hpp
/// \brief A ParaView state file (.pvsm, the XML state ParaView's "File > Load State"
/// reads; no Python needed) for a coupled run. Two 3-D views of the wing, wake and chain
/// series (the run's view from in front of and above the stroke, and a side view along
/// the span at mid-stroke), each coloured field with a scalar bar, and a line chart of
/// the lift (left axis) and CL (right axis) against t/T (ParaView's "Plot Global Variables
/// Over Time" on the frames' field data; every other column of that table is listed
/// hidden, since ParaView draws every column the state does not name). The wing's colour
/// range is symmetric, ± a robust percentile of |value| over the run, fixed (no
/// rescaling per frame); the wake is drawn as its vortex lines, translucent, so the wing
/// stays visible; both cameras use parallel projection and frame the wing's bounds over
/// the run, the front one from the direction that shows most of the wing at its most
/// edge-on frame (state_camera.hpp). Every file is named relative to the state file's folder, so the run folder
/// can be moved or copied whole. Written for ParaView 5.11 (Debian 12); docs/fsi.md,
/// "ParaView"; tools/paraview_state.py renders it without ParaView.

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/io/state_camera.hpp"

namespace flapsim::io {

/// Percentile of |value| that sets the colour ranges of the state [%] (98: the 2 % of
/// panel values beyond it, the leading-edge peaks of single frames, are drawn in the
/// end colours instead of greying out the rest of the wing).
inline constexpr double kStateColourPercentile = 98.0;

/// \brief The p-th percentile (nearest rank: the ceil(p/100 n)-th smallest) of |x| over
/// \p values; 0 for none. \p values is reordered.
double magnitude_percentile(std::vector<double>& values, double p);

/// The 3-D views' size in the state [pixels] (ParaView's layout may resize them; the
/// cameras frame the wing for this aspect).
inline constexpr int kStateViewWidth = 960, kStateViewHeight = 540;

/// What the state shows.
struct RunState {
  bool air = true;          ///< false (vacuum): no wing surface nor wake, only the chain
  std::string wing_pvd = "wing.pvd";    ///< relative to the state file
  std::string wake_pvd = "wake.pvd";
  std::string chain_pvd = "chain.pvd";
  /// The structure's series is the FEM's surface mesh (fem.pvd), not the chain's bars: in
  /// air thin translucent lines over the wing coloured by wing_field (as thick black lines
  /// its thousands of edges hid the colours), in vacuum its surface coloured by |displacement_m|.
  bool structure_mesh = false;
  double length_scale = 0.05;  ///< wing length [m], places the camera without bounds
  /// The wing's colour field (cell data): "Cp" when the frames carry it, else the
  /// pressure jump "pressure_jump_Pa".
  std::string wing_field = "pressure_jump_Pa";
  double wing_range = 1.0;         ///< colour map over ± this (unit of wing_field)
  double circulation_range = 1e-4; ///< |Γ| for the wake's colour map [m²/s]
  /// |displacement_m| for the colour map of a FEM's surface in vacuum (structure_mesh, no
  /// air): white at rest to blue [m] (a grey surface under its edges showed no deflection).
  double displacement_range = 1e-3;
  double percentile = kStateColourPercentile;  ///< of the ranges above [%] (a comment in the state)
  /// The field data names of the frames (each a column of the chart's table); all but
  /// lift_N and CL are listed hidden.
  std::vector<std::string> frame_fields = {"step", "t_over_T", "lift_N", "CL"};
  /// The wing's (or, in vacuum, the chain's) bounds over the frames written
  /// (xmin, xmax, ymin, ymax, zmin, zmax) [m]; without them the cameras frame a sphere of
  /// length_scale around the origin.
  std::optional<std::array<double, 6>> bounds;
  /// The front view's direction (StateCameraChooser::best over state_box); the side view
  /// looks along the span at mid-stroke (-y), level.
  ViewDirection front{{-0.933, -0.25, 0.259}, {0.0, 0.0, 1.0}};
  /// The time the state opens at [s] (a frame's TimeValue: state_start_time); without it
  /// ParaView opens at the first frame, t = 0, a wing without loads and no wake.
  std::optional<double> start_time;
};

/// \brief The time of the frame the state opens at [s]: of \p frame_times (ascending [s]),
/// the one nearest the last wingbeat's mid-downstroke (phase 0.25 of \p period [s]), the
/// frame `make run`'s preview and `make snapshot`'s front_phase_0.25 show; for a run that
/// stopped before phase 0.25 of its first wingbeat, its last frame. Empty without frames.
std::optional<double> state_start_time(const std::vector<double>& frame_times, double period);

/// \brief What the cameras frame: the bounds (or a cube of ± length_scale about the
/// origin), with 0.3 length_scale more below for the near wake [m].
std::array<double, 6> state_box(const RunState& state);

/// The chart's series (columns of the table) the state shows: lift_N (left axis) and CL (right axis).
inline const std::vector<std::string>& state_chart_series() {
  static const std::vector<std::string> shown = {"lift_N", "CL"};
  return shown;
}

/// \brief The XML text of the state (a <ParaView> document).
std::string run_state_xml(const RunState& state);

/// \brief Writes run_state_xml() to \p path atomically.
/// \throws OutputError
void write_run_state(const std::filesystem::path& path, const RunState& state);

}  // namespace flapsim::io
