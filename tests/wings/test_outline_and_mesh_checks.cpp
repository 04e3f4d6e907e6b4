// Outline CSV files (line of every error, bounded reading) and the checks that a wing can
// be meshed before gmsh runs (no sliver outline, a mesh-size budget).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/scratch_dir.hpp"
#include "expect_input_error.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/mesh_budget.hpp"
#include "wings/loader/outline_csv.hpp"
#include "wings/loader/toml_reader.hpp"
#include "wings/loader/wing_file.hpp"

namespace w = flapsim::wings;
using flapsim::InputError;

namespace {

// A 40 x 10 mm rectangle with one vein; `outline` and `mesh` replace those parts.
std::string wing_text(const std::string& outline, const std::string& mesh = "") {
  return "name = \"t\"\nlength_unit = \"mm\"\n[planform]\n" + outline +
         "clamp_y = 0.0\n"
         "[materials.film]\nyoungs_modulus = 4.0e9\npoisson_ratio = 0.3\ndensity = 1400.0\n"
         "[membrane]\nthickness = 0.05\nmaterial = \"film\"\n"
         "[[veins]]\nname = \"spar\"\npoints = [[1.0, 0.0], [1.0, 30.0]]\nouter_diameter = [0.5, 0.3]\n"
         "wall = [0.1, 0.05]\nmaterial = \"film\"\n" + mesh;
}
const std::string kRectangle = "outline = [[5.0, 0.0], [5.0, 40.0], [-5.0, 40.0], [-5.0, 0.0]]\n";

TEST(OutlineCsv, EveryBadRowIsNamedByItsLine) {
  flapsim::test::ScratchDir dir("outline_csv_lines");
  std::ofstream(dir / "o.csv") << "# comment\nx,y\n0,0\n1,0.5\n1e-320,1\n";
  auto e = expect_input_error([&] { w::read_outline_csv((dir / "o.csv").string(), "planform.outline_file"); });
  EXPECT_EQ(e.file(), (dir / "o.csv").string());
  EXPECT_EQ(e.line(), 5);  // the denormal on line 5
  EXPECT_EQ(e.key(), "planform.outline_file");
  std::ofstream(dir / "p.csv") << "x,y\n0,0\n1,0\n\n2,abc\n";
  EXPECT_EQ(expect_input_error([&] { w::read_outline_csv((dir / "p.csv").string(), "k"); }).line(), 5);
  const auto lines = w::read_outline_csv_lines(std::string(FLAPSIM_SOURCE_DIR) + "/wings/outlines/hawkmoth1_outline.csv", "k");
  EXPECT_EQ(lines.points.size(), lines.lines.size());
}

// A spreadsheet's "CSV UTF-8" starts with a byte-order mark and ends lines with CR LF. Before:
// "o.csv:1: key 'planform.outline_file': expected a line "x,y" with two finite numbers ...,
// found "\xEF\xBB\xBFx,y"" (the mark invisible in the message).
TEST(OutlineCsv, AByteOrderMarkAndCrLfLineEndsAreRead) {
  flapsim::test::ScratchDir dir("outline_csv_bom");
  std::ofstream(dir / "o.csv", std::ios::binary) << "\xEF\xBB\xBFx,y\r\n0.1,0\r\n0.1,1\r\n-0.2,1\r\n-0.2,0\r\n";
  const auto o = w::read_outline_csv_lines((dir / "o.csv").string(), "k");
  ASSERT_EQ(o.points.size(), 4u);
  EXPECT_EQ(o.points[0].x(), 0.1);
  EXPECT_EQ(o.points[3].y(), 0.0);
  EXPECT_EQ(o.lines[0], 2);  // the header is line 1
  // Without a header, the first point follows the mark.
  std::ofstream(dir / "p.csv", std::ios::binary) << "\xEF\xBB\xBF" "0.1,0\n0.1,1\n-0.2,1\n";
  EXPECT_EQ(w::read_outline_csv_lines((dir / "p.csv").string(), "k").points.size(), 3u);
}

// A tab- or space-separated outline (ImageJ's "XY coordinates" export: a header "X<tab>Y", then
// tab-separated pairs). Before: "expected a line "x,y" with two finite numbers ..., found
// "X\tY"" at line 1. Now the pairs are read; a comma still separates where there is one, so a
// decimal comma ("1,5 2,5") is still refused, as are three fields.
TEST(OutlineCsv, TabOrSpaceSeparatedPairsAreRead) {
  flapsim::test::ScratchDir dir("outline_csv_tabs");
  std::ofstream(dir / "t.csv") << "X\tY\n0.1\t0\n0.1\t1\n-0.2  1\n-0.2 \t 0\n";
  const auto o = w::read_outline_csv_lines((dir / "t.csv").string(), "k");
  ASSERT_EQ(o.points.size(), 4u);
  EXPECT_EQ(o.points[1], Eigen::Vector2d(0.1, 1.0));
  EXPECT_EQ(o.points[3], Eigen::Vector2d(-0.2, 0.0));
  EXPECT_EQ(o.lines[0], 2);  // the header is line 1
  std::ofstream(dir / "comma.csv") << "0,1 0,2\n0,1 1\n-0,2 1\n";
  EXPECT_EQ(expect_input_error([&] { w::read_outline_csv((dir / "comma.csv").string(), "k"); }).line(), 1);
  std::ofstream(dir / "three.csv") << "0.1 0 0\n0.1 1 0\n-0.2 1 0\n";
  EXPECT_EQ(expect_input_error([&] { w::read_outline_csv((dir / "three.csv").string(), "k"); }).line(), 1);
}

TEST(OutlineCsv, ASelfIntersectionIsReportedAtTheCsvLineOfItsEdge) {
  // A bow tie: edge 0 (points 0-1, lines 2-3) crosses edge 2 (points 2-3).
  flapsim::test::ScratchDir dir("outline_csv_bowtie");
  std::ofstream(dir / "bow.csv") << "x,y\n0,0\n1,1\n0,1\n1,0\n";
  std::ofstream(dir / "w.toml") << wing_text("outline_file = \"bow.csv\"\nspan = 40.0\n");
  auto e = expect_input_error([&] { w::load_wing_file((dir / "w.toml").string()); });
  EXPECT_EQ(e.file(), (dir / "bow.csv").lexically_normal().string()) << e.what();
  EXPECT_GE(e.line(), 2) << e.what();
  EXPECT_EQ(e.key(), "planform.outline_file");
}

TEST(OutlineCsv, ARepeatedPointIsNamedAsARepeatAtItsOwnLine) {
  // A closing point written twice (lines 8 and 9 repeat line 2): one is accepted, the other
  // was reported as "edge 0 (points 0-1) touches or crosses edge 5" at line 2.
  flapsim::test::ScratchDir dir("outline_csv_repeat");
  std::ofstream(dir / "dup.csv") << "x,y\n0.0,0.04\n0.05,0.5\n0.0,1.0\n-0.12,0.98\n-0.30,0.6\n-0.35,0.04\n"
                                    "0.0,0.04\n0.0,0.04\n";
  std::ofstream(dir / "w.toml") << wing_text("outline_file = \"dup.csv\"\nspan = 40.0\n");
  auto e = expect_input_error([&] { w::load_wing_file((dir / "w.toml").string()); });
  EXPECT_EQ(e.line(), 8) << e.what();
  EXPECT_EQ(e.key(), "planform.outline_file");
  EXPECT_NE(e.message().find("point 6 repeats point 0"), std::string::npos) << e.what();
  // A repeat inside the list, in the wing file: its own element's line.
  auto f = expect_input_error([&] {
    w::read_wing(w::parse_toml_string(
        wing_text("outline = [\n[5.0, 0.0],\n[5.0, 40.0],\n[5.0, 40.0],\n[-5.0, 40.0],\n[-5.0, 0.0]]\n"),
        "r.toml"));
  });
  EXPECT_EQ(f.line(), 7) << f.what();  // "[5.0, 40.0]," the second time
  EXPECT_NE(f.message().find("point 2 repeats point 1"), std::string::npos) << f.what();
}

// A point a hair from the next (1.4e-7 mm on a 40 mm wing, below kNearRepeat = 1e-6 of the
// outline's size) is a repeat too: it passed the exact comparison, and gmsh merged the two and
// stopped with "Could not create line", no line and no point named.
TEST(OutlineCsv, ANearlyRepeatedPointIsNamedAtItsLine) {
  auto f = expect_input_error([&] {
    w::read_wing(w::parse_toml_string(wing_text("outline = [\n[5.0, 0.0],\n[5.0, 40.0],\n[5.0000001, "
                                                "40.0000001],\n[-5.0, 40.0],\n[-5.0, 0.0]]\n"),
                                      "r.toml"));
  });
  EXPECT_EQ(f.line(), 7) << f.what();
  EXPECT_EQ(f.key(), "planform.outline");
  EXPECT_NE(f.message().find("point 2 nearly repeats point 1"), std::string::npos) << f.what();
  // In a CSV outline, at the CSV's line of the later point.
  flapsim::test::ScratchDir dir("outline_csv_near_repeat");
  std::ofstream(dir / "near.csv")
      << "x,y\n0.0,0.04\n0.05,0.5\n0.0,1.0\n0.0,1.0000000001\n-0.30,0.6\n-0.35,0.04\n";
  std::ofstream(dir / "w.toml") << wing_text("outline_file = \"near.csv\"\nspan = 40.0\n");
  auto e = expect_input_error([&] { w::load_wing_file((dir / "w.toml").string()); });
  EXPECT_EQ(e.line(), 5) << e.what();
  EXPECT_NE(e.message().find("point 3 nearly repeats point 2"), std::string::npos) << e.what();
  // A closing point that far from the first (a drawing's rounding) closes the outline: it is
  // dropped, not refused as a repeat of point 0.
  EXPECT_EQ(w::read_wing(w::parse_toml_string(
                             wing_text("outline = [[5.0, 0.0], [5.0, 40.0], [-5.0, 40.0], [-5.0, 0.0], "
                                       "[5.0000001, 0.0000001]]\n"),
                             "r.toml"))
                .outline.size(),
            4u);
  // 2e-6 of the size apart is a short edge, not a repeat: the wing loads (the sliver warning's
  // business, not an error).
  EXPECT_NO_THROW(w::read_wing(w::parse_toml_string(
      wing_text("outline = [\n[5.0, 0.0],\n[5.0, 40.0],\n[5.0, 40.00008],\n[-5.0, 40.0],\n[-5.0, 0.0]]\n"),
      "r.toml")));
}

// `span` scales the outline and `area` stretches it, but a vein's `points` stay as written:
// a wing scaled from 40 to 80 mm kept its spar over the inner half without a word
// (docs/wing_file.md, "Plausibility warnings").
TEST(OutlineCsv, VeinPointsOfARescaledOutlineAreWarned) {
  auto warned = [](const std::string& extra) {
    const w::Wing wing = w::read_wing(w::parse_toml_string(wing_text(kRectangle + extra), "r.toml"));
    for (const auto& warning : wing.warnings)
      if (warning.key == "veins[0].points") return warning.message;
    return std::string();
  };
  EXPECT_EQ(warned(""), "");               // as written: no warning
  EXPECT_EQ(warned("span = 40.0\n"), "");  // span equal to the outline's: no rescaling
  EXPECT_NE(warned("span = 80.0\n").find("scaled by 2 to 'span' = 80 mm"), std::string::npos)
      << warned("span = 80.0\n");
  EXPECT_NE(warned("area = 800.0\n").find("stretched along the chord by 2"), std::string::npos);
}

// A CSV outline's numbers carry no unit: one in the wing's millimetres whose tip is at the
// span was "scaled by 0.001 to 'span' = 40 mm" (the CSV's numbers against metres), warned for
// every vein with points, and a vein a little off it was refused saying "the outline was
// rescaled". Now a CSV is in the wing's length unit, or in units of the span when its tip is
// at y = 1 (the shipped outlines; a vein's points are then the scaled wing's).
TEST(OutlineCsv, ACsvOutlineInTheWingsUnitAtItsSpanIsNotRescaled) {
  flapsim::test::ScratchDir dir("outline_csv_unit");
  std::ofstream(dir / "mm.csv") << "x_mm,y_mm\n5,0\n5,40\n-5,40\n-5,0\n";
  std::ofstream(dir / "r.csv") << "x,y\n0.125,0\n0.125,1\n-0.125,1\n-0.125,0\n";
  auto warned = [&](const std::string& planform) {
    std::ofstream(dir / "w.toml") << wing_text(planform);
    const w::Wing wing = w::load_wing_file((dir / "w.toml").string());
    for (const auto& warning : wing.warnings)
      if (warning.key == "veins[0].points") return warning.message;
    return std::string();
  };
  EXPECT_EQ(warned("outline_file = \"mm.csv\"\nspan = 40.0\n"), "");
  EXPECT_NE(warned("outline_file = \"mm.csv\"\nspan = 80.0\n").find("scaled by 2 to 'span' = 80 mm"),
            std::string::npos);
  EXPECT_EQ(warned("outline_file = \"r.csv\"\nspan = 40.0\n"), "");
  // The spar at x = 1 mm on a wing reaching x = -5 ... 5: moved to x = 6 mm it leaves the
  // outline, and the error does not blame a rescaling that did not happen.
  std::string text = wing_text("outline_file = \"mm.csv\"\nspan = 40.0\n");
  text.replace(text.find("[[1.0, 0.0], [1.0, 30.0]]"), 25, "[[1.0, 0.0], [6.0, 30.0]]");
  std::ofstream(dir / "off.toml") << text;
  const auto e = expect_input_error([&] { w::load_wing_file((dir / "off.toml").string()); });
  EXPECT_EQ(e.key(), "veins[0].points") << e.what();
  EXPECT_EQ(std::string(e.what()).find("rescaled"), std::string::npos) << e.what();
}

TEST(OutlineCsv, AMissingOutlineFileIsTheWingFilesErrorAtItsLine) {
  // Before: "bow.csv: key 'planform.outline_file': the outline file does not exist" — the
  // missing file named, not the wing file and the line that names it.
  flapsim::test::ScratchDir dir("outline_csv_missing");
  std::ofstream(dir / "w.toml") << wing_text("outline_file = \"bwo.csv\"\nspan = 40.0\n");
  auto e = expect_input_error([&] { w::load_wing_file((dir / "w.toml").string()); });
  EXPECT_EQ(e.file(), (dir / "w.toml").string()) << e.what();
  EXPECT_EQ(e.line(), 4) << e.what();  // outline_file is the fourth line of wing_text
  EXPECT_EQ(e.key(), "planform.outline_file");
  EXPECT_NE(e.message().find("file not found"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("bwo.csv"), std::string::npos) << e.what();
}

TEST(OutlineCsv, AnOutlineFileThatIsNoFileIsTheWingFilesErrorAtItsLine) {
  // outline_file naming a folder or /dev/zero: before, the message named that path alone,
  // not the wing file and the line where it is written (as a missing file's does).
  flapsim::test::ScratchDir dir("outline_csv_not_a_file");
  std::filesystem::create_directories(dir / "a_folder.csv");
  for (const std::string target : {"a_folder.csv", "/dev/zero"}) {
    std::ofstream(dir / "w.toml") << wing_text("outline_file = \"" + target + "\"\nspan = 40.0\n");
    auto e = expect_input_error([&] { w::load_wing_file((dir / "w.toml").string()); });
    EXPECT_EQ(e.file(), (dir / "w.toml").string()) << e.what();
    EXPECT_EQ(e.line(), 4) << e.what();
    EXPECT_EQ(e.key(), "planform.outline_file");
    EXPECT_NE(e.message().find("not a regular file"), std::string::npos) << e.what();
    EXPECT_NE(e.message().find(target), std::string::npos) << e.what();
  }
}

TEST(OutlineCsv, DevicesAndHugeFilesAreRefusedWithoutReading) {
  // /dev/zero read without bound (the issue); now refused at once as not a regular file.
  const auto start = std::chrono::steady_clock::now();
  auto e = expect_input_error([&] { w::read_outline_csv("/dev/zero", "planform.outline_file"); });
  EXPECT_NE(e.message().find("not a regular file"), std::string::npos) << e.what();
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
  flapsim::test::ScratchDir dir("outline_csv_huge");
  {
    std::ofstream big(dir / "big.csv");
    const std::string row = "0.5,0.5\n";
    for (std::size_t n = 0; n <= w::kMaxOutlineFileBytes / row.size(); ++n) big << row;
  }
  e = expect_input_error([&] { w::read_outline_csv((dir / "big.csv").string(), "k"); });
  EXPECT_NE(e.message().find("larger than"), std::string::npos) << e.what();
}

TEST(MeshChecks, ASliverOutlinePassesNoLongerAndNamesTheOutline) {
  // The outline [[0,0],[1e-15,20],[0,40]]: aspect ratio R^2/S = 40^2 / (0.5 * 40 * 1e-15)
  // = 8e16, accepted by check and then fatal to gmsh.
  auto e = expect_input_error([&] {
    w::read_wing(w::parse_toml_string(wing_text("outline = [[0,0],[1e-15,20],[0,40]]\n"), "s.toml"));
  });
  EXPECT_EQ(e.key(), "planform.outline") << e.what();
  EXPECT_EQ(e.line(), 4);
  EXPECT_NE(e.message().find("sliver"), std::string::npos) << e.what();
}

TEST(MeshChecks, EstimatedElementCountFollowsAreaOverTriangleArea) {
  // 40 x 10 mm rectangle, h = h_v = 1 mm: S / (sqrt(3)/4 h^2) = 400 / 0.4330 = 923.8
  // membrane triangles, plus the vein band 2 * 30 mm * (0.5 + 3) mm = 210 mm^2 at the same
  // size (485.0) and 30 vein elements.
  const w::Wing wing = w::read_wing(
      w::parse_toml_string(wing_text(kRectangle, "[mesh]\nelement_size = 1.0\n"), "r.toml"));
  const double tri = std::sqrt(3.0) / 4.0;
  EXPECT_NEAR(w::estimated_mesh_elements(wing), 400.0 / tri + 210.0 / tri + 30.0, 1e-6);
}

TEST(MeshChecks, ATinyElementSizeIsRefusedBeforeMeshing) {
  // element_size = 1e-6 mm aborted with std::bad_alloc; 0.01 mm meshed for minutes.
  for (const char* h : {"1e-6", "0.01"}) {
    auto e = expect_input_error([&] {
      w::read_wing(w::parse_toml_string(wing_text(kRectangle, std::string("[mesh]\nelement_size = ") + h + "\n"),
                                        "r.toml"));
    });
    EXPECT_EQ(e.key(), "mesh.element_size") << e.what();
    EXPECT_EQ(e.line(), 20) << e.what();
    EXPECT_NE(e.message().find("budget"), std::string::npos) << e.what();
  }
  // The shipped wings stay well inside the budget.
  const w::Wing hawkmoth = w::load_wing_file(std::string(FLAPSIM_SOURCE_DIR) + "/wings/hawkmoth.toml");
  EXPECT_LT(w::estimated_mesh_elements(hawkmoth), 0.1 * w::kMaxMeshElements);
}

}  // namespace

TEST(VeinOnOutline, APointOutsideWithinTheToleranceIsMovedOntoTheOutline) {
  // The wing: a spar 0.03 mm outside a 40 mm wing's edge x = 5 mm (tolerance 0.1 %
  // of the span = 0.04 mm) passed check, was left outside the membrane by gmsh and made the
  // FEM singular. Each point now lies on the edge: x = 5 mm exactly (the nearest point of
  // the edge x = 5, y in [0, 40], to (5.03, y) is (5, y)).
  std::string text = wing_text(kRectangle);
  const std::string spar = "points = [[1.0, 0.0], [1.0, 30.0]]";
  text.replace(text.find(spar), spar.size(), "points = [[5.03, 2.0], [5.03, 30.0], [4.0, 35.0]]");
  const w::Wing wing = w::read_wing(w::parse_toml_string(text, "v.toml"));
  ASSERT_EQ(wing.veins[0].points.size(), 3u);
  EXPECT_EQ(wing.veins[0].points[0].x(), 5e-3);
  EXPECT_EQ(wing.veins[0].points[1].x(), 5e-3);
  EXPECT_NEAR(wing.veins[0].points[0].y(), 2e-3, 1e-15);
  EXPECT_NEAR(wing.veins[0].points[1].y(), 30e-3, 1e-15);
  EXPECT_EQ(wing.veins[0].points[2], Eigen::Vector2d(4e-3, 35e-3));  // inside: unchanged
  EXPECT_EQ(wing.veins[0].key, "veins[0].points");
  EXPECT_EQ(wing.veins[0].line, 15);
  // Beyond the tolerance (0.05 mm out) it is still refused, at the vein's key.
  text = wing_text(kRectangle);
  text.replace(text.find(spar), spar.size(), "points = [[5.05, 2.0], [5.05, 30.0]]");
  auto e = expect_input_error([&] { w::read_wing(w::parse_toml_string(text, "v.toml")); });
  EXPECT_EQ(e.key(), "veins[0].points") << e.what();
  EXPECT_NE(e.message().find("leaves the outline"), std::string::npos) << e.what();
  // How far: the edge is x = 5 mm, the vein x = 5.05 mm.
  EXPECT_NE(e.message().find("0.05 mm outside it"), std::string::npos) << e.what();
  EXPECT_EQ(e.message().find("spline"), std::string::npos) << e.what();
}

TEST(VeinOnOutline, APointInsideWithinTheToleranceIsMovedOntoTheOutlineToo) {
  // A user's root spar written to start on a swept leading edge, 1.1 µm inside it on a 95 mm
  // wing (tests/data/swept_film_50um_wing.toml): gmsh meshed the gap into a triangle of 0.03°
  // (fem.MeshSlivers.*). Here 1 µm inside the edge x = 5 mm of the 40 mm rectangle
  // (tolerance 0.04 mm): onto the edge, x = 5 mm exactly; 1 mm inside stays.
  std::string text = wing_text(kRectangle);
  const std::string spar = "points = [[1.0, 0.0], [1.0, 30.0]]";
  text.replace(text.find(spar), spar.size(), "points = [[4.999, 2.0], [3.0, 30.0], [4.0, 35.0]]");
  const w::Wing wing = w::read_wing(w::parse_toml_string(text, "v.toml"));
  ASSERT_EQ(wing.veins[0].points.size(), 3u);
  EXPECT_EQ(wing.veins[0].points[0].x(), 5e-3);
  EXPECT_NEAR(wing.veins[0].points[0].y(), 2e-3, 1e-15);
  EXPECT_EQ(wing.veins[0].points[1], Eigen::Vector2d(3e-3, 30e-3));
  EXPECT_EQ(wing.veins[0].points[2], Eigen::Vector2d(4e-3, 35e-3));
}

TEST(VeinOnOutline, AVeinAlongAStraightRunOfSplinePointsIsToldTheCurveSwings) {
  // A user's straight edge drawn as spline control points x = 5 mm at y = 0, 10, 20, 30, 40
  // with square corners: the periodic C² spline passes through them but swings inside
  // between them next to the corners (0.17 mm at y = 12.5 mm, measured), so a spar along
  // x = 5 mm leaves it. The message says how far and why, and what to do.
  std::string text = wing_text(
      "spline = [[5.0, 0.0], [5.0, 10.0], [5.0, 20.0], [5.0, 30.0], [5.0, 40.0], [-5.0, 40.0], "
      "[-5.0, 0.0]]\n");
  const std::string spar = "points = [[1.0, 0.0], [1.0, 30.0]]";
  text.replace(text.find(spar), spar.size(), "points = [[5.0, 2.0], [5.0, 30.0]]");
  auto e = expect_input_error([&] { w::read_wing(w::parse_toml_string(text, "v.toml")); });
  EXPECT_EQ(e.key(), "veins[0].points") << e.what();
  EXPECT_NE(e.message().find("mm outside it"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("draw straight edges with 'outline'"), std::string::npos) << e.what();
}

// An ellipse of n points (x semi-axis 0.15, y from 0 to 1: units of the span), as a CSV body.
std::string ellipse_csv(std::size_t n) {
  std::string s = "x,y\n";
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2.0 * M_PI * static_cast<double>(i) / static_cast<double>(n);
    s += std::to_string(0.15 * std::cos(t)) + "," + std::to_string(0.5 + 0.5 * std::sin(t)) + "\n";
  }
  return s;
}

TEST(OutlineLimits, AnOutlineOfMoreThanTheMostPointsIsRefusedAtThePointBeyond) {
  // A 20,000-point CSV outline took 36 CPU s of `check` (gmsh building one edge per point,
  // about n^2); the limit (5000 points) is refused while reading, at the first point beyond.
  flapsim::test::ScratchDir dir("outline_limits");
  std::ofstream(dir / "long.csv") << ellipse_csv(w::kMaxOutlinePoints + 1);
  std::ofstream(dir / "w.toml") << wing_text("outline_file = \"long.csv\"\nspan = 40.0\n");
  auto e = expect_input_error([&] { w::load_wing_file((dir / "w.toml").string()); });
  EXPECT_EQ(e.file(), (dir / "long.csv").lexically_normal().string()) << e.what();
  EXPECT_EQ(e.line(), static_cast<int>(w::kMaxOutlinePoints) + 2) << e.what();  // header on line 1
  EXPECT_EQ(e.key(), "planform.outline_file");
  EXPECT_NE(e.message().find("more than 5000 outline points"), std::string::npos) << e.what();
  // Exactly the limit is read.
  std::ofstream(dir / "max.csv") << ellipse_csv(w::kMaxOutlinePoints);
  EXPECT_EQ(w::read_outline_csv((dir / "max.csv").string(), "k").size(), w::kMaxOutlinePoints);

  // The same outline inline: refused at the line of point 5001 (one point a line).
  std::string rows = "outline = [\n";
  for (std::size_t i = 0; i <= w::kMaxOutlinePoints; ++i) {
    const double t = 2.0 * M_PI * static_cast<double>(i) / static_cast<double>(w::kMaxOutlinePoints + 1);
    rows += '[';  // appended piece by piece: GCC 12 warns (-Wrestrict) on "[" + string
    rows += std::to_string(6.0 * std::cos(t));
    rows += ", ";
    rows += std::to_string(20.0 + 20.0 * std::sin(t));
    rows += "],\n";
  }
  rows += "]\n";
  e = expect_input_error([&] { w::read_wing(w::parse_toml_string(wing_text(rows), "i.toml")); });
  EXPECT_EQ(e.key(), "planform.outline") << e.what();
  EXPECT_EQ(e.line(), 5 + static_cast<int>(w::kMaxOutlinePoints)) << e.what();  // point 1 on line 5

  // A shape or spline sampled with more points: outline_points is bounded by the same limit.
  e = expect_input_error([&] {
    w::read_wing(w::parse_toml_string(
        wing_text("shape = \"half_ellipse\"\nspan = 40.0\nchord = 12.0\noutline_points = 5001\n"), "s.toml"));
  });
  EXPECT_EQ(e.key(), "planform.outline_points") << e.what();
}

// A header with units ("x_mm,y_mm", "x [mm], y [mm]", "X_coord<tab>Y_coord") is a header: a
// user's own swept-wing outline with "x_mm,y_mm" on line 1 was refused as "expected a line
// "x,y" ... found "x_mm,y_mm"". A header naming the columns the other way round, or not as
// x and y, is named at its line as a header, with what the columns must be.
TEST(OutlineCsv, AHeaderWithUnitsIsAHeader) {
  flapsim::test::ScratchDir dir("outline_csv_header_units");
  for (const std::string header : {"x_mm,y_mm", "x [mm], y [mm]", "X_coord\tY_coord", "x,y"}) {
    std::ofstream(dir / "o.csv") << header << "\n0.1,0\n0.1,1\n-0.2,1\n";
    const auto o = w::read_outline_csv_lines((dir / "o.csv").string(), "k");
    ASSERT_EQ(o.points.size(), 3u) << header;
    EXPECT_EQ(o.lines[0], 2) << header;  // the header is line 1
  }
  for (const std::string header : {"y,x", "span,chord"}) {
    std::ofstream(dir / "p.csv") << "# drawn by hand\n" << header << "\n0.1,0\n0.1,1\n-0.2,1\n";
    const auto e = expect_input_error([&] { w::read_outline_csv((dir / "p.csv").string(), "k"); });
    EXPECT_EQ(e.line(), 2) << header;
    EXPECT_NE(std::string(e.what()).find("a header line names x first, then y"), std::string::npos)
        << e.what();
  }
  // A data line with a typo stays a data error, not a header's.
  std::ofstream(dir / "q.csv") << "x,y\n0.1,0\n0.1,1O\n-0.2,1\n";
  const auto e = expect_input_error([&] { w::read_outline_csv((dir / "q.csv").string(), "k"); });
  EXPECT_EQ(e.line(), 3);
  EXPECT_NE(std::string(e.what()).find("expected a line"), std::string::npos) << e.what();
}
