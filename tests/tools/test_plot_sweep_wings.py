#!/usr/bin/python3
"""ctest tools.PlotSweep.ASweepOverWingsIsPlottedAgainstTheWingsNames: a sweep.csv whose
first column is `wing` (flapsim sweep --vary wing=wings/a.toml,...) is a varied key (before:
"not a flapsim sweep.csv (no varied key ...)"), drawn with the wings at evenly spaced places
named by their file names (wings/hawkmoth.toml: hawkmoth). The table here is a sweep.csv's
layout with made-up results."""
import os
import subprocess
import sys

import tool_test_args

a, work = tool_test_args.arguments("source", "work")
tools = os.path.join(a.source, "tools")
sys.path.insert(0, tools)
import plot_sweep  # noqa: E402

failures = []
header = ["wing", "kinematics.rotation_phase", "mean_lift_N", "mean_CL", "mean_power_W", "folder", "status"]
if plot_sweep.varied_keys(header) != ["wing", "kinematics.rotation_phase"]:
    failures.append(f"varied keys {plot_sweep.varied_keys(header)}")
if plot_sweep.tick("wing", "wings/hawkmoth_rp.toml") != "hawkmoth_rp":
    failures.append(f"tick {plot_sweep.tick('wing', 'wings/hawkmoth_rp.toml')}")
if plot_sweep.tick("numerics.leading_edge", "shed") != "shed":
    failures.append("a word of another key is not its own tick")

table = os.path.join(work, "sweep.csv")
with open(table, "w") as f:
    f.write(",".join(header) + "\n")
    for i, (wing, phase, lift) in enumerate([("wings/hawkmoth.toml", 0, 8.3e-3), ("wings/hawkmoth.toml", 0.05, 7.2e-3),
                                             ("tests/data/drawn_wing.toml", 0, 3.0e-3),
                                             ("tests/data/drawn_wing.toml", 0.05, 2.8e-3)]):
        f.write(f"{wing},{phase},{lift},2.0,0.03,{i:02d}_x,ok\n")
r = subprocess.run(["/usr/bin/python3", os.path.join(tools, "plot_sweep.py"), table, os.path.join(work, "plots")],
                   capture_output=True, text=True)
if r.returncode != 0:
    failures.append(f"plot_sweep.py exit {r.returncode}: {r.stderr}")
for name in ("sweep_wing.png", "sweep_wing.pdf", "sweep_kinematics_rotation_phase.png"):
    path = os.path.join(work, "plots", name)
    if not os.path.exists(path) or os.path.getsize(path) == 0:
        failures.append(f"no {name}")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
