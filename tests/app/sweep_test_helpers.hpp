#pragma once
// Helpers of the sweep tests: a tiny deterministic case and sweep.csv read back.

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "pipeline/io/csv_writer.hpp"

namespace flapsim::test {

// The flat plate, rigid, eq. 8 kinematics, 3 x 4 panels, `steps` steps of one cycle:
// a few tenths of a second per case, the same numbers on every run (one OpenMP thread).
inline std::string tiny_plate_case(int steps = 24) {
  return "name = \"plate\"\nwing = \"" + std::string(FLAPSIM_SOURCE_DIR) +
         "/wings/flat_plate.toml\"\n"
         "[kinematics]\nfrequency_hz = 26.1\nrotation_phase = 0.0\n"
         "sweep = { mean_deg = 10.0, cos_deg = [50.0] }\n"
         "rotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
         "[structure]\nkind = \"rigid\"\n"
         "[numerics]\nsteps_per_cycle = " +
         std::to_string(steps) +
         "\ncycles = 1\n"
         "chordwise_panels = 3\nspanwise_panels = 4\ncore_radius = 0.2\n[output]\nvtk_every = 0\n";
}

// sweep.csv: the header and each row as column -> cell.
struct SweepTable {
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
  bool rectangular = true;  // every row has as many cells as the header
};


inline SweepTable read_sweep_table(const std::string& path) {
  SweepTable t;
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line)) return t;
  t.header = flapsim::io::split_csv_line(line);
  while (std::getline(in, line)) {
    const auto cells = flapsim::io::split_csv_line(line);
    if (cells.size() != t.header.size()) t.rectangular = false;
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < cells.size() && i < t.header.size(); ++i) row[t.header[i]] = cells[i];
    t.rows.push_back(std::move(row));
  }
  return t;
}

}  // namespace flapsim::test
