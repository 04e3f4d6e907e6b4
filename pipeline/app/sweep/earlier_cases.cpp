#include "pipeline/app/sweep/earlier_cases.hpp"

#include <system_error>

#include "pipeline/app/sweep/summary_reader.hpp"
#include "pipeline/io/atomic_file.hpp"

namespace flapsim::sweep {

namespace fs = std::filesystem;

void EarlierCases::scan() {
  scanned_ = true;
  std::error_code ec;
  for (fs::directory_iterator it(dir_, ec), end; !ec && it != end; it.increment(ec)) {
    if (!it->is_directory(ec) || own_.count(it->path().filename().string())) continue;
    const auto results = read_summary_results(it->path() / "summary.json");
    if (!results || results->text("status") != "ok") continue;
    folder_of_hash_.emplace(results->text("inputs_hash"), it->path().filename().string());
  }
}

std::optional<app::RunResults> EarlierCases::adopt(const std::string& inputs_hash, const std::string& folder) {
  if (!scanned_) scan();
  const auto found = folder_of_hash_.find(inputs_hash);
  if (found == folder_of_hash_.end() || found->second == folder) return std::nullopt;
  std::error_code ec;
  if (fs::exists(dir_ / folder, ec) || ec) return std::nullopt;
  const auto results = kept_results(dir_ / found->second / "summary.json", inputs_hash);
  if (!results) return std::nullopt;
  fs::rename(dir_ / found->second, dir_ / folder, ec);
  if (ec)
    throw io::OutputError(dir_ / found->second,
                          "the earlier case's folder cannot be moved to '" + folder + "': " + ec.message());
  folder_of_hash_.erase(found);
  return results;
}

}  // namespace flapsim::sweep
