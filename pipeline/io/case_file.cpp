#include "pipeline/io/case_file.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "mbd/angle_units.hpp"
#include "pipeline/io/gravity_warning.hpp"
#include "pipeline/io/kinematics_csv.hpp"
#include "pipeline/io/open_cycle_warning.hpp"
#include "pipeline/io/recorded_frequency_warning.hpp"
#include "pipeline/io/table_scatter_warning.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/path_from_file_hint.hpp"

namespace flapsim::io {

using wings::Bounds;
using wings::TomlTable;

namespace {

/// The largest initial joint rate a case takes [°/s] (structure.initial_rates_deg_per_s).
constexpr double kMaxInitialRateDegPerS = 1e7;

/// A number as a message shows it: 6 significant digits (0.25, 0.625, 1e-09).
std::string number_text(double x) {
  std::ostringstream o;
  o << x;
  return o.str();
}

std::string existing_file(const TomlTable& t, std::string_view key) {
  const std::string path = t.get_path(key);
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    // Written relative to the folder the command runs in (`wing = "wings/hawkmoth.toml"` in a
    // case elsewhere, run from the repository): say how to reach it from the case file's folder.
    const std::string written = t.get_string(key);
    const std::string hint = wings::path_from_file_hint(written, t.file(), "case");
    // The path as written, and where that is from the folder the command runs in.
    const std::string from_here = written == path ? "" : ", here " + path;
    t.fail(key, "file not found: " + written + " (paths are relative to the case file's folder" + from_here +
                    hint + ")");
  }
  if (!std::filesystem::is_regular_file(path, ec))
    t.fail(key, "not a regular file (a device, FIFO or folder): " + path);
  // Readable by this user (a file another user made, mode 600, was reported later as
  // "wing.toml: cannot open the file for reading": no line of the case, no cause).
  if (::access(path.c_str(), R_OK) != 0)
    t.fail(key, "cannot read " + path + ": " + std::strerror(errno));
  return path;
}

mbd::WingKinematics read_kinematics(const TomlTable& k, std::vector<InputWarning>& warnings) {
  k.expect_only({"frequency_hz", "rotation_phase", "stroke_plane_deg", "sweep", "deviation",
                 "rotation", "surge", "lateral", "heave", "revolution"});
  mbd::WingKinematics kin;
  kin.frequency = k.get_double("frequency_hz", Bounds{0.0, kMaxFrequencyHz, true, false});
  kin.rotation_phase = k.get_double("rotation_phase", 0.0, Bounds::closed(-1.0, 1.0));
  kin.stroke_plane_angle = k.get_double("stroke_plane_deg", 0.0, Bounds::closed(-180.0, 180.0)) * kDegToRad;
  if (!k.has("sweep")) k.fail("sweep", "missing required key (the sweep angle signal)");
  if (!k.has("rotation")) k.fail("rotation", "missing required key (the rotation angle signal)");
  const mbd::PeriodicSignal zero;
  kin.sweep = read_periodic_signal(k, "sweep", "_deg", "deg", kDegToRad, zero, kin.frequency, &warnings);
  kin.deviation =
      read_periodic_signal(k, "deviation", "_deg", "deg", kDegToRad, zero, kin.frequency, &warnings);
  kin.rotation =
      read_periodic_signal(k, "rotation", "_deg", "deg", kDegToRad, zero, kin.frequency, &warnings);
  // Translation of the pivot [m] along the ground axes.
  kin.surge = read_periodic_signal(k, "surge", "_m", "m", 1.0, zero, kin.frequency, &warnings);
  kin.lateral = read_periodic_signal(k, "lateral", "_m", "m", 1.0, zero, kin.frequency, &warnings);
  kin.heave = read_periodic_signal(k, "heave", "_m", "m", 1.0, zero, kin.frequency, &warnings);
  // A steady revolution added to the sweep (docs/kinematics.md, "A revolving wing").
  if (k.has("revolution")) {
    const TomlTable r = k.get_table("revolution");
    r.expect_only({"rate_deg_per_s", "ramp_s"});
    const double rate = r.get_double("rate_deg_per_s", Bounds::closed(-1e6, 1e6));
    if (rate == 0.0) r.fail("rate_deg_per_s", "a revolution needs a rate other than 0 (leave the table out for none)");
    kin.revolution.rate = rate * kDegToRad;
    kin.revolution.ramp = r.get_double("ramp_s", 0.0, Bounds::closed(0.0, 1e6));
  }
  return kin;
}

Case::Air read_air(const TomlTable& root) {
  Case::Air air;
  if (!root.has("air")) return air;  // standard sea-level air, hover
  if (root.is_string("air")) {
    const std::string v = root.get_choice("air", {"none"});
    air.enabled = v != "none";
    return air;
  }
  const TomlTable a = root.get_table("air");
  a.expect_only({"density", "freestream"});
  air.density = a.get_double("density", air.density, Bounds::any());
  if (!(air.density > 0.0)) {  // a vacuum is written otherwise
    a.fail("density",
           "value " + number_text(air.density) +
               " out of range: must be > 0 [kg/m^3]; for a run in vacuum write air = \"none\" at the top "
               "level instead of the [air] table");
  }
  if (a.has("freestream")) {
    const auto u = a.get_doubles("freestream");
    if (u.size() != 3) a.fail("freestream", "expected [u, v, w] in m/s (3 numbers), found " +
                                                std::to_string(u.size()));
    air.freestream = Eigen::Vector3d(u[0], u[1], u[2]);
  }
  return air;
}

// The [structure] keys of the FEM alone (kind = "fem"); another kind refuses them.
constexpr std::array<const char*, 5> kFemStructureKeys = {"element_size_mm", "vein_element_size_mm",
                                                          "stiffness_damping_s", "newton_geometric_terms",
                                                          "newton_matrix_per_piece"};

Case::Structure read_structure(const TomlTable& root) {
  using Kind = Case::Structure::Kind;
  Case::Structure s;
  const TomlTable t = root.get_table("structure");
  t.expect_only({"kind", "bodies", "gravity", "initial_angles_deg", "initial_rates_deg_per_s", "element_size_mm",
                 "vein_element_size_mm", "stiffness_damping_s", "newton_geometric_terms", "newton_matrix_per_piece"});
  s.kind = t.get_choice("kind", kStructureKindNames);
  if (s.kind == Kind::Rigid) {
    s.bodies = t.get_int("bodies", 1, Bounds::closed(1, 1000));
    if (s.bodies != 1)
      t.fail("bodies", "a rigid wing is one body (found " + std::to_string(s.bodies) +
                           "): omit bodies, or set kind = \"flexible\" for a chain of bodies");
  } else if (s.kind == Kind::Flexible) {
    s.bodies = t.get_int("bodies", Bounds::closed(2, 1000));
  } else {
    // The FEM has no bodies: a chain's count would say nothing about it.
    if (t.has("bodies"))
      t.fail("bodies", "kind = \"fem\" integrates the wing's own FEM, which has no bodies: omit bodies "
                       "(the mesh follows the wing file, or element_size_mm)");
    s.bodies = 1;
    s.fem_element_size = 1e-3 * t.get_double("element_size_mm", 0.0, Bounds::closed(1e-3, 1e3));
    s.fem_vein_element_size = 1e-3 * t.get_double("vein_element_size_mm", 0.0, Bounds::closed(1e-3, 1e3));
    s.fem_stiffness_damping = t.get_double("stiffness_damping_s", 0.0, Bounds::closed(0.0, 1.0));
    s.fem_linearised_geometric_terms =
        t.get_choice("newton_geometric_terms", {"linearised", "current"}, "linearised") == "linearised";
    s.fem_geometric_terms_written = t.has("newton_geometric_terms");
    s.fem_matrix_per_piece = t.get_bool("newton_matrix_per_piece", true);
  }
  if (s.kind != Kind::Fem)
    for (const char* key : kFemStructureKeys)
      if (t.has(key)) t.fail(key, "a key of the FEM structure (kind = \"fem\"); this case's kind has no FEM");
  if (t.has("bodies")) s.bodies_line = t.line_of("bodies");
  if (t.has("gravity")) {
    const auto g = t.get_doubles("gravity");
    if (g.size() != 3)
      t.fail("gravity", "expected [g_x, g_y, g_z] in m/s² (3 numbers), found " + std::to_string(g.size()));
    s.gravity = Eigen::Vector3d(g[0], g[1], g[2]);
  }
  for (const char* key : {"initial_angles_deg", "initial_rates_deg_per_s"}) {
    if (!t.has(key)) continue;
    if (s.kind == Kind::Rigid)
      t.fail(key, "a rigid wing has no joints: give initial angles for a flexible structure");
    if (s.kind == Kind::Fem)
      t.fail(key,
             "the FEM structure starts at rest relative to its base, undeformed; joint angles are "
             "the bar chain's (kind = \"flexible\")");
    const bool angles = std::string_view(key) == "initial_angles_deg";
    // A joint bent by more than half a turn, or turning faster than 10⁷ °/s (28 000 turns a
    // second), is a typo: refused here rather than failing the run's first step (1e300 was
    // read, and the run stopped with exit status 3 printing a 300-digit angle).
    const Bounds range = angles ? Bounds::closed(-180.0, 180.0)
                                : Bounds::closed(-kMaxInitialRateDegPerS, kMaxInitialRateDegPerS);
    std::vector<double> v = t.get_doubles(key, range, 1);
    for (double& x : v) x *= kDegToRad;
    (angles ? s.initial_angles : s.initial_rates) = v;
    (angles ? s.initial_angles_line : s.initial_rates_line) = t.line_of(key);
  }
  return s;
}

Case::Numerics read_numerics(const TomlTable& root) {
  Case::Numerics n;
  const auto t = root.find_table("numerics");
  if (!t) return n;
  // The keys a few to a line (one per line, as clang-format lays the list out, reads worse).
  // clang-format off
  t->expect_only({"steps_per_cycle", "cycles", "chordwise_panels", "spanwise_panels", "spacing",
                  "chordwise_spacing", "spanwise_spacing", "load_method", "leading_edge", "skin_friction",
                  "lesp_critical", "sheet_merge_steps", "sheet_merge_spread_steps", "sheet_core_radius",
                  "core_model", "core_radius", "wake_order", "wake_max_rows", "free_wake", "core_growth",
                  "core_growth_a1", "kinematic_viscosity", "near_wing_core", "frozen_wake_cycles",
                  "far_wake_cycles", "wake_sum", "tree_tolerance", "wake_precision", "circulation_rate",
                  "coupling", "max_coupling_iterations", "coupling_tolerance", "coupling_reuse_steps",
                  "added_mass", "rho_infinity", "structure_substeps", "steady", "settled_from_cycle"});
  // clang-format on
  n.steps_per_cycle = t->get_int("steps_per_cycle", n.steps_per_cycle, Bounds::closed(4, 1000000));
  n.cycles = t->get_int("cycles", n.cycles, Bounds::closed(1, 100000));
  n.settled_from_cycle = t->get_int("settled_from_cycle", n.settled_from_cycle, Bounds::closed(2, 100000));
  // The settled statistics take at least 3 cycles (a standard deviation that means something).
  if (t->has("settled_from_cycle") && n.cycles - n.settled_from_cycle + 1 < 3)
    t->fail("settled_from_cycle", "cycles " + std::to_string(n.settled_from_cycle) + " to " +
                                      std::to_string(n.cycles) +
                                      " are fewer than the 3 the settled statistics take: at most " +
                                      std::to_string(std::max(2, n.cycles - 2)) + ", or more cycles");
  // The product in 64 bits, against a documented maximum (an int would wrap).
  if (n.total_steps() > kMaxTotalSteps)
    t->fail(t->has("cycles") ? "cycles" : "steps_per_cycle",
            "steps_per_cycle x cycles = " + std::to_string(n.steps_per_cycle) + " x " + std::to_string(n.cycles) +
                " = " + std::to_string(n.total_steps()) + " time steps, more than the maximum " +
                std::to_string(kMaxTotalSteps));
  n.chordwise_panels = t->get_int("chordwise_panels", n.chordwise_panels, Bounds::closed(1, 1000));
  n.spanwise_panels = t->get_int("spanwise_panels", n.spanwise_panels, Bounds::closed(1, 1000));
  const uvlm::Spacing both = t->get_choice("spacing", kSpacingNames, std::optional(n.chordwise_spacing));
  n.chordwise_spacing = t->get_choice("chordwise_spacing", kSpacingNames, std::optional(both));
  n.spanwise_spacing = t->get_choice("spanwise_spacing", kSpacingNames, std::optional(both));
  n.load_method = t->get_choice("load_method", kLoadMethodNames, std::optional(n.load_method));
  n.circulation_rate = t->get_choice("circulation_rate", kCirculationRateNames, std::optional(n.circulation_rate));
  n.leading_edge = t->get_choice("leading_edge", kLeadingEdgeNames, std::optional(n.leading_edge));
  n.laminar_skin_friction = t->get_choice("skin_friction", {"none", "laminar"}, "none") == "laminar";
  n.lesp_critical = t->get_double("lesp_critical", n.lesp_critical, Bounds{0.0, 10.0, true, false});
  n.sheet_merge_steps = t->get_int("sheet_merge_steps", n.sheet_merge_steps, Bounds::closed(0, 1000000));
  n.sheet_merge_spread_steps =
      t->get_int("sheet_merge_spread_steps", n.sheet_merge_spread_steps, Bounds::closed(1, 1000000));
  n.sheet_core_radius = t->get_double("sheet_core_radius", n.sheet_core_radius, Bounds::closed(0.0, 2.0));
  // The keys of the shed leading edge's sheet act with it only.
  for (const char* key :
       {"lesp_critical", "sheet_merge_steps", "sheet_merge_spread_steps", "sheet_core_radius"})
    if (t->has(key) && n.leading_edge != uvlm::LeadingEdge::Shed)
      t->fail(key, "acts only with leading_edge = \"shed\" (docs/uvlm.md, \"Leading-edge vortex shedding\")");
  n.core_model = t->get_choice("core_model", kCoreModelNames, std::optional(n.core_model));
  n.core_radius = t->get_double("core_radius", n.core_radius, Bounds{0.0, 1.0, true, false});
  n.wake_order = t->get_int("wake_order", n.wake_order, Bounds::closed(1, 2));
  n.wake_max_rows = t->get_int("wake_max_rows", n.wake_max_rows, Bounds::non_negative());
  n.free_wake = t->get_bool("free_wake", n.free_wake);
  n.core_growth = t->get_bool("core_growth", n.core_growth);
  n.core_growth_a1 = t->get_double("core_growth_a1", n.core_growth_a1, Bounds::closed(0.0, 1.0));
  n.kinematic_viscosity = t->get_double("kinematic_viscosity", n.kinematic_viscosity, Bounds::positive());
  n.near_wing_core = t->get_double("near_wing_core", n.near_wing_core, Bounds::closed(0.0, 1.0));
  n.frozen_wake_cycles = t->get_double("frozen_wake_cycles", n.frozen_wake_cycles, Bounds::non_negative());
  n.far_wake_cycles = t->get_double("far_wake_cycles", n.far_wake_cycles, Bounds::non_negative());
  if (n.far_wake_cycles > 0.0 && n.frozen_wake_cycles > 0.0)
    t->fail("far_wake_cycles", "a far wake is either frozen (frozen_wake_cycles) or convected (far_wake_cycles), not both");
  n.wake_sum = t->get_choice("wake_sum", kWakeSumNames, std::optional(n.wake_sum));
  n.wake_precision = t->get_choice("wake_precision", kWakePrecisionNames, std::optional(n.wake_precision));
  n.tree_tolerance = t->get_double("tree_tolerance", n.tree_tolerance, Bounds{1e-8, 1e-2, false, false});
  n.coupling = t->get_choice("coupling", kCouplingMethodNames, std::optional(n.coupling));
  n.max_coupling_iterations =
      t->get_int("max_coupling_iterations", n.max_coupling_iterations, Bounds::closed(1, 100000));
  n.coupling_tolerance =
      t->get_double("coupling_tolerance", n.coupling_tolerance, Bounds{0.0, 1.0, true, true});
  n.coupling_reuse_steps = t->get_int("coupling_reuse_steps", n.coupling_reuse_steps, Bounds::closed(0, 50));
  if (t->has("coupling_reuse_steps") && n.coupling != CouplingMethod::InterfaceQuasiNewton)
    t->fail("coupling_reuse_steps", "reusing earlier steps' secant pairs needs coupling = \"iqn_ils\"");
  n.added_mass = t->get_bool("added_mass", n.added_mass);
  n.rho_infinity = t->get_double("rho_infinity", n.rho_infinity, Bounds::closed(0.0, 1.0));
  n.rho_infinity_written = t->has("rho_infinity");
  n.structure_substeps = t->get_int("structure_substeps", n.structure_substeps, Bounds::closed(1, 10000));
  n.steady = t->get_bool("steady", n.steady);
  return n;
}

int read_body(const TomlTable& t, int bodies) {
  return t.get_int("body", Bounds::closed(1, bodies));
}

PointLoad read_load(const TomlTable& t, int bodies, double frequency_hz) {
  t.expect_only({"body", "point", "frame", "force_x", "force_y", "force_z", "moment_x",
                 "moment_y", "moment_z"});
  PointLoad load;
  load.body = read_body(t, bodies);
  load.point = t.get_length_vector3("point", Eigen::Vector3d::Zero());
  load.frame = t.get_choice("frame", kLoadFrameNames);
  const mbd::PeriodicSignal zero;
  const char* forces[3] = {"force_x", "force_y", "force_z"};
  const char* moments[3] = {"moment_x", "moment_y", "moment_z"};
  for (int i = 0; i < 3; ++i) {
    load.force[i] = read_periodic_signal(t, forces[i], "", "value", 1.0, zero, frequency_hz);
    load.moment[i] = read_periodic_signal(t, moments[i], "", "value", 1.0, zero, frequency_hz);
  }
  return load;
}

Marker read_marker(const TomlTable& t, std::size_t i, int bodies) {
  t.expect_only({"name", "body", "point"});
  Marker m;
  m.name = t.get_string("name", "marker " + std::to_string(i + 1));
  // The name heads history.csv's columns <name>_x_m, …: a comma, a quote or a control
  // character there (quoted by RFC 4180) breaks the readers docs/output_files.md shows
  // (numpy.genfromtxt with names=True), and an empty name gives columns "_x_m".
  const bool plain = std::all_of(m.name.begin(), m.name.end(), [](char ch) {
    return static_cast<unsigned char>(ch) >= 0x20 && ch != 0x7f && ch != ',' && ch != '"';
  });
  if (m.name.empty() || m.name.size() > 64 || !plain)
    t.fail("name",
           "a marker's name (it heads history.csv's columns) is 1 to 64 characters without commas, "
           "quotes or control characters, found \"" +
               m.name + "\"");
  m.body = read_body(t, bodies);
  m.point = t.get_length_vector3("point");
  return m;
}

/// A measured cycle often ends where it began: phase 1 (the next cycle's 0) repeating
/// phase 0's value. That entry is dropped, as an outline's closing point is; phase 1 with
/// another value, or without phase 0, is bad input naming the entry's line, but in a table
/// fitted with harmonics = N (a measurement of the next cycle's start) is dropped too.
void drop_closing_phase(const TomlTable& s, std::string_view values_key, std::vector<double>& phase,
                        std::vector<double>& values, bool fitted) {
  const std::size_t last = phase.size() - 1;
  if (phase[last] != 1.0) return;
  const int line = s.line_of_element("phase", last);
  if (phase.front() != 0.0)
    s.fail_at(line, "phase",
              "phase 1 is phase 0 of the next cycle: phases lie in [0, 1) (a table that ends at 1 repeats "
              "its value at 0, which this one has no entry for)");
  const double first = values.front(), closing = values[last];
  if (!fitted && std::abs(closing - first) > 1e-9 * std::max(1.0, std::abs(first))) {
    char text[240];
    std::snprintf(
        text, sizeof text,
        "phase 1 is phase 0 of the next cycle, so its value must repeat phase 0's: %.10g against %.10g "
        "(a cycle that does not close; drop the entry or make the two equal)",
        closing, first);
    s.fail_at(s.line_of_element(values_key, last), values_key, text);
  }
  if (phase.size() < 4) s.fail_at(line, "phase", "at least 3 points besides phase 1, which repeats phase 0");
  phase.pop_back();
  values.pop_back();
}

/// A table whose points leave more than half the cycle without one: the spline (or series)
/// across the gap is a guess, and the usual cause is a table of times in seconds (a 26.1 Hz
/// wingbeat's 0 … 0.0364 s read as phases: the sweep's spline reached 580 deg, warned only as
/// an amplitude in the wrong unit). The message names the gap, and the times it may be (frequency_hz > 0).
constexpr double kLargestPhaseGap = 0.5;  // [cycles]
struct PhaseGap {
  std::string message;
  std::size_t from_row;  ///< the point the gap starts from (its index in the table as given)
};
std::optional<PhaseGap> gap_over_half_the_cycle(const std::vector<double>& phase, double frequency_hz) {
  // A fitted table's folded wingbeats are in any order: the points by phase.
  std::vector<std::size_t> order(phase.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return phase[a] < phase[b]; });
  const std::size_t n = phase.size();
  double gap = phase[order.front()] + 1.0 - phase[order.back()];
  std::size_t from = order.back();
  for (std::size_t i = 1; i < n; ++i)
    if (phase[order[i]] - phase[order[i - 1]] > gap) {
      gap = phase[order[i]] - phase[order[i - 1]];
      from = order[i - 1];
    }
  if (gap <= kLargestPhaseGap) return std::nullopt;
  char text[400];
  std::snprintf(
      text, sizeof text,
      "the points leave %.3g of the cycle without a point (from phase %.4g on): phases are fractions "
      "of the wingbeat (f t, in [0, 1)), and a curve across so long a gap is a guess",
      gap, phase[from]);
  std::string message = text;
  const double first = phase[order.front()], last = phase[order.back()];
  const double span = last - first;
  if (frequency_hz > 0.0 && span * frequency_hz > 0.5 && span * frequency_hz <= 1.0) {
    std::snprintf(text, sizeof text,
                  "; times in seconds? The last, %.4g, is %.3g of the %.4g Hz period: divide them by the "
                  "period, %.4g s",
                  last, last * frequency_hz, frequency_hz, 1.0 / frequency_hz);
    message += text;
  }
  return PhaseGap{std::move(message), from};
}

