#include "pipeline/io/output_manifest.hpp"

#include "pipeline/io/folder_lock.hpp"

#include <toml++/toml.h>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <system_error>

#include "pipeline/io/atomic_file.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/toml_preflight.hpp"

namespace flapsim::io {

namespace fs = std::filesystem;

namespace {

struct Entry {
  std::string status;
  std::vector<std::string> outputs;
};
using Manifest = std::map<std::string, Entry>;

/// True for a name one of the commands writes. A manifest is a file in the output folder
/// that anyone may edit: the names it lists are removed on a rerun, so only these are
/// taken (never "../x", "/x" or "*").
bool is_known_output(const std::string& name) {
  for (const char* command : {"mesh", "modes", "reduce", "run"})
    for (const auto& o : command_outputs(command))
      if (o == name) return true;
  return false;
}

Manifest read_manifest(const fs::path& dir) {
  Manifest m;
  const fs::path file = dir / kManifestName;
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return m;
  toml::table t;
  const auto unreadable = [&](const std::string& why) {
    return OutputError(file, "the folder's manifest is not readable (" + why + "); remove it or choose another folder");
  };
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw unreadable("cannot read the file");
  try {
    wings::refuse_toml_the_parser_cannot_read_safely(text.str(), file.string());
    t = toml::parse(text.str(), file.string());
  } catch (const InputError& e) {
    throw unreadable(e.message());
  } catch (const toml::parse_error& e) {
    throw unreadable(std::string(e.description()));
  }
  for (auto&& [command, node] : t) {
    const toml::table* entry = node.as_table();
    if (!entry) continue;
    Entry e;
    e.status = entry->get("status") ? entry->get("status")->value_or(std::string()) : std::string();
    if (const toml::array* outputs = entry->get_as<toml::array>("outputs"))
      for (const auto& o : *outputs)
        if (o.is_string() && is_known_output(*o.value<std::string>())) e.outputs.push_back(*o.value<std::string>());
    m[std::string(command.str())] = std::move(e);
  }
  return m;
}

void write_manifest(const fs::path& dir, const Manifest& m) {
  toml::table t;
  for (const auto& [command, e] : m) {
    toml::array outputs;
    for (const auto& o : e.outputs) outputs.push_back(o);
    t.insert(command, toml::table{{"status", e.status}, {"outputs", outputs}});
  }
  std::ostringstream text;
  text << "# Written by flapsim: which command wrote which files in this folder (docs/output_files.md).\n"
       << t << "\n";
  write_text_atomically(dir / kManifestName, text.str());
}

/// The files under \p dir a pattern names ("history.csv", "vtk/wing_*.vtp"), with
/// temporaries of the same names left by a killed process.
std::vector<fs::path> matching_files(const fs::path& dir, const std::string& pattern) {
  std::vector<fs::path> out;
  const fs::path p(pattern);
  const fs::path folder = dir / p.parent_path();
  const std::string name = p.filename().string();
  const auto star = name.find('*');
  const std::string prefix = name.substr(0, star), suffix = star == std::string::npos ? "" : name.substr(star + 1);
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return out;
  for (const auto& f : fs::directory_iterator(folder, ec)) {
    const std::string n = f.path().filename().string();
    const bool exact = star == std::string::npos && (n == name || n.rfind(name + ".tmp.", 0) == 0);
    const bool series = star != std::string::npos && n.size() >= prefix.size() + suffix.size() &&
                        n.rfind(prefix, 0) == 0 &&
                        (n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0 ||
                         n.find(suffix + ".tmp.") != std::string::npos);
    if ((exact || series) && f.is_regular_file(ec)) out.push_back(f.path());
  }
  return out;
}

void remove_outputs(const fs::path& dir, const std::vector<std::string>& patterns) {
  for (const auto& pattern : patterns) {
    for (const auto& f : matching_files(dir, pattern)) {
      std::error_code ec;
      fs::remove(f, ec);
      if (ec) throw OutputError(f, "cannot remove the earlier output: " + ec.message());
    }
    // A series' folder ("vtk/") goes too once empty; never the output folder itself (for
    // "history.csv" dir / "" is "dir/", which compared unequal to "dir": an empty output
    // folder was removed and made again, losing its permissions and the folder's lock).
    const fs::path sub = fs::path(pattern).parent_path();
    if (sub.empty()) continue;
    const fs::path folder = dir / sub;
    std::error_code ec;
    if (fs::is_directory(folder, ec) && fs::is_empty(folder, ec)) fs::remove(folder, ec);
  }
}

bool any_present(const fs::path& dir, const std::vector<std::string>& patterns) {
  for (const auto& p : patterns)
    if (!matching_files(dir, p).empty()) return true;
  return false;
}

std::vector<std::string> shared(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  std::vector<std::string> out;
  for (const auto& x : a)
    for (const auto& y : b)
      if (x == y) out.push_back(x);
  return out;
}

}  // namespace

void remove_command_outputs(const fs::path& dir, const std::string& command) {
  remove_outputs(dir, command_outputs(command));
}

std::vector<std::string> command_outputs(const std::string& command) {
  if (command == "mesh") return {"mesh.msh", "mesh.vtu"};
  if (command == "modes") return {"modes.csv", "fem.vtu", "fem_modes.pvsm"};
  if (command == "reduce")
    return {"beam.csv", "chain.toml", "reduction.vtm", "reduction/*.vtp", "report.md", "summary.json"};
  // optimize keeps no manifest (a rerun resumes from its evaluations.csv); named here so
  // that reduce, which also writes report.md, does not replace its report unasked.
  if (command == "optimize") return {"evaluations.csv", "optimum.toml", "optimum_wing.toml", "report.md"};
  if (command == "run")
    return {"history.csv", "summary.json", "span_loads.csv", "wing.pvd", "wake.pvd", "chain.pvd", "fem.pvd",
            "run.pvsm", "tip_path.vtp", "marker_*_path.vtp", "vtk/wing_*.vtp", "vtk/wake_*.vtp",
            "vtk/chain_*.vtp", "vtk/fem_*.vtp",
            // The pictures make draws from the run's frames (preview, snapshot, movie): a
            // rerun left the earlier run's beside its own, or beside none (vtk_every = 0).
            "preview.png", "snapshots/phase_*.png", "snapshots/front_phase_*.png",
            "snapshots/side_phase_*.png", "movie.mp4"};
  return {};
}

namespace {

// The commands whose outputs one folder may hold side by side, as long as no file name clashes.
constexpr const char* kFolderCommands[] = {"mesh", "modes", "reduce", "optimize", "run"};

// Another command's outputs present in \p dir that \p command would replace (its name and the
// clashing file names), or none.
std::optional<std::pair<std::string, std::vector<std::string>>> clashing_outputs(const fs::path& dir,
                                                                                 const Manifest& m,
                                                                                 const std::string& command) {
  const std::vector<std::string> mine = command_outputs(command);
  for (const std::string other : kFolderCommands) {
    if (other == command) continue;
    const auto clash = shared(mine, command_outputs(other));
    if (clash.empty()) continue;
    // Known from the manifest; without one, judged by the other command's own files
    // (e.g. reduce's chain.toml next to a summary.json).
    const bool present = m.count(other) ? any_present(dir, clash)
                                        : any_present(dir, clash) && [&] {
                                            std::vector<std::string> own;
                                            for (const auto& o : command_outputs(other))
                                              if (shared({o}, mine).empty()) own.push_back(o);
                                            return any_present(dir, own);
                                          }();
    if (present) return std::make_pair(other, clash);
  }
  return std::nullopt;
}

std::string clash_message(const std::string& other, const std::vector<std::string>& clash,
                          const std::string& command) {
  std::string names;
  for (const auto& c : clash) names += (names.empty() ? "" : ", ") + c;
  return "the folder holds the outputs of 'flapsim " + other + "' (" + names + "), which 'flapsim " +
         command + "' would replace; choose another folder (-o)";
}

}  // namespace

void refuse_clashing_outputs(const fs::path& dir, const std::string& command, bool offer_force) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return;
  if (const auto c = clashing_outputs(dir, read_manifest(dir), command))
    throw OutputError(dir, clash_message(c->first, c->second, command) +
                               (offer_force ? " or add --force to replace them" : ""));
}

