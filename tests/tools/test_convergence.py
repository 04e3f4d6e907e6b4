"""tools/convergence.py (make convergence): its order and extrapolation formulas against a
sequence whose answer is known, and the driver end to end on a tiny rigid hover (a flat
plate, 2 x 4 panels up to 8 x 16, 12 steps a cycle up to 48, one cycle): every level run,
the order and extrapolation it reports equal to the formulas of Roache (1998) applied here
to its own table, and bad levels refused with exit status 1."""
import csv
import importlib.util
import math
import os
import re
import subprocess
import sys

from tool_test_args import arguments

a, work = arguments("flapsim", "source", "work")
spec = importlib.util.spec_from_file_location("convergence", os.path.join(a.source, "tools", "convergence.py"))
conv = importlib.util.module_from_spec(spec)
spec.loader.exec_module(conv)
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


# 1. f(h) = 3 + 0.5 h^2 at h = 1, 1/2, 1/4: order 2, extrapolated value 3 (exact for a
# pure power law); f = 1 + h^1.5 at ratio 3: order 1.5, value 1.
p, ext, err = conv.observed_order([3 + 0.5, 3 + 0.125, 3 + 0.03125], 2.0)
check(abs(p - 2.0) < 1e-12 and abs(ext - 3.0) < 1e-12 and abs(err - 0.03125) < 1e-12, f"h^2: p {p}, ext {ext}")
hs = [1.0, 1 / 3, 1 / 9]
p, ext, _ = conv.observed_order([1 + h**1.5 for h in hs], 3.0)
check(abs(p - 1.5) < 1e-12 and abs(ext - 1.0) < 1e-12, f"h^1.5: p {p}, ext {ext}")
# Oscillating differences: no order claimed.
check(conv.observed_order([1.0, 1.2, 1.1], 2.0) == (None, None, None), "oscillating sequence gave an order")
check(abs(conv.refinement_ratio([60, 240, 960]) - 4.0) < 1e-12, "ratio of 60, 240, 960")

# 2. The driver on a tiny case.
case = os.path.join(work, "tiny.toml")
with open(case, "w") as f:
    f.write(f"""name = "tiny"
wing = "{os.path.join(os.path.abspath(a.source), 'wings', 'flat_plate.toml')}"
[kinematics]
frequency_hz = 20.0
rotation_phase = 0.0
stroke_plane_deg = 0.0
sweep = {{ mean_deg = 0.0, cos_deg = [40.0] }}
deviation = 0.0
rotation = {{ mean_deg = 90.0, sin_deg = [-40.0] }}
[air]
density = 1.225
freestream = [0.0, 0.0, 0.0]
[structure]
kind = "rigid"
[numerics]
steps_per_cycle = 12
cycles = 1
chordwise_panels = 2
spanwise_panels = 4
[output]
vtk_every = 0
""")
out = os.path.join(work, "out")
r = subprocess.run([sys.executable, os.path.join(a.source, "tools", "convergence.py"), case, "--flapsim", a.flapsim,
                    "-o", out, "-j", "2"], capture_output=True, text=True)
