#pragma once
/// \file atomic_file.hpp
/// \brief Writing output files so that a reader never sees a half-written file:
/// the content goes to "<path>.tmp.<pid>" in the same directory, every write is
/// checked, the data is flushed to the disk (fsync) and the file is then renamed onto
/// <path> (a rename within one file system replaces the target in one step); the
/// directory is synchronised after the rename. On any error (a full disk, a file-size
/// limit, no permission) the temporary file is removed, <path> is left as it was and
/// OutputError is thrown: the command line exits with status 4.

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <string_view>

namespace flapsim::io {

/// An output file or directory could not be written (no permission, disk full,
/// a file where a directory should be). Names the path.
class OutputError : public std::runtime_error {
 public:
  OutputError(const std::filesystem::path& path, const std::string& message)
      : std::runtime_error("cannot write '" + path.string() + "': " + message), path_(path) {}
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// \brief Creates the directory (and missing parents) if it does not exist.
/// \param dir  directory path; an empty path means the current directory
/// \throws OutputError if it cannot be created or exists as a non-directory
void ensure_directory(const std::filesystem::path& dir);

/// \brief An output folder made ready before any work: created if missing, and a file
/// created and removed in it, so that an unwritable folder is reported as such (exit 4)
/// before a long computation, not blamed on an input.
/// \throws OutputError naming the folder
void prepare_output_directory(const std::filesystem::path& dir);

/// \brief The temporary name used for \p path by this process: "<path>.tmp.<pid>".
std::filesystem::path temporary_path(const std::filesystem::path& path);

/// \brief Removes the temporaries ("<name>.tmp.<pid>") of other processes in \p dir and its
/// sub-folders one level down ("vtk/"): what a killed run left. Call it only while holding the
/// folder's lock (folder_lock.hpp): no other flapsim command is writing there then.
/// \throws OutputError naming a temporary that cannot be removed
void remove_stale_temporaries(const std::filesystem::path& dir);

/// \brief Renames \p from onto \p to (replacing it); removes \p from on failure.
/// \param sync_directory  flush the folder's entries to disk after the rename
/// \throws OutputError
void replace_file(const std::filesystem::path& from, const std::filesystem::path& to, bool sync_directory = true);

/// When a file written by publish_file_atomically reaches the disk.
enum class Flush {
  now,       ///< flushed (fsync) before the rename, the folder after it
  deferred,  ///< renamed at once; the caller flushes the file system (sync_file_system)
             ///< before it publishes anything that names the file (a run's ParaView frames)
};

/// \brief Flushes every written file of the file system holding \p dir to the disk
/// (syncfs: one call for many files, e.g. the frames of a time series).
/// \throws OutputError naming \p dir if the flush fails (a write-back error)
void sync_file_system(const std::filesystem::path& dir);

/// \brief Writes a file atomically through a stream.
/// \param path   final file name; its directory is created if missing
/// \param write  writes the whole content to the stream it is given; may throw
/// \throws OutputError on I/O failure; rethrows what \p write throws (no file left behind)
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

/// \brief Writes a file atomically through a writer that needs a file name (e.g. VTK,
/// gmsh). Such writers may not report a failed write (a full disk, a file-size limit),
/// so the file is checked to end with \p required_tail, the closing text of its format
/// (e.g. "</VTKFile>\n"), before it is flushed to disk and renamed.
/// \param path           final file name; its directory is created if missing
/// \param write          writes the complete file to the temporary name it is given; may throw
/// \param required_tail  text the complete file ends with ("" = no check)
/// \param flush          Flush::now, or Flush::deferred (checked and renamed, not flushed)
/// \throws OutputError if \p write leaves no file or a truncated one, or flushing or
///         renaming fails; rethrows what \p write throws
void publish_file_atomically(const std::filesystem::path& path,
                             const std::function<void(const std::filesystem::path& tmp)>& write,
                             std::string_view required_tail = {}, Flush flush = Flush::now);

/// \brief Flushes a written file's data to the disk (fsync).
/// \param reported  the name errors report (the final name of a temporary file)
/// \throws OutputError if the file cannot be opened or synchronised
void sync_file(const std::filesystem::path& file, const std::filesystem::path& reported);

/// \brief Whether the file ends with \p tail (false if it cannot be read).
bool file_ends_with(const std::filesystem::path& file, std::string_view tail);

/// \brief Writes \p text to \p path atomically.
void write_text_atomically(const std::filesystem::path& path, std::string_view text);

}  // namespace flapsim::io
