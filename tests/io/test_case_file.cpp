// Case files: the shipped hover case, signals (harmonic, tabulated, constant), defaults,
// loads and markers, and bad input located by file, line and key.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <numbers>
#include <string>

#include "mbd/angle_units.hpp"
#include "inline_case.hpp"
#include "pipeline/io/case_file.hpp"
#include "pipeline/io/case_model.hpp"
#include "pipeline/io/case_summary.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/toml_reader.hpp"

namespace p = flapsim::io;
using flapsim::InputError;

namespace {

const std::string kSource = FLAPSIM_SOURCE_DIR;
using flapsim::kDegToRad;

const std::string kHead =
    "wing = \"valid_tiny_wing.toml\"\n"                                   // 1
    "[kinematics]\n"                                                      // 2
    "frequency_hz = 20.0\n"                                               // 3
    "sweep = { mean_deg = 0.0, cos_deg = [60.0] }\n"                      // 4
    "rotation = { mean_deg = 90.0, sin_deg = [-60.0] }\n"                 // 5
    "[structure]\n"                                                       // 6
    "kind = \"rigid\"\n";                                                 // 7

/// Each of `bad` (two lines after kHead's and [numerics], the key on line 10) is bad input
/// naming numerics.`key` on line 10.
void expect_numerics_key_refused(const std::string& key, std::initializer_list<const char*> bad) {
  for (const char* text : bad) {
    const auto e = error_of(kHead + "[numerics]\n" + text);
    EXPECT_EQ(e.key(), "numerics." + key) << text;
    EXPECT_EQ(e.line(), 10) << text;
  }
}

/// A [numerics] choice key: `fallback` without it, `value` read from `name`, and an unknown
/// name bad input naming numerics.`key` on line 9.
template <class T>
void expect_numerics_choice(const std::string& key, T p::Case::Numerics::*member, T fallback, const std::string& name,
                            T value) {
  EXPECT_EQ(case_from_text(kHead).numerics.*member, fallback) << key;
  EXPECT_EQ(case_from_text(kHead + "[numerics]\n" + key + " = \"" + name + "\"\n").numerics.*member, value) << key;
  const auto e = error_of(kHead + "[numerics]\n" + key + " = \"no_such_" + name + "\"\n");  // line 9
  EXPECT_EQ(e.key(), "numerics." + key);
  EXPECT_EQ(e.line(), 9);
}

}  // namespace

TEST(CaseFile, HoverCaseIsEquation8) {
  const p::Case c = p::load_case_file(kSource + "/cases/hover.toml");
  EXPECT_EQ(c.name, "hover");
  EXPECT_NE(c.wing_file.find("wings/hawkmoth.toml"), std::string::npos);
  EXPECT_DOUBLE_EQ(c.kinematics.frequency, 26.1);
  EXPECT_DOUBLE_EQ(c.kinematics.rotation_phase, 0.0);
  EXPECT_EQ(c.structure.kind, p::Case::Structure::Kind::Flexible);
  EXPECT_EQ(c.structure.bodies, 10);
  EXPECT_EQ(c.numerics.chordwise_panels, 6);   // RP §3: 6 x 10 panels
  EXPECT_EQ(c.numerics.spanwise_panels, 10);
  EXPECT_TRUE(c.air.enabled);
  EXPECT_DOUBLE_EQ(c.air.density, 1.225);
  // Eq. 8 (RP), δψ = 0: φ = 10° + 50° cos 2πft, α = 90° − 45° sin 2πft.
  const double f = 26.1;
  for (double s : {0.0, 0.1, 0.25, 0.6, 0.75}) {
    const auto a = c.kinematics.angles(s / f);
    EXPECT_NEAR(a.sweep.value, (10.0 + 50.0 * std::cos(2 * std::numbers::pi * s)) * kDegToRad, 1e-12);
    EXPECT_NEAR(a.rotation.value, (90.0 - 45.0 * std::sin(2 * std::numbers::pi * s)) * kDegToRad, 1e-12);
    EXPECT_NEAR(a.deviation.value, 0.0, 1e-15);
  }
  // docs/kinematics.md: geometric angle of attack 45° at mid-downstroke and at mid-upstroke.
  EXPECT_NEAR(*p::geometric_angle_of_attack(c.kinematics.angles(0.25 / f)), 45.0 * kDegToRad, 1e-12);
  EXPECT_NEAR(*p::geometric_angle_of_attack(c.kinematics.angles(0.75 / f)), 45.0 * kDegToRad, 1e-12);
  EXPECT_FALSE(p::geometric_angle_of_attack(c.kinematics.angles(0.0)));  // stroke reversal
  // A measured wingbeat's spline stops at its reversal to round-off (a user's CSV of eq. 8:
  // φ̇ = −2.4e-9 rad/s at phase 0, which read "downstroke", 90°): at the wingbeat's frequency
  // a millionth of a 1 rad sweep's rate (1.6e-4 rad/s at 26.1 Hz) is still a reversal; the
  // mid-stroke rate, 2π f 50° = 143 rad/s, is not.
  flapsim::mbd::WingKinematics::Angles at_rest = c.kinematics.angles(0.0);
  at_rest.sweep.rate = -2.4e-9;
  EXPECT_TRUE(p::geometric_angle_of_attack(at_rest).has_value());  // without f: the absolute 1e-9 rad/s
  EXPECT_FALSE(p::geometric_angle_of_attack(at_rest, f).has_value());
  EXPECT_TRUE(p::geometric_angle_of_attack(c.kinematics.angles(0.25 / f), f).has_value());
}

