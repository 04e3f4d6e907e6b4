#!/usr/bin/python3
"""Forces in the prefix that suits them (tools/si_prefix.py): a fruit fly's lift of 3.2 uN
was titled "0.003211 mN" under its pictures, and a convergence study of it tabulated
changes of a few tenths of a micronewton as "+0.0000" mN; a hawkmoth's stays in mN."""
import importlib.util
import json
import os
import sys
import tempfile

source = sys.argv[sys.argv.index("--source") + 1]
sys.path.insert(0, os.path.join(source, "tools"))


def load(name):
    spec = importlib.util.spec_from_file_location(name, os.path.join(source, "tools", name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


si_prefix, convergence = load("si_prefix"), load("convergence")

# The prefix puts the largest |value| at 1 or more: N, mN, uN, nN; nan ignored; zeros in mN.
assert si_prefix.si_scale([3.211e-6, -1e-7], "N") == (1e6, "uN")
assert si_prefix.si_scale([8.398e-3, float("nan")], "N") == (1e3, "mN")
assert si_prefix.si_scale([0.52, 1e-4], "N") == (1e3, "mN")  # 520 mN
assert si_prefix.si_scale([2.5], "N") == (1.0, "N")
assert si_prefix.si_scale([4e-10], "N") == (1e9, "nN")
assert si_prefix.si_scale([0.0], "W") == (1e3, "mW")
assert si_prefix.si_scale([-2.5e-5], "W") == (1e6, "uW")

# One unit for every picture of a run: its mean lift's (summary.json), else the frame's.
with tempfile.TemporaryDirectory() as run:
    assert si_prefix.run_force_scale(run, 3.2e-6) == (1e6, "uN")  # no summary yet
    with open(os.path.join(run, "summary.json"), "w") as f:
        json.dump({"mean_lift_N": 3.21087e-06}, f)
    scale = si_prefix.run_force_scale(run, -2e-3)  # a frame's lift can be far off the mean
    assert scale == (1e6, "uN"), scale
    render_run = load("render_run")
    title = render_run.frame_title(0.01625, 200.0, 0.25, 6.655e-6, scale)
    assert title.endswith("lift = 6.655 uN"), title

# Convergence table of a micronewton wing: the changes keep their digits.
lines, _, _ = convergence.study_table("steps", ["steps per cycle"], [[30], [60], [120]],
                                      [3.0e-6, 3.2e-6, 3.25e-6], 2.0)
text = "\n".join(lines)
assert "mean lift [uN]" in text and "| 3.2000 | +0.2000 |" in text, text
assert "3.2667 uN" in text, text  # Richardson: 3.25 + 0.05 / (2^2 - 1)
print("ok")
