#!/usr/bin/python3
"""ctest tools.MakeRun.ReducesTheWingToTheCasesBodies: `make run CASE=x.toml` for a flexible
case without a chain file makes its wing's model first. Before: the model had the default
10 bodies whatever the case said, and a 6-body case stopped with "the case says 6 bodies,
but the chain file out/<wing>/chain.toml has 10". Now the reduction gets the case's
structure.bodies. Checked with `make -n` (what make would run, nothing run) and
tools/toml_inputs.py's CASE_BODIES."""
import os
import subprocess
import sys

import tool_test_args

a, work = tool_test_args.arguments("source", "build", "work")
case = os.path.join(work, "six_bodies.toml")
with open(case, "w") as f:
    f.write(f'name = "six_bodies"\nwing = "{a.source}/wings/flat_plate.toml"\n'
            "[kinematics]\nfrequency_hz = 20.0\nsweep = { cos_deg = [40.0] }\nrotation = 90.0\n"
            '[structure]\nkind = "flexible"\nbodies = 6\n')

failures = []
inputs = subprocess.run(["/usr/bin/python3", os.path.join(a.source, "tools", "toml_inputs.py"), "case", case],
                        capture_output=True, text=True).stdout.split()
if "CASE_BODIES=6" not in inputs:
    failures.append(f"toml_inputs.py case: no CASE_BODIES=6 in {inputs}")
r = subprocess.run(["make", "-n", "-C", a.source, "--no-print-directory", f"BUILD={a.build}",
                    f"OUT={os.path.join(work, 'out')}", "run", f"CASE={case}"], capture_output=True, text=True)
reduce_lines = [line for line in r.stdout.splitlines() if " reduce " in line]
print("\n".join(reduce_lines))
if not reduce_lines or not all(line.rstrip().endswith("--bodies 6") for line in reduce_lines):
    failures.append("make -n run: the wing is not reduced to the case's 6 bodies:\n" + r.stdout[-2000:] + r.stderr[-2000:])
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
