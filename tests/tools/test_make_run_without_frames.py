#!/usr/bin/python3
"""ctest tools.MakeRun.ACaseWithoutFramesEndsWithoutAPreview: `make run CASE=x.toml` for a case
whose [output] vtk_every = 0 (a user's case, written for sweeps) runs it and says that there is
no preview. Before: the run completed, then tools/render_run.py found no chain.pvd and make
stopped with Error 2 ("render_run: error: ...: no chain.pvd"), a successful run reported as a
failure. Each of the case's warnings is printed once (make run's check of the case printed
them too).
"""
import os
import sys

import tool_test_args

a, work = tool_test_args.arguments("source", "build", "work")
out = os.path.join(work, "out")
case = os.path.join(work, "noframes.toml")
with open(case, "w") as f:
    f.write(f'name = "noframes"\nwing = "{a.source}/wings/flat_plate.toml"\n[kinematics]\nfrequency_hz = 26.1\n'
            'sweep = { cos_deg = [50.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n'
            '[structure]\nkind = "rigid"\n[numerics]\nsteps_per_cycle = 12\ncycles = 1\nchordwise_panels = 2\n'
            'spanwise_panels = 3\n[output]\nvtk_every = 0\n')
r = tool_test_args.make_run(a.source, a.build, out, case)
failures = []
if r.returncode != 0:
    failures.append(f"make run exited {r.returncode}")
if not os.path.isfile(os.path.join(out, "noframes", "summary.json")):
    failures.append("no summary.json in out/noframes")
if "preview and ParaView state: none" not in r.stdout:
    failures.append("make run does not say that there is no preview")
# Its 12 steps a cycle in air are warned about, once: make run's check of the case showed its
# warnings too, so each was printed twice.
warnings = [line for line in r.stderr.splitlines() if "warning:" in line]
if not warnings:
    failures.append("no warning about the case's 12 steps a cycle")
if len(set(warnings)) != len(warnings):
    failures.append(f"a warning printed twice: {warnings}")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
