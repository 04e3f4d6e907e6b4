#pragma once
/// \file pvd_series.hpp
/// \brief A ParaView time-series collection (.pvd): a list of (time, data file).
/// The .pvd is rewritten atomically each time a step is added (or, with append, when
/// published), so it is valid and lists only files already written, even if the run
/// stops early.

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace flapsim::io {

class PvdSeries {
 public:
  struct Entry {
    double time;       ///< [s]
    int part;          ///< part index (several data sets at one time), usually 0
    std::string file;  ///< as stored: relative to the .pvd's directory, '/' separated
  };

  /// \brief Starts a series and writes an empty, valid collection to \p path.
  /// \param path  the .pvd file; its directory is created if missing
  /// \throws OutputError
  explicit PvdSeries(std::filesystem::path path);

  /// \brief Adds a data file (already written) and rewrites the .pvd atomically
  /// (append, then publish).
  /// \param time  [s]
  /// \param file  the data file as this process opened it (absolute, or relative to
  ///              the current directory, e.g. dir / "vtk/wing_000012.vtp");
  ///              stored relative to the .pvd's directory, as ParaView resolves it
  /// \param part  part index
  /// \throws OutputError
  void add(double time, const std::filesystem::path& file, int part = 0);

  /// \brief Adds a data file to the list without rewriting the .pvd: the file on disk
  /// keeps listing what was published, until publish(). For frames written with
  /// Flush::deferred: flush them (sync_file_system) before publish(). Arguments as add().
  void append(double time, const std::filesystem::path& file, int part = 0);

  /// \brief Rewrites the .pvd atomically with every entry, if any is not yet in it.
  /// \throws OutputError (the entries stay, to be published by a later call)
  void publish();

  /// Entries appended but not yet in the .pvd on disk.
  std::size_t unpublished() const { return entries_.size() - published_; }

  /// \brief File name of step \p step: "<stem>_<step, 6 digits>.<extension>",
  /// e.g. step_file_name("wing", 12, "vtp") == "wing_000012.vtp".
  static std::string step_file_name(std::string_view stem, long step, std::string_view extension);

  const std::filesystem::path& path() const { return path_; }
  const std::vector<Entry>& entries() const { return entries_; }
  std::size_t size() const { return entries_.size(); }

 private:
  void write() const;
  std::filesystem::path path_;
  std::vector<Entry> entries_;
  std::size_t published_ = 0;  ///< entries in the .pvd on disk
};

}  // namespace flapsim::io
