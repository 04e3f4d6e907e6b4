#include "pipeline/app/frames_size.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "fem/mesh.hpp"
#include "pipeline/app/resource_estimate.hpp"
#include "uvlm/leading_edge_sheet.hpp"

namespace flapsim::app {

double frames_bytes(const io::Case& c, int vtk_every, int fem_dofs) {
  if (vtk_every <= 0) return 0.0;
  const auto& n = c.numerics;
  const double steps = static_cast<double>(n.total_steps());
  const double every = vtk_every;
  const double frames = std::floor(steps / every) + 1.0;  // steps 0, N, 2N, ...
  const double ns = n.spanwise_panels;
  const double structure =
      fem_dofs > 0 ? kFemFrameBytesPerNode * fem_dofs / fem::kDofsPerNode : kChainFrameBytes;
  if (!c.air.enabled) return frames * structure;
  const double wing = kWingFrameBytes + kWingFrameBytesPerPanel * n.chordwise_panels * ns;
  const bool shed = n.leading_edge == uvlm::LeadingEdge::Shed;
  const double max_rows = n.wake_max_rows > 0 ? n.wake_max_rows : steps;
  // The wake's rings at step k: min(k, max_rows) rows of the span's panels, with the sheet's
  // merged rings; summed over at most 100 000 frames, evenly spaced, scaled to all of them.
  const double samples = std::min(frames, 1e5);
  double rings = 0.0;
  for (double j = 0.0; j < samples; ++j) {
    const double k = std::round(j * (frames - 1.0) / std::max(samples - 1.0, 1.0)) * every;
    double r = std::min(k, max_rows) * ns;
    if (shed) r += uvlm::merged_sheet_rings(n.sheet_merge_steps, k, n.sheet_merge_spread_steps) * ns;
    rings += r;
  }
  rings *= frames / samples;
  return frames * (structure + wing + kWakeFrameBytes) + kWakeFrameBytesPerRing * rings;
}

std::string frames_size_warning(const io::Case& c, int fem_dofs, std::optional<double> free_bytes) {
  const int vtk_every = c.output.vtk_every;
  const double bytes = frames_bytes(c, vtk_every, fem_dofs);
  const bool over_disk = free_bytes && bytes > *free_bytes;
  if (vtk_every <= 0 || !(bytes > kLargeFramesBytes || over_disk)) return "";
  // The interval that brings them under the limit: every part falls about as 1/N.
  const double limit = over_disk ? std::min(kLargeFramesBytes, 0.5 * *free_bytes) : kLargeFramesBytes;
  int every = static_cast<int>(std::min(std::ceil(bytes / limit) * vtk_every, 1e9));
  while (every < 1e9 && frames_bytes(c, every, fem_dofs) > limit) every = std::min(2 * every, 1000000000);
  const double fewer = frames_bytes(c, every, fem_dofs);
  char head[160];
  std::snprintf(head, sizeof head,
                "the run's ParaView frames will take about %s on disk (a frame every %d step%s",
                bytes_text(bytes).c_str(), vtk_every, vtk_every == 1 ? "" : "s");
  std::string w =
      std::string(head) +
      "; each holds the whole wake, which grows by a row a step, so their total grows as the square "
      "of the run's length)";
  if (over_disk)
    w += ", more than the " + bytes_text(*free_bytes) +
         " free where the run writes: it would stop with exit status 4 when the disk fills";
  w += ". [output] vtk_every = " + std::to_string(every) + " (or flapsim run --vtk-every " +
       std::to_string(every) + ") writes about " + bytes_text(fewer) +
       "; 0 writes none (docs/output_files.md, \"Writing cost\")";
  return w;
}

std::string frames_interval_warning(const io::Case& c) {
  const long steps = c.numerics.total_steps();
  const int every = c.output.vtk_every;
  if (every <= 0 || every <= steps) return "";
  return "[output] vtk_every = " + std::to_string(every) + " is more than the run's " +
         std::to_string(steps) +
         " steps: the ParaView series holds step 0 alone (the wing at rest, without load or wake), and "
         "run.pvsm "
         "opens on it; a frame every " +
         std::to_string(steps) +
         " steps or fewer (flapsim run --vtk-every N), or 0 for none (docs/output_files.md)";
}

}  // namespace flapsim::app
