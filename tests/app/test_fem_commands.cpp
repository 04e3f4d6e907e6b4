// `flapsim mesh` and `flapsim modes` end to end: their files, and exit status 2 with
// nothing written on bad input.

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace {

namespace fs = std::filesystem;
using flapsim::test::run_flapsim;

TEST(FemCommands, MeshAndModesWriteTheirFiles) {
  const flapsim::test::ScratchDir scratch("fem_commands");
  const fs::path dir = scratch / "out";
  const std::string wing = std::string(FLAPSIM_SOURCE_DIR) + "/wings/flat_plate.toml";
  ASSERT_EQ(run_flapsim("mesh " + wing + " -o " + dir.string()), 0);
  EXPECT_TRUE(fs::exists(dir / "mesh.msh"));
  EXPECT_TRUE(fs::exists(dir / "mesh.vtu"));
  ASSERT_EQ(run_flapsim("modes " + wing + " -o " + dir.string() + " --modes 4"), 0);
  std::ifstream csv(dir / "modes.csv");
  std::string header, first;
  std::getline(csv, header);
  std::getline(csv, first);
  EXPECT_EQ(header, "mode,frequency_hz,kind,beam_share,shape_kind");
  EXPECT_EQ(first.substr(0, 2), "1,");
  EXPECT_TRUE(fs::exists(dir / "fem.vtu"));
  // Bad input: a numeric option out of its range is a usage error (exit status 1, README),
  // a missing file bad input (2); nothing written.
  const fs::path bad = scratch / "bad";
  EXPECT_EQ(run_flapsim("modes " + wing + " -o " + bad.string() + " --modes 0"), 1);
  EXPECT_EQ(run_flapsim("mesh " + (scratch / "missing.toml").string() + " -o " + bad.string()), 2);
  EXPECT_FALSE(fs::exists(bad / "modes.csv"));
}

// The FEM mass `modes` prints has four significant digits at any size: a 40 x 10 um plate
// 0.2 um thick (1390 kg/m^3: 1.112e-13 kg) was "FEM mass 0.0000 mg" until 3 Dec.
TEST(FemCommands, ModesPrintsTheMassOfATinyWingInSignificantDigits) {
  const flapsim::test::ScratchDir scratch("fem_commands_tiny");
  std::ifstream plate(std::string(FLAPSIM_SOURCE_DIR) + "/wings/flat_plate.toml");
  std::string text((std::istreambuf_iterator<char>(plate)), std::istreambuf_iterator<char>());
  const std::string unit = "length_unit = \"mm\"";
  ASSERT_NE(text.find(unit), std::string::npos);
  text.replace(text.find(unit), unit.size(), "length_unit = \"um\"");
  std::ofstream(scratch / "tiny.toml") << text;
  const fs::path log = scratch / "modes.txt";
  ASSERT_EQ(run_flapsim("modes " + (scratch / "tiny.toml").string() + " -o " + (scratch / "out").string() +
                            " --modes 2",
                        log),
            0);
  std::ifstream in(log);
  const std::string printed((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // ρ h S = 1390 · 0.2e-6 · 400e-12 kg = 1.112e-7 mg (the FEM's consistent mass: exact).
  EXPECT_NE(printed.find("FEM mass 1.112e-07 mg"), std::string::npos) << printed;
}

// `flapsim modes --threads 2` runs the eigen-solve beside the static side (one factorisation
// of K shared by the tip load cases and the chain that names the modes) and assembles on
// two threads; every number must be the one of --threads 1, to the bit (both files).
TEST(FemCommands, ModesOnTwoThreadsWriteTheFilesOfOneThread) {
  const flapsim::test::ScratchDir scratch("modes_threads");
  const std::string wing = std::string(FLAPSIM_SOURCE_DIR) + "/wings/mav_film_wing_25um.toml";
  for (const char* t : {"1", "2"})
    ASSERT_EQ(run_flapsim("modes " + wing + " -o " + (scratch / t).string() + " --modes 8 --threads " + t), 0);
  auto bytes = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  for (const char* f : {"modes.csv", "fem.vtu"}) {
    const std::string one = bytes(scratch / "1" / f), two = bytes(scratch / "2" / f);
    EXPECT_GT(one.size(), 100u) << f;
    EXPECT_EQ(one, two) << f;
  }
}

// Cell \p index of a CSV line or markdown table row split by \p sep, trimmed.
std::string cell(const std::string& line, char sep, int index) {
  std::stringstream ss(line);
  std::string c;
  for (int i = 0; i <= index && std::getline(ss, c, sep); ++i) {
  }
  while (!c.empty() && c.front() == ' ') c.erase(c.begin());
  while (!c.empty() && c.back() == ' ') c.pop_back();
  return c;
}

// Issue 17: `flapsim modes` names the modes as `flapsim reduce` does — from the motion of
// the chain's stations (docs/reduction.md, "Mode kinds from the stations"), so the MAV
// film wing's film modes are "film", not "bending" (the 25 µm first design, its 12 lowest
// modes: 7 film).
TEST(FemCommands, ModesNamesModesAsTheReductionReportDoes) {
  const flapsim::test::ScratchDir scratch("modes_names");
  const std::string wing = std::string(FLAPSIM_SOURCE_DIR) + "/wings/mav_film_wing_25um.toml";
  ASSERT_EQ(run_flapsim("modes " + wing + " -o " + (scratch / "modes").string() + " --modes 12 --bodies 10"), 0);
  ASSERT_EQ(run_flapsim("reduce " + wing + " -o " + (scratch / "reduce").string() + " --modes 12 --bodies 10"), 0);
  std::vector<std::string> from_modes, from_report;
  std::ifstream csv(scratch / "modes" / "modes.csv");
  std::string line;
  std::getline(csv, line);  // header
  while (std::getline(csv, line))
    if (!line.empty()) from_modes.push_back(cell(line, ',', 2));
  std::ifstream report(scratch / "reduce" / "report.md");
  bool in_table = false;
  while (std::getline(report, line)) {
    if (line.rfind("## ", 0) == 0) in_table = line == "## FEM modes";
    if (in_table && line.size() > 2 && line[0] == '|' && std::isdigit(static_cast<unsigned char>(line[2])))
      from_report.push_back(cell(line, '|', 3));
  }
  ASSERT_EQ(from_modes.size(), 12u);
  EXPECT_EQ(from_modes, from_report);
  int film = 0;
  for (const auto& k : from_modes) film += k == "film";
  EXPECT_GE(film, 1);
}

// A sliver in the mesh (fem/mesh_quality.hpp) is warned about by mesh and check, exit 0: the
// swept film wing with a kinked vein whose corner lies 2 µm above its root spar (measured
// 0.0583° near (−24.71, 7.001) mm; fem.MeshSlivers.*); without that vein, no warning.
TEST(FemCommands, MeshAndCheckWarnOfASliverNamingWhereItLies) {
  const flapsim::test::ScratchDir scratch("fem_commands_sliver");
  const std::string shipped = std::string(FLAPSIM_SOURCE_DIR) + "/tests/data/swept_film_50um_wing.toml";
  std::stringstream text;
  text << std::ifstream(shipped).rdbuf();
  const fs::path wing = scratch / "kinked.toml";
  std::ofstream(wing) << text.str()
                      << "\n[[veins]]\nname = \"kinked vein\"\n"
                         "points = [[-20.0, 20.0], [-25.0, 7.002], [-35.0, 40.0]]\n"
                         "outer_diameter = 0.6\nwall = 0.3\nmaterial = \"carbon\"\n";
  for (const std::string command : {"mesh", "check"}) {
    const auto r = flapsim::test::run_flapsim_capturing_stderr(
        scratch.path(),
        command + " " + wing.string() + (command == "mesh" ? " -o " + (scratch / "m").string() : ""));
    EXPECT_EQ(r.status, 0) << command << ": " << r.err;
    EXPECT_NE(r.err.find("the wing's mesh has a sliver triangle, 0.05"), std::string::npos)
        << command << ": " << r.err;
    EXPECT_NE(r.err.find("near (x, y) = (-24.7"), std::string::npos) << command << ": " << r.err;
  }
  // mesh's summary line gives the smallest angle, warned or not.
  const fs::path out = scratch / "out.txt";
  ASSERT_EQ(run_flapsim("mesh " + wing.string() + " -o " + (scratch / "m").string() + " --force", out), 0);
  const std::string summary = flapsim::test::read_text(out);
  EXPECT_NE(summary.find("(3 veins), smallest angle 0.0583 deg"), std::string::npos) << summary;
  const auto plain = flapsim::test::run_flapsim_capturing_stderr(scratch.path(), "check " + shipped);
  EXPECT_EQ(plain.status, 0);
  EXPECT_EQ(plain.err.find("sliver"), std::string::npos) << plain.err;
}

}  // namespace

// A wing error the mesher finds (a vein along another, refused while meshing) came after the
// folder was claimed: mesh, modes and reduce removed the folder's earlier outputs (mesh.msh,
// modes.csv, chain.toml, ...) and then exited 2; into a new folder they made it, with a
// manifest saying "failed". Now the folder is claimed once the wing is meshed.
// mesh stages gmsh's file in TMPDIR: an unwritable TMPDIR (/proc, unwritable even for root)
// was reported as a wing gmsh cannot mesh ("check the outline ...", exit 2); it is the
// folder's fault, an output error (exit 4) naming it, and the output folder is not made.
// A TMPDIR that does not exist is named too (the message said 'TMPDIR').
TEST(FemCommands, AnUnwritableTemporaryFolderIsAnOutputErrorNotAWingError) {
  const flapsim::test::ScratchDir scratch("fem_commands_tmpdir");
  const std::string wing = std::string(FLAPSIM_SOURCE_DIR) + "/wings/flat_plate.toml";
  for (const std::string tmpdir : {"/proc", "/nonexistent_flapsim_tmpdir"}) {
    const fs::path out = scratch / ("model" + std::to_string(tmpdir.size()));
    const std::string cmd = "TMPDIR=" + tmpdir + " FLAPSIM_QUIET=1 '" + std::string(FLAPSIM_BINARY) +
                            "' mesh " + wing + " -o " + out.string() + " > /dev/null 2> " +
                            (scratch / "err.txt").string();
    const int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    const std::string err = flapsim::test::read_text(scratch / "err.txt");
    EXPECT_EQ(WEXITSTATUS(status), 4) << tmpdir << ": " << err;
    EXPECT_NE(err.find(tmpdir), std::string::npos) << err;
    EXPECT_EQ(err.find("check the outline"), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(out)) << tmpdir;
  }
}

TEST(FemCommands, AWingErrorFoundWhileMeshingLeavesTheFolderAsItWas) {
  const flapsim::test::ScratchDir scratch("fem_commands_mesher_error");
  const fs::path dir = scratch / "model";
  const std::string good = std::string(FLAPSIM_SOURCE_DIR) + "/wings/flat_plate.toml";
  ASSERT_EQ(run_flapsim("mesh " + good + " -o " + dir.string()), 0);
  for (const char* f :
       {"modes.csv", "fem.vtu", "fem_modes.pvsm", "beam.csv", "chain.toml", "report.md", "summary.json"})
    std::ofstream(dir / f) << "earlier " << f << "\n";
  std::vector<std::pair<fs::path, std::string>> before;
  for (const auto& e : fs::directory_iterator(dir))
    before.emplace_back(e.path(), flapsim::test::read_text(e.path()));
  ASSERT_EQ(before.size(), 10u);  // mesh.msh, mesh.vtu, the manifest and the seven above

  const fs::path bad = scratch / "vein_along_vein.toml";
  std::ofstream(bad)
      << flapsim::test::read_text(good)
      << "\n[materials.carbon]\nyoungs_modulus = 135.0e9\npoisson_ratio = 0.3\ndensity = 1550.0\n"
         "\n[[veins]]\nname = \"spar\"\npoints = [[0.0, 0.0], [0.0, 38.0]]\nshape = "
         "\"solid_circle\"\ndiameter = 0.5\n"
         "material = \"carbon\"\n"
         "\n[[veins]]\nname = \"doubler\"\npoints = [[0.0, 5.0], [0.0, 30.0]]\nshape = "
         "\"solid_circle\"\ndiameter = 0.3\n"
         "material = \"carbon\"\n";
  for (const char* command : {"mesh", "modes", "reduce"}) {
    const auto r = flapsim::test::run_flapsim_capturing_stderr(
        scratch.path(), std::string(command) + " " + bad.string() + " -o " + dir.string() + " --force");
    EXPECT_EQ(r.status, 2) << command << ": " << r.err;
    EXPECT_NE(r.err.find("vein 'doubler' lies along vein 'spar'"), std::string::npos)
        << command << ": " << r.err;
    for (const auto& [path, text] : before)
      EXPECT_EQ(flapsim::test::read_text(path), text) << command << " changed " << path;
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
    EXPECT_EQ(files, before.size()) << command;
    const fs::path fresh = scratch / (std::string("new_") + command);
    EXPECT_EQ(run_flapsim(std::string(command) + " " + bad.string() + " -o " + fresh.string()), 2) << command;
    EXPECT_FALSE(fs::exists(fresh)) << command << " made the folder of a refused wing";
  }
}
