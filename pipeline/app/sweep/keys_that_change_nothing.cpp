#include "pipeline/app/sweep/keys_that_change_nothing.hpp"

#include <array>
#include <map>
#include <optional>
#include <set>
#include <string_view>

#include "pipeline/io/case_model.hpp"
#include "wings/loader/input_error.hpp"
#include "wings/loader/toml_reader.hpp"

namespace flapsim::sweep {

namespace {

// At most this many values are listed in a message.
constexpr std::size_t kValuesListed = 8;

// The distinct values of key k over the points, in the order given: "0.3, 0.5".
std::string values_of(const std::vector<CasePoint>& points, std::size_t k) {
  std::set<std::pair<double, std::string>> seen;
  std::string list;
  for (const CasePoint& point : points) {
    if (!seen.insert(value_key(point[k])).second) continue;
    if (seen.size() > kValuesListed) return list + ", ...";
    list += (list.empty() ? "" : ", ") + value_label(point[k]);
  }
  return list;
}

// Refuses key k: "GIVEN: WHY, so the varied values change nothing; INSTEAD", where the keys
// were given (the case file for --vary values, a case table's header for its columns).
[[noreturn]] void refuse(const VariedKeys& varied, std::size_t k, const std::string& why,
                         const std::string& instead) {
  throw InputError(varied.file, varied.line, varied.keys[k],
                   varied.given[k] + ": " + why + ", so the varied values change nothing; " + instead);
}

// A wing-file mesh size that a FEM case's own key replaces (fem_structure_setup.cpp).
struct MeshSizeOverride {
  std::string_view wing_key;          ///< the varied key
  std::string_view case_key;          ///< the case's key that replaces it
  double io::Case::Structure::*size;  ///< that key's value [m]; 0 when not given
};

constexpr std::array kMeshSizeOverrides = {
    MeshSizeOverride{"wing.mesh.element_size", "structure.element_size_mm",
                     &io::Case::Structure::fem_element_size},
    MeshSizeOverride{"wing.mesh.vein_element_size", "structure.vein_element_size_mm",
                     &io::Case::Structure::fem_vein_element_size},
};

// The override of key k that every case has, if any.
std::optional<MeshSizeOverride> mesh_size_override(const VariedKeys& varied,
                                                   const std::vector<ResolvedCase>& cases, std::size_t k) {
  for (const MeshSizeOverride& o : kMeshSizeOverrides) {
    if (varied.keys[k] != o.wing_key) continue;
    for (const ResolvedCase& r : cases)
      if (r.c.structure.kind != io::Case::Structure::Kind::Fem || !(r.c.structure.*o.size > 0.0))
        return std::nullopt;
    return o;
  }
  return std::nullopt;
}

void refuse_mesh_size_the_case_sets(const VariedKeys& varied, const SweepInputs& inputs,
                                    const std::vector<ResolvedCase>& cases, std::size_t k) {
  const std::optional<MeshSizeOverride> o = mesh_size_override(varied, cases, k);
  if (!o || cases.empty()) return;
  const std::string case_key(o->case_key);
  const int line = cases.front().c.line_of(case_key);
  const std::string where = line > 0 ? " (" + inputs.case_file + " line " + std::to_string(line) + ")" : "";
  refuse(varied, k, "the case's " + case_key + where + " sets the FEM's mesh",
         "vary " + case_key + " instead");
}

// Whether the points that differ only in key k's value all have the same inputs hash (and
// there is at least one such pair): the key reaches no input of the run.
bool inputs_never_change_with(const std::vector<CasePoint>& points, const std::vector<ResolvedCase>& cases,
                              std::size_t k, std::string& common_hash) {
  // The other keys' values -> the key's value -> the inputs hash.
  using Value = std::pair<double, std::string>;  // value_key
  std::map<std::vector<Value>, std::map<Value, const std::string*>> groups;
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::vector<Value> others;
    for (std::size_t j = 0; j < points[i].size(); ++j)
      if (j != k) others.push_back(value_key(points[i][j]));
    groups[others].emplace(value_key(points[i][k]), &cases[i].inputs_hash);
  }
  bool compared = false;
  for (const auto& [others, hash_of_value] : groups) {
    if (hash_of_value.size() < 2) continue;
    compared = true;
    const std::string& first = *hash_of_value.begin()->second;
    for (const auto& [value, hash] : hash_of_value)
      if (*hash != first) return false;
    common_hash = first;
  }
  return compared;
}

void refuse_key_that_reaches_no_input(const VariedKeys& varied, const std::vector<CasePoint>& points,
                                      const std::vector<ResolvedCase>& cases, std::size_t k) {
  std::string hash;
  if (!inputs_never_change_with(points, cases, k, hash)) return;
  refuse(varied, k,
         "every value gives the same inputs (the resolved case and wing, inputs_hash " + hash +
             "): the values name the same thing (a file by two paths), or the run does not use the key with "
             "the case's other settings",
         "drop it from the " + varied.command);
}

// A sweep's value given twice (12 and 12.0), or two values that give the same inputs where the
// key's other values do not (a wing file by two paths): the same case would run twice, in two
// folders, without a word (a user's sweep, 6 Dec). Refused naming both.
void refuse_duplicate_values(const VariedKeys& varied, const std::vector<CasePoint>& points,
                             const std::vector<ResolvedCase>& cases, std::size_t k) {
  using Value = std::pair<double, std::string>;  // value_key
  // The other keys' values -> the points with them.
  std::map<std::vector<Value>, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::vector<Value> others;
    for (std::size_t j = 0; j < points[i].size(); ++j)
      if (j != k) others.push_back(value_key(points[i][j]));
    groups[others].push_back(i);
  }
  const auto duplicate = [&](const std::string& why, const std::string& instead) {
    throw InputError(varied.file, varied.line, varied.keys[k], varied.given[k] + ": " + why + "; " + instead);
  };
  for (const auto& [others, members] : groups) {
    // The first point of each value, and of each inputs hash, in the group.
    std::map<Value, std::size_t> first_of_value;
    std::map<std::string, std::size_t> first_of_hash;
    for (std::size_t i : members)
      if (!first_of_value.emplace(value_key(points[i][k]), i).second)
        duplicate(value_label(points[i][k]) + " is given twice: its case would run twice",
                  "give each value once");
    for (std::size_t i : members) first_of_hash.emplace(cases[i].inputs_hash, i);
    // All the group's values alike: a key the run does not use (refuse_key_that_reaches_no_input).
    if (first_of_hash.size() < 2) continue;
    for (std::size_t i : members) {
      const std::size_t first = first_of_hash.at(cases[i].inputs_hash);
      if (first == i) continue;
      const std::string a = value_label(points[first][k]), b = value_label(points[i][k]);
      duplicate((a == b ? "two values (" + a + ", by two paths)" : a + " and " + b) +
                    " give the same inputs (inputs_hash " + cases[i].inputs_hash +
                    "): their case would run twice",
                "give one of them");
    }
  }
}

