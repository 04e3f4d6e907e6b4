"""Forces and powers in the SI prefix that suits their size, so a fruit fly's lift reads
3.211 uN where a fixed mN showed 0.003211 (and a convergence table's changes of a
micronewton wing rounded to +0.0000 mN), and a large ornithopter's 2.5 N not 2500 mN."""

import json
import math
import os

# (size of one unit in SI, prefix), largest first; "u" for micro keeps the text ASCII.
PREFIXES = ((1.0, ""), (1e-3, "m"), (1e-6, "u"), (1e-9, "n"))


def si_scale(values, unit):
    """(factor, label): values [unit] times factor are shown in label, the prefix chosen so
    the largest finite |value| is at least 1 in it (N down to nN); all zero or none: milli."""
    largest = max((abs(v) for v in values if math.isfinite(v)), default=0.0)
    if largest == 0.0:
        return 1e3, "m" + unit
    for size, prefix in PREFIXES:
        if largest >= size:
            return 1.0 / size, prefix + unit
    return 1e9, "n" + unit


def run_force_scale(run_dir, fallback_N=0.0):
    """si_scale for the lift of the run in run_dir: by its mean lift (summary.json), so every
    picture of one run shows the same unit; without one, by fallback_N."""
    try:
        with open(os.path.join(run_dir, "summary.json")) as f:
            lift = abs(float(json.load(f).get("mean_lift_N", 0.0)))
    except (OSError, ValueError, TypeError):
        lift = 0.0
    return si_scale([lift or fallback_N], "N")
