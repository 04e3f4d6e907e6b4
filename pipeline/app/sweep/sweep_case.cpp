#include "pipeline/app/sweep/sweep_case.hpp"

#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/app/resource_estimate.hpp"
#include "pipeline/app/setup_warnings.hpp"
#include "pipeline/app/watched_setup.hpp"
#include "pipeline/app/wing_override.hpp"
#include "pipeline/io/case_file.hpp"
#include "pipeline/io/input_hash.hpp"
#include "wings/loader/input_error.hpp"

namespace flapsim::sweep {

namespace {
constexpr std::string_view kWingPrefix = "wing.";

bool starts_with(const std::string& s, std::string_view prefix) { return s.rfind(prefix, 0) == 0; }
bool ends_with(const std::string& s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// A wing key that cannot change the run is a sweep that varies nothing: every case would
// give the same numbers (a stiffness sweep with --chain gave identical rows). A flexible
// case with a chain file takes its structure from the chain: of the wing only the outline
// and the [surface] shape (the lattice) count. A rigid wing uses the outline and the mass, never the stiffness or
// the mesh.
void refuse_wing_keys_that_change_nothing(const SweepInputs& inputs, const ResolvedCase& r) {
  const bool flexible = r.c.structure.kind == io::Case::Structure::Kind::Flexible;
  const std::string chain = !inputs.chain_file.empty() ? inputs.chain_file : r.c.chain_file;
  for (const auto& [key, value] : r.wing_overrides) {
    (void)value;
    std::string why;
    if (flexible && !chain.empty() && !starts_with(key, "planform.") && !starts_with(key, "surface."))
      why = "the chain comes from the chain file " + chain +
            ", so of the wing only the lattice's outline and surface (planform.*, surface.*) reach the run; drop "
            "the chain file to have the "
            "wing reduced in process for each value, or vary spring_scale";
    else if (r.c.structure.kind == io::Case::Structure::Kind::Rigid && (ends_with(key, ".youngs_modulus") || ends_with(key, ".poisson_ratio") ||
                           starts_with(key, "mesh.")))
      why = "a rigid wing uses only the wing's outline and mass, not its stiffness or mesh";
    if (!why.empty())
      throw InputError(inputs.case_file, 0, std::string(kWingPrefix) + key,
                       "varying it changes nothing in these runs: " + why);
  }
}

// A problem of one varied key (its column), located where the key was written: a case
// table's header (the key's name) or row (its value); with --vary values, the case or wing
// file's key, after the point's values.
[[noreturn]] void fail_column(const SweepInputs& inputs, const CasePoint& point, const PointSource& source,
                              const std::string& column, bool concerns_the_key, const InputError& e,
                              const std::string& detail) {
  if (source.file.empty()) {
    if (point.empty()) throw e;
    throw InputError(e.file(), e.line(), e.key(), "with " + describe(point) + ": " + e.message());
  }
  const std::string& in_file = e.file().empty() ? inputs.case_file : e.file();
  std::string where = " (" + in_file;
  if (e.key() != column && !e.key().empty()) where += ", key '" + e.key() + "'";
  where += ")";
  throw InputError(source.file, concerns_the_key ? source.header_line : source.line, column, detail + where);
}

// The column of the point an override error concerns (a case key, or "wing." + a wing key).
const Assignment* column_of(const CasePoint& point, const OverrideInputError& e, bool in_case_file) {
  for (const Assignment& a : point) {
    const KeyTarget t = key_target(a.key);
    if (in_case_file && t == KeyTarget::case_file && a.key == e.override_key()) return &a;
    if (!in_case_file && t == KeyTarget::wing_file && a.key == std::string(kWingPrefix) + e.override_key())
      return &a;
  }
  return nullptr;
}

// A problem the run's setup finds in a case (its chain, its size, its lattice or reference
// speed), named where it was written: the table's row and column when it is a varied key of
// a case table; else the case, wing or chain file's key, after the point's values and (for
// a table) the row.
[[noreturn]] void fail_case(const SweepInputs& inputs, const CasePoint& point, const PointSource& source,
                            const InputError& e) {
  if (!source.file.empty()) {
    for (const Assignment& a : point)
      if (a.key == e.key() && key_target(a.key) == KeyTarget::case_file)
        throw InputError(source.file, source.line, a.key,
                         e.message() + " (" + (e.file().empty() ? inputs.case_file : e.file()) + ")");
    throw InputError(e.file(), e.line(), e.key(),
                     "with " + describe(point) + " (" + source.file + ":" + std::to_string(source.line) +
                         "): " + e.message());
  }
  if (point.empty()) throw e;
  throw InputError(e.file(), e.line(), e.key(), "with " + describe(point) + ": " + e.message());
}

// What `flapsim run` refuses before its first step, and `flapsim check` with it, checked for
// every case before any runs (a sweep used to run such cases and list them as errors, exit 0:
// a broken --chain, a chain of another body count, a case with no reference speed, a run too
// large for the memory that ended in std::bad_alloc). The run's setup is built as run builds
// it: the chain file read and matched to the case, loads and markers on existing bodies, the
// lattice, its attachment and the reference speed; then the run's size against the memory.
// A wing reduced in process is not reduced here (its FEM takes seconds to a minute per case,
// and a sweep runs each case's reduction once, in the case): the rest of its setup is built
// with the wing as a rigid body, and loads and markers are checked against structure.bodies,
// the number of bodies the reduction gives. Failures other than bad input (the numerics)
// are left to the case, which records them in its row.
void check_like_run(const SweepInputs& inputs, ResolvedCase& r) {
  const io::Case& c = r.c;
  int bodies = c.structure.kind == io::Case::Structure::Kind::Rigid ? 1 : c.structure.bodies, fem_dofs = 0;
  const app::SetupOptions options{inputs.chain_file, r.spring_scale, r.wing_overrides};
  try {
    if (!app::reduces_wing_in_process(c, inputs.chain_file) || c.wing_file.empty()) {
      const app::FsiSetup setup = app::build_fsi_setup(c, options);
      bodies = setup.chain().num_bodies();
      if (setup.fem_structure) fem_dofs = setup.fem_structure->num_dofs();
    } else {
      for (std::size_t i = 0; i < c.loads.size(); ++i)
        if (c.loads[i].body > bodies)
          throw InputError(c.file, c.line_of("loads." + std::to_string(i + 1) + ".body"), "loads.body",
                           "body " + std::to_string(c.loads[i].body) + " is outside the chain of " +
                               std::to_string(bodies) + " bodies");
      for (std::size_t i = 0; i < c.markers.size(); ++i)
        if (c.markers[i].body > bodies)
          throw InputError(c.file, c.line_of("markers." + std::to_string(i + 1) + ".body"), "markers.body",
                           "marker '" + c.markers[i].name + "' on body " + std::to_string(c.markers[i].body) +
                               " is outside the chain of " + std::to_string(bodies) + " bodies");
      io::Case lattice_only = c;
      lattice_only.structure.kind = io::Case::Structure::Kind::Rigid;
      lattice_only.loads.clear();
      lattice_only.markers.clear();
      lattice_only.structure.initial_angles.clear();
      lattice_only.structure.initial_rates.clear();
      (void)app::build_fsi_setup(lattice_only, options);
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception&) {
    return;  // a numerical failure of the setup: the case's run meets it and records it
  }
  const app::RunEstimate estimate = app::estimate_run(c, bodies, fem_dofs);
  app::refuse_if_it_cannot_fit(estimate, c);
  r.estimated_seconds = estimate.seconds;
}

}  // namespace

KeyTarget key_target(const std::string& key) {
  if (key == "spring_scale") return KeyTarget::spring_scale;
  if (key.rfind(kWingPrefix, 0) == 0) return KeyTarget::wing_file;
  return KeyTarget::case_file;
}

ResolvedCase resolve_case(const SweepInputs& inputs, const CasePoint& point, const PointSource& source) {
  ResolvedCase r;
  r.spring_scale = inputs.spring_scale;
  std::vector<std::pair<std::string, std::string>> case_overrides;
  if (!inputs.wing_file.empty()) case_overrides.push_back(app::wing_file_override(inputs.wing_file));
  for (const Assignment& a : point) {
    switch (key_target(a.key)) {
      case KeyTarget::case_file:
        // A wing file is a path from the current folder, as run --wing's.
        if (std::error_code ec; takes_paths(a.key) && !std::filesystem::is_regular_file(a.word, ec)) {
          const std::string why =
              "wing file not found: " + a.word + " (a path from the current folder, as run --wing's)";
          fail_column(inputs, point, source, a.key, false, InputError("", 0, a.key, why), why);
        }
        case_overrides.push_back(takes_paths(a.key) ? app::wing_file_override(a.word)
                                                    : std::pair{a.key, value_text(a)});
        break;
      case KeyTarget::wing_file:
        r.wing_overrides.emplace_back(a.key.substr(kWingPrefix.size()), value_text(a));
        break;
      case KeyTarget::spring_scale:
        if (!a.word.empty())
          fail_column(inputs, point, source, a.key, false,
                      InputError(inputs.case_file, 0, a.key, "'" + a.word + "' is not a number"),
                      "'" + a.word + "' is not a number (the factor on every joint spring)");
        if (!(a.value > 0.0))
          fail_column(inputs, point, source, a.key, false, InputError(inputs.case_file, 0, a.key, "must be > 0"),
                      "must be > 0 (the factor on every joint spring)");
        r.spring_scale = a.value;
        break;
    }
  }
  try {
    r.c = io::load_case_file(inputs.case_file, case_overrides);
  } catch (const OverrideInputError& e) {
    if (const Assignment* a = column_of(point, e, true))
      fail_column(inputs, point, source, a->key, e.concerns_the_key(), e, e.detail());
    fail_column(inputs, point, {}, "", false, e, "");
  } catch (const InputError& e) {
    fail_column(inputs, point, {}, "", false, e, "");
  }
  try {
    refuse_wing_keys_that_change_nothing(inputs, r);
  } catch (const InputError& e) {
    fail_column(inputs, point, source, e.key(), true, e, e.message());  // the column itself can change nothing
  }
  try {
    const auto wing = app::load_case_wing(r.c, r.wing_overrides);
    r.inputs_hash = io::input_hash(r.c, wing ? &*wing : nullptr, inputs.chain_file, r.spring_scale);
    r.file_warnings = app::file_warning_notes(r.c, wing ? &*wing : nullptr);
  } catch (const OverrideInputError& e) {
    if (const Assignment* a = column_of(point, e, false))
      fail_column(inputs, point, source, a->key, e.concerns_the_key(), e, e.detail());
    fail_column(inputs, point, {}, "", false, e, "");
  } catch (const InputError& e) {
    fail_column(inputs, point, {}, "", false, e, "");
  }
  try {
    check_like_run(inputs, r);
  } catch (const InputError& e) {
    fail_case(inputs, point, source, e);
  }
  return r;
}

std::string case_folder(std::size_t index, std::size_t count, const CasePoint& point) {
  int digits = 2;
  for (std::size_t n = count > 0 ? count - 1 : 0; n >= 100; n /= 10) ++digits;
  char head[32];
  std::snprintf(head, sizeof head, "%0*zu", digits, index);
  std::string name = head;
  for (const Assignment& a : point) name.append("_").append(value_label(a));
  return name;
}

std::string describe(const CasePoint& point) {
  std::string s;
  for (const Assignment& a : point) s += (s.empty() ? "" : ", ") + a.key + " = " + value_label(a);
  return s;
}

std::function<std::string(const app::FsiSetup&)> recorded_warnings(const ResolvedCase& r,
                                                                   std::vector<std::string>& notes) {
  notes = r.file_warnings;
  return [&notes, &r](const app::FsiSetup& setup) {
    for (const std::string& w : app::setup_warnings(r.c, setup)) notes.push_back(app::warning_headline(w));
    return app::join_notes(notes);
  };
}

}  // namespace flapsim::sweep
