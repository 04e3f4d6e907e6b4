// The module arrows of docs/architecture.md hold in the code: the table of modules
// ("folder | library | uses") has no cycle, each module's CMakeLists.txt links exactly
// the modules it says it uses, and every quoted #include of every source, test and
// benchmark stays within what its module may use (itself and the closure of its uses).
// The compiler enforces the same arrows through the include roots (the ctest tests
// architecture.ForbiddenInclude.*); this test reads the whole tree at once and names
// every offending line, and it is what ties the table to the code.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
const fs::path kRoot = FLAPSIM_SOURCE_DIR;

struct Module {
  std::string name;            ///< library name without "flapsim_": "fem", "io"
  std::string folder;          ///< from the repository root, no trailing '/': "pipeline/io"
  std::string library;         ///< "flapsim_io"
  std::set<std::string> uses;  ///< names of the modules it uses directly
};
using Modules = std::map<std::string, Module>;

std::string read_file(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

// The first `backticked` word of a table cell, without a trailing '/'.
std::string code_word(const std::string& cell) {
  const auto a = cell.find('`');
  const auto b = a == std::string::npos ? a : cell.find('`', a + 1);
  std::string w = b == std::string::npos ? trim(cell) : cell.substr(a + 1, b - a - 1);
  while (!w.empty() && w.back() == '/') w.pop_back();
  return w;
}

// The module table of architecture.md: the rows under the header line that starts
// with "| folder | library | uses |". Throws if there is none.
Modules parse_modules(const std::string& markdown) {
  Modules modules;
  std::istringstream in(markdown);
  bool in_table = false;
  for (std::string line; std::getline(in, line);) {
    if (!in_table) {
      in_table = line.rfind("| folder | library | uses |", 0) == 0;
      if (in_table) std::getline(in, line);  // the |---| line
      continue;
    }
    if (line.empty() || line[0] != '|') break;
    std::vector<std::string> cells;
    std::stringstream row(line.substr(1));
    for (std::string c; std::getline(row, c, '|');) cells.push_back(trim(c));
    if (cells.size() < 3) throw std::runtime_error("short row: " + line);
    Module m;
    m.folder = code_word(cells[0]);
    m.library = code_word(cells[1]);
    if (m.library.rfind("flapsim_", 0) != 0) throw std::runtime_error("library not flapsim_*: " + line);
    m.name = m.library.substr(8);
    std::stringstream uses(cells[2]);
    for (std::string u; std::getline(uses, u, ',');) {
      u = trim(u);
      if (!u.empty() && u != "—" && u != "-") m.uses.insert(u);
    }
    modules[m.name] = m;
  }
  if (modules.empty()) throw std::runtime_error("no '| folder | library | uses |' table");
  return modules;
}

// A cycle of arrows as "a -> b -> a", or nothing.
std::optional<std::string> find_cycle(const Modules& modules) {
  std::map<std::string, int> state;  // 0 new, 1 on the path, 2 done
  std::vector<std::string> path;
  std::optional<std::string> cycle;
  std::function<void(const std::string&)> visit = [&](const std::string& n) {
    if (cycle) return;
    state[n] = 1;
    path.push_back(n);
    const auto it = modules.find(n);
    if (it != modules.end())
      for (const auto& u : it->second.uses) {
        if (state[u] == 1) {
          std::string text;
          for (auto p = std::find(path.begin(), path.end(), u); p != path.end(); ++p) text += *p + " -> ";
          cycle = text + u;
          return;
        }
        if (state[u] == 0) visit(u);
      }
    path.pop_back();
    state[n] = 2;
  };
  for (const auto& [name, m] : modules)
    if (state[name] == 0) visit(name);
  return cycle;
}

// The module itself and every module reachable along its arrows.
std::set<std::string> reachable(const Modules& modules, const std::string& name) {
  std::set<std::string> seen{name};
  std::vector<std::string> todo{name};
  while (!todo.empty()) {
    const std::string n = todo.back();
    todo.pop_back();
    const auto it = modules.find(n);
    if (it == modules.end()) continue;
    for (const auto& u : it->second.uses)
      if (seen.insert(u).second) todo.push_back(u);
  }
  return seen;
}

// The module whose folder holds `path` (from the repository root), the longest
// matching folder; "" if none.
std::string module_of(const Modules& modules, const std::string& path) {
  std::string best, best_folder;
  for (const auto& [name, m] : modules)
    if (path.rfind(m.folder + "/", 0) == 0 && m.folder.size() > best_folder.size()) {
      best = name;
      best_folder = m.folder;
    }
  return best;
}

std::vector<std::string> quoted_includes(const std::string& text) {
  static const std::regex re(R"re(^\s*#\s*include\s*"([^"]+)")re");
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_search(line, m, re)) out.push_back(m[1]);
  }
  return out;
}

bool is_code(const fs::path& p) { return p.extension() == ".cpp" || p.extension() == ".hpp"; }

std::string repo_relative(const fs::path& p) { return p.lexically_relative(kRoot).generic_string(); }

// Checks one file's quoted includes. `allowed`: modules whose headers it may include;
// `test_helpers`: for files under tests/, whether tests/<module>/ helpers of allowed
// modules and tests/common/ may be included. Returns one line per offence.
std::vector<std::string> check_file(const Modules& modules, const fs::path& file,
                                    const std::set<std::string>& allowed, bool test_helpers) {
  std::vector<std::string> offences;
  const std::string name = repo_relative(file);
  for (const std::string& inc : quoted_includes(read_file(file))) {
    const auto offence = [&](const std::string& why) {
      offences.push_back(name + ": #include \"" + inc + "\": " + why);
    };
    if (inc.find("..") != std::string::npos) {
      offence("climbs out of its folder; include headers by their path from the root");
      continue;
    }
    if (fs::exists(file.parent_path() / inc)) {
      const std::string owner = module_of(modules, repo_relative(file.parent_path() / inc));
      if (!owner.empty() && !allowed.count(owner)) offence("module '" + owner + "' is not used here");
      continue;  // a header of the same folder
    }
    if (test_helpers && fs::exists(kRoot / "tests" / inc)) {
      const std::string folder = inc.substr(0, inc.find('/'));
      if (folder != "common" && !allowed.count(folder))
        offence("test helper of module '" + folder + "', which this module does not use");
      continue;
    }
    const std::string owner = module_of(modules, inc);
    if (owner.empty())
      offence("is not a header of any module in docs/architecture.md");
    else if (!allowed.count(owner))
      offence("module '" + owner + "' is not among the uses of this file's module (docs/architecture.md)");
  }
  return offences;
}

// The flapsim_* module libraries named in the target_link_libraries(<library> ...)
// calls of a CMakeLists.txt.
std::set<std::string> linked_modules(const Modules& modules, const std::string& cmake,
                                     const std::string& library) {
  std::set<std::string> out;
  const std::string open = "target_link_libraries(" + library;
  for (auto at = cmake.find(open); at != std::string::npos; at = cmake.find(open, at + 1)) {
    const char next = cmake[at + open.size()];
    if (next != ' ' && next != '\n') continue;  // a longer target name
    const std::string call = cmake.substr(at + open.size(), cmake.find(')', at) - at - open.size());
    static const std::regex word(R"(flapsim_(\w+))");
    for (std::sregex_iterator it(call.begin(), call.end(), word), end; it != end; ++it)
      if (modules.count((*it)[1])) out.insert((*it)[1]);
  }
  return out;
}

const Modules& tree_modules() {
  static const Modules m = parse_modules(read_file(kRoot / "docs" / "architecture.md"));
  return m;
}

std::string join(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

// ---------------------------------------------------------------------------------
// The checker itself, on a made-up table: it must see what it is there to see.

const char* kToyTable =
    "text\n"
    "| folder | library | uses | external libraries | what it holds |\n"
    "|---|---|---|---|---|\n"
    "| `base/` | `flapsim_base` | — | | |\n"
    "| `mid/` | `flapsim_mid` | base | | |\n"
    "| `top/a/` | `flapsim_a` + `prog` | mid | | |\n"
    "| `top/b/` | `flapsim_b` | base | | |\n"
    "\nmore text\n";

TEST(ModuleArrows, CheckerReadsTheTableAndTheClosure) {
  const Modules m = parse_modules(kToyTable);
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m.at("a").folder, "top/a");
  EXPECT_EQ(m.at("a").library, "flapsim_a");
  EXPECT_EQ(reachable(m, "a"), (std::set<std::string>{"a", "mid", "base"}));
  EXPECT_EQ(reachable(m, "b"), (std::set<std::string>{"b", "base"}));
  EXPECT_EQ(module_of(m, "top/a/x.hpp"), "a");
  EXPECT_EQ(module_of(m, "top/x.hpp"), "");
  EXPECT_EQ(module_of(m, "midway/x.hpp"), "");
  EXPECT_FALSE(find_cycle(m).has_value());
}

TEST(ModuleArrows, CheckerFindsACycle) {
  std::string cyclic = kToyTable;
  const std::string none = "| `flapsim_base` | —";
  cyclic.replace(cyclic.find(none), none.size(), "| `flapsim_base` | a");
  const auto cycle = find_cycle(parse_modules(cyclic));
  ASSERT_TRUE(cycle.has_value());
  EXPECT_NE(cycle->find("a -> mid -> base -> a"), std::string::npos) << *cycle;
}

TEST(ModuleArrows, CheckerFindsAForbiddenInclude) {
  // A file of module b (uses base only) that includes a header of module a.
  const Modules m = parse_modules(kToyTable);
  const fs::path dir = fs::temp_directory_path() / ("flapsim_arrows_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "file.cpp") << "#include \"base/ok.hpp\"\n#include \"top/a/no.hpp\"\n"
                                     "#include \"nowhere/x.hpp\"\n#include \"../up.hpp\"\n";
  const auto offences = check_file(m, dir / "file.cpp", reachable(m, "b"), false);
  fs::remove_all(dir);
  ASSERT_EQ(offences.size(), 3u) << join(offences);
  EXPECT_NE(offences[0].find("module 'a' is not among the uses"), std::string::npos) << offences[0];
  EXPECT_NE(offences[1].find("not a header of any module"), std::string::npos) << offences[1];
  EXPECT_NE(offences[2].find("climbs out"), std::string::npos) << offences[2];
}

TEST(ModuleArrows, CheckerReadsTheLinkedModulesOfACMakeFile) {
  const Modules m = parse_modules(kToyTable);
  const std::string cmake =
      "target_link_libraries(flapsim_a PUBLIC flapsim_mid Eigen3::Eigen\n  flapsim_toml PRIVATE flapsim_base)\n"
      "target_link_libraries(flapsim_ab PUBLIC flapsim_b)\n"
      "target_link_libraries(prog PRIVATE flapsim_a)\n";
  EXPECT_EQ(linked_modules(m, cmake, "flapsim_a"), (std::set<std::string>{"mid", "base"}));
}

// ---------------------------------------------------------------------------------
// The tree.

TEST(ModuleArrows, TableListsEveryCodeFolderWithoutCycles) {
  const Modules& m = tree_modules();
  for (const char* name : {"wings", "fem", "mbd", "uvlm", "reduction", "fsi", "io", "app"})
    EXPECT_TRUE(m.count(name)) << name << " missing from the table of docs/architecture.md";
  for (const auto& [name, mod] : m) {
    EXPECT_TRUE(fs::is_directory(kRoot / mod.folder)) << mod.folder;
    for (const auto& u : mod.uses) EXPECT_TRUE(m.count(u)) << name << " uses unknown module " << u;
  }
  const auto cycle = find_cycle(m);
  EXPECT_FALSE(cycle.has_value()) << "the arrows of docs/architecture.md have a cycle: " << *cycle;
}

TEST(ModuleArrows, CMakeLinksWhatTheTableSays) {
  const Modules& m = tree_modules();
  for (const auto& [name, mod] : m) {
    const std::string cmake = read_file(kRoot / mod.folder / "CMakeLists.txt");
    EXPECT_EQ(linked_modules(m, cmake, mod.library), mod.uses)
        << mod.folder << "/CMakeLists.txt links other modules than docs/architecture.md says";
    // The module's tests link the module's own library and no other.
    const fs::path tests = kRoot / "tests" / name / "CMakeLists.txt";
    ASSERT_TRUE(fs::exists(tests)) << "no tests/" << name;
    const std::string t = read_file(tests);
    static const std::regex word(R"(flapsim_(\w+))");
    std::set<std::string> linked;
    for (std::sregex_iterator it(t.begin(), t.end(), word), end; it != end; ++it)
      if (m.count((*it)[1])) linked.insert((*it)[1]);
    EXPECT_EQ(linked, std::set<std::string>{name}) << "tests/" << name << "/CMakeLists.txt";
  }
}

TEST(ModuleArrows, EverySourceIncludesOnlyWhatItsModuleMayUse) {
  const Modules& m = tree_modules();
  std::vector<std::string> offences;
  int files = 0;
  for (const char* top : {"wings", "fem", "mbd", "uvlm", "reduction", "pipeline"})
    for (const auto& e : fs::recursive_directory_iterator(kRoot / top)) {
      if (!e.is_regular_file() || !is_code(e.path())) continue;
      const std::string owner = module_of(m, repo_relative(e.path()));
      if (owner.empty()) {
        offences.push_back(repo_relative(e.path()) + ": belongs to no module of docs/architecture.md");
        continue;
      }
      const auto found = check_file(m, e.path(), reachable(m, owner), false);
      offences.insert(offences.end(), found.begin(), found.end());
      ++files;
    }
  EXPECT_GT(files, 100);  // the whole tree was read
  EXPECT_TRUE(offences.empty()) << join(offences);
}

TEST(ModuleArrows, EveryTestIncludesOnlyWhatItsModuleMayUse) {
  const Modules& m = tree_modules();
  std::vector<std::string> offences;
  int files = 0;
  for (const auto& [name, mod] : m) {
    const fs::path dir = kRoot / "tests" / name;
    for (const auto& e : fs::directory_iterator(dir)) {
      if (!e.is_regular_file() || !is_code(e.path())) continue;
      const auto found = check_file(m, e.path(), reachable(m, name), true);
      offences.insert(offences.end(), found.begin(), found.end());
      ++files;
    }
  }
  // tests/common/ serves every test folder: it may include no module at all.
  for (const auto& e : fs::directory_iterator(kRoot / "tests" / "common")) {
    const auto found = check_file(m, e.path(), {}, true);
    offences.insert(offences.end(), found.begin(), found.end());
  }
  EXPECT_GT(files, 40);
  EXPECT_TRUE(offences.empty()) << join(offences);
}

TEST(ModuleArrows, BenchmarksIncludeModuleHeadersAndTestHelpersOnly) {
  const Modules& m = tree_modules();
  std::set<std::string> all;
  for (const auto& [name, mod] : m) all.insert(name);
  std::vector<std::string> offences;
  for (const auto& e : fs::directory_iterator(kRoot / "bench"))
    if (e.is_regular_file() && is_code(e.path())) {
      const auto found = check_file(m, e.path(), all, true);  // may use the tests' helpers
      offences.insert(offences.end(), found.begin(), found.end());
    }
  EXPECT_TRUE(offences.empty()) << join(offences);
}

}  // namespace
