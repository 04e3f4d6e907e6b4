#!/usr/bin/python3
"""ctest tools.RenderRun.AFemRunInAirShowsItsWake: tools/render_run.py (make run's preview)
draws an FEM run's own deformed surface in place of the lattice, and the wake was drawn
only with the lattice: the pictures of an FEM run in air had no wake (docs/fsi.md shows
one), and --no-wake changed nothing. A tiny run of wings/flat_plate.toml's own FEM in air
(half a wingbeat, 4 x 6 panels, a frame every 4 steps) rendered at phase 0.5 with and without
--no-wake: the wake adds pixels, so the two pictures differ in at least 0.5 % of them."""
import os
import subprocess
import sys

import tool_test_args

a, work = tool_test_args.arguments("flapsim", "source", "work")
case = os.path.join(work, "case.toml")
with open(case, "w") as f:
    f.write(f'name = "fem_plate_air"\nwing = "{a.source}/wings/flat_plate.toml"\n'
            "[kinematics]\nfrequency_hz = 26.1\nsweep = { cos_deg = [40.0] }\n"
            "rotation = { mean_deg = 90.0, sin_deg = [-40.0] }\n"
            '[structure]\nkind = "fem"\nelement_size_mm = 5.0\n'
            "[numerics]\nsteps_per_cycle = 24\ncycles = 1\nchordwise_panels = 4\nspanwise_panels = 6\n"
            "[output]\nvtk_every = 4\n")
env = dict(os.environ, FLAPSIM_QUIET="1", OMP_NUM_THREADS="1")
run = os.path.join(work, "run")
subprocess.run([a.flapsim, "run", case, "-o", run, "-q"], check=True, env=env)
check = tool_test_args.Checks()
failures = check.failures

check(os.path.isfile(os.path.join(run, "fem.pvd")), "no fem.pvd")
check(os.path.isfile(os.path.join(run, "wake.pvd")), "no wake.pvd")
script = os.path.join(a.source, "tools", "render_run.py")
pictures = {}
for label, extra in (("wake", []), ("no_wake", ["--no-wake"])):
    png = os.path.join(work, f"{label}.png")
    subprocess.run(tool_test_args.XVFB_RUN + ["/usr/bin/python3", script, run, "--phases", "0.5",
                    "-o", png, "--size", "600", "400"] + extra, check=True)
    pictures[label] = tool_test_args.read_png_rgb(png)
difference = (abs(pictures["wake"] - pictures["no_wake"]).sum(axis=2) > 0.05).mean()
print(f"pixels the wake changes: {100 * difference:.2f} %")
check(difference > 0.005, f"the wake changes {100 * difference:.3f} % of the picture, expected > 0.5 %")
sys.exit(1 if failures else 0)
