#include "pipeline/app/optimize/evaluation_table.hpp"

#include <algorithm>
#include <fstream>
#include <variant>

#include "pipeline/app/after_run_notes.hpp"
#include "pipeline/app/setup_warnings.hpp"
#include "pipeline/io/csv_writer.hpp"

namespace flapsim::optimize {

namespace {

// The results in the table: all but those a varied key of the same name gives
// (spring_scale), whose column the key's is.
std::vector<std::size_t> result_columns(const std::vector<std::string>& keys) {
  std::vector<std::size_t> columns;
  for (std::size_t i = 0; i < app::kRunResults.size(); ++i)
    if (std::find(keys.begin(), keys.end(), app::kRunResults[i].key) == keys.end()) columns.push_back(i);
  return columns;
}

std::vector<std::string> table_header(const std::vector<std::string>& keys) {
  std::vector<std::string> h{"evaluation"};
  h.insert(h.end(), keys.begin(), keys.end());
  for (std::size_t i : result_columns(keys)) h.emplace_back(app::kRunResults[i].key);
  for (const char* c : {"message", "rank", "host"}) h.emplace_back(c);
  return h;
}

std::size_t column_of(const std::vector<std::string>& header, std::string_view name) {
  return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
}

// One line per row: a line break inside a message becomes a space.
std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

std::string cell(const app::RunResults& r, std::size_t i) {
  const auto& v = r.at(i);
  if (!v) return "";
  if (const auto* d = std::get_if<double>(&*v)) return io::format_number(*d);
  if (const auto* n = std::get_if<std::int64_t>(&*v)) return std::to_string(*n);
  if (const auto* s = std::get_if<std::string>(&*v)) return one_line(*s);
  return std::get<bool>(*v) ? "true" : "false";
}

}  // namespace

EvaluationTable::EvaluationTable(std::filesystem::path path, std::vector<std::string> keys)
    : path_(std::move(path)), header_(table_header(keys)), results_(result_columns(keys)),
      hash_column_(column_of(header_, "inputs_hash")), status_column_(column_of(header_, "status")) {
  std::ifstream in(path_);
  std::string line;
  if (!in || !std::getline(in, line) || io::split_csv_line(line) != header_) return;
  while (std::getline(in, line)) {
    auto cells = io::split_csv_line(line);
    if (cells.size() != header_.size() || row_of_hash_.count(cells[hash_column_])) continue;
    row_of_hash_.emplace(cells[hash_column_], rows_.size());
    rows_.push_back(std::move(cells));
  }
}

std::string evaluation_notes(const Evaluation& e) {
  std::vector<std::string> notes;
  if (e.results.has("warnings")) notes.push_back(e.results.text("warnings"));
  for (std::string& note : app::after_run_notes(e.results)) notes.push_back(std::move(note));
  return app::join_notes(notes);
}

std::size_t EvaluationTable::record(const Evaluation& e) {
  const auto found = row_of_hash_.find(e.inputs_hash);
  // A point an earlier run evaluated keeps its row, unless that run did not complete it
  // (failed, interrupted) and this one did.
  if (found != row_of_hash_.end() && (rows_[found->second][status_column_] == "ok" || e.status != "ok")) {
    io::write_csv(path_, header_, rows_);  // the file as read (also when it was missing)
    return found->second + 1;
  }
  const std::size_t number = found != row_of_hash_.end() ? found->second + 1 : rows_.size() + 1;
  std::vector<std::string> row{std::to_string(number)};
  for (const sweep::Assignment& a : e.point) row.push_back(io::format_number(a.value));
  // A run that did not complete has no result: its numbers (from the summary.json it wrote
  // when it stopped: the means of a partial wingbeat) are nan, as in a sweep's sweep.csv;
  // whole numbers (steps: how far it got) and texts stay. Before, a failed evaluation's
  // partial mean lift sorted above the optimum.
  const bool completed = e.status == "ok";
  for (std::size_t i : results_) {
    const auto& v = e.results.at(i);
    row.push_back(!completed && v && std::holds_alternative<double>(*v) ? "nan" : cell(e.results, i));
  }
  // The evaluation's own hash and status (a point that could not run has no summary.json).
  row[hash_column_] = e.inputs_hash;
  row[status_column_] = e.status;
  row.push_back(one_line(e.message));
  row.push_back(std::to_string(e.rank));
  row.push_back(e.host);
  if (found != row_of_hash_.end()) {
    rows_[found->second] = std::move(row);
  } else {
    row_of_hash_.emplace(e.inputs_hash, rows_.size());
    rows_.push_back(std::move(row));
  }
  io::write_csv(path_, header_, rows_);
  return number;
}

}  // namespace flapsim::optimize