TEST(CaseFile, DefaultsWhenSectionsAreOmitted) {
  const p::Case c = case_from_text(kHead);
  EXPECT_EQ(c.name, "inline_case");
  EXPECT_EQ(c.structure.kind, p::Case::Structure::Kind::Rigid);
  EXPECT_EQ(c.structure.bodies, 1);
  EXPECT_EQ(c.numerics.steps_per_cycle, 100);
  EXPECT_EQ(c.numerics.cycles, 3);
  EXPECT_EQ(c.numerics.chordwise_panels, 6);
  EXPECT_EQ(c.numerics.spanwise_panels, 10);
  EXPECT_EQ(c.numerics.core_model, flapsim::uvlm::CoreModel::LambOseen);
  EXPECT_EQ(c.numerics.wake_order, 1);
  EXPECT_TRUE(c.numerics.free_wake);
  EXPECT_DOUBLE_EQ(c.air.density, 1.225);
  EXPECT_TRUE(c.air.freestream.isZero());
  // Eq. 7 in the convention of docs/kinematics.md: α = 90° − 60° sin 2πft → AoA 30° at mid-downstroke.
  EXPECT_NEAR(*p::geometric_angle_of_attack(c.kinematics.angles(0.25 / 20.0)), 30.0 * kDegToRad, 1e-12);
}

TEST(CaseFile, TabulatedAndConstantSignalsVacuumLoadsMarkers) {
  const p::Case c = case_from_text(
      "length_unit = \"mm\"\n" + kHead +
      "[kinematics.deviation]\n"
      "phase = [0.0, 0.25, 0.5, 0.75]\n"
      "deg = [0.0, 5.0, 0.0, -5.0]\n"
      "[air]\n"
      "freestream = [1.5, 0.0, 0.0]\n"
      "[[loads]]\n"
      "body = 1\n"
      "point = [0.0, 10.0, 0.0]\n"
      "frame = \"body\"\n"
      "force_z = { mean = 0.001, sin = [0.002] }\n"
      "moment_x = 0.5\n"
      "[[markers]]\n"
      "name = \"tip\"\n"
      "body = 1\n"
      "point = [0.0, 10.0, 0.0]\n");
  // The spline passes through its knots (deg → rad).
  EXPECT_NEAR(c.kinematics.deviation.at_phase(0.25).value, 5.0 * kDegToRad, 1e-12);
  EXPECT_NEAR(c.kinematics.deviation.at_phase(0.75).value, -5.0 * kDegToRad, 1e-12);
  EXPECT_DOUBLE_EQ(c.air.freestream.x(), 1.5);
  ASSERT_EQ(c.loads.size(), 1u);
  EXPECT_EQ(c.loads[0].frame, flapsim::mbd::LoadFrame::body);
  EXPECT_NEAR(c.loads[0].point.y(), 0.01, 1e-15);  // 10 mm
  EXPECT_NEAR(c.loads[0].force[2].at_phase(0.25).value, 0.003, 1e-15);
  EXPECT_NEAR(c.loads[0].moment[0].at_phase(0.3).value, 0.5, 1e-15);
  EXPECT_NEAR(c.loads[0].force[0].at_phase(0.3).value, 0.0, 1e-15);
  ASSERT_EQ(c.markers.size(), 1u);
  EXPECT_EQ(c.markers[0].name, "tip");
  const p::Case vac = case_from_text("air = \"none\"\n" + kHead);
  EXPECT_FALSE(vac.air.enabled);
}

