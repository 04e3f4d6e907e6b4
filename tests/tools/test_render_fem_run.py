#!/usr/bin/python3
"""ctest tools.RenderRun.AFemRunShowsItsDeformedSurface: a tiny run of the wing's own FEM
(structure kind "fem": the 0.2 mm PET plate of wings/flat_plate.toml flapped in vacuum,
sweep 20°, 48 steps) writes fem.pvd instead of chain.pvd; tools/render_run.py draws the
FEM's deformed surface coloured by its displacement (white at rest to dark blue at the
frame's largest, hue 0.6). The PNG read back must show that blue: at least 1 % of the
pixels are saturated blue (b > r + 0.15, b > g), their centre in the middle of the picture,
and the plate's root (no displacement, white-grey) and tip (dark blue) both drawn: the
blue pixels span a range of saturations."""
import os
import subprocess
import sys


import tool_test_args

a, work = tool_test_args.arguments("flapsim", "source", "work")
case = os.path.join(work, "case.toml")
with open(case, "w") as f:
    f.write(f'name = "fem_plate"\nwing = "{a.source}/wings/flat_plate.toml"\nair = "none"\n'
            "[kinematics]\nfrequency_hz = 26.1\nsweep = { cos_deg = [20.0] }\nrotation = 90.0\n"
            '[structure]\nkind = "fem"\nelement_size_mm = 2.5\n'
            "[numerics]\nsteps_per_cycle = 48\ncycles = 1\n[output]\nvtk_every = 6\n")
env = dict(os.environ, FLAPSIM_QUIET="1", OMP_NUM_THREADS="1")
run = os.path.join(work, "run")
subprocess.run([a.flapsim, "run", case, "-o", run, "-q"], check=True, env=env)
check = tool_test_args.Checks()
failures = check.failures


check(os.path.isfile(os.path.join(run, "fem.pvd")), "no fem.pvd")
check(not os.path.exists(os.path.join(run, "chain.pvd")), "a FEM run wrote chain.pvd")
script = os.path.join(a.source, "tools", "render_run.py")
png = os.path.join(work, "fem.png")
subprocess.run(tool_test_args.XVFB_RUN + ["/usr/bin/python3", script, run,
                "--phases", "0.25", "-o", png, "--size", "600", "400"], check=True)
rgb = tool_test_args.read_png_rgb(png)
h, w, _ = rgb.shape
r, g, b = rgb[:, :, 0], rgb[:, :, 1], rgb[:, :, 2]
blue = (b > r + 0.15) & (b > g)
share = blue.mean()
print(f"blue pixels: {100 * share:.1f} % of {w} x {h}")
check(share > 0.01, f"the FEM surface covers {100 * share:.2f} % of the picture, expected > 1 %")
if blue.any():
    ys, xs = blue.nonzero()
    cx, cy = xs.mean() / w, ys.mean() / h
    check(0.2 < cx < 0.8 and 0.2 < cy < 0.8, f"the surface's centre ({cx:.2f}, {cy:.2f}) is not in the middle")
    saturation = (b - r)[blue]
    print(f"saturation of the blue pixels: {saturation.min():.2f} ... {saturation.max():.2f}")
    check(saturation.max() - saturation.min() > 0.3, "one colour over the plate: the displacement is not shown")
sys.exit(1 if failures else 0)
