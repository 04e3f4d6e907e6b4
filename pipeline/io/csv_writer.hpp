#pragma once
/// \file csv_writer.hpp
/// \brief CSV output: a streaming time-series writer whose published file stays a
/// valid CSV at every moment of a run that may die, and a one-shot table writer.
///
/// Column names carry their units ("t_s", "lift_N", "phi_rad"). Numbers are written
/// in the shortest form that reads back to the same double (std::to_chars).

#include <Eigen/Core>

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace flapsim::io {

/// \brief Shortest round-trip text of a number; "nan", "inf", "-inf" for non-finite values.
std::string format_number(double value);

/// \brief The cells of one CSV line as write_csv quotes them (RFC 4180: "a, b", and "" for
/// a quote inside); a trailing CR is dropped.
std::vector<std::string> split_csv_line(const std::string& line);

/// \brief A CSV time series (one row per step) for long runs.
///
/// Rows are appended to a working file "<path>.tmp.<pid>". Every \p publish_every
/// rows, and on close() or destruction, the rows so far are published: the working
/// file is flushed, copied to a second temporary name and renamed onto <path>. So
/// <path> always holds the header and a whole number of rows: if the process dies,
/// it holds every row up to the last publication; if an exception unwinds the
/// writer (a diverging run), the destructor publishes every row appended.
/// close() renames the working file onto <path> and leaves no temporary file.
class CsvTimeSeriesWriter {
 public:
  /// \param path           the published file; its directory is created if missing
  /// \param columns        column names with units, e.g. {"t_s", "lift_N"}
  /// \param publish_every  rows between publications (≥ 1)
  /// \param max_interval   0: publish every publish_every rows. Otherwise the rows between
  ///                       publications grow with the series — publish_every rows at
  ///                       first, then as many as are published (20, 40, 80, … rows) —
  ///                       but a publication is due at the latest max_interval (wall time)
  ///                       after the last one (once publish_every rows are new). Each
  ///                       publication copies the file and flushes it to disk (fsync, a
  ///                       few milliseconds on a busy disk), so a fast run publishes a
  ///                       few times instead of every few steps (docs/output_files.md).
  /// \throws OutputError if the files cannot be written; std::invalid_argument on
  ///         no columns, publish_every < 1 or max_interval < 0
  CsvTimeSeriesWriter(std::filesystem::path path, std::vector<std::string> columns,
                      int publish_every = 10,
                      std::chrono::steady_clock::duration max_interval = std::chrono::steady_clock::duration::zero());
  ~CsvTimeSeriesWriter();
  CsvTimeSeriesWriter(const CsvTimeSeriesWriter&) = delete;
  CsvTimeSeriesWriter& operator=(const CsvTimeSeriesWriter&) = delete;

  /// \brief Appends one row; publishes when publish_every rows have accumulated (with a
  /// max_interval: and as many as are published, or max_interval has passed).
  /// \param values  one value per column
  /// \throws std::invalid_argument on a wrong number of values; OutputError on I/O failure
  void append(std::span<const double> values);
  void append(std::initializer_list<double> values) {
    append(std::span<const double>(values.begin(), values.size()));
  }
  void append(const Eigen::Ref<const Eigen::VectorXd>& values) {
    append(std::span<const double>(values.data(), static_cast<std::size_t>(values.size())));
  }

  /// \brief Publishes the rows appended so far (flush, copy, rename).
  void publish();

  /// \brief Publishes all rows and removes the working file. Idempotent.
  void close();

  std::size_t rows() const { return rows_; }                ///< rows appended
  std::size_t published_rows() const { return published_; }  ///< rows in the published file
  const std::filesystem::path& path() const { return path_; }
  const std::vector<std::string>& columns() const { return columns_; }

 private:
  std::filesystem::path path_, working_, staging_;
  std::vector<std::string> columns_;
  int publish_every_;
  std::chrono::steady_clock::duration max_interval_;
  std::chrono::steady_clock::time_point last_publication_;
  std::ofstream stream_;
  std::size_t rows_ = 0, published_ = 0;
  bool closed_ = false;
};

/// \brief Writes a whole numeric table atomically.
/// \param header  column names with units
/// \param rows    each of header.size() values
/// \throws std::invalid_argument on a row of the wrong length; OutputError on I/O failure
void write_csv(const std::filesystem::path& path, const std::vector<std::string>& header,
               const std::vector<std::vector<double>>& rows);

/// \brief Same, from a matrix (one row per matrix row, header.size() columns).
void write_csv(const std::filesystem::path& path, const std::vector<std::string>& header,
               const Eigen::Ref<const Eigen::MatrixXd>& table);

/// \brief Writes a table of text cells atomically (for mixed columns such as a mode
/// "kind"); cells containing a comma, quote or newline are quoted as in RFC 4180.
/// Format numbers with format_number().
void write_csv(const std::filesystem::path& path, const std::vector<std::string>& header,
               const std::vector<std::vector<std::string>>& rows);

}  // namespace flapsim::io
