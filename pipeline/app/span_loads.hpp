#pragma once
/// \file span_loads.hpp
/// \brief The lift along the span: each spanwise strip of the vortex lattice's share of the
/// run's mean lift over the last cycle, written as span_loads.csv (docs/fsi.md, "Outputs").
///
/// A strip is the lattice's panels between two neighbouring spanwise stations (root to
/// tip, `numerics.spanwise_panels` of them); its lift is the sum over its panels of the
/// panel force (pressure jump, edge force, skin friction) along the run's lift direction,
/// as the run's lift is the sum over all panels (so the strips' means add up to
/// summary.json's mean_lift_N). The strips' shape is where a leading-edge model puts its
/// lift: with `leading_edge = "shed"` the tip strip of a revolving wing carries 29–43 % of
/// it, with `none` and `separated` 12–17 % (docs/uvlm.md, "Where shed's lift lies along the
/// span").

#include <filesystem>
#include <vector>

#include <Eigen/Core>

#include "uvlm/planform_grid.hpp"
#include "uvlm/vortex_lattice.hpp"

namespace flapsim::app {

/// \brief Appends to \p out each strip's force along \p up [N], root to tip: Σ over its
/// panels of loads.force · up (m.spanwise values: a run keeps its steps' strips in one series).
void append_strip_lifts(const uvlm::VortexLatticeModel& m, const uvlm::PanelLoads& loads,
                        const Eigen::Vector3d& up, std::vector<double>& out);

/// A strip of the undeformed lattice, in the wing frame.
struct SpanStrip {
  double y_inner = 0.0;  ///< spanwise station of its inner side, at the leading edge [m]
  double y_outer = 0.0;  ///< of its outer side [m]
  double chord = 0.0;    ///< the mean of its two sides' chords, leading- to trailing-edge node [m]
};

/// \brief The strips of a planform grid, root to tip.
std::vector<SpanStrip> span_strips(const uvlm::PlanformGrid& grid);

/// \brief Writes span_loads.csv (atomically): a row per strip, root to tip, with its
/// stations and chord [m], its mean lift over the last cycle [N], that per unit span [N/m]
/// and its share of the strips' sum [-].
/// \param mean_lift  each strip's mean lift [N], as many as the strips
/// \throws std::invalid_argument if the counts differ; io::OutputError on I/O failure
void write_span_loads(const std::filesystem::path& path, const std::vector<SpanStrip>& strips,
                      const std::vector<double>& mean_lift);

}  // namespace flapsim::app