/// A tabulated signal of `s`: inline { phase = [...], <values_key> = [...] } or a CSV file's
/// column { file = "...", column = "..." } (pipeline/io/kinematics_csv.hpp), a periodic spline
/// through the points or, with harmonics = N, their least-squares Fourier series; a spline's
/// scatter is warned into `warnings` (pipeline/io/table_scatter_warning.hpp; nullptr: not checked).
mbd::PeriodicSignal read_table_signal(const TomlTable& s, std::string_view values_key, double scale,
                                      double frequency_hz, std::vector<InputWarning>* warnings) {
  const bool from_file = s.has("file");
  std::vector<double> phase, values;
  std::vector<int> file_lines;  // a CSV file's row lines (kinematics_csv.hpp)
  std::string file_path;
  bool from_times = false;                        // a CSV's first column is a time
  const double case_frequency_hz = frequency_hz;  // [Hz]
  const std::string where = from_file ? "file" : "phase";
  if (from_file) {
    // A measured wingbeat's column of a CSV file (pipeline/io/kinematics_csv.hpp).
    s.expect_only({"file", "column", "harmonics"});
    const std::string path = existing_file(s, "file");
    KinematicsCsvColumn table = read_kinematics_csv(path, s.get_string("column"), frequency_hz,
                                                    s.key_path("file"), s.has("harmonics"));
    phase = std::move(table.phase);
    values = std::move(table.values);
    file_lines = std::move(table.lines);
    file_path = path;
    // A table of times is one wingbeat by construction: no guess at seconds below.
    from_times = table.from_times;
    if (table.from_times) frequency_hz = 0.0;
  } else {
    s.expect_only({"phase", values_key, "harmonics"});
    phase = s.get_doubles("phase", Bounds::closed(0.0, 1.0), 3);
    values = s.get_doubles(values_key, Bounds::any(), 3);
    if (values.size() != phase.size())
      s.fail(values_key, "needs as many entries as 'phase' (" + std::to_string(phase.size()) + "), found " +
                             std::to_string(values.size()));
    drop_closing_phase(s, values_key, phase, values, s.has("harmonics"));
    for (std::size_t i = 1; i < phase.size(); ++i)
      if (!(phase[i] > phase[i - 1]))
        s.fail_at(s.line_of_element("phase", i), "phase",
                  "phases must be strictly increasing (entry " + std::to_string(i) + ")");
  }
  if (const auto gap = gap_over_half_the_cycle(phase, frequency_hz)) {
    if (from_file)  // the CSV's row the gap starts from, under the case's key
      throw InputError(file_path, file_lines.at(gap->from_row), s.key_path("file"), gap->message);
    s.fail(where, gap->message);
  }
  if (s.has("harmonics")) {
    // A measured cycle as its least-squares Fourier series (mbd/fourier_fit.hpp): the
    // spline through scattered points turns the scatter into accelerations
    // (mbd/table_scatter.hpp; docs/case_file.md, "Measured kinematics").
    const int harmonics =
        s.get_int("harmonics", Bounds::closed(1.0, static_cast<double>(kMaxSignalHarmonics)));
    if (static_cast<std::size_t>(2 * harmonics + 1) > phase.size())
      s.fail("harmonics", std::to_string(harmonics) + " harmonics have " + std::to_string(2 * harmonics + 1) +
                              " coefficients, more than the table's " + std::to_string(phase.size()) +
                              " points determine: at most " + std::to_string((phase.size() - 1) / 2));
    for (double& v : values) v *= scale;
    try {
      return mbd::PeriodicSignal::fitted(phase, values, harmonics);
    } catch (const std::invalid_argument& e) {
      s.fail("harmonics", e.what());
    }
  }
  std::vector<double> scaled = values;
  for (double& v : scaled) v *= scale;
  mbd::PeriodicSignal spline;
  try {
    spline = mbd::PeriodicSignal::tabulated(phase, scaled);
  } catch (const std::invalid_argument& e) {
    s.fail(where, e.what());
  }
  const std::string values_where = from_file ? "file" : std::string(values_key);
  // A table that does not close is warned as such; its closing step would otherwise be taken
  // for the points' scatter, and the fit the scatter warning offers does not close it either.
  if (warnings) {
    if (from_times && !s.has("harmonics"))
      if (auto w = recorded_frequency_warning(phase, values, case_frequency_hz, s.get_string("column"),
                                              file_path, file_lines.back(), s.key_path("file")))
        warnings->push_back(std::move(*w));
    if (auto w = open_cycle_warning(phase, values, std::string(values_key), s.file(), s.line_of(values_where),
                                    s.key_path(values_where)))
      warnings->push_back(std::move(*w));
    else if (auto w = scattered_table_warning(phase, values, std::string(values_key), s.file(),
                                              s.line_of(values_where), s.key_path(values_where)))
      warnings->push_back(std::move(*w));
  }
  return spline;
}

}  // namespace

