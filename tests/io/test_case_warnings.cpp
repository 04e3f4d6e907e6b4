// A hover of many cycles with every wake row free is accepted with a warning. Before: a
// 10-cycle hover of the rigid hawkmoth (hover.toml with cycles = 10, 40 steps, 4 x 6 panels)
// ran without a word, its mean lift per cycle 7.2, 6.8, 6.8, 7.0, 6.4, 6.7, 7.3, 7.2, then
// 11.3 and 13.0 mN (peak 36.8 mN): the wake piles up under the wing (docs/uvlm.md, "Hover
// over many cycles", measured there from cycle 4-6 on). Shorter ones already hinge on
// round-off: cases/rotation_phase_rigid.toml with the whole wake free, its frequency changed
// by 1e-9 of itself, moved the mean lift of cycle 1 by 4e-8, of cycle 2 by 0.2-1.2 %, of
// cycle 3 by 12-39 % (docs/case_file.md, "Checks"). So every hover of more than one cycle
// with the whole wake free is warned. The warning names numerics.cycles and the remedy
// (far_wake_cycles); a far wake, a truncated wake, a free stream or a one-cycle run gives
// none.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "hover_case_text.hpp"
#include "inline_case.hpp"
#include "pipeline/io/input_hash.hpp"

namespace {

/// `c` has exactly one warning, at `key` on `line`, whose message contains `text`.
void expect_only_warning(const flapsim::io::Case& c, const std::string& key, int line,
                         const std::string& text) {
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_EQ(c.warnings[0].key, key);
  EXPECT_EQ(c.warnings[0].line, line);
  EXPECT_NE(c.warnings[0].message.find(text), std::string::npos) << c.warnings[0].message;
}

TEST(CaseWarnings, ALongHoverWithTheWholeWakeFreeIsWarned) {
  // The whole wake free is asked for (far_wake_cycles = 0): a hover that leaves the key out
  // gets the far wake (below).
  expect_only_warning(case_from_text(hover_case_text("cycles = 10\nfar_wake_cycles = 0.0\n")),
                      "numerics.cycles", 10, "far_wake_cycles = 0.5");
}

// A hover case that leaves far_wake_cycles out gets 0.5, what every shipped hover case sets:
// with the whole wake free the rigid hawkmoth hover's cycle-3 mean lift moved by up to 39 %
// under a 1e-9 change of the frequency (docs/uvlm.md, "Hover over many cycles"; read_case).
// Not a wing in a free stream, a revolving one, one whose sweep does not swing (its far wake
// would have no disk), nor a prescribed or truncated wake; a written 0 stays 0.
TEST(CaseWarnings, AHoverWithoutAFarWakeKeyGetsTheFarWakeAfterHalfACycle) {
  const auto far_wake = [](const std::string& numerics, const std::string& air = "") {
    return case_from_text(hover_case_text(numerics, air)).numerics.far_wake_cycles;
  };
  EXPECT_EQ(far_wake("cycles = 10\n"), 0.5);
  EXPECT_TRUE(case_from_text(hover_case_text("cycles = 10\n")).warnings.empty());
  EXPECT_EQ(far_wake("cycles = 10\nfar_wake_cycles = 0.0\n"), 0.0);
  EXPECT_EQ(far_wake("cycles = 10\nfar_wake_cycles = 0.625\n"), 0.625);
  EXPECT_EQ(far_wake("cycles = 10\n", "[air]\nfreestream = [-3.0, 0.0, 0.0]\n"), 0.0);
  EXPECT_EQ(far_wake("cycles = 10\nfree_wake = false\n"), 0.0);
  EXPECT_EQ(far_wake("cycles = 10\nwake_max_rows = 40\n"), 0.0);
  EXPECT_EQ(far_wake("cycles = 10\nfrozen_wake_cycles = 1.0\n"), 0.0);
  std::string still_sweep = hover_case_text("cycles = 10\n");
  still_sweep.replace(still_sweep.find("sweep = { cos_deg = [50.0] }"), 28, "sweep = 10.0");
  EXPECT_EQ(case_from_text(still_sweep).numerics.far_wake_cycles, 0.0);
  EXPECT_EQ(case_from_text(revolving_instead(hover_case_text("cycles = 10\n"))).numerics.far_wake_cycles,
            0.0);
  std::string heaving = hover_case_text("cycles = 10\n");  // a pivot that moves (a plunge)
  heaving.replace(heaving.find("frequency_hz = 20.0\n"), 20,
                  "frequency_hz = 20.0\nheave = { sin_m = [0.005] }\n");
  EXPECT_EQ(case_from_text(heaving).numerics.far_wake_cycles, 0.0);
}

TEST(CaseWarnings, AFarWakeATruncatedWakeAFreeStreamOrAShortRunIsNotWarned) {
  EXPECT_TRUE(case_from_text(hover_case_text("cycles = 10\nfar_wake_cycles = 0.5\n")).warnings.empty());
  EXPECT_TRUE(case_from_text(hover_case_text("cycles = 10\nwake_max_rows = 40\n")).warnings.empty());
  EXPECT_TRUE(case_from_text(hover_case_text("cycles = 10\n", "[air]\nfreestream = [-3.0, 0.0, 0.0]\n")).warnings.empty());
  EXPECT_TRUE(case_from_text(hover_case_text("cycles = 1\n")).warnings.empty());
}

// A revolving wing's cycles are time units: over less than one revolution it never comes
// round to its wake, so the hover's wake warnings (the whole free wake's round-off, a
// prescribed or frozen wake it sweeps back through, the far wake's measured range) do not
// apply (the Robofly wing's half revolution in 2 cycles, cases/robofly_revolving.toml, was
// warned of the round-off); once it turns beyond one revolution it meets its wake as a hover
// does, and is.
TEST(CaseWarnings, ARevolvingWingIsWarnedOfItsWakeOnlyOnceItComesRound) {
  auto revolving = [](double rate_deg_per_s, int cycles, const std::string& more = "") {
    std::string text = hover_case_text("cycles = " + std::to_string(cycles) + "\n" + more);
    const std::string flapping =
        "sweep = { cos_deg = [50.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n";
    text.replace(text.find(flapping), flapping.size(),
                 "sweep = 0.0\nrotation = 50.0\nrevolution = { rate_deg_per_s = " +
                     std::to_string(rate_deg_per_s) + " }\n");
    return case_from_text(text);
  };
  // 20 Hz: a cycle is 0.05 s. 2 cycles at −1800°/s: 180°; 8 cycles: 720°.
  EXPECT_TRUE(revolving(-1800.0, 2).warnings.empty());
  EXPECT_TRUE(revolving(-1800.0, 3).warnings.empty());  // 270°
  EXPECT_TRUE(revolving(-1800.0, 3, "free_wake = false\n").warnings.empty());
  EXPECT_TRUE(revolving(-1800.0, 3, "frozen_wake_cycles = 1.0\n").warnings.empty());
  EXPECT_TRUE(revolving(-1800.0, 3, "far_wake_cycles = 2.0\n").warnings.empty());
  // The revolution adds a line to [kinematics]: numerics from line 11.
  expect_only_warning(revolving(-1800.0, 8), "numerics.cycles", 11, "round-off");
  expect_only_warning(revolving(-1800.0, 8, "free_wake = false\n"), "numerics.free_wake", 12,
                      "set free_wake = true");
  // The far wake's measured range is in wingbeats of a flapping hover; a revolving wing's
  // cycle is a time unit (until 2 Dec the same run was warned or not with frequency_hz).
  EXPECT_TRUE(revolving(-1800.0, 8, "far_wake_cycles = 2.0\n").warnings.empty());
  // Its revolutions are what the long hover's warning counts: 720° in 8 cycles.
  EXPECT_NE(revolving(-1800.0, 8).warnings[0].message.find("2 revolutions of hover with the whole wake free"),
            std::string::npos);
}

// A wing whose span sweeps no disk (it plunges: its pivot moves, its span keeps one direction)
// cannot have the far wake (refused, pipeline/app/fsi_setup.cpp): the long hover's warning
// names what it can do instead (until 2 Dec it said "set far_wake_cycles = 0.5", which is
// then refused).
TEST(CaseWarnings, ALongHoverOfAWingWithoutASweepIsNotToldToSetTheFarWake) {
  std::string text = hover_case_text("cycles = 3\nfar_wake_cycles = 0.0\n");
  const std::string sweep = "sweep = { cos_deg = [50.0] }\n";
  ASSERT_NE(text.find(sweep), std::string::npos);
  text.replace(text.find(sweep), sweep.size(), "sweep = 0.0\nheave = { sin_m = [0.005] }\n");
  const flapsim::io::Case c = case_from_text(text);
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_EQ(c.warnings[0].key, "numerics.cycles");
  EXPECT_NE(c.warnings[0].message.find("sweeps no disk"), std::string::npos) << c.warnings[0].message;
  EXPECT_EQ(c.warnings[0].message.find("set far_wake_cycles = 0.5"), std::string::npos)
      << c.warnings[0].message;
}

// A revolution's ramp that lasts beyond the start of the last cycle: the reported mean (the
// last cycle's) is taken while the wing still speeds up, on the full rate's reference speed
// (cases/robofly_revolving.toml, "separated": mean CL 2.280 without a ramp, 1.771 with a
// 0.45 s ramp of a 0.5 s run; pipeline/io/case_file.cpp). Warned at the revolution's line
// with the cycles that would hold the ramp; a ramp that ends by the last cycle is not.
TEST(CaseWarnings, ARevolutionStillSpeedingUpInTheLastCycleIsWarned) {
  auto revolving = [](const std::string& ramp_s, int cycles) {
    std::string text = hover_case_text("cycles = " + std::to_string(cycles) + "\nfar_wake_cycles = 0.5\n");
    const std::string flapping =
        "sweep = { cos_deg = [50.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n";
    text.replace(
        text.find(flapping), flapping.size(),
        "sweep = 0.0\nrotation = 50.0\nrevolution = { rate_deg_per_s = -1800.0, ramp_s = " + ramp_s + " }\n");
    return case_from_text(text);
  };
  // 20 Hz: a cycle is 0.05 s; 3 cycles start their last at 0.1 s.
  EXPECT_TRUE(revolving("0.1", 3).warnings.empty());
  EXPECT_TRUE(revolving("0.0", 1).warnings.empty());
  // The revolution is on line 6 (after the wing, [kinematics], frequency_hz, sweep and rotation).
  expect_only_warning(revolving("0.12", 3), "kinematics.revolution.ramp_s", 6, "run at least 4 cycles");
  expect_only_warning(revolving("1.0", 3), "kinematics.revolution.ramp_s", 6, "run at least 21 cycles");
}

// A rotation phase with nothing to shift: δψ moves the sweep and deviation against the
// rotation, so with a constant sweep (a revolving wing) it changes nothing (the Robofly case
// over rotation_phase = -0.1, 0: the same mean CL to the last digit); warned at its line, and
// its inputs hash leaves it out. A flapping stroke is shifted: no warning, another hash.
TEST(CaseWarnings, ARotationPhaseWithNothingToShiftIsWarnedAndLeftOutOfTheHash) {
  const std::string flapping =
      "sweep = { cos_deg = [50.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n";
  auto with_phase = [&](const std::string& phase, bool revolving) {
    std::string text = hover_case_text("cycles = 1\n");
    text.replace(
        text.find(flapping), flapping.size(),
        (revolving ? "sweep = 0.0\nrotation = 50.0\nrevolution = { rate_deg_per_s = -1800.0 }\n" : flapping) +
            "rotation_phase = " + phase + "\n");
    return case_from_text(text);
  };
  // The phase is line 7, after the wing, [kinematics], frequency_hz, the sweep, the rotation and the
  // revolution.
  expect_only_warning(with_phase("0.1", true), "kinematics.rotation_phase", 7, "it changes nothing");
  EXPECT_TRUE(with_phase("0.0", true).warnings.empty());
  EXPECT_TRUE(with_phase("0.1", false).warnings.empty());
  EXPECT_EQ(flapsim::io::input_hash(with_phase("0.1", true), nullptr, "", 1.0),
            flapsim::io::input_hash(with_phase("-0.2", true), nullptr, "", 1.0));
  EXPECT_NE(flapsim::io::input_hash(with_phase("0.1", false), nullptr, "", 1.0),
            flapsim::io::input_hash(with_phase("-0.2", false), nullptr, "", 1.0));
}

// Few steps a wingbeat: the flexible hawkmoth hover's mean lift lies 18, 13, 9, 6, 5 % below its
// 100-step value at 7, 12, 16, 20, 24 steps a cycle and 1 % at 40-50 (measured 1 Dec,
// pipeline/io/case_file.cpp): below 24 steps warned at the key's line, with the numbers; a
// revolving wing (its cycle a time unit) is not.
TEST(CaseWarnings, FewStepsAWingbeatAreWarned) {
  auto with_steps = [](int steps, const std::string& numerics = "cycles = 1\n") {
    std::string text = hover_case_text(numerics);
    const std::string forty = "steps_per_cycle = 40";
    text.replace(text.find(forty), forty.size(), "steps_per_cycle = " + std::to_string(steps));
    return text;
  };
  expect_only_warning(case_from_text(with_steps(20)), "numerics.steps_per_cycle", 9, "5 % at 24");
  expect_only_warning(case_from_text(with_steps(7)), "numerics.steps_per_cycle", 9, "7 steps a wingbeat");
  EXPECT_TRUE(case_from_text(with_steps(24)).warnings.empty());
  EXPECT_TRUE(case_from_text(revolving_instead(with_steps(12))).warnings.empty());
}

// A thin wake core in hover: below 0.15 mean chords the hover's lift goes erratic with finer
// steps (the rigid hawkmoth hover's last-cycle CL 2.27 / 0.23 / 4.34 at 50 / 100 / 200 steps with
// 0.05; 2.780 / 2.771 / 2.775 with 0.2; pipeline/io/case_file.cpp, test
// app.DefaultCoreHover.*): warned at the key; 0.15, the default, a free stream or a
// revolving wing not.
TEST(CaseWarnings, AThinWakeCoreInHoverIsWarned) {
  expect_only_warning(case_from_text(hover_case_text("cycles = 1\ncore_radius = 0.05\n")),
                      "numerics.core_radius", 11, "cores below 0.15 make its lift erratic");
  expect_only_warning(case_from_text(hover_case_text("cycles = 1\ncore_radius = 0.1\n")),
                      "numerics.core_radius", 11, "a wake core of 0.1 mean chords in hover");
  EXPECT_TRUE(case_from_text(hover_case_text("cycles = 1\ncore_radius = 0.15\n")).warnings.empty());
  EXPECT_TRUE(case_from_text(hover_case_text("cycles = 1\n")).warnings.empty());
  EXPECT_TRUE(case_from_text(hover_case_text("cycles = 1\ncore_radius = 0.05\n",
                                             "[air]\nfreestream = [-3.0, 0.0, 0.0]\n"))
                  .warnings.empty());
  EXPECT_TRUE(case_from_text(revolving_instead(hover_case_text("cycles = 1\ncore_radius = 0.05\n")))
                  .warnings.empty());
}

// A liquid with air's viscosity: water's density and no numerics.kinematic_viscosity gives
// the core growth and the Reynolds number of air (pipeline/io/case_file.cpp): warned at
// air.density; with the fluid's ν written, or at 8 times air's density, not.
TEST(CaseWarnings, AFluidDenserThanAirWithAirsViscosityIsWarned) {
  expect_only_warning(case_from_text(hover_case_text("cycles = 1\n", "[air]\ndensity = 998.0\n")),
                      "air.density", 9, "numerics.kinematic_viscosity left at air's 1.5e-5");
  EXPECT_TRUE(case_from_text(
                  hover_case_text("cycles = 1\nkinematic_viscosity = 1.0e-6\n", "[air]\ndensity = 998.0\n"))
                  .warnings.empty());
  EXPECT_TRUE(case_from_text(hover_case_text("cycles = 1\n", "[air]\ndensity = 9.8\n")).warnings.empty());
  EXPECT_EQ(flapsim::io::kDenseFluidDensity, 10.0);
}

TEST(CaseWarnings, ATwoCycleHoverWithTheWholeWakeFreeIsWarned) {
  const flapsim::io::Case c = case_from_text(hover_case_text("cycles = 2\nfar_wake_cycles = 0.0\n"));
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_EQ(c.warnings[0].key, "numerics.cycles");
  EXPECT_NE(c.warnings[0].message.find("round-off"), std::string::npos) << c.warnings[0].message;
}

}  // namespace

