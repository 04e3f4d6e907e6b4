#include "pipeline/app/slow_stream_hover_warning.hpp"

#include <cstdio>

#include "pipeline/io/case_file.hpp"

namespace flapsim::app {

namespace {

double half_stroke_travel(const io::Case& c, const FsiSetup& setup) {  // U∞ T/2 [m]
  return setup.reference.free_stream_speed * 0.5 / c.kinematics.frequency;
}

}  // namespace

double wake_travel_per_half_stroke_chords(const io::Case& c, const FsiSetup& setup) {
  return half_stroke_travel(c, setup) / setup.reference.mean_chord;
}

std::string slow_stream_hover_warning(const io::Case& c, const FsiSetup& setup) {
  if (!setup.model.air || !(setup.reference.free_stream_speed > 0.0) || !(setup.reference.mean_chord > 0.0) ||
      c.numerics.cycles <= io::kLongFreeHoverCycles || !io::flaps_with_whole_free_wake(c))
    return "";
  const double chords = wake_travel_per_half_stroke_chords(c, setup);
  if (!(chords < kSlowStreamWakeChords)) return "";
  char text[1200];
  std::snprintf(
      text, sizeof text,
      "the free stream carries the wake %.2f mean chords in a half stroke (%s:%d, key "
      "'numerics.far_wake_cycles'): %.3g m/s for %.3g ms, %.3g mm against a mean chord of %.3g mm, "
      "less than %g chord: the wing sweeps back through the wake it shed, as in hover, and with the whole "
      "wake free (far_wake_cycles = 0, a free stream's default) its later cycles' lift grows "
      "erratic (the rigid hawkmoth of cases/lua_rigid.toml, 10 cycles: the cycles' mean lift scattering by "
      "20 %% at 0.60 chords, 3.4 %% at 0.75, 1.3 %% at 0.90; with far_wake_cycles = 0.5 by 0.1-0.6 %%); set "
      "far_wake_cycles = 0.5, as a hover gets by default (docs/uvlm.md, \"Hover over many cycles\")",
      chords, c.file.c_str(), c.line_of("numerics.far_wake_cycles"), setup.reference.free_stream_speed,
      0.5e3 / c.kinematics.frequency, half_stroke_travel(c, setup) * 1e3, setup.reference.mean_chord * 1e3,
      kSlowStreamWakeChords);
  return text;
}

}  // namespace flapsim::app