mbd::PeriodicSignal read_periodic_signal(const TomlTable& table, std::string_view key,
                                         std::string_view suffix, std::string_view values_key, double scale,
                                         const mbd::PeriodicSignal& fallback, double frequency_hz,
                                         std::vector<InputWarning>* warnings) {
  if (!table.has(key)) return fallback;
  if (table.is_number(key))
    return mbd::PeriodicSignal::harmonic(table.get_double(key) * scale, {}, {});
  if (!table.is_table(key))
    table.fail(key, "expected a number or a signal table { mean" + std::string(suffix) + " = ..., cos" +
                        std::string(suffix) + " = [...], sin" + std::string(suffix) +
                        " = [...] }, { phase = [...], " + std::string(values_key) +
                        " = [...] } or { file = \"wingbeat.csv\", column = \"...\" }");
  const TomlTable s = table.get_table(key);
  const std::string mean_k = "mean" + std::string(suffix), cos_k = "cos" + std::string(suffix),
                    sin_k = "sin" + std::string(suffix);
  if (s.has("file") || s.has("phase") || s.has(values_key))
    return read_table_signal(s, values_key, scale, frequency_hz, warnings);
  s.expect_only({mean_k, cos_k, sin_k});
  auto cos_c = s.find_doubles(cos_k);
  auto sin_c = s.find_doubles(sin_k);
  for (const auto* k : {&cos_k, &sin_k})
    if ((k == &cos_k ? cos_c : sin_c).size() > kMaxSignalHarmonics)
      s.fail_at(s.line_of_element(*k, kMaxSignalHarmonics), *k,
                "more than " + std::to_string(kMaxSignalHarmonics) +
                    " harmonics (a time step resolves harmonic n only with more than 2n steps per cycle)");
  for (double& v : cos_c) v *= scale;
  for (double& v : sin_c) v *= scale;
  return mbd::PeriodicSignal::harmonic(s.get_double(mean_k, 0.0, Bounds::any()) * scale,
                                       std::move(cos_c), std::move(sin_c));
}