void preflight_output_folder(const fs::path& dir, const std::string& command, bool force) {
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir, ec)) throw OutputError(dir, "exists and is not a directory");
    prepare_output_directory(dir);            // writable: a probe file, removed at once
    { const FolderLock busy(dir, command); }  // no other command writing into it now
    if (!force) refuse_clashing_outputs(dir, command, true);
    return;
  }
  // A folder to be made: its nearest existing parent must take it.
  fs::path parent = fs::absolute(dir, ec).parent_path();
  while (!parent.empty() && !fs::exists(parent, ec) && parent != parent.parent_path())
    parent = parent.parent_path();
  if (!fs::is_directory(parent, ec))
    throw OutputError(dir, "cannot create directory: '" + parent.string() + "' is not a directory");
  if (::access(parent.c_str(), W_OK | X_OK) != 0)
    throw OutputError(
        dir, "cannot create directory: '" + parent.string() + "' is not writable: " + std::strerror(errno));
}

void claim_output_folder(const fs::path& dir, const std::string& command, bool force) {
  prepare_output_directory(dir);
  Manifest m = read_manifest(dir);
  const std::vector<std::string> mine = command_outputs(command);
  // Another command's outputs that this command would replace.
  while (const auto c = clashing_outputs(dir, m, command)) {
    if (!force)
      throw OutputError(dir, clash_message(c->first, c->second, command) + " or add --force to replace them");
    remove_outputs(dir, command_outputs(c->first));
    m.erase(c->first);
  }
  // This command's earlier outputs: all of them go, so the folder holds one run's files.
  std::vector<std::string> earlier = mine;
  if (m.count(command))
    for (const auto& o : m[command].outputs) earlier.push_back(o);
  remove_outputs(dir, earlier);
  m[command] = Entry{"running", mine};
  write_manifest(dir, m);
}

