// One definition of a run's results (pipeline/app/run_results.hpp): summary.json's keys,
// the report `flapsim run` prints and the columns of sweep.csv and of the sweep table
// are all made from it, and every result and history column is documented.

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/fsi_run.hpp"
#include "pipeline/app/run_history.hpp"
#include "pipeline/app/run_results.hpp"
#include "pipeline/io/case_file.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;
using app::kRunResults;
using test::read_text;
using test::run_flapsim;

// The flat plate with eq. 8 kinematics, 3 x 4 panels, one cycle of 24 steps.
std::string plate_case(double rotation_phase) {
  return "name = \"plate\"\nwing = \"" + std::string(FLAPSIM_SOURCE_DIR) + "/wings/flat_plate.toml\"\n"
         "[kinematics]\nfrequency_hz = 26.1\nrotation_phase = " + std::to_string(rotation_phase) + "\n"
         "sweep = { mean_deg = 10.0, cos_deg = [50.0] }\n"
         "rotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
         "[structure]\nkind = \"rigid\"\n"
         "[numerics]\nsteps_per_cycle = 24\ncycles = 1\nchordwise_panels = 3\nspanwise_panels = 4\n"
         "core_radius = 0.2\n[output]\nvtk_every = 0\n";
}

// The keys of summary.json in file order, with their value text.
std::vector<std::pair<std::string, std::string>> json_items(const std::string& text) {
  static const std::regex item(R"re(^\s*"([^"]+)": (.*?),?$)re");
  std::vector<std::pair<std::string, std::string>> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_match(line, m, item)) out.emplace_back(m[1], m[2]);
  }
  return out;
}

std::vector<std::string> csv_split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  for (std::string c; std::getline(s, c, ',');) cells.push_back(c);
  return cells;
}

std::size_t index_of(const std::string& key) {
  for (std::size_t i = 0; i < kRunResults.size(); ++i)
    if (kRunResults[i].key == key) return i;
  return kRunResults.size();
}

TEST(RunResults, DefinitionsAreWellFormed) {
  std::set<std::string_view> keys;
  for (const app::ResultDefinition& d : kRunResults) {
    EXPECT_TRUE(keys.insert(d.key).second) << "key defined twice: " << d.key;
    EXPECT_FALSE(d.description.empty()) << d.key;
    // The unit is also the key's suffix, as in every column name ("m/s" -> "_m_s").
    if (!d.unit.empty()) {
      std::string suffix = "_";
      for (char ch : d.unit)
        if (ch == '/') suffix += '_';
        else if (ch != '^') suffix += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      std::string key(d.key);
      for (char& ch : key) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      EXPECT_TRUE(key.size() > suffix.size() && key.compare(key.size() - suffix.size(), suffix.size(), suffix) == 0)
          << d.key << " does not end with its unit " << d.unit;
    }
    if (d.kind == app::ResultKind::number) {
      EXPECT_FALSE(d.format.empty()) << d.key;
    }
    if (!d.sweep_label.empty()) {
      EXPECT_EQ(d.kind, app::ResultKind::number) << d.key;
    }
  }
  // Every placeholder of the report names a result.
  for (const app::ReportLine& line : app::kRunReport) {
    const std::string t(line.text);
    for (std::size_t open = t.find('{'); open != std::string::npos; open = t.find('{', open + 1)) {
      const std::string key = t.substr(open + 1, t.find('}', open) - open - 1);
      EXPECT_LT(index_of(key), kRunResults.size()) << "report names an undefined result: " << key;
    }
  }
}

TEST(RunResults, AValueOfTheWrongKindIsRefused) {
  app::RunResults r;
  EXPECT_THROW(r.set("mean_lift_N", "text"), std::logic_error);
  EXPECT_THROW(r.set("steps", 1.5), std::logic_error);
  EXPECT_THROW(r.set("air", 1), std::logic_error);
  r.set("mean_lift_N", 0.25);
  r.set("steps", 12);
  EXPECT_EQ(r.number("mean_lift_N"), 0.25);
  EXPECT_EQ(r.integer("steps"), 12);
  EXPECT_TRUE(std::isnan(r.number("mean_CL")));  // not set
  // Only what was set goes into summary.json, in the order of the definition.
  EXPECT_EQ(app::summary_json(r).to_string(), "{\n  \"steps\": 12,\n  \"mean_lift_N\": 0.25\n}\n");
}