bool is_case_document(const TomlTable& root) { return root.has("kinematics"); }

bool flaps_with_whole_free_wake(const Case& c) {
  const Case::Numerics& n = c.numerics;
  const mbd::WingKinematics& k = c.kinematics;
  return c.air.enabled && !k.revolution.active() && !k.pivot_translates() && !k.sweep.is_constant() &&
         n.free_wake && !n.steady && !(n.far_wake_cycles > 0.0) && !(n.frozen_wake_cycles > 0.0) &&
         n.wake_max_rows <= 0;
}

namespace {

/// A hover: air without a free stream (the wake moves only by what it induces).
bool in_still_air(const Case& c) { return c.air.enabled && !(c.air.freestream.norm() > 0.0); }

/// A wing in still air that comes back to the wake it shed: a flapping wing from its first
/// reversal, a revolving wing (the revolving-wing experiments) once it has turned a whole
/// revolution within the run. Short of that a revolving wing's cycles are time units, not
/// wingbeats through its wake (the Robofly wing's half revolution in 2 cycles,
/// cases/robofly_revolving.toml, was warned of a round-off it does not have).
bool meets_its_own_wake(const Case& c) {
  if (!in_still_air(c)) return false;
  const mbd::WingKinematics::Revolution& turn = c.kinematics.revolution;
  return !turn.active() ||
         std::abs(turn.at(c.numerics.cycles / c.kinematics.frequency).value) >= 2.0 * std::numbers::pi;
}

/// The far wake's default in hover: a flapping wing in still air (a fixed pivot, a sweep that
/// swings, its wake free and kept whole) whose case leaves `far_wake_cycles` out gets
/// kHoverFarWakeCycles, what every shipped hover case sets; otherwise 0, the whole wake free
/// (docs/case_file.md, far_wake_cycles). Whole, the hover's wake makes the lift hinge on
/// round-off from the second cycle and grow erratic after 5-8 (docs/uvlm.md, "Hover over many
/// cycles": a change of the frequency by 1e-9 moved a hawkmoth hover's cycle-3 mean lift by up
/// to 39 %); with the far wake after half a cycle the cycle means settle (cycles 2-8 within
/// 0.6 %). A revolving wing, a free stream or a translating pivot keep 0.
void default_far_wake_in_hover(const TomlTable& root, Case& c) {
  if (const auto t = root.find_table("numerics"); t && t->has("far_wake_cycles")) return;
  if (!in_still_air(c) || !flaps_with_whole_free_wake(c)) return;
  c.numerics.far_wake_cycles = kHoverFarWakeCycles;
}

/// A warning at numerics.`key`, on its line of the [numerics] table (0 if the key is not written).
void warn_at_numerics_key(const TomlTable& root, Case& c, const std::string& key, std::string message) {
  const auto t = root.find_table("numerics");
  c.warnings.push_back({c.file, t ? t->line_of(key) : 0, "numerics." + key, std::move(message)});
}

}  // namespace

// A hover (no free stream) of more than one cycle with every wake row free: from the
// second cycle on the wake the wing meets is chaotic, so the lift hinges on round-off (a
// rigid hawkmoth hover, cases/rotation_phase_rigid.toml with the whole wake free: a change
// of the frequency by 1e-9 of itself moved the mean lift of cycle 1 by 4e-8, of cycle 2 by
// 0.2-1.2 %, of cycle 3 by 12-39 %), and after 5-8 cycles the wake piles up under the wing
// and the lift grows erratic (docs/uvlm.md, "Hover over many cycles": cycles 9 and 10 at
// +60 %, +90 %, peak 2.4x).
// leading_edge = "shed" is verified in the 2-D limit and, with viscous cores and 10 spanwise
// panels, on the revolving Robofly wing at 50-60 deg (docs/uvlm.md, "Leading-edge vortex
// shedding: measurements": CL within 10 % of the fit there, converged in the step from 120
// steps per half revolution, 8-15 % low at 10-40 deg; an agreement that comes from the end
// strips, which do not shed, as the numbers on 40 and 80 strips below show); on flapping wings
// its per-step lift is not converged in the step (the Lua hover: spikes of 3-8 times the mean
// at reversal), its cycles do not repeat, and its mean over many cycles is the result (3-5 %
// above Lua et al.'s over 150 cycles); long runs may diverge. Its lift along the span is not a
// wing's (docs/uvlm.md, "Where shed's lift lies along the span", 4 Dec): on the revolving
// Robofly the tip strip carries 29-43 % of it and the mid-span strips 0.4-7 %, on an outline
// whose tip is rounded within its last strip 79 % (at 50 deg), and a square-tipped or swept
// wing revolving falls below "none" (a rectangle of aspect ratio 4: CL 0.97 against 1.29; a 30
// deg swept one: 1.20 against 1.73). Nor is it converged along the span (5 Dec, "The two load
// routes part on the shed sheet"): the Robofly at 30 / 50 deg gives CL 1.295 / 1.648 on 10
// strips, 1.173 / 1.404 on 40 (-9 / -15 %), where "none" holds (1.280 / 1.388 and 1.288 /
// 1.402): on 40 strips "shed" adds no vortex lift there; at 60 deg 1.531 on 10, 1.377 on 40
// (-10 %; "none" 1.167 / 1.179). Lua et al.'s hover (12 cycles): 2.212 on 10 strips, 1.858 on
// 40 (+6.3 / -10.7 % of 2.08; "none" 1.844 / 1.774, "separated" 2.336 / 2.231). On 80 strips
// ("Converged along the span") the Robofly at 10-60 deg gives 0.520, 0.940, 1.170, 1.344,
// 1.465, 1.402 (-15 ... -24 % of the fit; "none" 0.505, 0.947, 1.266, 1.415, 1.374, 1.155) and
// Lua et al.'s hover stops at step 391. Hovering in cases/hover.toml's stroke ("Other
// planforms in a hover"), a rigid 40 mm plate of 5 mm chord stops at step 70, plates tapered
// to 0.5 / 0.3 / 0.1 of the root chord at 210 / 101 / 65, where the 10 mm plate and
// "separated" complete (test app.ShedOtherPlanforms.*).
void warn_experimental_shedding(const TomlTable& root, Case& c) {
  // In vacuum (air = "none") there is no lattice and nothing is shed: no warning.
  if (c.numerics.leading_edge != uvlm::LeadingEdge::Shed || !c.air.enabled) return;
  warn_at_numerics_key(
      root, c, "leading_edge",
      "\"shed\" is experimental: its lift is not converged along the span (a revolving wing's "
      "comes within 8 % of \"none\"'s at 10-50 deg on 80 spanwise panels, 12-24 % below the "
      "measurement at 10-60 deg; the agreement on 10 panels comes from the end strips, which do not "
      "shed), on a flapping wing its "
      "cycles do not repeat (read summary.json's settled_mean_CL over many cycles), and a run may "
      "break down (a long one on the shipped wings, a tapered or slender plate hovering within a "
      "few half-strokes); \"separated\" (the default) and \"none\" bracket the measured lift "
      "(docs/uvlm.md, \"Leading-edge vortex shedding: measurements\", its first paragraph)");
}