void record_command_status(const fs::path& dir, const std::string& command, const std::string& status) {
  Manifest m = read_manifest(dir);
  m[command].status = status;
  if (m[command].outputs.empty()) m[command].outputs = command_outputs(command);
  write_manifest(dir, m);
}

namespace {

// Room kept on the disk for the manifest's last record: a command that ends by a full disk
// must still be able to say so (before: the manifest kept "running" after an exit 4).
constexpr off_t kReserveBytes = 64 * 1024;

fs::path reserve_path(const fs::path& dir) { return temporary_path(dir / ".flapsim_outputs_reserve"); }

// The reserve, made before anything else is written: a disk without room for it is
// refused (the command would fill it and could not record how it ended). Other failures (a
// file system without fallocate) leave no reserve: the last record is then best effort.
void make_reserve(const fs::path& dir) {
  const fs::path p = reserve_path(dir);
  // A reserve of a killed command (SIGKILL leaves its own): under the folder's lock every
  // other one is stale.
  std::error_code listing;
  for (const auto& f : fs::directory_iterator(dir, listing)) {
    const std::string name = f.path().filename().string();
    if (name.rfind(".flapsim_outputs_reserve.tmp.", 0) == 0 && f.path() != p) {
      std::error_code ignored;
      fs::remove(f.path(), ignored);
    }
  }
  const int fd = ::open(p.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  int err = fd < 0 ? errno : ::posix_fallocate(fd, 0, kReserveBytes);
  if (fd >= 0) ::close(fd);
  if (err == 0) return;
  std::error_code ignored;
  fs::remove(p, ignored);
  if (err == ENOSPC || err == EDQUOT)
    throw OutputError(dir, "less than 64 KiB free on its disk: no room to record how the command ends "
                           "(free some space, or write the outputs elsewhere with -o)");
}

void release_reserve(const fs::path& dir) {
  std::error_code ignored;
  fs::remove(reserve_path(dir), ignored);
}

}  // namespace

OutputFolderClaim::OutputFolderClaim(fs::path dir, std::string command)
    : dir_(std::move(dir)), command_(std::move(command)) {}

// The folder's lock (lock_) is released after the body: the last record is made under it.
OutputFolderClaim::~OutputFolderClaim() {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (state_ != State::open) return;
  state_ = State::ended;
  release_reserve(dir_);
  try {
    record_command_status(dir_, command_, "failed");
  } catch (...) {
    // The folder cannot be written any more: the error that ended the command is reported.
  }
}

void OutputFolderClaim::claim(bool force) {
  const std::lock_guard<std::mutex> lock(mutex_);
  // Another command writing here now would have its files removed and mixed with ours.
  prepare_output_directory(dir_);
  if (!lock_) lock_ = std::make_unique<FolderLock>(dir_, command_);
  make_reserve(dir_);  // before the manifest says "running": refused on a disk without room
  try {
    claim_output_folder(dir_, command_, force);
  } catch (...) {
    release_reserve(dir_);
    throw;
  }
  state_ = State::open;
}

void OutputFolderClaim::claim_once(bool force) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (state_ != State::unclaimed) return;
  }
  claim(force);
}

void OutputFolderClaim::finish(const std::string& status) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (state_ == State::ended) return;
  const bool was_open = state_ == State::open;
  state_ = State::ended;
  if (was_open) release_reserve(dir_);
  record_command_status(dir_, command_, status);
}

OutputFolderClaim::State OutputFolderClaim::end_if_open(const std::string& status) {
  const std::lock_guard<std::mutex> lock(mutex_);
  const State found = state_;
  if (found != State::open) return found;
  state_ = State::ended;
  release_reserve(dir_);
  record_command_status(dir_, command_, status);
  return found;
}

}  // namespace flapsim::io