TEST(RunResults, SummaryReportAndSweepComeFromTheOneDefinition) {
  const test::ScratchDir dir("run_results");
  std::ofstream(dir / "case.toml") << plate_case(-0.1);

  // 1. In process: the results of the run, and its summary.json.
  app::RunOptions options;
  options.output_dir = dir / "in_process";
  options.progress = app::ProgressLine::Mode::quiet;
  const app::RunResults results = app::run_case(io::load_case_file((dir / "case.toml").string()), options);
  const auto items = json_items(read_text(dir / "in_process" / "summary.json"));
  std::vector<std::string> expected_keys;
  for (std::size_t i = 0; i < kRunResults.size(); ++i)
    if (results.at(i)) expected_keys.emplace_back(kRunResults[i].key);
  std::vector<std::string> keys;
  for (const auto& [key, value] : items) keys.push_back(key);
  EXPECT_EQ(keys, expected_keys);  // summary.json = the set results, in the defined order
  for (const auto& [key, value] : items) {
    const std::size_t i = index_of(key);
    ASSERT_LT(i, kRunResults.size()) << "summary.json key not in the definition: " << key;
    if (kRunResults[i].kind == app::ResultKind::number && value != "null") {
      EXPECT_EQ(std::strtod(value.c_str(), nullptr), std::get<double>(*results.at(i))) << key;
    }
  }
  EXPECT_EQ(results.text("status"), "ok");
  EXPECT_NEAR(results.number("base_rotation_phase"), -0.1, 1e-3);  // the case's δψ, measured

  // 2. `flapsim run` prints the report of the definition: the same lines (the run is
  //    deterministic and the report holds no wall time), then where the outputs are.
  ASSERT_EQ(run_flapsim("run " + (dir / "case.toml").string() + " -o " + (dir / "cli").string(),
                        dir / "run.txt"),
            0);
  EXPECT_EQ(read_text(dir / "run.txt"),
            app::run_report(results) + "outputs in " + (dir / "cli").string() +
                " (history.csv, summary.json, span_loads.csv)\n");  // vtk_every = 0: no series
  EXPECT_NE(app::run_report(results).find("mean lift (last cycle) "), std::string::npos);

  // 3. `flapsim sweep`: sweep.csv = the varied key, the results with a sweep label, then
  //    the sweep-only columns (folder, status, message, rank, host); each result cell is
  //    the number of that case's summary.json.
  ASSERT_EQ(run_flapsim("sweep " + (dir / "case.toml").string() +
                            " --vary kinematics.rotation_phase=-0.1,0.05 -j 1 -o " + (dir / "sweep").string(),
                        dir / "sweep.txt"),
            0);
  std::ifstream table(dir / "sweep" / "sweep.csv");
  std::string line;
  std::getline(table, line);
  std::vector<std::string> header{"kinematics.rotation_phase"};
  std::vector<std::string> labels;
  for (std::size_t i : app::sweep_results()) {
    header.emplace_back(kRunResults[i].key);
    labels.emplace_back(kRunResults[i].sweep_label);
  }
  for (const app::SweepColumn& c : app::kSweepColumns) header.emplace_back(c.key);
  EXPECT_EQ(csv_split(line), header);
  const std::size_t folder = 1 + labels.size();
  ASSERT_EQ(header[folder], "folder");
  int rows = 0;
  while (std::getline(table, line)) {
    const auto cells = csv_split(line);
    ASSERT_EQ(cells.size(), header.size()) << line;
    std::map<std::string, std::string> summary;
    for (const auto& [k, v] : json_items(read_text(dir / "sweep" / cells[folder] / "summary.json")))
      summary[k] = v;
    for (std::size_t c = 1; c < folder; ++c) {
      if (!summary.contains(header[c])) {  // not set for this run (the settled_ results of a short run)
        EXPECT_EQ(cells[c], "nan") << header[c] << " of " << cells.front();
        continue;
      }
      EXPECT_EQ(std::strtod(cells[c].c_str(), nullptr), std::strtod(summary.at(header[c]).c_str(), nullptr))
          << header[c] << " of " << cells.front();
    }
    ++rows;
  }
  EXPECT_EQ(rows, 2);
  // The table on stdout has the same columns, titled by their labels.
  const std::string printed = read_text(dir / "sweep.txt");
  std::size_t at = 0;
  for (const std::string& label : labels) {
    at = printed.find(label, at);
    EXPECT_NE(at, std::string::npos) << label << " not in the printed table:\n" << printed;
  }
}

