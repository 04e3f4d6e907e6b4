#pragma once
/// \file atomic_file.hpp
/// \brief Writing output files so that a reader never sees a half-written file:
/// the content goes to "<path>.tmp.<pid>" in the same directory and is then
/// renamed onto <path> (a rename within one file system replaces the target in
/// one step). On any error the temporary file is removed and <path> is left as it
/// was.

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

/// \brief The temporary name used for \p path by this process: "<path>.tmp.<pid>".
std::filesystem::path temporary_path(const std::filesystem::path& path);

/// \brief Renames \p from onto \p to (replacing it); removes \p from on failure.
/// \throws OutputError
void replace_file(const std::filesystem::path& from, const std::filesystem::path& to);

/// \brief Writes a file atomically through a stream.
/// \param path   final file name; its directory is created if missing
/// \param write  writes the whole content to the stream it is given; may throw
/// \throws OutputError on I/O failure; rethrows what \p write throws (no file left behind)
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

/// \brief Writes a file atomically through a writer that needs a file name (e.g. VTK).
/// \param path   final file name; its directory is created if missing
/// \param write  writes the complete file to the temporary name it is given; may throw
/// \throws OutputError if \p write leaves no file or renaming fails; rethrows what \p write throws
void publish_file_atomically(const std::filesystem::path& path,
                             const std::function<void(const std::filesystem::path& tmp)>& write);

/// \brief Writes \p text to \p path atomically.
void write_text_atomically(const std::filesystem::path& path, std::string_view text);

}  // namespace flapsim::io