TEST(CaseFileErrors, EachProblemNamesLineAndKey) {
  struct Bad {
    std::string text;
    int line;
    std::string key;
  };
  const Bad cases[] = {
      // missing frequency: reported at the [kinematics] header
      {"wing = \"valid_tiny_wing.toml\"\n[kinematics]\nsweep = 0.0\nrotation = 1.0\n"
       "[structure]\nkind = \"rigid\"\n",
       2, "kinematics.frequency_hz"},
      {kHead + "[numerics]\nsteps_per_cycle = -5\n", 9, "numerics.steps_per_cycle"},
      {kHead + "[numerics]\ncore_model = \"vatistas\"\n", 9, "numerics.core_model"},
      {kHead + "[numerics]\ncylces = 3\n", 9, "numerics.cylces"},
      {kHead + "[numerics]\nfrozen_wake_cycles = 2\nfar_wake_cycles = -1\n", 10, "numerics.far_wake_cycles"},
      // a far wake is frozen or convected, not both
      {kHead + "[numerics]\nfrozen_wake_cycles = 2\nfar_wake_cycles = 1\n", 10, "numerics.far_wake_cycles"},
      {"length_unit = \"furlong\"\n" + kHead, 1, "length_unit"},
      {"air = \"vacuum\"\n" + kHead, 1, "air"},
      {kHead + "[[markers]]\nbody = 2\npoint = [0, 0, 0]\n", 9, "markers[0].body"},
      // two markers of one name would write the same history.csv columns twice
      {kHead + "[[markers]]\nname = \"tip\"\nbody = 1\npoint = [0, 0, 0]\n[[markers]]\nname = \"tip\"\nbody "
               "= 1\npoint = [0, 0, 0]\n",
       13, "markers[1].name"},
      // a marker's name heads history.csv's columns: no comma, quote or control character
      // (they broke numpy.genfromtxt's names=True), and not empty (columns "_x_m")
      {kHead + "[[markers]]\nname = \"le, 70%\"\nbody = 1\npoint = [0, 0, 0]\n", 9, "markers[0].name"},
      {kHead + "[[markers]]\nname = \"\"\nbody = 1\npoint = [0, 0, 0]\n", 9, "markers[0].name"},
      {kHead + "[[markers]]\nname = \"a\\nb\"\nbody = 1\npoint = [0, 0, 0]\n", 9, "markers[0].name"},
      // initial joint angles beyond half a turn, rates beyond 1e7 °/s (1e300 was read and the
      // run failed its first step)
      {kHead.substr(0, kHead.find("kind")) +
           "kind = \"flexible\"\nbodies = 2\ninitial_angles_deg = [190, 0]\n",
       9, "structure.initial_angles_deg[0]"},
      {kHead.substr(0, kHead.find("kind")) +
           "kind = \"flexible\"\nbodies = 2\ninitial_rates_deg_per_s = [0, -2e7]\n",
       9, "structure.initial_rates_deg_per_s[1]"},
      {"wing = \"no_such_wing.toml\"\n" + kHead.substr(kHead.find('\n') + 1), 1, "wing"},
      {kHead + "bodies = 2\n", 8, "structure.bodies"},  // rigid has one body
      {"[kinematics]\nfrequency_hz = 1.0\nsweep = 0.0\nrotation = 0.0\n[structure]\nkind = \"rigid\"\n", 1,
       "wing"},
      {kHead.substr(0, kHead.find("frequency_hz = 20.0")) + "frequency_hz = \"20\"\n" +
           kHead.substr(kHead.find("sweep")),
       3, "kinematics.frequency_hz"},
  };
  for (const auto& b : cases) {
    const auto e = error_of(b.text);
    EXPECT_EQ(e.line(), b.line) << e.what();
    EXPECT_EQ(e.key(), b.key) << e.what();
  }
}

