#pragma once
/// \file earlier_cases.hpp
/// \brief The completed cases an earlier sweep left in other sub-folders of the output
/// folder. A case's folder name starts with its index (`03_-0.05`), so a grid extended at
/// its start (`-0.3:0.1:0.1` after `-0.2:0.1:0.1`) or a reordered case table renames every
/// case: the earlier results sit in a folder of another name. They are found by their
/// inputs hash (summary.json status "ok") and moved to the case's folder (docs/sweeps.md,
/// "Resuming a sweep").

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "pipeline/app/run_results.hpp"

namespace flapsim::sweep {

class EarlierCases {
public:
  /// Reads the summary.json of every sub-folder of \p output_dir (once, when first asked)
  /// except \p own_folders, the folders of this sweep's own cases: those are never moved
  /// (two rows of a case table with the same values share a hash).
  EarlierCases(std::filesystem::path output_dir, std::set<std::string> own_folders)
      : dir_(std::move(output_dir)), own_(std::move(own_folders)) {}

  /// \brief The results of a completed earlier case with \p inputs_hash found in another
  /// sub-folder, after moving that folder to \p folder (a sub-folder name); std::nullopt when
  /// there is none, or \p folder exists already (nothing is replaced).
  /// \throws io::OutputError when the folder cannot be moved
  std::optional<app::RunResults> adopt(const std::string& inputs_hash, const std::string& folder);

private:
  void scan();
  std::filesystem::path dir_;
  std::set<std::string> own_;
  bool scanned_ = false;
  std::map<std::string, std::string> folder_of_hash_;  ///< inputs hash → sub-folder name
};

}  // namespace flapsim::sweep
