#!/usr/bin/python3
"""ctest tools.MakeRun.AFemCaseEndsWithItsPreview: `make run CASE=x.toml` for a case flown
on the wing's own FEM (structure kind "fem", which writes fem.pvd, not chain.pvd) leaves
preview.png beside run.pvsm and says where they are. Before: make looked for chain.pvd
alone, said "preview and ParaView state: none (the case writes no frames ...)" and made no
preview, though the run had written its frames and its state."""
import os
import sys

import tool_test_args

a, work = tool_test_args.arguments("source", "build", "work")
out = os.path.join(work, "out")
case = os.path.join(work, "fem_preview.toml")
with open(case, "w") as f:  # the FEM plate of test_render_fem_run.py, flapped in vacuum
    f.write(f'name = "fem_preview"\nwing = "{a.source}/wings/flat_plate.toml"\nair = "none"\n'
            "[kinematics]\nfrequency_hz = 26.1\nsweep = { cos_deg = [20.0] }\nrotation = 90.0\n"
            '[structure]\nkind = "fem"\nelement_size_mm = 2.5\n'
            "[numerics]\nsteps_per_cycle = 48\ncycles = 1\n[output]\nvtk_every = 6\n")
r = tool_test_args.make_run(a.source, a.build, out, case)
check = tool_test_args.Checks()
run = os.path.join(out, "fem_preview")
check(r.returncode == 0, f"make run exited {r.returncode}")
check(os.path.isfile(os.path.join(run, "fem.pvd")) and os.path.isfile(os.path.join(run, "run.pvsm")),
      "the run wrote fem.pvd and run.pvsm")
check(os.path.isfile(os.path.join(run, "preview.png")) and os.path.getsize(os.path.join(run, "preview.png")) > 1000,
      "preview.png written")
check(f"preview: {run}/preview.png" in r.stdout, "make run says where the preview is")
check("preview and ParaView state: none" not in r.stdout, "make run says there is no preview")
sys.exit(1 if check.failures else 0)
