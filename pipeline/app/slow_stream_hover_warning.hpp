#pragma once
/// \file slow_stream_hover_warning.hpp
/// \brief A warning for a flapping wing in a free stream too slow to carry its wake away.
///
/// In still air a flapping wing gets the convected far wake by default (`far_wake_cycles`
/// 0.5): with the whole wake free the wing sweeps back through the wake it shed and the lift
/// of its later cycles grows erratic (docs/uvlm.md, "Hover over many cycles"). With any free
/// stream the default is the whole wake free, but a slow stream changes little: the wake
/// the wing meets half a stroke later has moved U∞ T/2, and where that is less than the mean
/// chord c̄ the wing meets it as in hover. Measured (4 Dec 2026; `cases/lua_rigid.toml`'s
/// rigid hawkmoth, `separated`, 50 steps a cycle, 10 cycles, the stream along the stroke
/// plane): the cycles' mean lift (2–10) scatters by 20, 50 and 56 % (rms) with the stream
/// carrying the wake 0.60, 0.30 and 0.12 c̄ a half stroke, 3.4 % at 0.75 c̄, 1.3–1.6 % at
/// 0.90–1.05 c̄, 0.8–0.9 % at 1.2–1.8 c̄ (7.1 % in still air); with `far_wake_cycles = 0.5`
/// 0.1–0.6 % at each. A narrow plate (5 × 40 mm) scatters less either way (1.2–2.0 % whole,
/// 0.1–0.3 % with the far wake).

#include <string>

#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/io/case_model.hpp"

namespace flapsim::app {

/// A free stream that carries the wake less than this many mean chords in a half stroke is
/// warned (the wing meets its wake within about a chord of its path).
inline constexpr double kSlowStreamWakeChords = 1.0;

/// U∞ T/2 / c̄: how far the free stream carries the wake in a half stroke, in mean chords.
double wake_travel_per_half_stroke_chords(const io::Case& c, const FsiSetup& setup);

/// \brief "" or the warning for a flapping wing (a sweep that swings, a fixed pivot, no
/// revolution) in a free stream that carries its wake less than kSlowStreamWakeChords a half
/// stroke, with the whole wake free (no far, frozen or capped wake) over more than one cycle.
std::string slow_stream_hover_warning(const io::Case& c, const FsiSetup& setup);

}  // namespace flapsim::app