namespace {

TEST(CaseMessages, ARigidWingWithSeveralBodiesSaysWhatToDo) {
  // Before: "value 5 out of range: must be in [1, 1]".
  const flapsim::InputError e = error_of(
      "wing = \"valid_tiny_wing.toml\"\n[kinematics]\nfrequency_hz = 20.0\nsweep = 40.0\nrotation = 90.0\n"
      "[structure]\nkind = \"rigid\"\nbodies = 5\n");
  EXPECT_EQ(e.key(), "structure.bodies");
  EXPECT_EQ(e.line(), 8);
  EXPECT_NE(e.message().find("a rigid wing is one body (found 5)"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("kind = \"flexible\""), std::string::npos) << e.what();
}

TEST(CaseMessages, AnAirOfNoDensitySaysHowAVacuumIsWritten) {
  // Before: "value 0 out of range: must be > 0", for a user who meant a run in vacuum.
  const flapsim::InputError e = error_of(
      "wing = \"valid_tiny_wing.toml\"\n[kinematics]\nfrequency_hz = 20.0\nsweep = 40.0\nrotation = 90.0\n"
      "[air]\ndensity = 0.0\n[structure]\nkind = \"rigid\"\n");
  EXPECT_EQ(e.key(), "air.density");
  EXPECT_EQ(e.line(), 7);
  EXPECT_NE(e.message().find("must be > 0"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("air = \"none\""), std::string::npos) << e.what();
}

}  // namespace

// leading_edge = "shed" is warned about as experimental at its key (pipeline/io/case_file.cpp,
// warn_experimental_shedding); in vacuum there is no lattice and nothing is shed, so no
// warning (a user's case with air = "none" was told "shed is experimental").
TEST(CaseWarnings, TheShedLeadingEdgeIsWarnedAboutInAirOnly) {
  const auto c = case_from_text(hover_case_text("leading_edge = \"shed\"\n"));
  const auto shed = std::find_if(c.warnings.begin(), c.warnings.end(),
                                 [](const auto& w) { return w.key == "numerics.leading_edge"; });
  ASSERT_NE(shed, c.warnings.end());
  EXPECT_EQ(shed->line, 10);
  EXPECT_NE(shed->message.find("\"shed\" is experimental"), std::string::npos) << shed->message;
  EXPECT_TRUE(case_from_text("air = \"none\"\n" + hover_case_text("leading_edge = \"shed\"\n")).warnings.empty());
}

namespace {

TEST(CaseWarnings, APrescribedWakeInStillAirIsWarnedAndWithAShedLeadingEdgeRefused) {
  // pipeline/io/case_file.cpp, still_air_prescribed_wake: a prescribed wake moves with the
  // free stream only (test app.StillAirPrescribedWake.*: the rigid hawkmoth hover lifts 11 %
  // less with it, a third less without far_wake_cycles). Warned naming numerics.free_wake on
  // its line; in a free stream (the flat wake of the verification cases) not; with
  // leading_edge = "shed" in still air bad input naming numerics.free_wake; in a free stream
  // accepted.
  expect_only_warning(case_from_text(hover_case_text("cycles = 1\nfree_wake = false\n")),
                      "numerics.free_wake", 11, "set free_wake = true");
  const std::string stream = "[air]\nfreestream = [-3.0, 0.0, 0.0]\n";
  EXPECT_TRUE(case_from_text(hover_case_text("cycles = 1\nfree_wake = false\n", stream)).warnings.empty());
  const flapsim::InputError e =
      error_of(hover_case_text("cycles = 1\nleading_edge = \"shed\"\nfree_wake = false\n"));
  EXPECT_EQ(e.key(), "numerics.free_wake");
  EXPECT_EQ(e.line(), 12);
  EXPECT_NE(e.message().find("needs a free wake"), std::string::npos) << e.what();
  const flapsim::io::Case glide =
      case_from_text(hover_case_text("cycles = 1\nleading_edge = \"shed\"\nfree_wake = false\n", stream));
  EXPECT_FALSE(glide.numerics.free_wake);
}

TEST(CaseWarnings, AFrozenFarWakeInStillAirIsWarned) {
  // pipeline/io/case_file.cpp, warn_frozen_wake_in_still_air: frozen rows in hover stay where
  // they were shed (the rigid hawkmoth hover: mean CL 2.30 against 2.77 with the far wake
  // convected, test app.StillAirPrescribedWake.AFrozenFarWake…). Warned naming
  // numerics.frozen_wake_cycles on its line; in a free stream not, in a run of one cycle (a
  // longer one is: its rows pile up behind the wing, CaseWarnings.AFrozenWakeInAFreeStreamIsWarned).
  expect_only_warning(case_from_text(hover_case_text("cycles = 1\nfrozen_wake_cycles = 0.5\n")),
                      "numerics.frozen_wake_cycles", 11, "set far_wake_cycles = 0.5");
  EXPECT_TRUE(case_from_text(hover_case_text("cycles = 1\nfrozen_wake_cycles = 0.5\n",
                                             "[air]\nfreestream = [-3.0, 0.0, 0.0]\n"))
                  .warnings.empty());
}

// A rigid case's chain file is not read (the wing file's outline is the one rigid body): a
// broken chain file (garbage = [) passed check and run without a word, where --chain on such
// a case is warned. The case's chain key is warned too, at its line. (The file need only
// exist; any existing file stands for it here.) A flexible case reads it: no warning.
TEST(CaseWarnings, ARigidCasesChainFileIsWarnedAsUnused) {
  const std::string rigid = "chain = \"valid_tiny_case.toml\"\n" + hover_case_text("cycles = 1\n");
  expect_only_warning(case_from_text(rigid), "chain", 1, "not used: structure.kind = \"rigid\"");
  std::string flexible = rigid;
  flexible.replace(flexible.find("kind = \"rigid\""), 14, "kind = \"flexible\"\nbodies = 2");
  EXPECT_TRUE(case_from_text(flexible).warnings.empty());
}

// A harmonic the time step cannot resolve (harmonic n needs more than 2n steps a cycle,
// docs/case_file.md): a sweep with a 21st harmonic at 40 steps ran without a word, its motion
// aliased. Warned at steps_per_cycle, naming the harmonic and the signal; the 19th is not.
TEST(CaseWarnings, AHarmonicTheStepCannotResolveIsWarned) {
  const auto with_highest = [](int n) {
    std::string coefficients = "50.0";
    for (int k = 2; k <= n; ++k) coefficients += k == n ? ", 0.5" : ", 0.0";
    std::string text = hover_case_text("cycles = 1\n");
    const std::string sweep = "sweep = { cos_deg = [50.0] }";
    text.replace(text.find(sweep), sweep.size(), "sweep = { cos_deg = [" + coefficients + "] }");
    return case_from_text(text);
  };
  expect_only_warning(with_highest(21), "numerics.steps_per_cycle", 9,
                      "do not resolve harmonic 21 of kinematics.sweep");
  expect_only_warning(with_highest(20), "numerics.steps_per_cycle", 9, "use more than 40 steps a cycle");
  EXPECT_TRUE(with_highest(19).warnings.empty());
}

}  // namespace
