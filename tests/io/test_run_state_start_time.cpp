// The time run.pvsm opens at (pipeline/io/pvsm_state.hpp, state_start_time): ParaView
// opened every state at t = 0, the pose before the first solve (a wing without loads, no
// wake); the state now opens on the frame make run's preview shows, the last wingbeat's
// mid-downstroke (phase 0.25), or a short run's last frame.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pipeline/io/pvsm_state.hpp"

namespace io = flapsim::io;

namespace {

// Frames every 4 of 40 steps a wingbeat of period T up to step `last` [s].
std::vector<double> frames(double period, int last) {
  std::vector<double> t;
  for (int k = 0; k <= last; k += 4) t.push_back(k * period / 40.0);
  return t;
}

// The value of property `name` of proxy `id` in the state ("" if none).
std::string property(const std::string& xml, int id, const std::string& name) {
  const auto at = xml.find("id=\"" + std::to_string(id) + "." + name + "\"");
  if (at == std::string::npos) return "";
  const auto value = xml.find("value=\"", at);
  return xml.substr(value + 7, xml.find('"', value + 7) - value - 7);
}

TEST(RunStateStartTime, TheLastWingbeatsMidDownstrokeOrAShortRunsLastFrame) {
  const double T = 1.0 / 26.1;  // s
  // Three wingbeats: t/T = 2.2 and 2.3 are the frames either side of 2.25; 2.2 is written
  // first and as near (round-off decides; either is the preview's frame).
  const auto three = frames(T, 120);
  const double opened = io::state_start_time(three, T).value();
  EXPECT_TRUE(opened == three[22] || opened == three[23]) << opened / T;
  // Stopped at step 24 (t/T 0.6): 0.25 reached, the frames at 0.2 and 0.3.
  const auto partial = frames(T, 24);
  const double p = io::state_start_time(partial, T).value();
  EXPECT_TRUE(p == partial[2] || p == partial[3]) << p / T;
  // Stopped at step 8 (t/T 0.2): before phase 0.25, its last frame, not t = 0.
  const auto short_run = frames(T, 8);
  EXPECT_EQ(io::state_start_time(short_run, T).value(), short_run.back());
  EXPECT_FALSE(io::state_start_time({}, T).has_value());
}

TEST(RunStateStartTime, TheStateSetsTheTimeKeeperAndTheAnimationThere) {
  io::RunState state;
  const std::string without = io::run_state_xml(state);
  EXPECT_EQ(property(without, 256, "Time"), "");  // ids of pvsm_state.cpp: time keeper 256, scene 261
  state.start_time = 0.08620689655172414;
  const std::string with = io::run_state_xml(state);
  EXPECT_EQ(property(with, 256, "Time"), "0.08620689655172414");
  EXPECT_EQ(property(with, 261, "AnimationTime"), "0.08620689655172414");
}

}  // namespace