// A prescribed wake (free_wake = false) moves with the free stream only (uvlm::WakeModel::
// Prescribed): in still air it stays where the trailing edge shed it, and a flapping wing
// sweeps back through it, a revolving wing once it has come round (meets_its_own_wake; its
// part older than far_wake_cycles moves on with the far wake). Measured (1 Dec;
// cases/hover.toml as a rigid wing, 2 cycles, mean CL of the second; far_wake_cycles = 0.5 as
// the case, 0 in brackets): "separated" 2.45 (1.87) and "none" 1.86 (1.63) against 2.77 and
// 2.05 with the free wake; "shed" 4.71 (8.45; per-step CL peaking at 7, 11, 15 and 26 in the
// four half-strokes) against 2.99: its sheet stays on the edge's path, so that combination is
// refused (read_case), the others warned.
namespace {

bool still_air_prescribed_wake(const Case& c) {
  return in_still_air(c) && !c.numerics.free_wake && !c.numerics.steady;
}

void warn_still_air_prescribed_wake(const TomlTable& root, Case& c) {
  if (!still_air_prescribed_wake(c) || !meets_its_own_wake(c)) return;
  warn_at_numerics_key(
      root, c, "free_wake",
      "free_wake = false in still air: a prescribed wake moves with the free stream only, so it "
      "stays where the trailing edge shed it (until far_wake_cycles) and the wing sweeps back "
      "through it (the rigid hawkmoth hover of cases/hover.toml: mean CL 2.45 with \"separated\" "
      "and 1.86 with \"none\" against 2.77 and 2.05 with the free wake; 1.87 and 1.63 without "
      "far_wake_cycles); set free_wake = true (docs/case_file.md, free_wake)");
}

// A frozen far wake (frozen_wake_cycles) in still air is the same: its rows stay where they
// were shed and the wing sweeps back through them (docs/uvlm.md, "Far wake, frozen": "the
// pile-up made permanent"). Measured (1 Dec; cases/hover.toml as a rigid wing, 4 cycles,
// "separated", the mean CL of cycles 2-4): frozen after 0.5 cycles 2.30 ± 0.11 (its cycles
// scattering by 0.20) against 2.77 ± 0.005 with far_wake_cycles = 0.5.
void warn_frozen_wake_in_still_air(const TomlTable& root, Case& c) {
  const Case::Numerics& n = c.numerics;
  if (!meets_its_own_wake(c) || !n.free_wake || n.steady || !(n.frozen_wake_cycles > 0.0)) return;
  warn_at_numerics_key(
      root, c, "frozen_wake_cycles",
      "a frozen far wake in still air stays where it was shed and the wing sweeps back through "
      "it (the rigid hawkmoth hover of cases/hover.toml, 4 cycles, frozen after 0.5: mean CL "
      "2.30, its cycles scattering by 0.20, against 2.77 and periodic with far_wake_cycles = "
      "0.5); set far_wake_cycles = 0.5 instead (docs/uvlm.md, \"Hover over many cycles\")");
}

// In a free stream the frozen rows stop too, where the stream had carried them by then, while
// the younger wake comes on: the rows pile up at U∞ times the frozen age behind the wing for as
// long as the run lasts. Measured (6 Dec; the flexible hover of cases/hover_flexible.toml at
// 40 steps a wingbeat in a 2 m/s stream along -x, 20 wingbeats): frozen after 1 wingbeat the
// cycles' mean CL climbed from 4.29 to 5.36 by cycle 15 (+19 %), against 4.41 ± 0.04 without
// a trend with the whole wake free.
void warn_frozen_wake_in_a_stream(const TomlTable& root, Case& c) {
  const Case::Numerics& n = c.numerics;
  // At least two wingbeats of frozen rows piling up (a convention: the measured climb went on
  // from the first wingbeat past the frozen age, +3 % by the second).
  if (!c.air.enabled || in_still_air(c) || !n.free_wake || n.steady || !(n.frozen_wake_cycles > 0.0) ||
      !(n.cycles >= n.frozen_wake_cycles + 2.0))
    return;
  warn_at_numerics_key(
      root, c, "frozen_wake_cycles",
      "a frozen far wake in a free stream stops where the stream has carried it and piles up there "
      "behind the wing as the run goes on (the flexible hawkmoth hover in a 2 m/s stream, 20 "
      "wingbeats, frozen after 1: its cycles' mean CL climbing from 4.29 to 5.36, +19 %, where the "
      "whole free wake gives 4.41 without a trend); leave it out (the whole wake free, as in forward "
      "flight by default) or set far_wake_cycles, which carries the old wake on (docs/uvlm.md, \"Hover "
      "over many cycles (the far wake)\")");
}

// A wake capped at fewer rows than the far wake's age drops every row before it is old enough
// to join the far wake: there is none, and the run is the truncated wake's (the flexible
// hawkmoth hover at 40 steps a wingbeat, wake_max_rows = 20 with far_wake_cycles = 0.5: +4.2 %
// lift, as the far wake dropped in docs/uvlm.md, "Hover over many cycles": +4.4 %).
void warn_wake_cap_before_the_far_wake(const TomlTable& root, Case& c) {
  const Case::Numerics& n = c.numerics;
  const bool convected = n.far_wake_cycles > 0.0;
  const double far_cycles = convected ? n.far_wake_cycles : n.frozen_wake_cycles;
  if (!c.air.enabled || !n.free_wake || n.steady || n.wake_max_rows <= 0 || !(far_cycles > 0.0)) return;
  const double far_rows = far_cycles * n.steps_per_cycle;  // rows shed before a row reaches the age
  if (static_cast<double>(n.wake_max_rows) > far_rows) return;
  const char* kind = convected ? "far" : "frozen";
  char text[520];
  std::snprintf(
      text, sizeof text,
      "wake_max_rows = %d keeps the newest %d rows, %.4g of a cycle at %d steps a cycle: every row is "
      "dropped before it reaches the %s wake's age (%s_wake_cycles = %g, %.4g rows), so the run has no "
      "%s wake, only the truncated one (its lift as the far wake dropped: +4.4 %% on the rigid "
      "hawkmoth hover); wake_max_rows above %.4g, or 0 (docs/uvlm.md, \"Hover over many cycles (the far "
      "wake)\")",
      n.wake_max_rows, n.wake_max_rows, n.wake_max_rows / static_cast<double>(n.steps_per_cycle),
      n.steps_per_cycle, kind, kind, far_cycles, far_rows, kind, far_rows);
  warn_at_numerics_key(root, c, "wake_max_rows", text);
}

}  // namespace

void warn_long_free_hover(const TomlTable& root, Case& c) {
  const Case::Numerics& n = c.numerics;
  const mbd::WingKinematics& k = c.kinematics;
  // A revolving wing's cycles are a time unit (frequency_hz): it comes back to its wake once
  // a revolution, so its revolutions are what count.
  const double wingbeats = k.revolution.active() ? std::abs(k.revolution.at(n.cycles / k.frequency).value) /
                                                       (2.0 * std::numbers::pi)
                                                 : static_cast<double>(n.cycles);
  if (!meets_its_own_wake(c) || !n.free_wake || !(wingbeats > kLongFreeHoverCycles) ||
      n.far_wake_cycles > 0.0 || n.frozen_wake_cycles > 0.0 || n.wake_max_rows > 0)
    return;
  // The far wake needs a span that sweeps a disk (fsi_setup.cpp refuses it otherwise: a wing
  // that only pitches or plunges); such a wing is told what it can do instead.
  const bool sweeps_a_disk = k.revolution.active() || !k.sweep.is_constant() || !k.deviation.is_constant();
  const std::string remedy = sweeps_a_disk
                                 ? "set far_wake_cycles = 0.5 (as cases/hover_periodic.toml)"
                                 : "this wing's span sweeps no disk for a far wake (far_wake_cycles is "
                                   "refused): read its first cycles, or cap the wake (wake_max_rows)";
  const std::string what =
      k.revolution.active() ? number_text(wingbeats) + " revolutions" : std::to_string(n.cycles) + " cycles";
  warn_at_numerics_key(
      root, c, "cycles",
      what +
          " of hover with the whole wake free: from the second "
          "cycle on the lift hinges on round-off (a change of the frequency by 1e-9 moved a "
          "hawkmoth hover's cycle-3 mean lift by up to 39 %), and it grows erratic after 5-8 "
          "cycles (docs/uvlm.md, \"Hover over many cycles\"); " +
          remedy);
}

