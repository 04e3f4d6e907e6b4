#!/usr/bin/python3
"""tools/rotation_phase.py against a history.csv written from formulas: eq. 8 of the
rotation-phase paper at the base (phi = 10 + 50 cos 2 pi (f t + dpsi), alpha = 90 - 45 sin 2 pi f t)
and a tip whose alpha lags the base's by L periods and whose phi lags by Ls periods. Analytic
answers: base = dpsi, RP tip phase (Figs. 10 and 15: the tip's crossing minus the base's
reversal, same cycle) = dpsi + L, lead = L, own phase (the tip's crossing minus its own
reversal, summary.json's measure) = dpsi + L - Ls. Plus the errors: a missing column or a run
shorter than a cycle exit 2 naming the file."""
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import tool_test_args  # noqa: E402

args, work = tool_test_args.arguments("source", "work")
sys.path.insert(0, os.path.join(args.source, "tools"))
import rotation_phase  # noqa: E402

check = tool_test_args.Checks()
F = 26.1
T = 1.0 / F


def write_run(folder, dpsi, lag, sweep_lag, cycles=4, steps=400, drop=None):
    os.makedirs(folder, exist_ok=True)
    cols = ["t_s", "phi_base_deg", "alpha_base_deg", "phi_tip_deg", "alpha_tip_deg", "phi_outer_deg", "alpha_outer_deg"]
    if drop:
        cols.remove(drop)
    with open(os.path.join(folder, "history.csv"), "w") as f:
        f.write(",".join(cols) + "\n")
        for k in range(cycles * steps + 1):
            t = k * T / steps
            v = {"t_s": t,
                 "phi_base_deg": 10 + 50 * math.cos(2 * math.pi * (F * t + dpsi)),
                 "alpha_base_deg": 90 - 45 * math.sin(2 * math.pi * F * t),
                 "phi_tip_deg": 10 + 50 * math.cos(2 * math.pi * (F * (t - sweep_lag * T) + dpsi)),
                 "alpha_tip_deg": 90 - 45 * math.sin(2 * math.pi * F * (t - lag * T)),
                 "phi_outer_deg": 10 + 50 * math.cos(2 * math.pi * (F * t + dpsi)),
                 "alpha_outer_deg": 90 - 45 * math.sin(2 * math.pi * F * (t - 0.5 * lag * T))}
            f.write(",".join("%.12g" % v[c] for c in cols) + "\n")
    with open(os.path.join(folder, "summary.json"), "w") as f:
        f.write('{"frequency_hz": %r}\n' % F)
    return folder


# Leads of the size the paper's Fig. 15 shows (tip 5 and 13 % ahead) and one near the window
# edge (dpsi + lag = -0.48: the same-cycle rule must not take the crossing of the next cycle).
# Two-cycle runs (the shortened reproduction's) hold a whole wingbeat only with the sweep
# minimum before the maximum for some dpsi (+0.10) and after it for others (-0.10).
for dpsi, lag, sweep_lag, cycles in [(-0.10, -0.05, 0.02, 4), (0.10, -0.13, 0.03, 4), (0.0, -0.007, 0.0, 4),
                                     (-0.20, -0.28, 0.01, 4), (-0.10, -0.05, 0.02, 2), (0.10, -0.13, 0.03, 2)]:
    run = write_run(os.path.join(work, "r_%+.2f_%+.3f_%d" % (dpsi, lag, cycles)), dpsi, lag, sweep_lag, cycles=cycles)
    r = rotation_phase.run_phases(run, "tip")
    # 400 samples a period and linear interpolation of a sine near its zero: error below 1e-5 T.
    for key, want in (("base", dpsi), ("rp_phase", dpsi + lag), ("rp_lead", lag), ("own_phase", dpsi + lag - sweep_lag)):
        check(abs(r[key] - want) < 1e-5, "dpsi %+.2f lag %+.3f: %s %.6f, formula %.6f" % (dpsi, lag, key, r[key], want))
    o = rotation_phase.run_phases(run, "outer")
    check(abs(o["rp_lead"] - 0.5 * lag) < 1e-5, "outer lead %.6f, formula %.6f" % (o["rp_lead"], 0.5 * lag))
    # The last complete cycle starts at a base sweep maximum, f t0 + dpsi an integer.
    frac = (F * r["cycle_start_s"] + dpsi) % 1.0
    check(min(frac, 1 - frac) < 1e-6, "cycle start at f t + dpsi = %.7f (mod 1), not the sweep maximum" % frac)

# The command line: the same numbers; bad inputs exit 2 naming the file.
tool = os.path.join(args.source, "tools", "rotation_phase.py")
run = os.path.join(work, "r_-0.10_-0.050_4")
p = subprocess.run([sys.executable, tool, run], capture_output=True, text=True)
check(p.returncode == 0 and "tip_rp_lead -0.0500" in p.stdout, "command line: %d %r" % (p.returncode, p.stdout))
bad = write_run(os.path.join(work, "no_alpha_tip"), 0.0, 0.0, 0.0, drop="alpha_tip_deg")
p = subprocess.run([sys.executable, tool, bad], capture_output=True, text=True)
check(p.returncode == 2 and "history.csv" in p.stderr and "alpha_tip_deg" in p.stderr,
      "missing column: %d %r" % (p.returncode, p.stderr))
short = write_run(os.path.join(work, "short"), 0.0, 0.0, 0.0, cycles=1)
p = subprocess.run([sys.executable, tool, short], capture_output=True, text=True)
check(p.returncode == 2 and "no complete wingbeat" in p.stderr, "one cycle: %d %r" % (p.returncode, p.stderr))

sys.exit(1 if check.failures else 0)