TEST(CaseFileErrors, BadTabulatedSignal) {
  const auto e = error_of(kHead +
                          "[kinematics.deviation]\n"           // 8
                          "phase = [0.0, 0.5, 0.25]\n"         // 9
                          "deg = [0.0, 1.0, 2.0]\n");
  EXPECT_EQ(e.line(), 9);
  EXPECT_EQ(e.key(), "kinematics.deviation.phase");
  const auto short_table = error_of(kHead + "[kinematics.deviation]\nphase = [0.0, 0.5]\ndeg = [0.0, 1.0]\n");
  EXPECT_EQ(short_table.key(), "kinematics.deviation.phase");
}

TEST(CaseFile, ATableThatClosesItsCycleAtPhaseOneIsReadWithoutTheRepeat) {
  // A measured cycle exported from 0 to 1 inclusive: phase 1 repeats phase 0 and is dropped
  // (docs/case_file.md, [kinematics]); the signal is the one without it, value for value.
  const std::string closed =
      "[kinematics.deviation]\nphase = [0.0, 0.25, 0.5, 0.75, 1.0]\n"
      "deg = [0.0, 5.0, 0.0, -5.0, 0.0]\n";
  const std::string open =
      "[kinematics.deviation]\nphase = [0.0, 0.25, 0.5, 0.75]\ndeg = [0.0, 5.0, 0.0, -5.0]\n";
  const auto with = case_from_text(kHead + closed).kinematics,
             without = case_from_text(kHead + open).kinematics;
  for (double t : {0.0, 0.003, 0.0125, 0.031, 0.05})
    EXPECT_EQ(with.angles(t).deviation.value, without.angles(t).deviation.value) << t;
  // Phase 1 with another value than phase 0's: a cycle that does not close, named at its value.
  const auto open_cycle = error_of(kHead +
                                   "[kinematics.deviation]\n"               // 8
                                   "phase = [0.0, 0.25, 0.5, 0.75, 1.0]\n"  // 9
                                   "deg = [0.0, 5.0, 0.0, -5.0, 0.5]\n");   // 10
  EXPECT_EQ(open_cycle.key(), "kinematics.deviation.deg");
  EXPECT_EQ(open_cycle.line(), 10);
  EXPECT_NE(std::string(open_cycle.what()).find("does not close"), std::string::npos) << open_cycle.what();
  // Phase 1 without a phase 0 to repeat, and a closed table of fewer than 3 other points.
  EXPECT_EQ(
      error_of(kHead + "[kinematics.deviation]\nphase = [0.1, 0.4, 0.7, 1.0]\ndeg = [0.0, 1.0, 2.0, 3.0]\n")
          .key(),
      "kinematics.deviation.phase");
  EXPECT_EQ(
      error_of(kHead + "[kinematics.deviation]\nphase = [0.0, 0.5, 1.0]\ndeg = [1.0, 2.0, 1.0]\n").key(),
      "kinematics.deviation.phase");
  // Beyond 1 stays out of range.
  EXPECT_EQ(
      error_of(kHead + "[kinematics.deviation]\nphase = [0.0, 0.5, 0.8, 1.2]\ndeg = [1.0, 2.0, 1.0, 1.0]\n")
          .key(),
      "kinematics.deviation.phase[3]");
}

