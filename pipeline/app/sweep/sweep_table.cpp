#include "pipeline/app/sweep/sweep_table.hpp"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <fstream>
#include <stdexcept>

#include "pipeline/app/after_run_notes.hpp"
#include "pipeline/app/setup_warnings.hpp"
#include "pipeline/app/sweep/summary_reader.hpp"
#include "pipeline/io/csv_writer.hpp"

namespace flapsim::sweep {

namespace {
constexpr std::string_view kKept = "kept";
}  // namespace

std::string with_notes(std::string message, const std::vector<std::string>& notes) {
  const std::string joined = app::join_notes(notes);
  if (message.empty() || joined.empty()) return message + joined;
  return message + "; " + joined;
}

std::string kept_message(const app::RunResults& earlier) {
  std::vector<std::string> notes;
  if (earlier.has("warnings")) notes.push_back(earlier.text("warnings"));
  for (std::string& note : app::after_run_notes(earlier)) notes.push_back(std::move(note));
  return with_notes(std::string(kKept), notes);
}

std::map<std::string, RanOn> earlier_ran_on(const std::filesystem::path& path) {
  std::map<std::string, RanOn> out;
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line)) return out;
  const std::vector<std::string> header = io::split_csv_line(line);
  const auto column = [&](const char* name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t folder = column("folder"), rank = column("rank"), host = column("host");
  if (folder == header.size() || rank == header.size() || host == header.size()) return out;
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = io::split_csv_line(line);
    if (cells.size() != header.size()) continue;
    int r = 0;
    const std::string& text = cells[rank];
    if (std::from_chars(text.data(), text.data() + text.size(), r).ec != std::errc{}) continue;
    out[cells[folder]] = RanOn{r, cells[host]};
  }
  return out;
}

bool kept_from_earlier_run(const CaseOutcome& outcome) {
  const std::string& m = outcome.message;
  return m == kKept || m.rfind(std::string(kKept) + "; ", 0) == 0;
}

std::vector<std::string> sweep_table_header(const std::vector<std::string>& keys) {
  std::vector<std::string> header = keys;
  for (std::size_t i : app::sweep_results()) header.emplace_back(app::kRunResults[i].key);
  for (const app::SweepColumn& c : app::kSweepColumns) header.emplace_back(c.key);
  return header;
}

void write_sweep_table(const std::filesystem::path& path, const std::vector<std::string>& keys,
                       const std::vector<SweepRow>& rows) {
  std::vector<std::vector<std::string>> cells;
  for (const SweepRow& r : rows) {
    if (!r.done) continue;
    std::vector<std::string> row;
    for (const Assignment& a : r.point) row.push_back(a.word.empty() ? io::format_number(a.value) : a.word);
    for (std::string& cell : app::sweep_cells(r.outcome.results)) row.push_back(std::move(cell));
    // In the order of app::kSweepColumns.
    row.push_back(r.folder);
    row.push_back(r.outcome.status);
    row.push_back(r.outcome.message);
    row.push_back(std::to_string(r.outcome.rank));
    row.push_back(r.outcome.host);
    cells.push_back(std::move(row));
  }
  static_assert(app::kSweepColumns.size() == 5, "write_sweep_table writes five sweep-only columns");
  io::write_csv(path, sweep_table_header(keys), cells);
}

namespace {

void put(std::string& out, std::string_view field) {
  out += std::to_string(field.size());
  out += ':';
  out += field;
}

std::string_view take(const std::string& in, std::size_t& at) {
  const auto colon = in.find(':', at);
  std::size_t n = 0;
  if (colon == std::string::npos || std::from_chars(in.data() + at, in.data() + colon, n).ec != std::errc() ||
      colon + 1 + n > in.size())
    throw std::runtime_error("sweep: a case outcome from another rank is garbled");
  at = colon + 1 + n;
  return std::string_view(in).substr(colon + 1, n);
}

}  // namespace

std::string encode_outcome(std::size_t index, const CaseOutcome& o) {
  std::string out;
  put(out, std::to_string(index));
  put(out, o.status);
  put(out, o.message);
  put(out, std::to_string(o.rank));
  put(out, o.host);
  put(out, io::format_number(o.overhead_s));
  put(out, app::summary_json(o.results).to_string());
  return out;
}

CaseOutcome decode_outcome(const std::string& bytes, std::size_t& index) {
  std::size_t at = 0;
  CaseOutcome o;
  index = std::stoul(std::string(take(bytes, at)));
  o.status = take(bytes, at);
  o.message = take(bytes, at);
  o.rank = std::stoi(std::string(take(bytes, at)));
  o.host = take(bytes, at);
  o.overhead_s = std::stod(std::string(take(bytes, at)));
  auto results = parse_summary_json(take(bytes, at));
  if (!results) throw std::runtime_error("sweep: the results from another rank do not read");
  o.results = std::move(*results);
  return o;
}

std::string host_name() {
  char buf[256] = {};
  if (gethostname(buf, sizeof buf - 1) != 0 || buf[0] == '\0') return "unknown";
  return buf;
}

}  // namespace flapsim::sweep
