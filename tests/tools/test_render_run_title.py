#!/usr/bin/python3
"""tools/render_run.py titles each picture with the phase of the frame it shows: when no
frame lies at the phase asked for (vtk_every 4 of 40 steps per cycle: frames at phases
0.0, 0.1, ...; 0.25 asked), the title names the frame's phase (0.30) and the one asked
for; it said "phase 0.25" under a picture at 0.30."""
import importlib.util
import os
import sys

source = sys.argv[sys.argv.index("--source") + 1]
spec = importlib.util.spec_from_file_location("render_run", os.path.join(source, "tools", "render_run.py"))
render_run = importlib.util.module_from_spec(spec)
spec.loader.exec_module(render_run)

f = 20.0  # Hz
# t/T = 9.3 (step 372 of 40 per cycle at 20 Hz: t = 0.465 s), 0.25 asked.
title = render_run.frame_title(0.465, f, 0.25, 2.064e-3)
assert title.startswith("t/T = 9.300 (phase 0.30, the frame nearest to 0.25)"), title
# A frame at the phase asked for: no note (t/T = 9.25).
title = render_run.frame_title(0.4625, f, 0.25, 2.064e-3)
assert title.startswith("t/T = 9.250 (phase 0.25)   t = 462.50 ms"), title
# Phase 0 asked, frame at t/T = 10.000 (phase 0.00, round-off either side of the integer).
title = render_run.frame_title(0.49999999999999994, f, 0.0, 0.0)
assert "(phase 0.00)" in title and "nearest" not in title, title
print("ok")
