#!/usr/bin/python3
"""tools/plot_phase_study.py cuts the last wingbeat of each case with the case's own
frequency (its summary.json), not a fixed 26.1 Hz: a case at 20 Hz (T = 50 ms) had only
its last 38.3 ms (1/26.1 Hz) drawn as "the last wingbeat"."""
import importlib.util
import json
import os
import sys
import tempfile

import numpy as np

source = sys.argv[sys.argv.index("--source") + 1]
spec = importlib.util.spec_from_file_location("plot_phase_study", os.path.join(source, "tools", "plot_phase_study.py"))
plots = importlib.util.module_from_spec(spec)
spec.loader.exec_module(plots)

with tempfile.TemporaryDirectory() as folder:
    with open(os.path.join(folder, "summary.json"), "w") as f:
        json.dump({"case": "c", "frequency_hz": 20.0}, f)
    f_hz = plots.case_frequency(folder)
    assert f_hz == 20.0, f_hz
    # Two cycles of 40 steps at 20 Hz: t = k * 1.25 ms, k = 1..80.
    h = np.zeros(80, dtype=[("t_s", float)])
    h["t_s"] = np.arange(1, 81) * (1.0 / 20.0 / 40.0)
    keep, s = plots.last_cycle(h, f_hz)
    # The last wingbeat: t from 50 ms to 100 ms, steps 40..80 (41 samples, both ends), s from 0 to 1.
    assert keep.sum() == 41, keep.sum()
    assert abs(s[0]) < 1e-9 and abs(s[-1] - 1.0) < 1e-9, (s[0], s[-1])
print("ok")
