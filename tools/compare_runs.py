#!/usr/bin/python3
"""Two flapsim runs side by side, column by column: for each history column both runs
wrote (default: the tip's bend and twist, lift, the drive moment), over the last complete
wingbeat of the shorter run, the largest difference of the second run from the first and
that difference as a share of the first run's amplitude (half its peak-to-peak), and the
two runs' means of the column; then the summary.json results both runs have (mean lift,
power, ...) with their relative difference. Runs of the bar chain and of the wing's FEM
(structure kind "fem") write the same columns by design (docs/fsi.md, "The chain against
the FEM"):

    tools/compare_runs.py out/vac_chain out/vac_fem
    tools/compare_runs.py out/hover_flexible out/hover_fem --columns lift_N tip_twist_deg

The runs need the same time steps (the rows are paired by time; a row whose times differ
by more than 1e-9 s is bad input). Exit status 0, or 2 on bad input (a folder without
history.csv or summary.json, a column one run lacks, different time steps)."""
import argparse
import csv
import json
import math
import os
import sys

DEFAULT_COLUMNS = ["tip_bend_deg", "tip_twist_deg", "lift_N", "Mx_drive_Nm", "My_drive_Nm", "Mz_drive_Nm"]
RESULTS = ["mean_lift_N", "mean_CL", "mean_power_W", "mean_drive_power_W", "peak_drive_moment_Nm",
           "peak_tip_bend_deg", "peak_tip_twist_deg", "tip_rotation_phase", "mean_coupling_iterations",
           "wall_time_s"]


def fail(message):
    print(f"compare_runs.py: error: {message}", file=sys.stderr)
    sys.exit(2)


def read_run(folder):
    history = os.path.join(folder, "history.csv")
    summary = os.path.join(folder, "summary.json")
    for f in (history, summary):
        if not os.path.isfile(f):
            fail(f"{folder}: no {os.path.basename(f)}")
    with open(history, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        fail(f"{history}: no rows")
    with open(summary) as f:
        results = json.load(f)
    return rows, results


def last_cycle(rows, frequency):
    """The rows of the last complete wingbeat: t in (t_end − T, t_end]."""
    t_end = float(rows[-1]["t_s"])
    period = 1.0 / frequency
    # t_end − T itself belongs to the wingbeat before: the margin lies inside the window
    # (a margin outside took T/Δt + 1 rows, the mean over 41 rows of a 40-step wingbeat).
    start = t_end - period * (1.0 - 1e-9)
    return [r for r in rows if float(r["t_s"]) > start]


def compare(a_rows, b_rows, columns, frequency):
    n = min(len(a_rows), len(b_rows))
    a_rows, b_rows = a_rows[:n], b_rows[:n]
    for ra, rb in zip(a_rows, b_rows):
        if abs(float(ra["t_s"]) - float(rb["t_s"])) > 1e-9:
            fail(f"the runs' time steps differ (t = {ra['t_s']} s against {rb['t_s']} s): "
                 "compare runs of the same steps_per_cycle")
    a_last = last_cycle(a_rows, frequency)
    b_last = b_rows[len(b_rows) - len(a_last):]
    table = []
    for c in columns:
        if c not in a_rows[0] or c not in b_rows[0]:
            fail(f"column {c} is not in both runs' history.csv")
        x = [float(r[c]) for r in a_last]
        y = [float(r[c]) for r in b_last]
        amplitude = 0.5 * (max(x) - min(x))
        worst = max(abs(p - q) for p, q in zip(x, y))
        share = worst / amplitude if amplitude > 0 else math.nan
        table.append((c, sum(x) / len(x), sum(y) / len(y), amplitude, worst, share))
    return table, len(a_last)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("first", help="output folder of the reference run (e.g. the chain's)")
    p.add_argument("second", help="output folder of the run compared with it (e.g. the FEM's)")
    p.add_argument("--columns", nargs="+", default=None, help="history columns (default: " +
                   " ".join(DEFAULT_COLUMNS) + ")")
    args = p.parse_args()
    a_rows, a_res = read_run(args.first)
    b_rows, b_res = read_run(args.second)
    frequency = a_res.get("frequency_hz")
    if not frequency or frequency != b_res.get("frequency_hz"):
        fail("the runs' frequency_hz differ (or are missing)")
    columns = args.columns or [c for c in DEFAULT_COLUMNS if c in a_rows[0] and c in b_rows[0]]
    table, rows = compare(a_rows, b_rows, columns, frequency)
    print(f"last wingbeat ({rows} steps): {args.second} against {args.first}")
    print(f"{'column':<16} {'mean 1':>12} {'mean 2':>12} {'amplitude 1':>12} {'max |2 - 1|':>12} {'of ampl.':>9}")
    for c, ma, mb, amp, worst, share in table:
        print(f"{c:<16} {ma:12.5g} {mb:12.5g} {amp:12.5g} {worst:12.5g} {100 * share:8.2f}%")
    print()
    print(f"{'result':<26} {'run 1':>13} {'run 2':>13} {'2 / 1 - 1':>10}")
    for k in RESULTS:
        if isinstance(a_res.get(k), (int, float)) and isinstance(b_res.get(k), (int, float)):
            x, y = float(a_res[k]), float(b_res[k])
            # a relative difference of a result near zero (a phase of 1e-16) says nothing
            rel = f"{100 * (y / x - 1):9.2f}%" if abs(x) > 1e-9 * max(abs(y), 1e-300) and abs(x) > 1e-12 else "        —"
            print(f"{k:<26} {x:13.6g} {y:13.6g} {rel}")


if __name__ == "__main__":
    main()