TEST(CaseFile, OverridesForSweeps) {
  const std::string path = kSource + "/cases/hover.toml";
  const p::Case c = p::load_case_file(path, {{"kinematics.rotation_phase", "-0.1"},
                                             {"numerics.spacing", "\"cosine\""},
                                             {"kinematics.sweep.cos_deg", "[40.0]"},
                                             {"output.vtk_every", "0"}});
  EXPECT_DOUBLE_EQ(c.kinematics.rotation_phase, -0.1);
  EXPECT_EQ(c.numerics.chordwise_spacing, flapsim::uvlm::Spacing::Cosine);  // `spacing` sets both
  EXPECT_EQ(c.numerics.spanwise_spacing, flapsim::uvlm::Spacing::Cosine);
  EXPECT_EQ(c.output.vtk_every, 0);
  EXPECT_EQ(c.numerics.chordwise_panels, 6);  // untouched keys keep their values
  // φ(0) = 10° + 40° cos(2π·(−0.1)) with the overridden amplitude and phase.
  EXPECT_NEAR(c.kinematics.angles(0.0).sweep.value,
              (10.0 + 40.0 * std::cos(-0.2 * std::numbers::pi)) * kDegToRad, 1e-12);
  try {
    p::load_case_file(path, {{"numerics.wake_order", "3"}});
    ADD_FAILURE() << "wake_order 3 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "numerics.wake_order");
    EXPECT_EQ(e.line(), 0);
    EXPECT_NE(e.message().find("override"), std::string::npos);
  }
  EXPECT_THROW(p::load_case_file(path, {{"numerics.spacing", "cosine"}}), InputError);  // unquoted
  EXPECT_THROW(p::load_case_file(path, {{"numerics.cylces", "2"}}), InputError);        // typo
}

// The amplitudes of eq. 8 (cases/rotation_phase_rigid.toml) set as array elements,
// KEY[i]: φ = 10° + A_φ cos 2π(ft + δψ), α = 90° + b_1 sin 2πft.
TEST(CaseFile, ArrayElementOverridesSetTheAmplitudes) {
  const std::string path = kSource + "/cases/rotation_phase_rigid.toml";
  const p::Case c = p::load_case_file(
      path, {{"kinematics.sweep.cos_deg[0]", "55"}, {"kinematics.rotation.sin_deg[0]", "-30"}});
  const double f = c.kinematics.frequency;  // [Hz]
  ASSERT_EQ(f, 26.1);
  EXPECT_NEAR(c.kinematics.angles(0.0).sweep.value, (10.0 + 55.0) * kDegToRad, 1e-12);
  EXPECT_NEAR(c.kinematics.angles(0.25 / f).rotation.value, (90.0 - 30.0) * kDegToRad, 1e-12);
  try {
    p::load_case_file(path, {{"kinematics.rotation.sin_deg[1]", "-30"}});  // one harmonic only
    ADD_FAILURE() << "an element beyond the array accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "kinematics.rotation.sin_deg[1]");
    EXPECT_EQ(e.line(), 0);
    EXPECT_NE(e.message().find("has 1 element"), std::string::npos) << e.what();
  }
}

TEST(CaseFile, LoadModelAndSpacingKeys) {
  // docs/case_file.md: `spacing` sets both directions, the per-direction keys override it;
  // the load route and the leading-edge model are named choices.
  const p::Case c = case_from_text(kHead +
                                   "[numerics]\n"
                                   "spacing = \"cosine\"\n"
                                   "spanwise_spacing = \"uniform\"\n"
                                   "load_method = \"kutta_joukowski\"\n"
                                   "leading_edge = \"attached\"\n");
  EXPECT_EQ(c.numerics.chordwise_spacing, flapsim::uvlm::Spacing::Cosine);
  EXPECT_EQ(c.numerics.spanwise_spacing, flapsim::uvlm::Spacing::Uniform);
  EXPECT_EQ(c.numerics.load_method, flapsim::uvlm::LoadMethod::KuttaJoukowski);
  EXPECT_EQ(c.numerics.leading_edge, flapsim::uvlm::LeadingEdge::Attached);
  const p::Case d = case_from_text(kHead);
  EXPECT_EQ(d.numerics.load_method, flapsim::uvlm::LoadMethod::Bernoulli);
  EXPECT_EQ(d.numerics.leading_edge, flapsim::uvlm::LeadingEdge::Separated);  // the documented default
  const auto e = error_of(kHead + "[numerics]\nleading_edge = \"polhamus\"\n");  // line 9
  EXPECT_EQ(e.key(), "numerics.leading_edge");
  EXPECT_EQ(e.line(), 9);
}

