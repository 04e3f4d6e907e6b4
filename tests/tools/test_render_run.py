#!/usr/bin/python3
"""ctest tools.RenderRun.SnapshotShowsTheWing: a tiny flapsim run (flat plate, rigid,
3 x 4 panels, 12 steps) rendered offscreen under Xvfb by tools/render_run.py with VTK's
Python; the PNG read back with VTK's PNG reader must show the wing: with the wing drawn
in one colour (orange, the chain black, the background white), at least 2 % of the
pixels are that orange and their centre lies in the middle of the picture, where the
script's camera frames the wing; the default picture (pressure colours) is not blank.
One camera serves every picture of a run: at the two stroke reversals (phases 0 and 0.5)
the wing lies on opposite sides of the picture (a camera per frame centred both).
A folder without the series is bad input (exit status 2)."""
import os
import subprocess
import sys


import tool_test_args

a, work = tool_test_args.arguments("flapsim", "source", "work")
case = tool_test_args.write_flapping_plate_case(a.source, os.path.join(work, "case.toml"), "plate", 12, 1, 3)
run = os.path.join(work, "run")
tool_test_args.run_case(a.flapsim, case, run)

script = os.path.join(a.source, "tools", "render_run.py")
xvfb = tool_test_args.XVFB_RUN
check = tool_test_args.Checks()
failures = check.failures


def render(extra, png, phase="0.25"):
    subprocess.run(xvfb + ["/usr/bin/python3", script, run, "--phases", phase, "-o", png,
                           "--size", "600", "400"] + extra, check=True)
    return tool_test_args.read_png_rgb(png)


# 1. The wing in one colour: orange (1, 0.5, 0) shaded keeps g ≈ r/2 and b ≈ 0.
rgb = render(["--wing-color", "1", "0.5", "0", "--no-wake"], os.path.join(work, "orange.png"))
h, w, _ = rgb.shape
r, g, b = rgb[:, :, 0], rgb[:, :, 1], rgb[:, :, 2]
orange = (r > 0.2) & (g > 0.3 * r) & (g < 0.7 * r) & (b < 0.15 * r + 0.02)
share = orange.mean()
print(f"orange pixels: {100 * share:.1f} % of {w} x {h}")
check(share > 0.02, f"the wing covers {100 * share:.2f} % of the picture, expected > 2 %")
if orange.any():
    ys, xs = orange.nonzero()
    cx, cy = xs.mean() / w, ys.mean() / h
    print(f"centre of the wing pixels: ({cx:.2f}, {cy:.2f}) of the picture")
    check(0.2 < cx < 0.8 and 0.2 < cy < 0.8, f"the wing's centre ({cx:.2f}, {cy:.2f}) is not in the middle")
white = (rgb > 0.98).all(axis=2).mean()
check(white > 0.3, f"only {100 * white:.1f} % background: the camera does not frame the wing")

# 1b. Mid-upstroke (phase 0.75): the hover's wing has turned through 90° about its span since
# mid-downstroke, and a camera facing only mid-downstroke's face saw it edge-on (0.0 % of the
# picture, until 3 Dec); the camera faces both: the wing covers a share of the picture as at
# mid-downstroke.
rgb = render(["--wing-color", "1", "0.5", "0", "--no-wake"], os.path.join(work, "orange_up.png"), "0.75")
r, g, b = rgb[:, :, 0], rgb[:, :, 1], rgb[:, :, 2]
up = ((r > 0.2) & (g > 0.3 * r) & (g < 0.7 * r) & (b < 0.15 * r + 0.02)).mean()
print(f"orange pixels at mid-upstroke: {100 * up:.1f} % (mid-downstroke {100 * share:.1f} %)")
check(up > 0.02 and up > 0.4 * share, f"the wing at mid-upstroke covers {100 * up:.2f} % of the picture")

# 2. The default picture (pressure jump colours, wake) is not blank.
rgb = render([], os.path.join(work, "default.png"))
non_white = 1.0 - (rgb > 0.98).all(axis=2).mean()
print(f"default picture: {100 * non_white:.1f} % not background")
check(non_white > 0.02, "the default picture is blank")

# 3. One camera for the run: the wing's centre at the two stroke reversals, orange as in 1.
centres = []
for phase in ("0.0", "0.5"):
    rgb = render(["--wing-color", "1", "0.5", "0", "--no-wake"], os.path.join(work, f"reversal_{phase}.png"), phase)
    r, g, b = rgb[:, :, 0], rgb[:, :, 1], rgb[:, :, 2]
    mask = (r > 0.2) & (g > 0.3 * r) & (g < 0.7 * r) & (b < 0.15 * r + 0.02)
    ys, xs = mask.nonzero()
    centres.append((xs.mean() / mask.shape[1], ys.mean() / mask.shape[0]) if mask.any() else (float("nan"),) * 2)
    edge = mask[0, :].any() or mask[-1, :].any() or mask[:, 0].any() or mask[:, -1].any()
    check(not edge, f"the wing at phase {phase} touches the picture's edge: the camera does not frame the stroke")
print(f"wing centres at the reversals: {centres}")
apart = ((centres[0][0] - centres[1][0]) ** 2 + (centres[0][1] - centres[1][1]) ** 2) ** 0.5
check(apart > 0.1, f"the wing's centres at the two reversals are {apart:.3f} of the picture apart: one camera per frame")

# 4. Bad input: a folder without series.
empty = os.path.join(work, "empty")
os.makedirs(empty)
status = subprocess.run(xvfb + ["/usr/bin/python3", script, empty], capture_output=True).returncode
check(status == 2, f"a folder without chain.pvd gave exit status {status}, expected 2")

sys.exit(1 if failures else 0)