// A hover (no free stream) whose convected far wake starts outside the measured range
// (kHoverFarWakeCyclesMin–Max): earlier, the wing meets rows of the far wake, which move as
// a block and do not give way to it; later, the free wake's own instability makes the cycle
// means wander (docs/uvlm.md, "Hover over many cycles").
void warn_far_wake_outside_measured_range(const TomlTable& root, Case& c) {
  const double f = c.numerics.far_wake_cycles;
  // The range is in wingbeats of a flapping hover; a revolving wing's cycle is a time unit
  // (frequency_hz): the same run at another frequency_hz was warned or not.
  if (c.kinematics.revolution.active()) return;
  if (!meets_its_own_wake(c) || !c.numerics.free_wake || !(f > 0.0) ||
      (f >= kHoverFarWakeCyclesMin && f <= kHoverFarWakeCyclesMax))
    return;
  const std::string why =
      f < kHoverFarWakeCyclesMin
          ? "the wing may meet rows of the far wake, which move as a block and do not give way to it "
            "(hawkmoth hover: within a core radius at 0.25 and 0.375)"
          : "the longer free wake's instability makes the cycle means wander (hawkmoth hover, cycles "
            "10-20: 0.8 % at 0.75, 1.4 % at 1, 4.8 % at 2)";
  warn_at_numerics_key(root, c, "far_wake_cycles",
                       "far_wake_cycles = " + number_text(f) + " in hover is outside the measured range " +
                           number_text(kHoverFarWakeCyclesMin) + " to " +
                           number_text(kHoverFarWakeCyclesMax) + ": " + why +
                           " (docs/uvlm.md, \"Hover over many cycles\")");
}

// A revolution whose ramp lasts beyond the start of the last cycle: the last cycle's mean
// (summary.json mean_CL, the reported mean lift) is then taken while the wing still speeds up,
// and its coefficients are on the full rate's speed Ω r2 R, which the wing has not reached.
// Measured (1 Dec; cases/robofly_revolving.toml, "separated", 2 cycles of 0.25 s): mean CL
// 2.280 without a ramp, 2.252 with 0.1 s, 2.164 (-5 %) with 0.3 s, 1.771 (-22 %) with 0.45 s.
namespace {
void warn_revolution_ramp_into_last_cycle(const TomlTable& root, Case& c) {
  const mbd::WingKinematics::Revolution& turn = c.kinematics.revolution;
  const double period = 1.0 / c.kinematics.frequency;                // [s]
  const double last_cycle_start = (c.numerics.cycles - 1) * period;  // [s]
  if (!turn.active() || c.numerics.steady || !(turn.ramp > last_cycle_start)) return;
  const int cycles_needed = static_cast<int>(std::ceil(turn.ramp / period)) + 1;
  const auto t = root.find_table("kinematics");
  c.warnings.push_back(
      {c.file, t ? t->line_of("revolution") : 0, "kinematics.revolution.ramp_s",
       "the revolution's ramp (" + number_text(turn.ramp) + " s) lasts beyond the start of the last cycle (" +
           number_text(last_cycle_start) + " s of a " + number_text(c.numerics.cycles * period) +
           " s run): the last cycle's mean lift and its coefficients (on the full rate's speed at r2) "
           "are taken while the wing still speeds up (cases/robofly_revolving.toml with a 0.45 s ramp: "
           "mean CL 22 % low); run at least " +
           std::to_string(cycles_needed) + " cycles or shorten the ramp"});
}
}  // namespace

// A rotation phase that shifts nothing: δψ moves the sweep and deviation against the rotation
// (mbd::WingKinematics::angles); with both constant (a revolving wing's sweep = 0, a plate that
// only pitches) every δψ gives the same run (cases/robofly_revolving.toml swept over
// rotation_phase = -0.1, 0: the same mean CL 1.652 to the last digit). Its inputs hash leaves it
// out then (io::input_hash), so a sweep over it is refused as one that changes nothing.
namespace {
void warn_rotation_phase_that_shifts_nothing(const TomlTable& root, Case& c) {
  const mbd::WingKinematics& k = c.kinematics;
  if (k.rotation_phase == 0.0 || !k.sweep.is_constant() || !k.deviation.is_constant()) return;
  const auto t = root.find_table("kinematics");
  c.warnings.push_back(
      {c.file, t ? t->line_of("rotation_phase") : 0, "kinematics.rotation_phase",
       "the rotation phase shifts the sweep and the deviation against the rotation, and both "
       "are constant here (no stroke to time the rotation against): it changes nothing"});
}

// The converse: a constant rotation (a wing held at a fixed angle, its film pitching
// passively: cases/mav_film_wing.toml) and a pivot that does not translate. δψ then shifts the
// whole wingbeat in time, the periodic wingbeat is the same, and runs differ only by how they
// start from rest (a sweep of the MAV film wing's δψ = -0.25, 0, 0.25 read 3.956, 3.787, 3.956
// mN over 2 wingbeats and 3.824, 3.772, 3.824 over 8, as a design effect; 6 Dec).
void warn_rotation_phase_that_only_shifts_time(const TomlTable& root, Case& c) {
  const mbd::WingKinematics& k = c.kinematics;
  if (k.rotation_phase == 0.0 || !k.rotation.is_constant() || k.pivot_translates() || k.revolution.active() ||
      (k.sweep.is_constant() && k.deviation.is_constant()))
    return;
  const auto t = root.find_table("kinematics");
  c.warnings.push_back(
      {c.file, t ? t->line_of("rotation_phase") : 0, "kinematics.rotation_phase",
       "the rotation is constant here, so the rotation phase only shifts the whole wingbeat in time: the "
       "periodic wingbeat is the same whatever its value, and runs differ only by how they start from rest "
       "(their first wingbeats); a sweep over it measures the start, not the timing of a rotation"});
}
}  // namespace

// A liquid with air's viscosity: a case whose fluid is far denser than air (water 998, the
// Robofly's mineral oil 880 kg/m³) and that leaves numerics.kinematic_viscosity at air's
// 1.5e-5 m²/s gets the core growth and the Reynolds number of air (docs/uvlm.md, "Reynolds
// number"): warned at air.density. The bound, 10 kg/m³, is 8 times sea-level air.
namespace {
void warn_dense_fluid_with_air_viscosity(const TomlTable& root, Case& c) {
  if (!c.air.enabled || !(c.air.density > kDenseFluidDensity)) return;
  if (const auto t = root.find_table("numerics"); t && t->has("kinematic_viscosity")) return;
  const auto a = root.find_table("air");
  c.warnings.push_back(
      {c.file, a ? a->line_of("density") : 0, "air.density",
       "a fluid of " + number_text(c.air.density) +
           " kg/m^3 with numerics.kinematic_viscosity left at air's 1.5e-5 m^2/s: the wake's core growth and "
           "the Reynolds number `check` prints are then air's; set it to the fluid's (water 1.0e-6, the "
           "Robofly's mineral oil 7.3e-4 m^2/s as cases/robofly_revolving.toml)"});
}
}  // namespace

// Few steps per wingbeat: the lift converges from below as the step shrinks. Measured (1 Dec;
// cases/hover_flexible.toml, mean CL of its 3 wingbeats against 100 steps a cycle, 3.407):
// 7 steps -17.9 %, 12 -12.6 %, 16 -8.6 %, 20 -5.8 %, 24 -4.8 %, 30 -2.7 %, 40 -0.8 %, 50 -1.0 %.
// Below 24 steps the error passes 5 %: warned. A revolving wing's cycle is a time unit (its
// steps per chord of travel matter) and a steady solve has no steps: neither is warned.
namespace {
constexpr int kFewStepsPerCycle = 24;
void warn_few_steps_per_cycle(const TomlTable& root, Case& c) {
  const Case::Numerics& n = c.numerics;
  if (!c.air.enabled || n.steady || c.kinematics.revolution.active() ||
      n.steps_per_cycle >= kFewStepsPerCycle)
    return;
  warn_at_numerics_key(
      root, c, "steps_per_cycle",
      std::to_string(n.steps_per_cycle) +
          " steps a wingbeat resolve it coarsely: the flexible hawkmoth hover's mean lift "
          "(cases/hover_flexible.toml) lies 18, 13, 9 and 6 % below its value at 100 steps with "
          "7, 12, 16 and 20 steps a cycle, 5 % at 24, 1 % at 40-50; use 40 or more, or measure "
          "the change with make convergence CASE=... (docs/uvlm.md, \"Convergence study\")");
}
}  // namespace

// A harmonic the time step does not resolve: harmonic n needs more than 2n steps per cycle
// (docs/case_file.md, "Kinematics"); a 21st harmonic at 24 steps ran without a word, its
// motion aliased to a lower one.
namespace {
void warn_unresolved_harmonic(const TomlTable& root, Case& c) {
  const mbd::WingKinematics& k = c.kinematics;
  int highest = 0;
  std::string key;
  for (const auto& named : k.named_signals())
    if (named.signal->highest_harmonic() > highest) {
      highest = named.signal->highest_harmonic();
      key = named.name;
    }
  if (c.numerics.steady || c.numerics.steps_per_cycle > 2 * highest) return;
  warn_at_numerics_key(
      root, c, "steps_per_cycle",
      std::to_string(c.numerics.steps_per_cycle) + " steps a cycle do not resolve harmonic " +
          std::to_string(highest) + " of kinematics." + key +
          " (a step resolves harmonic n only with more than 2n steps a cycle): its motion is "
          "sampled as a lower harmonic's; use more than " +
          std::to_string(2 * highest) + " steps a cycle");
}
}  // namespace

