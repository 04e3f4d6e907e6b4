#include "pipeline/app/run_results.hpp"

#include <cstdio>
#include <limits>

#include "pipeline/io/csv_writer.hpp"

namespace flapsim::app {

namespace {

const char* kind_name(ResultKind k) {
  switch (k) {
    case ResultKind::number: return "a number";
    case ResultKind::integer: return "an integer";
    case ResultKind::text: return "text";
    case ResultKind::flag: return "true/false";
  }
  return "?";
}

// The index of the result named `key` (run time: report templates).
std::size_t index_of(std::string_view key) {
  for (std::size_t i = 0; i < kRunResults.size(); ++i)
    if (kRunResults[i].key == key) return i;
  throw std::logic_error("the report names '" + std::string(key) + "', which is not in kRunResults");
}

}  // namespace

void RunResults::put(std::size_t index, ResultKind kind, Value value) {
  const ResultDefinition& d = kRunResults[index];
  if (d.kind != kind)
    throw std::logic_error("result '" + std::string(d.key) + "' is " + kind_name(d.kind) + ", set as " +
                           kind_name(kind));
  values_[index] = std::move(value);
}

void RunResults::set_value(std::size_t i, Value value) {
  static constexpr ResultKind kinds[] = {ResultKind::number, ResultKind::integer, ResultKind::text,
                                         ResultKind::flag};  // in the order of Value's alternatives
  put(i, kinds[value.index()], std::move(value));
}

void RunResults::set(Key key, double value) { put(key.index(), ResultKind::number, Value(value)); }
void RunResults::set(Key key, std::string value) {
  put(key.index(), ResultKind::text, Value(std::move(value)));
}
void RunResults::set(Key key, bool value) { put(key.index(), ResultKind::flag, Value(value)); }

double RunResults::number(Key key) const {
  const auto& v = values_[key.index()];
  return v ? std::get<double>(*v) : std::numeric_limits<double>::quiet_NaN();
}

std::int64_t RunResults::integer(Key key) const {
  const auto& v = values_[key.index()];
  return v ? std::get<std::int64_t>(*v) : 0;
}

std::string RunResults::text(Key key) const {
  const auto& v = values_[key.index()];
  return v ? std::get<std::string>(*v) : std::string();
}

io::SummaryJson summary_json(const RunResults& results) {
  io::SummaryJson json;
  for (std::size_t i = 0; i < kRunResults.size(); ++i) {
    const auto& v = results.at(i);
    if (!v) continue;
    std::visit([&](const auto& x) { json.set(kRunResults[i].key, x); }, *v);
  }
  return json;
}

std::string format_result(const RunResults& results, std::size_t index) {
  const auto& v = results.at(index);
  if (!v) return "-";
  const ResultDefinition& d = kRunResults[index];
  switch (d.kind) {
    case ResultKind::number: {
      char buf[64];
      std::snprintf(buf, sizeof buf, std::string(d.format).c_str(), std::get<double>(*v));
      return buf;
    }
    case ResultKind::integer: return std::to_string(std::get<std::int64_t>(*v));
    case ResultKind::text: return std::get<std::string>(*v);
    case ResultKind::flag: return std::get<bool>(*v) ? "true" : "false";
  }
  return "-";
}

std::string run_report(const RunResults& results) {
  std::string out;
  for (const ReportLine& line : kRunReport) {
    if (line.shown && !line.shown(results)) continue;
    const std::string_view t = line.text;
    for (std::size_t pos = 0; pos < t.size();) {
      const auto open = t.find('{', pos);
      if (open == std::string_view::npos) {
        out += t.substr(pos);
        break;
      }
      const auto close = t.find('}', open);
      if (close == std::string_view::npos) throw std::logic_error("unclosed '{' in a report line");
      out += t.substr(pos, open - pos);
      const std::size_t i = index_of(t.substr(open + 1, close - open - 1));
      out += format_result(results, i);
      if (!kRunResults[i].unit.empty()) out.append(" ").append(kRunResults[i].unit);
      pos = close + 1;
    }
    out += "\n";
  }
  return out;
}

std::vector<std::size_t> sweep_results() {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < kRunResults.size(); ++i)
    if (!kRunResults[i].sweep_label.empty()) out.push_back(i);
  return out;
}

std::vector<std::string> sweep_cells(const RunResults& results) {
  std::vector<std::string> cells;
  for (std::size_t i : sweep_results()) {
    const auto& v = results.at(i);
    if (!v) {
      cells.push_back("nan");
    } else if (const double* x = std::get_if<double>(&*v)) {
      cells.push_back(io::format_number(*x));
    } else {
      cells.push_back(format_result(results, i));
    }
  }
  return cells;
}

}  // namespace flapsim::app
