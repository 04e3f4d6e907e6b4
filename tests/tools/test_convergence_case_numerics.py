#!/usr/bin/python3
"""tools/convergence.py (make convergence) starts its levels from the case's resolution. It
read the case line by line and missed numerics written as valid TOML in other forms (a
dotted key `numerics.steps_per_cycle = 30`, an inline table, `1_000`): it then labelled its
levels with the defaults (6 x 10, 100 steps) while flapsim ran the case's own values. The
case is read as TOML."""
import importlib.util
import os
import sys
import tempfile

source = sys.argv[sys.argv.index("--source") + 1]
sys.path.insert(0, os.path.join(source, "tools"))
spec = importlib.util.spec_from_file_location("convergence", os.path.join(source, "tools", "convergence.py"))
convergence = importlib.util.module_from_spec(spec)
spec.loader.exec_module(convergence)

head = 'name = "c"\nwing = "w.toml"\n[kinematics]\nfrequency_hz = 20.0\n'
forms = {
    "table": "[numerics]\nsteps_per_cycle = 30\nchordwise_panels = 3\nspanwise_panels = 5\n",
    "dotted": "numerics.steps_per_cycle = 30\nnumerics.chordwise_panels = 3\nnumerics.spanwise_panels = 5\n",
    "inline": "numerics = { steps_per_cycle = 30, chordwise_panels = 3, spanwise_panels = 5 }\n",
    "commented": "[numerics]\nsteps_per_cycle = 3_0  # thirty\nchordwise_panels = 3\nspanwise_panels = 5\n",
}
with tempfile.TemporaryDirectory() as folder:
    for name, numerics in forms.items():
        # Dotted keys and inline tables must come before the first [table] of the file.
        text = (numerics + head) if name in ("dotted", "inline") else (head + numerics)
        case = os.path.join(folder, f"{name}.toml")
        with open(case, "w") as f:
            f.write(text)
        got = convergence.case_numerics(case)
        assert got == {"chordwise_panels": 3, "spanwise_panels": 5, "steps_per_cycle": 30}, (name, got)
    # Keys left out take the defaults of docs/case_file.md.
    case = os.path.join(folder, "defaults.toml")
    with open(case, "w") as f:
        f.write(head)
    assert convergence.case_numerics(case) == {"chordwise_panels": 6, "spanwise_panels": 10, "steps_per_cycle": 100}
print("ok")
