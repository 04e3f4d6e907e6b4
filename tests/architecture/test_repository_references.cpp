// What the repository refers to is in the repository: no source, test or page cites a
// file a user does not have (the project's working notes, paths of the machine it was
// written on), and every relative link of the Markdown pages leads to a file.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
const fs::path kRoot = FLAPSIM_SOURCE_DIR;

std::string read_file(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The files users get: code, tests, benchmarks, documents, cases, wings, tools.
std::vector<fs::path> repository_files() {
  std::vector<fs::path> out;
  for (const char* top : {"wings", "fem", "reduction", "mbd", "uvlm", "pipeline", "tests", "bench", "docs",
                          "cases", "tools"})
    for (const auto& e : fs::recursive_directory_iterator(kRoot / top))
      if (e.is_regular_file()) {
        const auto ext = e.path().extension();
        if (ext == ".cpp" || ext == ".hpp" || ext == ".md" || ext == ".toml" || ext == ".txt" ||
            ext == ".py" || ext == ".mk" || ext == ".sh" || ext == ".csv")
          out.push_back(e.path());
      }
  for (const char* f : {"README.md", "CMakeLists.txt", "Makefile"}) out.push_back(kRoot / f);
  return out;
}

TEST(RepositoryReferences, NothingCitesAFileOutsideTheRepository) {
  // Spelled in pieces so that this file does not match itself.
  const std::vector<std::string> outside = {std::string("DESIGN") + ".md", std::string("STYLE") + ".md",
                                            std::string("/work") + "/", std::string("work/") + "shared"};
  std::vector<std::string> found;
  int files = 0;
  for (const fs::path& p : repository_files()) {
    std::istringstream in(read_file(p));
    int line_no = 0;
    for (std::string line; std::getline(in, line);) {
      ++line_no;
      for (const std::string& o : outside)
        if (line.find(o) != std::string::npos)
          found.push_back(p.lexically_relative(kRoot).generic_string() + ":" + std::to_string(line_no) +
                          ": " + o + " (cite docs/references.md or docs/validation.md instead)");
    }
    ++files;
  }
  EXPECT_GT(files, 200);
  std::string text;
  for (const auto& f : found) text += f + "\n";
  EXPECT_TRUE(found.empty()) << text;
}

TEST(RepositoryReferences, EveryRelativeLinkOfTheDocumentsLeadsToAFile) {
  static const std::regex link(R"(\]\(([^)#\s]+)(#[^)]*)?\))");
  std::vector<std::string> broken;
  int links = 0;
  std::vector<fs::path> pages{kRoot / "README.md"};
  for (const auto& e : fs::directory_iterator(kRoot / "docs"))
    if (e.path().extension() == ".md") pages.push_back(e.path());
  for (const fs::path& page : pages) {
    const std::string text = read_file(page);
    for (std::sregex_iterator it(text.begin(), text.end(), link), end; it != end; ++it) {
      const std::string target = (*it)[1];
      if (target.find("://") != std::string::npos || target.rfind("mailto:", 0) == 0) continue;
      ++links;
      if (!fs::exists(page.parent_path() / target))
        broken.push_back(page.lexically_relative(kRoot).generic_string() + ": " + target);
    }
  }
  EXPECT_GT(links, 20);
  std::string text;
  for (const auto& b : broken) text += b + "\n";
  EXPECT_TRUE(broken.empty()) << "links to missing files:\n" << text;
}

}  // namespace