TEST(CaseFile, ShedLeadingEdgeAndItsCriticalLesp) {
  // docs/case_file.md: leading_edge = "shed" with lesp_critical in (0, 10], default 0.11
  // (Ramesh et al. 2014's flat plate); the key with another leading-edge model is bad input.
  const p::Case c = case_from_text(kHead + "[numerics]\nleading_edge = \"shed\"\nlesp_critical = 0.2\n");
  EXPECT_EQ(c.numerics.leading_edge, flapsim::uvlm::LeadingEdge::Shed);
  EXPECT_EQ(c.numerics.lesp_critical, 0.2);
  EXPECT_EQ(case_from_text(kHead + "[numerics]\nleading_edge = \"shed\"\n").numerics.lesp_critical, 0.11);
  expect_numerics_key_refused("lesp_critical", {"leading_edge = \"shed\"\nlesp_critical = 0.0\n",
                                                "leading_edge = \"shed\"\nlesp_critical = 11\n",
                                                "leading_edge = \"separated\"\nlesp_critical = 0.2\n"});
}

TEST(CaseFile, ShedLeadingEdgesSheetMergeSteps) {
  // docs/case_file.md: sheet_merge_steps in [0, 10^6], default 8, 0 = never; with another
  // leading-edge model bad input.
  EXPECT_EQ(case_from_text(kHead + "[numerics]\nleading_edge = \"shed\"\n").numerics.sheet_merge_steps, 8);
  EXPECT_EQ(case_from_text(kHead + "[numerics]\nleading_edge = \"shed\"\nsheet_merge_steps = 0\n").numerics.sheet_merge_steps, 0);
  EXPECT_EQ(case_from_text(kHead + "[numerics]\nleading_edge = \"shed\"\nsheet_merge_steps = 16\n").numerics.sheet_merge_steps, 16);
  expect_numerics_key_refused("sheet_merge_steps", {"leading_edge = \"shed\"\nsheet_merge_steps = -1\n",
                                                    "leading_edge = \"shed\"\nsheet_merge_steps = 2.5\n",
                                                    "leading_edge = \"separated\"\nsheet_merge_steps = 8\n"});
}

TEST(CaseFile, ShedLeadingEdgesSheetMergeSpreadSteps) {
  // docs/case_file.md: sheet_merge_spread_steps in [1, 10^6], default 1 (at once); with
  // another leading-edge model bad input.
  EXPECT_EQ(case_from_text(kHead + "[numerics]\nleading_edge = \"shed\"\n").numerics.sheet_merge_spread_steps,
            1);
  EXPECT_EQ(case_from_text(kHead + "[numerics]\nleading_edge = \"shed\"\nsheet_merge_spread_steps = 4\n")
                .numerics.sheet_merge_spread_steps,
            4);
  expect_numerics_key_refused("sheet_merge_spread_steps",
                              {"leading_edge = \"shed\"\nsheet_merge_spread_steps = 0\n",
                               "leading_edge = \"shed\"\nsheet_merge_spread_steps = 1.5\n",
                               "leading_edge = \"separated\"\nsheet_merge_spread_steps = 4\n"});
}

TEST(CaseFile, ShedLeadingEdgesSheetCoreRadius) {
  // docs/case_file.md: sheet_core_radius in [0, 2] mean chords, default 0 = core_radius;
  // with another leading-edge model bad input.
  EXPECT_EQ(case_from_text(kHead + "[numerics]\nleading_edge = \"shed\"\n").numerics.sheet_core_radius, 0.0);
  EXPECT_EQ(case_from_text(kHead + "[numerics]\nleading_edge = \"shed\"\nsheet_core_radius = 0.5\n").numerics.sheet_core_radius,
            0.5);
  expect_numerics_key_refused("sheet_core_radius", {"leading_edge = \"shed\"\nsheet_core_radius = -0.1\n",
                                                    "leading_edge = \"shed\"\nsheet_core_radius = 2.5\n",
                                                    "leading_edge = \"none\"\nsheet_core_radius = 0.5\n"});
}

