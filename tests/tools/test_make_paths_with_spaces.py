#!/usr/bin/python3
"""ctest tools.MakeRun.APathWithASpaceIsRefusedPlainly: make splits its values at spaces.
Before: `make run CASE="my dir/my case.toml"` ran tools/toml_inputs.py with three words
(it printed its usage), left the case name empty and handed flapsim
`run my dir/my case.toml ... -o out/` (outputs into out/ itself), which stopped with a usage
error naming none of this. Now make stops at once naming CASE (or WING for `make model`) and
the remedy. Checked with `make -n` (nothing is run)."""
import argparse
import subprocess
import sys

p = argparse.ArgumentParser()
p.add_argument("--source", required=True)
p.add_argument("--build", required=True)
a = p.parse_args()

failures = []
for goal, var, path in [("run", "CASE", "/tmp/my dir/my case.toml"),
                        ("model", "WING", "/tmp/my dir/my wing.toml")]:
    r = subprocess.run(["make", "-n", "-C", a.source, "--no-print-directory", f"BUILD={a.build}", goal,
                        f"{var}={path}"], capture_output=True, text=True)
    expected = f'{var} = "{path}" holds a space'
    print(goal, r.returncode, r.stderr.strip()[-300:])
    if r.returncode == 0 or expected not in r.stderr:
        failures.append(f"make -n {goal} {var}='{path}': exit {r.returncode}, no '{expected}':\n{r.stderr[-1000:]}")
    if " flapsim " in r.stdout or "/flapsim" in r.stdout:
        failures.append(f"make -n {goal}: would still run flapsim:\n{r.stdout[-1000:]}")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