// A thin wake core in hover: the wing sweeps back through the wake it shed half a stroke
// before, and cores below 0.15 mean chords make its lift erratic, the more so the finer the
// step (docs/uvlm.md, "Hover results with leading_edge = none": 0.05 and 0.1 noisy, even a
// negative mean; 0.15-0.3 periodic). Measured 1 Dec on the rigid hawkmoth hover (eq. 8) at
// 50 / 100 / 200 steps a cycle: last-cycle CL 2.269 / 0.232 / 4.342 with 0.05 against 2.780 /
// 2.771 / 2.775 with 0.2, the default. A free stream carries the wake away (a small core is
// the more accurate there), and a revolving wing was not measured: neither is warned.
namespace {
constexpr double kThinHoverCore = 0.15;  // [mean chords]
void warn_thin_core_in_hover(const TomlTable& root, Case& c) {
  const Case::Numerics& n = c.numerics;
  const mbd::WingKinematics& k = c.kinematics;
  if (!c.air.enabled || n.steady || !n.free_wake || !c.air.freestream.isZero(0.0) || k.pivot_translates() ||
      k.revolution.active() || n.core_radius >= kThinHoverCore)
    return;
  warn_at_numerics_key(
      root, c, "core_radius",
      "a wake core of " + number_text(n.core_radius) +
          " mean chords in hover: the wing sweeps back through the wake it shed half a stroke before, "
          "and cores below 0.15 make its lift erratic, the more so the finer the step (the rigid "
          "hawkmoth hover's last-cycle CL 2.27 / 0.23 / 4.34 at 50 / 100 / 200 steps a cycle with 0.05, "
          "per-step CL from -95 to 244; 2.780 / 2.771 / 2.775 with 0.2, the default); use 0.15-0.3 "
          "(docs/case_file.md, core_radius)");
}
}  // namespace

// Angles in radians where degrees are expected (`cos_deg = [0.87]` for a 50° stroke): every
// value the sweep and rotation take stays within ±2π degrees, a wing that hardly moves. No
// flapping kinematics is that small: insects and the shipped cases sweep ±50–60° and rotate
// about 90° ± 45°. And a sweep beyond ±180°, more than half a turn either way.
constexpr double kRadianSuspicionDeg = 2.0 * 3.14159265358979323846;
void warn_implausible_angles(const TomlTable& root, Case& c) {
  const mbd::WingKinematics& k = c.kinematics;
  double largest_deg = 0.0, largest_sweep_deg = 0.0, largest_rotation_deg = 0.0;
  double lowest_sweep = std::numeric_limits<double>::infinity(), highest_sweep = -lowest_sweep;  // [deg]
  double lowest_rotation = std::numeric_limits<double>::infinity(),
         highest_rotation = -lowest_rotation;  // [deg]
  for (int i = 0; i < 360; ++i) {
    const double s = i / 360.0;
    const double signed_sweep = k.sweep.at_phase(s).value / kDegToRad;
    lowest_sweep = std::min(lowest_sweep, signed_sweep);
    highest_sweep = std::max(highest_sweep, signed_sweep);
    const double sweep = std::abs(signed_sweep);
    largest_sweep_deg = std::max(largest_sweep_deg, sweep);
    const double signed_rotation = k.rotation.at_phase(s).value / kDegToRad;
    lowest_rotation = std::min(lowest_rotation, signed_rotation);
    highest_rotation = std::max(highest_rotation, signed_rotation);
    const double rotation = std::abs(signed_rotation);
    largest_rotation_deg = std::max(largest_rotation_deg, rotation);
    largest_deg = std::max({largest_deg, sweep, rotation});
  }
  // The stroke alone in radians (rotation in degrees): a sweep that swings, by less than
  // ±2π degrees. A sweep that does not swing at all (0: a plunging or pitching wing) is not.
  const double sweep_amplitude_deg = 0.5 * (highest_sweep - lowest_sweep);
  const auto t = root.find_table("kinematics");
  auto fixed = [](double x) {
    std::ostringstream o;
    o.precision(3);
    o << x;
    return o.str();
  };
  // Small angles throughout are what a wing in a free stream, a heaving one or a revolving
  // one has (a plate at 5°, a pitching aerofoil, a Robofly wing revolving at 5° incidence):
  // only a wing that moves by its angles alone is suspect.
  const bool moved_otherwise = c.air.freestream.norm() > 0.0 || k.pivot_translates() || k.revolution.active();
  const double rotation_amplitude_deg = 0.5 * (highest_rotation - lowest_rotation);
  if (!moved_otherwise && largest_deg > 0.0 && largest_deg <= kRadianSuspicionDeg)
    c.warnings.push_back({c.file, t ? t->line_of("sweep") : 0, "kinematics.sweep",
                          "the sweep and rotation angles never exceed " + fixed(largest_deg) +
                              " degrees: were they written in radians? Keys ending in _deg and the deg "
                              "column of a table are in degrees (a 50-degree stroke is cos_deg = [50.0])"});
  else if (sweep_amplitude_deg > 1e-9 && sweep_amplitude_deg <= kRadianSuspicionDeg)
    c.warnings.push_back({c.file, t ? t->line_of("sweep") : 0, "kinematics.sweep",
                          "the sweep swings by only +-" + fixed(sweep_amplitude_deg) + " degrees (from " +
                              fixed(lowest_sweep) + " to " + fixed(highest_sweep) + ") while the rotation reaches " +
                              fixed(largest_deg) +
                              ": was the stroke written in radians? Keys ending in _deg and the deg column of a "
                              "table are in degrees (a 50-degree stroke is cos_deg = [50.0]); the lift "
                              "coefficient's reference speed, the flapping speed at r2, is then tiny"});
  // The rotation alone in radians (the stroke in degrees): a rotation that pitches, never
  // beyond ±2π degrees, under a sweep that swings by more. A constant rotation (an angle of
  // attack held through the stroke) is not suspect.
  else if (!moved_otherwise && sweep_amplitude_deg > kRadianSuspicionDeg && rotation_amplitude_deg > 1e-9 &&
           largest_rotation_deg <= kRadianSuspicionDeg)
    c.warnings.push_back({c.file, t ? t->line_of("rotation") : 0, "kinematics.rotation",
                          "the rotation never exceeds " + fixed(largest_rotation_deg) + " degrees (from " +
                              fixed(lowest_rotation) + " to " + fixed(highest_rotation) +
                              ") while the sweep swings by +-" + fixed(sweep_amplitude_deg) +
                              ": was the rotation written in radians? Keys ending in _deg and the deg "
                              "column of a table are in degrees (a wing pitching 90 +- 45 degrees is "
                              "mean_deg = 90.0, sin_deg = [45.0])"});
  else if (largest_sweep_deg > 180.0)
    c.warnings.push_back({c.file, t ? t->line_of("sweep") : 0, "kinematics.sweep",
                          "the sweep angle reaches " + fixed(largest_sweep_deg) +
                              " degrees, more than half a turn from the stroke's zero: an amplitude in the "
                              "wrong unit or a coefficient off?"});
  // A rotation beyond a whole turn (1e300 degrees ran to a lift of -0.7 mN unwarned): no
  // wing pitches that far; 90 +- 90 degrees is the most a stroke's reversal asks.
  if (largest_rotation_deg > 360.0)
    c.warnings.push_back({c.file, t ? t->line_of("rotation") : 0, "kinematics.rotation",
                          "the rotation angle reaches " + fixed(largest_rotation_deg) +
                              " degrees, more than a whole turn from the wing's zero: an amplitude in the "
                              "wrong unit or a coefficient off?"});
}

