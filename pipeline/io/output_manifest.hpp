#pragma once
/// \file output_manifest.hpp
/// \brief One run per output folder. Each command that writes into a folder (mesh, modes,
/// reduce, run) records there, in DIR/flapsim_outputs.toml, which files it writes and
/// whether it completed. Before it writes anything, a command claims the folder:
///  - its own earlier outputs (listed in the manifest, or present under its names) are
///    removed, so a rerun replaces the previous outputs entirely: no stale `.vtp` of a
///    longer earlier run, no earlier summary.json next to an interrupted rerun;
///  - if another command's outputs would be replaced (run and reduce both write
///    summary.json), it refuses (io::OutputError, exit 4) unless forced (--force), which
///    removes that command's outputs too.
/// Commands that share no file name (mesh, modes and reduce of `make hawkmoth-model`)
/// live side by side in one folder. Format: docs/output_files.md, "The output folder".

#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace flapsim::io {

class FolderLock;

/// The manifest's file name in an output folder.
inline constexpr const char* kManifestName = "flapsim_outputs.toml";

/// The outputs of a command: file names relative to the folder; a name may hold one '*'
/// in its file part ("vtk/wing_*.vtp") for a series.
std::vector<std::string> command_outputs(const std::string& command);

/// \brief Removes \p command's outputs from \p dir (command_outputs, with temporaries of
/// them; a series' folder once empty): a folder with no manifest whose command runs again,
/// as a sweep's case folder. \throws OutputError if one cannot be removed
void remove_command_outputs(const std::filesystem::path& dir, const std::string& command);

/// \brief Claims \p dir for \p command (see the file comment).
/// \param command  "mesh", "modes", "reduce" or "run" ("optimize" has no claim:
///                 refuse_clashing_outputs)
/// \param force    replace another command's outputs that clash with this command's
/// \throws OutputError naming the folder and the clashing command if not forced, or if
///         the folder or the manifest cannot be written
void claim_output_folder(const std::filesystem::path& dir, const std::string& command, bool force);

/// \brief Refuses \p dir if it holds another command's outputs that \p command would replace
/// (as claim_output_folder without --force), for a command that keeps no manifest of its own
/// ("optimize", whose report.md reduce writes too); a folder not yet made holds none.
/// \throws OutputError naming the folder, the other command and the clashing files
void refuse_clashing_outputs(const std::filesystem::path& dir, const std::string& command,
                             bool offer_force = false);

/// \brief The checks of claim_output_folder that write nothing, made before a command's work
/// (mesh, modes, reduce: the wing's errors found while meshing come after them, and a claim
/// made before those removed the folder's earlier outputs, then exit 2): \p dir, if it
/// exists, is a writable folder no other command is writing into, holding no other
/// command's outputs that \p command would replace unless \p force; if it does not exist,
/// its nearest existing parent is a writable folder. Creates nothing (a probe file in an
/// existing folder is removed at once). The claim itself follows once the input is known good.
/// \throws OutputError naming the folder
void preflight_output_folder(const std::filesystem::path& dir, const std::string& command, bool force);

/// \brief Records in the manifest how \p command ended: "complete", "failed" or "interrupted".
/// \throws OutputError
void record_command_status(const std::filesystem::path& dir, const std::string& command,
                           const std::string& status);

/// \brief A command's claim on its folder, from claim() to finish(): a command that leaves
/// by an exception after claiming (an output error, a numerical failure, anything) records
/// "failed" as it goes, so the manifest never keeps "running" for a command that ended.
/// That last record is best effort (on a full disk the manifest may stay as it was).
/// The manifest is written under a lock: a signal watcher on another thread
/// (pipeline/app/stage_monitor.hpp) may end the claim with "interrupted" while the command
/// itself finishes it; the first end recorded is the one that stays.
class OutputFolderClaim {
 public:
  OutputFolderClaim(std::filesystem::path dir, std::string command);
  ~OutputFolderClaim();
  OutputFolderClaim(const OutputFolderClaim&) = delete;
  OutputFolderClaim& operator=(const OutputFolderClaim&) = delete;

  /// claim_output_folder(dir, command, force), holding the folder's lock (folder_lock.hpp)
  /// until the claim is destroyed.
  /// \throws OutputError also if another flapsim command is writing into the folder
  void claim(bool force);
  /// claim(force) if not claimed yet; nothing once claimed or ended (a command that claims
  /// at whichever of several points it reaches first).
  void claim_once(bool force);
  /// record_command_status with "complete", "failed" or "interrupted"; ends the claim.
  /// Does nothing if the claim was already ended (by end_if_open from another thread).
  void finish(const std::string& status);

  /// How the command stands, for a watcher on another thread.
  enum class State { unclaimed, open, ended };
  /// \brief Ends an open claim with \p status (as finish) and returns the state it found:
  /// open (recorded now), unclaimed (nothing written yet; nothing recorded) or ended
  /// (the command had finished; nothing changed).
  /// \throws OutputError if the manifest cannot be written
  State end_if_open(const std::string& status);

  const std::filesystem::path& dir() const { return dir_; }
  const std::string& command() const { return command_; }

 private:
  std::filesystem::path dir_;
  std::string command_;
  std::mutex mutex_;  // guards state_ and the manifest's writes
  State state_ = State::unclaimed;
  std::unique_ptr<FolderLock> lock_;  // held from claim() on
};

}  // namespace flapsim::io
