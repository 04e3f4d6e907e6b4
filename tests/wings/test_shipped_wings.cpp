// The shipped wings (wings/*.toml) load, and wings/README.md, where a user looks for them,
// lists each one with its span, area and mass as the loader computes them and names cases
// that really fly it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "wings/loader/planform_geometry.hpp"
#include "wings/loader/wing_file.hpp"
#include "wings/loader/wing_mass_properties.hpp"

namespace {

namespace fs = std::filesystem;
namespace w = flapsim::wings;
const fs::path kWings = fs::path(FLAPSIM_SOURCE_DIR) / "wings";

std::string file_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct ReadmeRow {
  double span_mm = 0.0, area_mm2 = 0.0, mass_mg = 0.0;
  std::string flown_by;
};

// The rows of the table "| wing file | what it is | span | area | mass | flown by |".
std::map<std::string, ReadmeRow> readme_rows() {
  static const std::regex row(
      R"(^\| `([a-z0-9_]+\.toml)` \|[^|]*\| ([0-9.]+) \| ([0-9.]+) \| ([0-9.]+) \|([^|]*)\|$)");
  std::map<std::string, ReadmeRow> rows;
  std::istringstream in(file_text(kWings / "README.md"));
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_match(line, m, row)) continue;
    EXPECT_FALSE(rows.count(m[1])) << m[1] << " listed twice in wings/README.md";
    rows[m[1]] = {std::stod(m[2]), std::stod(m[3]), std::stod(m[4]), m[5]};
  }
  return rows;
}

std::vector<std::string> shipped_wing_files() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(kWings))
    if (e.is_regular_file() && e.path().extension() == ".toml") names.push_back(e.path().filename().string());
  return names;
}

TEST(ShippedWings, EveryWingFileLoadsAndTheFoldersReadmeGivesItsSpanAreaAndMass) {
  const auto rows = readme_rows();
  const auto files = shipped_wing_files();
  ASSERT_GE(files.size(), 8u);  // hawkmoth (3), flat plate, robofly, MAV (2), film wing: as shipped
  for (const std::string& name : files) {
    SCOPED_TRACE(name);
    const w::Wing wing = w::load_wing_file((kWings / name).string());
    EXPECT_TRUE(wing.warnings.empty()) << "a shipped wing warns: " << wing.warnings.front().message;
    ASSERT_TRUE(rows.count(name)) << "wings/README.md does not list " << name;
    const ReadmeRow& r = rows.at(name);
    const w::PlanformProperties p = w::planform_properties(wing.outline);
    // The table rounds to one decimal: within half its last digit.
    EXPECT_NEAR(wing.span * 1e3, r.span_mm, 0.05);
    EXPECT_NEAR(p.area * 1e6, r.area_mm2, 0.05);
    EXPECT_NEAR(w::estimate_wing_mass(wing).total() * 1e6, r.mass_mg, 0.05);
  }
  for (const auto& [name, row] : rows)
    EXPECT_TRUE(fs::exists(kWings / name)) << "wings/README.md lists " << name;
}

TEST(ShippedWings, TheCasesTheReadmeNamesFlyTheirWing) {
  static const std::regex named_case(R"(cases/([a-z0-9_]+\.toml))");
  int checked = 0;
  for (const auto& [name, row] : readme_rows())
    for (std::sregex_iterator it(row.flown_by.begin(), row.flown_by.end(), named_case), end; it != end;
         ++it) {
      const fs::path c = kWings.parent_path() / "cases" / (*it)[1].str();
      ASSERT_TRUE(fs::exists(c)) << name << ": " << c;
      EXPECT_NE(file_text(c).find("\"../wings/" + name + "\""), std::string::npos)
          << c << " does not fly " << name;
      ++checked;
    }
  EXPECT_GE(checked, 10);  // the hawkmoth's six cases and the Robofly's, the MAV wings' and the film wing's
}

}  // namespace
