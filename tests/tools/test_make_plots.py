#!/usr/bin/python3
"""ctest tools.MakePlots.WritesPdfPngAndTheStudysNumbers: a tiny rotation-phase study (the flat plate,
rigid and on a stiff 2-body chain, 3 x 4 panels, 12 steps per wingbeat, 2 wingbeats,
five phases each) made with `flapsim sweep`, then `make plots` on it: every figure of
tools/plot_phase_study.py exists as a PDF (a PDF file, vector) and as a PNG of at least
1000 pixels width; the per-sweep figures of tools/plot_sweep.py too, PDF and PNG. And the
figures draw the study's numbers: the points of fig12a (from its CSV of plotted data) are
the sweeps' mean lifts (sweep.csv, in mN, against δψ in %), and fig12b's curves are the
last wingbeat of each case's history.csv (its peak lift, in mN)."""
import csv
import os
import struct
import subprocess
import sys

import tool_test_args

a, work = tool_test_args.arguments("flapsim", "source", "work")
env = dict(os.environ, FLAPSIM_QUIET="1", OMP_NUM_THREADS="1")

with open(os.path.join(work, "chain.toml"), "w") as f:
    f.write('root = "rigid"\n'
            "[[bodies]]\nlength = 0.02\nmass = 1e-5\ncenter_of_mass = [0, 0.01, 0]\n"
            "inertia = [[4e-10,0,0],[0,1e-11,0],[0,0,4e-10]]\n"
            "[[bodies]]\nlength = 0.02\nmass = 1e-5\ncenter_of_mass = [0, 0.01, 0]\n"
            "inertia = [[4e-10,0,0],[0,1e-11,0],[0,0,4e-10]]\n"
            "[bodies.joint]\nbend_stiffness = 1e-2\ntwist_stiffness = 1e-2\n")
for kind, extra, structure in (("rigid", "", 'kind = "rigid"\n'),
                               ("flexible", 'chain = "chain.toml"\n', 'kind = "flexible"\nbodies = 2\n')):
    with open(os.path.join(work, f"{kind}.toml"), "w") as f:
        f.write(f'name = "{kind}"\nwing = "{a.source}/wings/flat_plate.toml"\n{extra}'
                "[kinematics]\nfrequency_hz = 26.1\nrotation_phase = 0.0\n"
                "sweep = { mean_deg = 10.0, cos_deg = [50.0] }\n"
                "rotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
                f"[structure]\n{structure}"
                "[numerics]\nsteps_per_cycle = 12\ncycles = 2\nchordwise_panels = 3\nspanwise_panels = 4\n"
                "core_radius = 0.2\n[output]\nvtk_every = 0\n")
    phases = "-0.15:0.05:0.05" if kind == "rigid" else "-0.10:0.05:0.10"
    subprocess.run([a.flapsim, "sweep", os.path.join(work, f"{kind}.toml"), "--vary",
                    f"kinematics.rotation_phase={phases}", "-o", os.path.join(work, "study", kind), "-j", "2"],
                   check=True, env=env, stdout=subprocess.DEVNULL)

plots = os.path.join(work, "plots")
r = subprocess.run(["make", "-C", a.source, "--no-print-directory", "plots", f"PHASE_OUT={work}/study",
                    f"PLOTS_OUT={plots}"], capture_output=True, text=True)
print(r.stdout[-2000:], r.stderr[-2000:])
failures = []
if r.returncode != 0:
    failures.append(f"make plots exited {r.returncode}")
for name in ("fig12a_mean_lift_vs_phase", "fig12b_rigid_lift_cycle", "fig13b_flexible_lift_cycle",
             "fig14_euler_angles", "fig15_tip_base_phase"):
    pdf, png = os.path.join(plots, name + ".pdf"), os.path.join(plots, name + ".png")
    if not (os.path.isfile(pdf) and open(pdf, "rb").read(5) == b"%PDF-"):
        failures.append(f"{name}.pdf missing or not a PDF")
    if not os.path.isfile(png):
        failures.append(f"{name}.png missing")
        continue
    with open(png, "rb") as f:
        head = f.read(24)
    width = struct.unpack(">I", head[16:20])[0]
    if head[:8] != b"\x89PNG\r\n\x1a\n" or width < 1000:
        failures.append(f"{name}.png is not a PNG of at least 1000 px width ({width})")
for sub in ("rigid", "flexible"):
    for ext in (".png", ".pdf"):
        if not any(f.endswith(ext) for f in os.listdir(os.path.join(plots, sub))):
            failures.append(f"no sweep figure ({ext}) in plots/{sub}")


def plotted(name):
    """{series: [(x, y), ...]} of a figure's CSV of plotted data."""
    series = {}
    with open(os.path.join(plots, name + ".csv")) as f:
        for r in csv.DictReader(f):
            series.setdefault(r["series"], []).append((float(r["x"]), float(r["y"])))
    return series


def sweep_rows(kind):
    with open(os.path.join(work, "study", kind, "sweep.csv")) as f:
        return [r for r in csv.DictReader(f) if r["status"] == "ok"]


try:
    fig12a = plotted("fig12a_mean_lift_vs_phase")
    for kind in ("rigid", "flexible"):
        rows = sweep_rows(kind)
        expected = sorted((100 * float(r["kinematics.rotation_phase"]), 1e3 * float(r["mean_lift_N"])) for r in rows)
        got = sorted(fig12a.get(f"{kind} wing", []))
        if len(got) != len(expected) or any(abs(g[0] - e[0]) > 1e-9 or abs(g[1] - e[1]) > 1e-9 * max(1.0, abs(e[1]))
                                            for g, e in zip(got, expected)):
            failures.append(f"fig12a's {kind} points {got} are not sweep.csv's {expected}")
    fig12b = plotted("fig12b_rigid_lift_cycle")
    for r in sweep_rows("rigid"):
        label = "δψ = %+.0f %%" % (100 * float(r["kinematics.rotation_phase"]))
        if label not in fig12b:
            continue
        with open(os.path.join(work, "study", "rigid", r["folder"], "history.csv")) as f:
            lift = [float(h["lift_N"]) for h in csv.DictReader(f)]
        last = lift[-13:]  # the last wingbeat, t >= t_end - T: 13 rows at 12 steps per wingbeat
        peak = max(y for _, y in fig12b[label])
        if abs(peak - 1e3 * max(last)) > 1e-9 * abs(peak):
            failures.append(f"fig12b {label}: peak {peak} mN, history's last wingbeat {1e3 * max(last)} mN")
except (OSError, KeyError, ValueError) as e:
    failures.append(f"plotted data unreadable: {e!r}")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