Case read_case(TomlTable root) {
  // Another kind of flapsim file where a case belongs: say what it is rather than list its
  // tables as unknown keys.
  if (!root.has("kinematics")) {
    if (root.has("planform"))
      root.fail("planform", "this is a wing file (it has [planform]), not a case file (no [kinematics]): a case "
                            "file names its wing with wing = \"...\" (docs/case_file.md); 'flapsim check' reads either");
    if (root.has("bodies"))
      root.fail("bodies", "this is a chain file (it has [[bodies]], as 'flapsim reduce' writes it), not a case file "
                          "(no [kinematics]): give it to a case with chain = \"...\" or to 'flapsim run CASE --chain'");
  }
  root.expect_only({"name", "description", "length_unit", "wing", "chain", "kinematics", "air",
                    "structure", "numerics", "output", "loads", "markers"});
  root.read_length_unit();
  Case c;
  c.file = root.file();
  c.length_unit = root.length_unit();
  c.length_scale = root.length_scale();
  for (const std::string& key : root.keys()) {
    c.key_lines[key] = root.line_of(key);
    if (root.is_table(key))
      for (const TomlTable t = root.get_table(key); const std::string& sub : t.keys())
        c.key_lines[key + "." + sub] = t.line_of(sub);
    else if (key == "loads" || key == "markers") {  // "loads.2.body": the second [[loads]]'s body
      const std::vector<TomlTable> tables = root.get_tables(key);
      for (std::size_t i = 0; i < tables.size(); ++i)
        for (const std::string& sub : tables[i].keys())
          c.key_lines[key + "." + std::to_string(i + 1) + "." + sub] = tables[i].line_of(sub);
    }
  }
  c.name = root.get_string("name", std::filesystem::path(root.file()).stem().string());
  // A name is a label, never a path: "../../x" or "/tmp/x" would lead the default output
  // folder (out/<name>) elsewhere.
  if (root.has("name")) {
    if (c.name.empty() || c.name.size() > 128 || folder_name_of(c.name) != c.name)
      root.fail("name",
                "a case name is 1 to 128 letters, digits, '-', '_' or '.', not starting with '.' "
                "(it names the default output folder out/<name>), found \"" + c.name + "\"");
  }
  if (root.has("description")) root.get_string("description");
  if (!root.has("wing") && !root.has("chain"))
    root.fail("wing", "missing required key: a case names a wing file ('wing') or a chain file ('chain')");
  if (root.has("wing")) c.wing_file = existing_file(root, "wing");
  if (root.has("chain")) c.chain_file = existing_file(root, "chain");

  c.kinematics = read_kinematics(root.get_table("kinematics"), c.warnings);
  c.air = read_air(root);
  c.structure = read_structure(root);
  if (const auto s = root.find_table("structure"); s && s->has("gravity"))
    if (auto w = gravity_warning(c.structure.gravity, c.file, s->line_of("gravity")))
      c.warnings.push_back(std::move(*w));
  c.numerics = read_numerics(root);
  default_far_wake_in_hover(root, c);
  if (c.structure.kind == Case::Structure::Kind::Fem) {
    // The FEM is built from the wing file; the chain's keys would be read and ignored.
    if (root.has("chain"))
      root.fail("chain", "kind = \"fem\" integrates the wing's own FEM, built from the wing file; a chain file is the "
                         "bar chain's (kind = \"flexible\"): remove chain (and give wing), or set kind = \"flexible\"");
    if (const auto n = root.find_table("numerics"); n && n->has("structure_substeps"))
      n->fail("structure_substeps", "substeps of the bar chain's integrator; the FEM structure (kind = \"fem\") "
                                    "splits its own steps where they fail (docs/fsi.md, \"Step halving of the FEM\"): "
                                    "remove structure_substeps");
  }
  // A rigid wing is the wing file's outline as one body: a chain file is not read (a broken
  // one passed check and run without a word, where --chain on such a case is warned).
  if (c.structure.kind == Case::Structure::Kind::Rigid && root.has("chain") && root.has("wing"))
    c.warnings.push_back(
        {c.file, root.line_of("chain"), "chain",
         "not used: structure.kind = \"rigid\" flies the wing file's outline as one rigid body; "
         "the chain file is read only with kind = \"flexible\" (it is not checked either)"});
  // The steady lattice's wake leaves along the free stream (docs/uvlm.md, "Steady lattice").
  if (c.numerics.steady && !(c.air.enabled && c.air.freestream.norm() > 0.0))
    root.get_table("numerics").fail("steady", "the steady lattice needs air with a free stream "
                                              "([air] freestream, not zero); its wake leaves along it");
  // Nor does it shed: with it "shed" was the attached edge, bit for bit (a rigid hawkmoth
  // wing flapping in a 3 m/s stream, cases/hover.toml's kinematics: mean CL 4.33, as
  // "attached", where "separated" gives 3.23), which a user who asked for shedding would not
  // expect.
  if (c.numerics.steady && c.numerics.leading_edge == uvlm::LeadingEdge::Shed)
    root.get_table("numerics")
        .fail("steady",
              "the steady lattice sheds nothing: with it leading_edge = \"shed\" "
              "would be the attached edge (\"attached\"); shed in the unsteady "
              "lattice (steady = false), or choose \"attached\", \"separated\" or "
              "\"none\"");
  // The leading-edge sheet is free vortices ("shed": docs/uvlm.md, "Leading-edge vortex
  // shedding"); in still air a prescribed one would never leave the edge's path
  // (still_air_prescribed_wake).
  if (still_air_prescribed_wake(c) && c.numerics.leading_edge == uvlm::LeadingEdge::Shed)
    root.get_table("numerics")
        .fail("free_wake",
              "leading_edge = \"shed\" in still air needs a free wake: a prescribed wake (free_wake = false) "
              "moves with the free stream only, so without one the shed vortices stay where the leading "
              "edge released them and the wing sweeps back through them (the rigid hawkmoth hover of "
              "cases/hover.toml: mean CL 4.71, and 8.45 without far_wake_cycles, against 2.99 with the free "
              "wake); set free_wake = true");
  if (const auto out = root.find_table("output")) {
    out->expect_only({"vtk_every"});
    c.output.vtk_every = out->get_int("vtk_every", c.output.vtk_every, Bounds::non_negative());
  }
  const auto loads = root.get_tables("loads");
  // Point loads and markers name the chain's bodies; the FEM structure has none.
  if (c.structure.kind == Case::Structure::Kind::Fem) {
    if (!loads.empty())
      loads.front().fail("body", "point loads act on the bodies of a chain; the FEM structure (kind = \"fem\") "
                                 "has none: remove [[loads]] or run the chain (kind = \"flexible\")");
    if (const auto markers = root.get_tables("markers"); !markers.empty())
      markers.front().fail("body", "markers ride on the bodies of a chain; the FEM structure (kind = \"fem\") "
                                   "has none: remove [[markers]] or run the chain (kind = \"flexible\")");
  }
  for (const auto& t : loads) c.loads.push_back(read_load(t, c.structure.bodies, c.kinematics.frequency));
  const auto markers = root.get_tables("markers");
  for (std::size_t i = 0; i < markers.size(); ++i) {
    c.markers.push_back(read_marker(markers[i], i, c.structure.bodies));
    // Each name heads its own history.csv columns (<name>_x_m, ...): no two alike.
    for (std::size_t k = 0; k < i; ++k)
      if (c.markers[k].name == c.markers[i].name)
        markers[i].fail("name", "'" + c.markers[i].name + "' is already the name of marker " + std::to_string(k + 1) +
                                    " (each marker's name heads its own history.csv columns " + c.markers[i].name +
                                    "_x_m, _y_m, _z_m)");
  }
  warn_long_free_hover(root, c);
  warn_still_air_prescribed_wake(root, c);
  warn_frozen_wake_in_still_air(root, c);
  warn_frozen_wake_in_a_stream(root, c);
  warn_wake_cap_before_the_far_wake(root, c);
  warn_experimental_shedding(root, c);
  warn_far_wake_outside_measured_range(root, c);
  warn_implausible_angles(root, c);
  warn_revolution_ramp_into_last_cycle(root, c);
  warn_rotation_phase_that_shifts_nothing(root, c);
  warn_rotation_phase_that_only_shifts_time(root, c);
  warn_few_steps_per_cycle(root, c);
  warn_unresolved_harmonic(root, c);
  warn_thin_core_in_hover(root, c);
  warn_dense_fluid_with_air_viscosity(root, c);
  return c;
}

std::string folder_name_of(const std::string& name) {
  std::string out;
  for (char ch : name) {
    const bool safe = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
                      ch == '-' || ch == '_' || ch == '.';
    out += safe ? ch : '_';
  }
  if (out.empty()) return "case";
  if (out[0] == '.') out[0] = '_';
  return out.substr(0, 128);
}

Case load_case_file(const std::string& path) { return read_case(wings::parse_toml_file(path)); }

Case load_case_file(const std::string& path,
                    const std::vector<std::pair<std::string, std::string>>& overrides) {
  TomlTable root = wings::parse_toml_file(path);
  root.apply_overrides(overrides);
  // A sweep over structure.kind (rigid, flexible, fem) of a case written for one kind: the
  // file's keys of another kind (a chain's bodies, the FEM's mesh and Newton keys) do not
  // apply to the kind set here, and are left out unless the same point sets them too. Before,
  // `--vary structure.kind=rigid,flexible,fem` of a chain case was refused ("a rigid wing is
  // one body (found 8)"), and no case table could leave bodies out for the FEM.
  const auto set_here = [&](const std::string& key) {
    return std::any_of(overrides.begin(), overrides.end(), [&](const auto& o) { return o.first == key; });
  };
  if (set_here("structure.kind")) {
    const std::string kind = root.get_table("structure").get_string("kind", "");
    if (kind != "flexible" && !set_here("structure.bodies")) root.remove_key("structure", "bodies");
    if (kind != "fem")
      for (const char* key : kFemStructureKeys)
        if (!set_here(std::string("structure.") + key)) root.remove_key("structure", key);
  }
  return read_case(root);
}

}  // namespace flapsim::io
