#!/usr/bin/python3
"""ctest tools.CompareRuns.PairsTheLastWingbeatColumnByColumn: tools/compare_runs.py on
two rigid runs of the flat plate (wings/flat_plate.toml, 2 cycles of 12 steps) that differ
only in the rotation phase (0 and -0.1): the largest lift difference over the last
wingbeat and the amplitude it prints equal those computed here from the two history.csv
files (rows paired by time), the wingbeat's 12 rows and their mean (until 3 Dec it took 13,
t_end − T too, and a mean 2.1 % off on a 40-step hover), a run compared with itself differs by 0, and runs of
different time steps or a column one run lacks are bad input (exit status 2)."""
import csv
import os
import subprocess
import sys

import tool_test_args

a, work = tool_test_args.arguments("flapsim", "source", "work")
env = dict(os.environ, FLAPSIM_QUIET="1", OMP_NUM_THREADS="1")
script = os.path.join(a.source, "tools", "compare_runs.py")
check = tool_test_args.Checks()
failures = check.failures


def run(name, phase, steps):
    case = os.path.join(work, name + ".toml")
    with open(case, "w") as f:
        f.write(f'name = "{name}"\nwing = "{a.source}/wings/flat_plate.toml"\n'
                f"[kinematics]\nfrequency_hz = 26.1\nrotation_phase = {phase}\n"
                "sweep = { mean_deg = 10.0, cos_deg = [50.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
                '[structure]\nkind = "rigid"\n'
                f"[numerics]\nsteps_per_cycle = {steps}\ncycles = 2\nchordwise_panels = 3\nspanwise_panels = 4\n"
                "core_radius = 0.2\nfar_wake_cycles = 0.5\n[output]\nvtk_every = 0\n")
    out = os.path.join(work, name)
    subprocess.run([a.flapsim, "run", case, "-o", out, "-q"], check=True, env=env)
    return out


def compare(*args):
    return subprocess.run(["/usr/bin/python3", script, *args], capture_output=True, text=True)


first, second = run("a", 0.0, 12), run("b", -0.1, 12)
result = compare(first, second, "--columns", "lift_N")
print(result.stdout)
check(result.returncode == 0, f"exit status {result.returncode}: {result.stderr}")
rows = [list(csv.DictReader(open(os.path.join(d, "history.csv")))) for d in (first, second)]
last = [r[-12:] for r in rows]  # the last wingbeat: 12 steps
x = [float(r["lift_N"]) for r in last[0]]
y = [float(r["lift_N"]) for r in last[1]]
worst = max(abs(p - q) for p, q in zip(x, y))
amplitude = 0.5 * (max(x) - min(x))
line = next((l for l in result.stdout.splitlines() if l.startswith("lift_N")), "")
fields = line.split()
check(len(fields) == 6, f"no lift_N row: {result.stdout}")
if len(fields) == 6:
    check(abs(float(fields[3]) - amplitude) <= 1e-4 * amplitude, f"amplitude {fields[3]} against {amplitude:.5g}")
    check(abs(float(fields[4]) - worst) <= 1e-4 * worst, f"max difference {fields[4]} against {worst:.5g}")
    check(worst > 0.05 * amplitude, "the rotation phase changed the lift by nothing: not a comparison")
    mean = sum(x) / len(x)
    check(abs(float(fields[1]) - mean) <= 1e-4 * abs(mean), f"mean {fields[1]} against the last 12 rows' {mean:.5g}")
check("last wingbeat (12 steps)" in result.stdout, f"not the wingbeat's 12 steps: {result.stdout}")
same = compare(first, first, "--columns", "lift_N", "tip_twist_deg")
check(same.returncode == 0 and " 0.00%" in same.stdout, f"a run against itself: {same.stdout}{same.stderr}")
other_steps = run("c", 0.0, 16)
check(compare(first, other_steps).returncode == 2, "runs of different time steps were compared")
check(compare(first, second, "--columns", "no_such_column").returncode == 2, "an unknown column was accepted")
check(compare(first, os.path.join(work, "nothing")).returncode == 2, "a folder without a run was accepted")
sys.exit(1 if failures else 0)