print(r.stdout, r.stderr)
check(r.returncode == 0, f"driver exit {r.returncode}")
rows = list(csv.DictReader(open(os.path.join(out, "convergence.csv")))) if r.returncode == 0 else []
check(len(rows) == 6, f"{len(rows)} rows, expected 3 lattice and 3 step levels")
lattice = [(int(x["chordwise"]), int(x["spanwise"])) for x in rows if x["study"] == "lattice"]
steps = [int(x["steps_per_cycle"]) for x in rows if x["study"] == "steps"]
check(lattice == [(2, 4), (4, 8), (8, 16)], f"lattice levels {lattice}")
check(steps == [12, 24, 48], f"step levels {steps}")
md = open(os.path.join(out, "convergence.md")).read() if r.returncode == 0 else ""
for study in ("lattice", "steps"):
    f = [float(x["mean_lift_N"]) for x in rows if x["study"] == study]
    if len(f) != 3:
        continue
    check(all(math.isfinite(v) and v > 0 for v in f), f"{study}: mean lift {f}")
    # Roache's formulas, written here: p = ln((f1 - f2)/(f2 - f3))/ln 2.
    q = (f[0] - f[1]) / (f[1] - f[2]) if f[1] != f[2] else math.inf
    title = "Lattice" if study == "lattice" else "Time step"
    section = md.split("### " + title, 1)[1].split("###", 1)[0] if ("### " + title) in md else ""
    m = re.search(r"observed order p = ([0-9.]+); Richardson-extrapolated mean lift ([0-9.]+) mN", section)
    if q > 1.0 and math.isfinite(q):
        p = math.log(q) / math.log(2.0)
        ext = f[2] + (f[2] - f[1]) / (2.0**p - 1.0)
        check(m is not None, f"{study}: no order reported though the differences shrink ({f})")
        if m:
            check(abs(float(m.group(1)) - p) < 0.006, f"{study}: order {m.group(1)} against {p:.4f}")
            check(abs(float(m.group(2)) - 1e3 * ext) < 1e-4 * abs(1e3 * ext) + 1e-4,
                  f"{study}: extrapolation {m.group(2)} mN against {1e3 * ext:.4f}")
    else:
        # The reason named: changes of one sign that do not shrink, or changes of both signs.
        why = "the changes do not shrink" if (f[0] - f[1]) * (f[1] - f[2]) > 0 else "the changes change sign"
        check(m is None and why in section and "no observed order" in section,
              f"{study}: an order claimed for {f}, or not '{why}'")

# 2b. The same command again keeps every level (until 3 Dec it always passed --force and ran
# them all again) and writes the same table.
if r.returncode == 0:
    first = open(os.path.join(out, "convergence.csv")).read()
    again = subprocess.run([sys.executable, os.path.join(a.source, "tools", "convergence.py"), case, "--flapsim",
                            a.flapsim, "-o", out, "-j", "2"], capture_output=True, text=True)
    check(again.returncode == 0, f"second driver exit {again.returncode}")
    kept = [row["message"] for sub in ("lattice", "steps")
            for row in csv.DictReader(open(os.path.join(out, sub, "sweep.csv")))]
    check(len(kept) == 6 and all(m.startswith("kept") for m in kept), f"second run's levels: {kept}")
    check(open(os.path.join(out, "convergence.csv")).read() == first, "second run's table differs")

# 2c. SIGTERM to the driver reaches the sweep under way: exit 143, no flapsim left running in
# its folder (until 3 Dec the sweep ran on with parent 1, and the driver said 3, "a level
# failed"). A longer case: 40 cycles a level.
import signal
import time
slow = os.path.join(work, "slow.toml")
with open(case) as f:
    open(slow, "w").write(f.read().replace("cycles = 1", "cycles = 40"))
slow_out = os.path.join(work, "slow_out")
p = subprocess.Popen([sys.executable, os.path.join(a.source, "tools", "convergence.py"), slow, "--flapsim",
                      a.flapsim, "-o", slow_out, "--study", "steps", "-j", "1"],
                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
time.sleep(1.5)
p.send_signal(signal.SIGTERM)
try:
    _, err = p.communicate(timeout=60)
except subprocess.TimeoutExpired:
    p.kill()
    _, err = p.communicate()
check(p.returncode == 143, f"SIGTERM: driver exit {p.returncode}, {err.strip()[-300:]}")
check("interrupted" in err, f"SIGTERM: no word of the interruption: {err.strip()[-300:]}")
left = subprocess.run(["ps", "-eo", "args"], capture_output=True, text=True).stdout
check(slow_out not in left, "SIGTERM: a process still runs in the study's folder")

# 3. Bad levels: exit status 1, nothing run.
for bad in (["--lattice", "6x10,12x20"], ["--lattice", "6x10,12x24,24x40"], ["--steps", "100,50,25"],
            ["--levels", "5"]):
    r = subprocess.run([sys.executable, os.path.join(a.source, "tools", "convergence.py"), case, "--flapsim",
                        a.flapsim, "-o", os.path.join(work, "bad")] + bad, capture_output=True, text=True)
    check(r.returncode == 1 and "convergence:" in r.stderr, f"{bad}: exit {r.returncode}, {r.stderr.strip()}")
    check(not os.path.exists(os.path.join(work, "bad", "convergence.csv")), f"{bad}: wrote a table")

print("failures:", len(failures))
sys.exit(1 if failures else 0)
