#include "pipeline/app/sweep/sweep_case.hpp"

#include <cmath>
#include <cstdio>

#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/io/case_file.hpp"
#include "pipeline/io/input_hash.hpp"
#include "wings/input_error.hpp"

namespace flapsim::sweep {

namespace {
constexpr std::string_view kWingPrefix = "wing.";
}

KeyTarget key_target(const std::string& key) {
  if (key == "spring_scale") return KeyTarget::spring_scale;
  if (key.rfind(kWingPrefix, 0) == 0) return KeyTarget::wing_file;
  return KeyTarget::case_file;
}

ResolvedCase resolve_case(const SweepInputs& inputs, const CasePoint& point) {
  ResolvedCase r;
  r.spring_scale = inputs.spring_scale;
  std::vector<std::pair<std::string, std::string>> case_overrides;
  for (const Assignment& a : point) {
    switch (key_target(a.key)) {
      case KeyTarget::case_file: case_overrides.emplace_back(a.key, value_text(a.value)); break;
      case KeyTarget::wing_file:
        r.wing_overrides.emplace_back(a.key.substr(kWingPrefix.size()), value_text(a.value));
        break;
      case KeyTarget::spring_scale:
        if (!(a.value > 0.0))
          throw InputError(inputs.case_file, 0, a.key, "with " + describe(point) + ": must be > 0");
        r.spring_scale = a.value;
        break;
    }
  }
  try {
    r.c = io::load_case_file(inputs.case_file, case_overrides);
    const auto wing = app::load_case_wing(r.c, r.wing_overrides);
    r.inputs_hash = io::input_hash(r.c, wing ? &*wing : nullptr, inputs.chain_file, r.spring_scale);
  } catch (const InputError& e) {
    if (point.empty()) throw;
    throw InputError(e.file(), e.line(), e.key(), "with " + describe(point) + ": " + e.message());
  }
  return r;
}

std::string case_folder(std::size_t index, std::size_t count, const CasePoint& point) {
  int digits = 2;
  for (std::size_t n = count > 0 ? count - 1 : 0; n >= 100; n /= 10) ++digits;
  char head[32];
  std::snprintf(head, sizeof head, "%0*zu", digits, index);
  std::string name = head;
  for (const Assignment& a : point) name += "_" + value_label(a.value);
  return name;
}

std::string describe(const CasePoint& point) {
  std::string s;
  for (const Assignment& a : point) s += (s.empty() ? "" : ", ") + a.key + " = " + value_label(a.value);
  return s;
}

}  // namespace flapsim::sweep