TEST(CaseFile, WakePrecisionKey) {
  // docs/case_file.md: `wake_precision` = "single" (default) | "double" for the wake's direct sums.
  expect_numerics_choice("wake_precision", &p::Case::Numerics::wake_precision, p::WakePrecision::Single, "double",
                         p::WakePrecision::Double);
}

TEST(CaseFile, CirculationRateKey) {
  // docs/case_file.md: `circulation_rate` = "bdf2" (default) | "bdf1", the pressure's ∂Γ/∂t.
  expect_numerics_choice("circulation_rate", &p::Case::Numerics::circulation_rate, p::CirculationRate::Bdf2, "bdf1",
                         p::CirculationRate::Bdf1);
}

TEST(CaseFile, CouplingKey) {
  // docs/case_file.md: `coupling` = "aitken" (default) | "iqn_ils" (docs/fsi.md, "Coupling").
  expect_numerics_choice("coupling", &p::Case::Numerics::coupling, p::CouplingMethod::Aitken, "iqn_ils",
                         p::CouplingMethod::InterfaceQuasiNewton);
}

TEST(CaseFile, CouplingReuseStepsKey) {
  // docs/case_file.md: `coupling_reuse_steps` in [0, 50], default 0, only with coupling =
  // "iqn_ils" (docs/fsi.md, "Coupling"); out of range or with Aitken it is bad input naming it.
  EXPECT_EQ(case_from_text(kHead).numerics.coupling_reuse_steps, 0);
  const p::Case c = case_from_text(kHead + "[numerics]\ncoupling = \"iqn_ils\"\ncoupling_reuse_steps = 4\n");
  EXPECT_EQ(c.numerics.coupling_reuse_steps, 4);
  for (const char* bad : {"coupling = \"iqn_ils\"\ncoupling_reuse_steps = -1\n",
                          "coupling = \"iqn_ils\"\ncoupling_reuse_steps = 51\n",
                          "coupling = \"aitken\"\ncoupling_reuse_steps = 2\n"}) {
    const auto e = error_of(kHead + "[numerics]\n" + bad);  // the key on line 10
    EXPECT_EQ(e.key(), "numerics.coupling_reuse_steps") << bad;
    EXPECT_EQ(e.line(), 10) << bad;
  }
}

TEST(CaseFile, SteadyKey) {
  // docs/case_file.md: `steady` (default false) selects the steady lattice, whose wake
  // leaves along the free stream: without one it is bad input naming the key and its line.
  EXPECT_FALSE(case_from_text(kHead).numerics.steady);
  const std::string air = "[air]\nfreestream = [-5.0, 0.0, 0.0]\n";  // lines 8, 9
  const p::Case c = case_from_text(kHead + air + "[numerics]\nsteady = true\n");
  EXPECT_TRUE(c.numerics.steady);
  const auto e = error_of(kHead + "[numerics]\nsteady = true\n");  // line 9
  EXPECT_EQ(e.key(), "numerics.steady");
  EXPECT_EQ(e.line(), 9);
  EXPECT_NE(std::string(e.what()).find("free stream"), std::string::npos) << e.what();
  // The steady lattice sheds nothing: "shed" with it is bad input naming steady (it ran as
  // "attached", bit for bit; pipeline/io/case_file.cpp).
  const auto shed =
      error_of(kHead + air + "[numerics]\nleading_edge = \"shed\"\nsteady = true\n");  // line 12
  EXPECT_EQ(shed.key(), "numerics.steady");
  EXPECT_EQ(shed.line(), 12);
  EXPECT_NE(std::string(shed.what()).find("sheds nothing"), std::string::npos) << shed.what();
}