TEST(RunResults, EveryResultAndHistoryColumnIsDocumented) {
  // docs/fsi.md lists summary.json and history.csv: a new result or column needs its line.
  const std::string doc = read_text(fs::path(FLAPSIM_SOURCE_DIR) / "docs" / "fsi.md");
  for (const app::ResultDefinition& d : kRunResults)
    EXPECT_NE(doc.find("| `" + std::string(d.key) + "` |"), std::string::npos)
        << "docs/fsi.md has no row for summary.json's " << d.key;
  for (const app::HistoryColumn& c : app::history_columns())
    EXPECT_NE(doc.find("| `" + std::string(c.name) + "` |"), std::string::npos)
        << "docs/fsi.md has no row for history.csv's " << c.name;
}

TEST(RunResults, EveryDocumentedHistoryColumnExists) {
  // The reverse: each row of docs/fsi.md's history.csv table names a column the run writes
  // (the per-joint and per-marker rows by their patterns), and the column names that
  // docs/output_files.md gives as examples are columns (it named phi_rad and tip_z_m, which
  // no file has).
  std::set<std::string> columns;
  for (const app::HistoryColumn& c : app::history_columns()) columns.emplace(c.name);
  const std::string doc = read_text(fs::path(FLAPSIM_SOURCE_DIR) / "docs" / "fsi.md");
  const std::size_t table = doc.find("| column | content |");
  ASSERT_NE(table, std::string::npos);
  std::istringstream rows(doc.substr(table));
  std::string line;
  std::getline(rows, line);  // header
  std::getline(rows, line);  // |---|---|
  int documented = 0;
  while (std::getline(rows, line) && line.rfind("| `", 0) == 0) {
    const std::string name = line.substr(3, line.find('`', 3) - 3);
    if (name.find('<') != std::string::npos) continue;  // bend_<k>_rad, <marker>_x_m
    EXPECT_EQ(columns.count(name), 1u) << "docs/fsi.md documents a history.csv column '" << name << "' the run does not write";
    ++documented;
  }
  EXPECT_EQ(documented, static_cast<int>(columns.size()));
  const std::string files = read_text(fs::path(FLAPSIM_SOURCE_DIR) / "docs" / "output_files.md");
  const std::size_t units = files.find("CSV column names carry their unit");
  ASSERT_NE(units, std::string::npos);
  const std::string sentence = files.substr(units, files.find(')', units) - units);
  for (std::size_t at = sentence.find('`'); at != std::string::npos; at = sentence.find('`', sentence.find('`', at + 1) + 1)) {
    const std::string name = sentence.substr(at + 1, sentence.find('`', at + 1) - at - 1);
    if (name.find('<') != std::string::npos) continue;
    EXPECT_EQ(columns.count(name), 1u) << "docs/output_files.md names a history.csv column '" << name << "' that does not exist";
  }
}

