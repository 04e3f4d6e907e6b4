#pragma once
/// \file case_table.hpp
/// \brief `flapsim sweep CASE.toml --cases TABLE.csv`: one case per row of a CSV table
/// whose header names the varied keys (the keys `--vary` accepts, sweep_values.hpp) and
/// whose cells are numbers. Blank lines and lines starting with '#' are skipped.
///
///     kinematics.rotation_phase,spring_scale,wing.membrane.thickness
///     -0.10,1,0.012
///     0.05,2,0.015

#include <string>
#include <vector>

#include "pipeline/app/sweep/sweep_values.hpp"

namespace flapsim::sweep {

struct CaseTable {
  std::vector<std::string> keys;  ///< the header, in order
  std::vector<CasePoint> points;  ///< one per data row, in file order
  int header_line = 0;            ///< line of the header in the file (1-based)
  std::vector<int> lines;         ///< line of each data row (1-based), as points
};

/// \brief Reads a case table.
/// \throws flapsim::InputError naming the file, the line and the column's key: missing
///         file, empty header, a key twice, a row with the wrong number of cells, a cell
///         that is not a finite number, no rows
CaseTable read_case_table(const std::string& path);

}  // namespace flapsim::sweep