// The joint springs' factor of a case with no joint springs (a rigid wing, the wing's own
// FEM): io::input_hash leaves it out for such a case, so the same-inputs rule below would
// refuse it too; this says why (an optimisation of it on a rigid case once ran 7 equal runs
// and wrote the optimum of a flat objective without a word; a sweep, identical rows).
void refuse_spring_scale_without_springs(const VariedKeys& varied, const SweepInputs& inputs,
                                         const std::vector<ResolvedCase>& cases, std::size_t k) {
  if (varied.keys[k] != "spring_scale" || cases.empty()) return;
  for (const ResolvedCase& r : cases)
    if (r.c.structure.kind == io::Case::Structure::Kind::Flexible) return;
  const io::Case& c = cases.front().c;
  const int line = c.line_of("structure.kind");
  const std::string where = line > 0 ? " (" + inputs.case_file + " line " + std::to_string(line) + ")" : "";
  refuse(varied, k,
         "the case's structure.kind = \"" +
             std::string(wings::choice_name(io::kStructureKindNames, c.structure.kind)) + "\"" + where +
             " has no joint springs to scale",
         "drop it from the " + varied.command + ", or fly a flexible case (structure.kind = \"flexible\")");
}

}  // namespace

void refuse_interval_the_command_sets(const VariedKeys& varied, int vtk_every) {
  for (std::size_t k = 0; k < varied.keys.size(); ++k) {
    if (varied.keys[k] != "output.vtk_every") continue;
    const std::string option = vtk_every > 0 ? "--vtk-every " + std::to_string(vtk_every)
                                             : std::string("--vtk-every (0 when not given: no series)");
    refuse(varied, k,
           "the " + varied.command + "'s " + option +
               " sets every case's ParaView series in place of the case's",
           "give the " + varied.command + " --vtk-every N instead (one interval for every case)");
  }
}

void refuse_keys_that_change_nothing(const VariedKeys& varied, const SweepInputs& inputs,
                                     const std::vector<CasePoint>& points,
                                     const std::vector<ResolvedCase>& cases, int vtk_every) {
  refuse_interval_the_command_sets(varied, vtk_every);
  for (std::size_t k = 0; k < varied.keys.size(); ++k) {
    refuse_mesh_size_the_case_sets(varied, inputs, cases, k);
    refuse_spring_scale_without_springs(varied, inputs, cases, k);
    refuse_key_that_reaches_no_input(varied, points, cases, k);
  }
}

void refuse_keys_that_change_nothing(const SweepInputs& inputs, const SweepPlan& plan,
                                     const std::vector<ResolvedCase>& cases, int vtk_every) {
  const bool from_table = !plan.table_file.empty();
  VariedKeys varied{"sweep",
                    plan.keys,
                    {},
                    from_table ? plan.table_file : inputs.case_file,
                    from_table ? plan.header_line : 0};
  for (std::size_t k = 0; k < plan.keys.size(); ++k)
    varied.given.push_back(from_table ? "the column's values " + values_of(plan.points, k)
                                      : "--vary " + plan.keys[k] + " = " + values_of(plan.points, k));
  // A case table's rows are its cases: a row given twice is a duplicate of all its keys at once,
  // which the per-key groups below see as well.
  for (std::size_t k = 0; k < plan.keys.size(); ++k) refuse_duplicate_values(varied, plan.points, cases, k);
  refuse_keys_that_change_nothing(varied, inputs, plan.points, cases, vtk_every);
}

}  // namespace flapsim::sweep
