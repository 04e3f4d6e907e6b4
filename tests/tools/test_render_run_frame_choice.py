#!/usr/bin/python3
"""tools/render_run.py (make run's preview) and tools/paraview_state.py (make snapshot)
pick the frame of each phase with frame_at. A run that stopped before one wingbeat
(interrupted, or a divergence's exit 3) at t/T = 0.2 showed its first frame (t = 0: no
wake, no lift) at phases 0.25, 0.5 and 0.75, though frames up to 0.2 existed; its last
frame is the nearest it has. The choice within a complete run is unchanged."""
import importlib.util
import os
import sys

source = sys.argv[sys.argv.index("--source") + 1]
spec = importlib.util.spec_from_file_location("render_run", os.path.join(source, "tools", "render_run.py"))
render_run = importlib.util.module_from_spec(spec)
spec.loader.exec_module(render_run)

f = 25.0  # Hz
dt = 1.0 / (f * 40)  # s, 40 steps a wingbeat, a frame every 4 steps: phases 0, 0.1, ...


def series(last_step):
    return [(k * dt, f"frame_{k}.vtp") for k in range(0, last_step + 1, 4)]


# Stopped at step 8 (t/T = 0.2): phases 0.25, 0.5, 0.75 show the frame at 0.2, phase 0 the start.
short = series(8)
for phase in (0.25, 0.5, 0.75):
    t, name = render_run.frame_at(short, f, phase)
    assert name == "frame_8.vtp", (phase, name)
assert render_run.frame_at(short, f, 0.0)[1] == "frame_0.vtp"
# Stopped at step 24 (t/T = 0.6): 0.25 and 0.5 are theirs, 0.75 the last frame.
partial = series(24)
assert render_run.frame_at(partial, f, 0.25)[1] in ("frame_8.vtp", "frame_12.vtp")
assert render_run.frame_at(partial, f, 0.5)[1] == "frame_20.vtp"
assert render_run.frame_at(partial, f, 0.75)[1] == "frame_24.vtp"
# Three complete wingbeats (step 120): the last wingbeat's frames, as before.
full = series(120)
assert render_run.frame_at(full, f, 0.5)[1] == "frame_100.vtp"
assert render_run.frame_at(full, f, 0.0)[1] == "frame_120.vtp"
assert render_run.frame_at(full, f, 0.75)[1] in ("frame_108.vtp", "frame_112.vtp")
print("ok")