TEST(CaseFile, AddedMassKey) {
  // docs/case_file.md: `added_mass` (default true) puts the lattice's added mass into the
  // structure's step; not a boolean: bad input naming the key and its line.
  EXPECT_TRUE(case_from_text(kHead).numerics.added_mass);
  EXPECT_FALSE(case_from_text(kHead + "[numerics]\nadded_mass = false\n").numerics.added_mass);
  const auto e = error_of(kHead + "[numerics]\nadded_mass = \"yes\"\n");  // line 9
  EXPECT_EQ(e.key(), "numerics.added_mass");
  EXPECT_EQ(e.line(), 9);
}

TEST(CaseFile, BaseTranslationSignals) {
  // docs/case_file.md: heave, surge and lateral move the pivot along z_G, x_G, y_G [m], as
  // signals of s = f t; pose() gives their position, velocity and acceleration.
  auto with_kinematics = [](const std::string& extra) {
    std::string text = kHead;
    return text.insert(text.find("[structure]"), extra);
  };
  const p::Case c = case_from_text(with_kinematics("heave = { sin_m = [0.01] }\nsurge = 0.002\n"));
  const double f = 20.0, w = 2 * std::numbers::pi * f, t = 0.3 / f;
  const auto pose = c.kinematics.pose(t);
  EXPECT_NEAR(pose.position.z(), 0.01 * std::sin(w * t), 1e-15);
  EXPECT_NEAR(pose.velocity.z(), 0.01 * w * std::cos(w * t), 1e-12);
  EXPECT_NEAR(pose.acceleration.z(), -0.01 * w * w * std::sin(w * t), 1e-9);
  EXPECT_DOUBLE_EQ(pose.position.x(), 0.002);
  EXPECT_DOUBLE_EQ(pose.position.y(), 0.0);
  EXPECT_EQ(error_of(with_kinematics("heave = { sin_deg = [1.0] }\n")).key(), "kinematics.heave.sin_deg");
}

// Issue 17: gravity, the initial state of the chain and the integrator's ρ∞ as case keys
// (docs/case_file.md); angles in degrees, read in radians.
TEST(CaseFile, GravityInitialStateAndRhoInfinity) {
  const std::string head =
      "wing = \"valid_tiny_wing.toml\"\n"
      "[kinematics]\n"
      "frequency_hz = 20.0\n"
      "sweep = { cos_deg = [60.0] }\n"
      "rotation = 90.0\n"
      "[structure]\n"
      "kind = \"flexible\"\n"
      "bodies = 3\n"
      "gravity = [0.0, 0.0, -9.81]\n"
      "initial_angles_deg = [10.0, -5.0, 0.0, 2.0]\n"
      "initial_rates_deg_per_s = [100.0, 0.0, 0.0, 0.0]\n"
      "[numerics]\n"
      "rho_infinity = 0.6\n";
  const p::Case c = case_from_text(head);
  EXPECT_DOUBLE_EQ(c.structure.gravity.z(), -9.81);
  ASSERT_EQ(c.structure.initial_angles.size(), 4u);
  EXPECT_NEAR(c.structure.initial_angles[0], 10.0 * kDegToRad, 1e-15);
  EXPECT_NEAR(c.structure.initial_angles[1], -5.0 * kDegToRad, 1e-15);
  EXPECT_NEAR(c.structure.initial_rates[0], 100.0 * kDegToRad, 1e-13);
  EXPECT_DOUBLE_EQ(c.numerics.rho_infinity, 0.6);
  EXPECT_DOUBLE_EQ(case_from_text(kHead).numerics.rho_infinity, 0.9);  // the default
  // Out of [0, 1], and gravity that is not a 3-vector: bad input at the key.
  EXPECT_NE(std::string(error_of(kHead + "[numerics]\nrho_infinity = 1.5\n").what()).find("rho_infinity"),
            std::string::npos);
  EXPECT_NE(std::string(error_of(kHead + "gravity = [0.0, -9.81]\n").what()).find("gravity"), std::string::npos);
  // A rigid wing has no joints to start bent.
  EXPECT_NE(std::string(error_of(kHead + "initial_angles_deg = [1.0, 2.0]\n").what()).find("rigid"),
            std::string::npos);
}
