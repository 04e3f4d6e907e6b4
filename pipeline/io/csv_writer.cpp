#include "pipeline/io/csv_writer.hpp"

#include "pipeline/io/atomic_file.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <system_error>

namespace flapsim::io {

namespace fs = std::filesystem;

namespace {

/// Writes the shortest round-trip text of v to a stack buffer; returns its length.
std::size_t to_text(double v, char (&buf)[32]) {
  if (std::isnan(v)) {
    buf[0] = 'n', buf[1] = 'a', buf[2] = 'n';
    return 3;
  }
  const auto r = std::to_chars(buf, buf + sizeof(buf), v);
  return static_cast<std::size_t>(r.ptr - buf);  // "inf" / "-inf" for infinities
}

void write_row(std::ostream& out, std::span<const double> values) {
  char buf[32];
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) out.put(',');
    out.write(buf, static_cast<std::streamsize>(to_text(values[i], buf)));
  }
  out.put('\n');
}

std::string quoted(const std::string& cell) {
  if (cell.find_first_of(",\"\n\r") == std::string::npos) return cell;
  std::string q = "\"";
  for (char c : cell) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + '"';
}

void write_header(std::ostream& out, const std::vector<std::string>& header) {
  for (std::size_t i = 0; i < header.size(); ++i) out << (i ? "," : "") << quoted(header[i]);
  out << '\n';
}

}  // namespace

std::string format_number(double value) {
  char buf[32];
  return std::string(buf, to_text(value, buf));
}

CsvTimeSeriesWriter::CsvTimeSeriesWriter(fs::path path, std::vector<std::string> columns,
                                         int publish_every, std::chrono::steady_clock::duration max_interval)
    : path_(std::move(path)), columns_(std::move(columns)), publish_every_(publish_every),
      max_interval_(max_interval) {
  if (columns_.empty()) throw std::invalid_argument("CSV time series: no columns");
  if (publish_every_ < 1) throw std::invalid_argument("CSV time series: publish_every must be >= 1");
  if (max_interval_ < std::chrono::steady_clock::duration::zero())
    throw std::invalid_argument("CSV time series: max_interval must be >= 0");
  ensure_directory(path_.parent_path());
  working_ = temporary_path(path_);
  staging_ = working_;
  staging_ += ".pub";
  stream_.open(working_, std::ios::binary | std::ios::trunc);
  if (!stream_) throw OutputError(path_, "cannot open the working file " + working_.string());
  write_header(stream_, columns_);
  try {
    publish();  // the header alone is already a valid (empty) series
  } catch (...) {
    // A constructor that throws runs no destructor: remove the working file here.
    stream_.close();
    std::error_code ignored;
    fs::remove(working_, ignored);
    fs::remove(staging_, ignored);
    throw;
  }
}

CsvTimeSeriesWriter::~CsvTimeSeriesWriter() {
  // Reached without close() when a run is unwinding: keep every row appended.
  try {
    close();
  } catch (...) {
    std::error_code ignored;
    fs::remove(working_, ignored);
    fs::remove(staging_, ignored);
  }
}

void CsvTimeSeriesWriter::append(std::span<const double> values) {
  if (closed_) throw std::logic_error("CSV time series '" + path_.string() + "': append after close");
  if (values.size() != columns_.size())
    throw std::invalid_argument("CSV time series '" + path_.string() + "': row of " +
                                std::to_string(values.size()) + " values for " +
                                std::to_string(columns_.size()) + " columns");
  write_row(stream_, values);
  ++rows_;
  const std::size_t fresh = rows_ - published_;
  if (fresh < static_cast<std::size_t>(publish_every_)) return;
  if (max_interval_ > std::chrono::steady_clock::duration::zero() && fresh < published_ &&
      std::chrono::steady_clock::now() - last_publication_ < max_interval_)
    return;
  publish();
}

void CsvTimeSeriesWriter::publish() {
  if (closed_) return;
  stream_.flush();
  if (!stream_) throw OutputError(path_, "write failed (disk full?)");
  std::error_code ec;
  fs::copy_file(working_, staging_, fs::copy_options::overwrite_existing, ec);
  if (ec) {
    const std::string why = ec.message();  // before the removal below reuses ec (it said "Success")
    fs::remove(staging_, ec);
    throw OutputError(path_, "cannot copy the working file: " + why + " (disk full?)");
  }
  try {
    sync_file(staging_, path_);
  } catch (...) {
    fs::remove(staging_, ec);
    throw;
  }
  replace_file(staging_, path_);
  published_ = rows_;
  last_publication_ = std::chrono::steady_clock::now();
}

void CsvTimeSeriesWriter::close() {
  if (closed_) return;
  closed_ = true;
  stream_.flush();
  const bool ok = static_cast<bool>(stream_);
  stream_.close();
  if (!ok || stream_.fail()) {
    std::error_code ignored;
    fs::remove(working_, ignored);
    throw OutputError(path_, "write failed (disk full?); the file holds the rows up to the last publication");
  }
  try {
    sync_file(working_, path_);
  } catch (...) {
    std::error_code ignored;
    fs::remove(working_, ignored);
    throw;
  }
  replace_file(working_, path_);
  published_ = rows_;
}

void write_csv(const fs::path& path, const std::vector<std::string>& header,
               const std::vector<std::vector<double>>& rows) {
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (rows[r].size() != header.size())
      throw std::invalid_argument("write_csv '" + path.string() + "': row " + std::to_string(r) + " has " +
                                  std::to_string(rows[r].size()) + " values for " +
                                  std::to_string(header.size()) + " columns");
  write_file_atomically(path, [&](std::ostream& out) {
    write_header(out, header);
    for (const auto& row : rows) write_row(out, row);
  });
}

void write_csv(const fs::path& path, const std::vector<std::string>& header,
               const Eigen::Ref<const Eigen::MatrixXd>& table) {
  if (static_cast<std::size_t>(table.cols()) != header.size())
    throw std::invalid_argument("write_csv '" + path.string() + "': " + std::to_string(table.cols()) +
                                " matrix columns for " + std::to_string(header.size()) + " header names");
  write_file_atomically(path, [&](std::ostream& out) {
    write_header(out, header);
    std::vector<double> row(static_cast<std::size_t>(table.cols()));
    for (Eigen::Index r = 0; r < table.rows(); ++r) {
      for (Eigen::Index c = 0; c < table.cols(); ++c) row[static_cast<std::size_t>(c)] = table(r, c);
      write_row(out, row);
    }
  });
}

void write_csv(const fs::path& path, const std::vector<std::string>& header,
               const std::vector<std::vector<std::string>>& rows) {
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (rows[r].size() != header.size())
      throw std::invalid_argument("write_csv '" + path.string() + "': row " + std::to_string(r) + " has " +
                                  std::to_string(rows[r].size()) + " cells for " +
                                  std::to_string(header.size()) + " columns");
  write_file_atomically(path, [&](std::ostream& out) {
    write_header(out, header);
    for (const auto& row : rows) write_header(out, row);
  });
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::string cur;
  bool in_quotes = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (in_quotes) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cur += '"';
        ++i;
      } else if (c == '"') {
        in_quotes = false;
      } else {
        cur += c;
      }
    } else if (c == '"') {
      in_quotes = true;
    } else if (c == ',') {
      cells.push_back(std::move(cur));
      cur.clear();
    } else if (c != '\r') {
      cur += c;
    }
  }
  cells.push_back(std::move(cur));
  return cells;
}

}  // namespace flapsim::io
