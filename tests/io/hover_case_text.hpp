#pragma once
// A small rigid hover case as text for the case-warning tests: the tiny wing of
// tests/io/data, eq. 8-like kinematics at 20 Hz, no free stream unless `air` gives one;
// `numerics` lines start at line 10 of the text.

#include <string>

inline std::string hover_case_text(const std::string& numerics, const std::string& air = "") {
  return "wing = \"valid_tiny_wing.toml\"\n"                                    // 1
         "[kinematics]\nfrequency_hz = 20.0\n"                                   // 2-3
         "sweep = { cos_deg = [50.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"  // 4-5
         "[structure]\nkind = \"rigid\"\n" + air +                               // 6-7
         "[numerics]\nsteps_per_cycle = 40\n" + numerics;                        // 8-9, 10
}

/// The same case revolving instead of flapping (sweep 0, rotation 50°, −1800°/s from rest):
/// a revolving wing's cycles are time units, which the hover warnings leave alone.
inline std::string revolving_instead(std::string text) {
  const std::string flapping =
      "sweep = { cos_deg = [50.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n";
  text.replace(text.find(flapping), flapping.size(),
               "sweep = 0.0\nrotation = 50.0\nrevolution = { rate_deg_per_s = -1800.0 }\n");
  return text;
}