// The last line names the files the run wrote. Before: "(history.csv, summary.json, wing.pvd,
// wake.pvd, chain.pvd, run.pvsm)" also for a run with vtk_every = 0, which writes the first two.
TEST(RunResults, TheLastLineNamesOnlyTheFilesWritten) {
  flapsim::test::ScratchDir dir("run_outputs_line");
  std::ofstream(dir / "case.toml") << "name = \"plate\"\nwing = \"" << FLAPSIM_SOURCE_DIR
                                   << "/wings/flat_plate.toml\"\n[kinematics]\nfrequency_hz = 26.1\n"
                                      "sweep = { cos_deg = [50.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
                                      "[structure]\nkind = \"rigid\"\n[numerics]\nsteps_per_cycle = 12\ncycles = 1\n"
                                      "chordwise_panels = 2\nspanwise_panels = 3\n[output]\nvtk_every = 0\n";
  ASSERT_EQ(flapsim::test::run_flapsim("run " + (dir / "case.toml").string() + " -o " + (dir / "out").string(),
                                       dir / "run.txt"),
            0);
  const std::string text = flapsim::test::read_text(dir / "run.txt");
  EXPECT_NE(
      text.find("outputs in " + (dir / "out").string() + " (history.csv, summary.json, span_loads.csv)\n"),
      std::string::npos)
      << text;
  EXPECT_FALSE(fs::exists(dir / "out" / "wing.pvd"));
}

// A run in vacuum has no lift and no coefficient. Before: cases/three_body.toml (air = "none")
// reported "mean lift (last cycle) 0 N, mean CL 0.0000", as if the wing had made none, and
// summary.json kept "mean_CL": 0 (a coefficient without a reference speed) after the report
// had lost it.
TEST(RunResults, AVacuumRunReportsNoLiftCoefficient) {
  flapsim::test::ScratchDir dir("run_vacuum_report");
  ASSERT_EQ(flapsim::test::run_flapsim("run " + std::string(FLAPSIM_SOURCE_DIR) + "/cases/three_body.toml -o " +
                                           (dir / "out").string(),
                                       dir / "run.txt"),
            0);
  const std::string text = flapsim::test::read_text(dir / "run.txt");
  EXPECT_NE(text.find("in vacuum (air = \"none\"): no aerodynamic loads, no lift\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("mean CL"), std::string::npos) << text;
  const std::string summary = flapsim::test::read_text(dir / "out" / "summary.json");
  EXPECT_EQ(summary.find("\"mean_CL\""), std::string::npos) << summary;
  EXPECT_EQ(summary.find("\"mean_CD\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"mean_lift_N\": 0"), std::string::npos) << summary;  // no air, no force
}

// A wing held still in a free stream does no work on the air (power −Σ F·v over panels that do
// not move: 0 exactly), so it has no lift per power. Before: the report read "lift/power nan
// N/W" (a gliding hawkmoth wing at 40 deg in 3 m/s).
TEST(RunResults, AWingHeldInAFreeStreamReportsNoLiftPerPower) {
  flapsim::test::ScratchDir dir("run_held_wing_report");
  std::ofstream(dir / "case.toml")
      << "name = \"held\"\nwing = \"" << FLAPSIM_SOURCE_DIR
      << "/wings/flat_plate.toml\"\n[kinematics]\nfrequency_hz = 26.1\n"
         "sweep = 0.0\nrotation = 10.0\n[air]\nfreestream = [-3.0, 0.0, 0.0]\n"
         "[structure]\nkind = \"rigid\"\n[numerics]\nsteps_per_cycle = 12\ncycles = 1\n"
         "chordwise_panels = 2\nspanwise_panels = 3\n[output]\nvtk_every = 0\n";
  ASSERT_EQ(flapsim::test::run_flapsim(
                "run " + (dir / "case.toml").string() + " -o " + (dir / "out").string(), dir / "run.txt"),
            0);
  const std::string text = flapsim::test::read_text(dir / "run.txt");
  EXPECT_NE(text.find("aerodynamic power 0 W (a wing that does no work on the air: no lift/power)"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("nan"), std::string::npos) << text;
  const std::string summary = flapsim::test::read_text(dir / "out" / "summary.json");
  EXPECT_NE(summary.find("\"lift_per_power_N_W\": null"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"mean_power_W\": 0,"), std::string::npos) << summary;
}

}  // namespace
