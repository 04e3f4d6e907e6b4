#!/usr/bin/python3
"""ctest tools.MakeModel.StagesRerunOnlyWhenTheirInputsChange: `make model WING=...` as a
user runs it, into a temporary OUT under build/:
  1. wings/robofly.toml: the first call builds out/robofly/ (mesh, modes, beam, chain);
     a second call runs no stage; touching only its outline CSV re-runs mesh, modes and
     reduce (issue 18's "done when");
  2. a small wing whose outline is a CSV file (copied into the work folder): the first
     call builds mesh, modes and chain; a second call runs no stage (every file keeps its
     time stamp); touching only the outline re-runs mesh, modes and reduce; another
     BODIES re-runs the reduction only;
  3. another wing of the same file name in another folder, older than the model, re-runs
     every stage, and so does going back to the first."""
import os
import subprocess
import sys
import time

import tool_test_args

a, work = tool_test_args.arguments("source", "build", "work")
out = os.path.join(work, "out")
failures = []


def check(ok, message):
    print(("ok: " if ok else "FAIL: ") + message)
    if not ok:
        failures.append(message)


def make(*args):
    cmd = ["make", "-C", a.source, "--no-print-directory", f"BUILD={a.build}", f"OUT={out}", *args]
    r = subprocess.run(cmd, capture_output=True, text=True, env=dict(os.environ, OMP_NUM_THREADS="1"))
    print("$", " ".join(cmd[1:]), f"-> {r.returncode}")
    if r.returncode != 0:
        print(r.stdout[-3000:], r.stderr[-3000:])
    return r


def stamps(folder, names):
    return {n: os.stat(os.path.join(folder, n)).st_mtime_ns for n in names}


# Part 2's wing, a 30 x 8 mm film wing with a CSV outline, 3 bodies; each stage's files.
with open(os.path.join(work, "strip_outline.csv"), "w") as f:
    f.write("# a rectangle in units of the span\nx,y\n0.1,0\n0.1,1\n-0.166,1\n-0.166,0\n")
wing = os.path.join(work, "strip.toml")
with open(wing, "w") as f:
    f.write('length_unit = "mm"\n[planform]\noutline_file = "strip_outline.csv"\nspan = 30.0\nclamp_y = 0.0\n'
            '[materials.film]\nyoungs_modulus = 4.0e9\npoisson_ratio = 0.3\ndensity = 1400.0\n'
            '[membrane]\nmaterial = "film"\nthickness = 0.2\n[mesh]\nelement_size = 2.0\n')
stages = {"mesh": ["mesh.msh", "mesh.vtu"], "modes": ["modes.csv", "fem.vtu"],
          "reduce": ["chain.toml", "beam.csv", "reduction.vtm", "report.md", "summary.json"]}
files = [f for fs in stages.values() for f in fs]
model = os.path.join(out, "strip")

# 1. robofly, the whole model, as the issue asks.
robofly = os.path.join(out, "robofly")
r = make("model", "WING=wings/robofly.toml")
check(r.returncode == 0, "make model WING=wings/robofly.toml builds out/robofly/")
check(all(os.path.isfile(os.path.join(robofly, f)) for f in files), "every stage's files exist in out/robofly/")
if failures:
    sys.exit(1)
rf_first = stamps(robofly, files)
time.sleep(1.1)  # time stamps of the next writes are distinct
r = make("model", "WING=wings/robofly.toml")
check(r.returncode == 0 and stamps(robofly, files) == rf_first, "a second make model (robofly) rewrites nothing")
os.utime(os.path.join(a.source, "wings", "outlines", "robofly_dickinson_outline.csv"))  # touch the outline only
r = make("model", "WING=wings/robofly.toml")
rf_after = stamps(robofly, files)
check(r.returncode == 0, "make model (robofly) after touching its outline")
for stage, names in stages.items():
    check(all(rf_after[n] > rf_first[n] for n in names), f"touching robofly's outline re-ran {stage}")

# 2. The small film wing.

r = make("model", f"WING={wing}", "BODIES=3")
check(r.returncode == 0, "first make model builds out/strip/")
check(all(os.path.isfile(os.path.join(model, f)) for f in files), "every stage's files exist")
if failures:
    sys.exit(1)
first = stamps(model, files)

time.sleep(1.1)  # time stamps of the next writes are distinct
r = make("model", f"WING={wing}", "BODIES=3")
check(r.returncode == 0 and stamps(model, files) == first, "a second make model rewrites nothing")
check(" mesh " not in r.stdout and " reduce " not in r.stdout, "a second make model runs no flapsim stage")

os.utime(os.path.join(work, "strip_outline.csv"))  # touch the outline only
r = make("model", f"WING={wing}", "BODIES=3")
after = stamps(model, files)
check(r.returncode == 0, "make model after touching the outline")
for stage, names in stages.items():
    check(all(after[n] > first[n] for n in names), f"touching the outline re-ran {stage}")

time.sleep(1.1)
r = make("model", f"WING={wing}", "BODIES=2")
again = stamps(model, files)
check(all(again[n] == after[n] for n in stages["mesh"] + stages["modes"]), "another BODIES keeps mesh and modes")
check(all(again[n] > after[n] for n in stages["reduce"]), "another BODIES re-runs the reduction")
with open(os.path.join(model, "chain.toml")) as f:
    stiff_chain = f.read()
check(stiff_chain.count("[[bodies]]") == 2, "the chain has the 2 bodies asked for")

# 3. Another wing of the same file name in another folder (its film 4 times softer), its
# files an hour older than the model: out/strip/ is the model of either, and judged by time
# stamps alone it looked up to date and make run flew the stiffer wing's chain. Its paths
# and contents (.wing_source) re-run every stage; going back to the first wing does too.
other = os.path.join(work, "other")
os.makedirs(other, exist_ok=True)
other_wing = os.path.join(other, "strip.toml")
with open(wing) as f, open(other_wing, "w") as g:
    g.write(f.read().replace("youngs_modulus = 4.0e9", "youngs_modulus = 1.0e9"))
with open(os.path.join(work, "strip_outline.csv")) as f, open(os.path.join(other, "strip_outline.csv"), "w") as g:
    g.write(f.read())
hour_ago = time.time() - 3600
for path in (other_wing, os.path.join(other, "strip_outline.csv")):
    os.utime(path, (hour_ago, hour_ago))
time.sleep(1.1)
r = make("model", f"WING={other_wing}", "BODIES=2")
softer = stamps(model, files)
check(r.returncode == 0, "make model with the other wing of the same name")
for stage, names in stages.items():
    check(all(softer[n] > again[n] for n in names), f"another wing of the same name re-ran {stage}")
with open(os.path.join(model, "chain.toml")) as f:
    check(f.read() != stiff_chain, "the other wing's chain is its own (a softer film: other springs)")
time.sleep(1.1)
r = make("model", f"WING={wing}", "BODIES=2")
back = stamps(model, files)
check(r.returncode == 0 and all(back[n] > softer[n] for n in files), "back to the first wing re-ran every stage")
with open(os.path.join(model, "chain.toml")) as f:
    check(f.read() == stiff_chain, "back to the first wing, its chain again")
time.sleep(1.1)
r = make("model", f"WING={wing}", "BODIES=2")
check(r.returncode == 0 and stamps(model, files) == back, "and a second call rewrites nothing")

sys.exit(1 if failures else 0)
