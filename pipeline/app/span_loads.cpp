#include "pipeline/app/span_loads.hpp"

#include <cmath>
#include <stdexcept>

#include "pipeline/io/csv_writer.hpp"

namespace flapsim::app {

void append_strip_lifts(const uvlm::VortexLatticeModel& m, const uvlm::PanelLoads& loads,
                        const Eigen::Vector3d& up, std::vector<double>& out) {
  for (int j = 0; j < m.spanwise; ++j) {
    double lift = 0.0;
    for (int i = 0; i < m.chordwise; ++i) lift += loads.force.col(m.panel(i, j)).dot(up);
    out.push_back(lift);
  }
}

std::vector<SpanStrip> span_strips(const uvlm::PlanformGrid& grid) {
  const int nc = grid.chordwise;
  const auto node = [&](int i, int j) { return grid.nodes.col(i + (nc + 1) * j); };
  const auto chord = [&](int j) { return (node(0, j) - node(nc, j)).norm(); };
  std::vector<SpanStrip> strips;
  for (int j = 0; j < grid.spanwise; ++j)
    strips.push_back({node(0, j).y(), node(0, j + 1).y(), 0.5 * (chord(j) + chord(j + 1))});
  return strips;
}

void write_span_loads(const std::filesystem::path& path, const std::vector<SpanStrip>& strips,
                      const std::vector<double>& mean_lift) {
  if (strips.size() != mean_lift.size())
    throw std::invalid_argument("write_span_loads: a mean lift for each strip is needed");
  double total = 0.0;
  for (double l : mean_lift) total += l;
  std::vector<std::vector<double>> rows;
  for (std::size_t j = 0; j < strips.size(); ++j) {
    const SpanStrip& s = strips[j];
    const double width = s.y_outer - s.y_inner;
    rows.push_back({static_cast<double>(j + 1), s.y_inner, s.y_outer, s.chord, mean_lift[j],
                    width > 0.0 ? mean_lift[j] / width : 0.0,
                    // Of the sum's size, so that a strip's share has its lift's sign also where
                    // the wing's net lift is down (the shares then add up to −1).
                    total != 0.0 ? mean_lift[j] / std::abs(total) : 0.0});
  }
  io::write_csv(
      path, {"strip", "y_inner_m", "y_outer_m", "chord_m", "mean_lift_N", "lift_per_span_N_m", "lift_share"},
      rows);
}

}  // namespace flapsim::app
