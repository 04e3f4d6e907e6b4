#!/usr/bin/python3
"""Figures of a flapsim optimize folder (docs/optimize.md, "Plotting an optimisation"):

  optimize_objective.png   the objective of each evaluation in order, and the best so far
  optimize_path.png        the path through the varied keys (one key: its value against the
                           evaluation; two or more: the first two keys, points joined in
                           order), start and optimum marked, axes at the bounds
  optimize_lift_cycle.png  the lift over the last cycle of the optimum's run beside the
                           start's (their DIR/runs/<inputs hash>/history.csv)

each also as PDF. The objective and the optimum's run come from DIR/optimum.toml's header,
the start's values and the bounds from DIR/report.md, every evaluation from
DIR/evaluations.csv.

Usage: plot_optimize.py DIR [OUTPUT_DIR]   (default OUTPUT_DIR: DIR/plots; Debian's
python3-matplotlib)
"""
import csv
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def problem(folder):
    """The objective, the optimum's run folder, and per key (name, lower, upper, start)."""
    header = open(os.path.join(folder, "optimum.toml")).read(4000)
    m = re.search(r"flapsim optimize \((\w+) = [^,]+, the run in runs/([0-9a-f]+)/\)", header)
    if not m:
        sys.exit("plot_optimize.py: %s/optimum.toml has no header of flapsim optimize" % folder)
    keys = []
    for line in open(os.path.join(folder, "report.md")):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 5 and cells[0].startswith("`") and cells[0] != "`key`":
            keys.append((cells[0].strip("`"), float(cells[1]), float(cells[2]), float(cells[3])))
    return m.group(1), m.group(2), keys


def save(fig, out, name):
    fig.tight_layout()
    for ext in ("png", "pdf"):
        fig.savefig(os.path.join(out, name + "." + ext), dpi=200)
    plt.close(fig)


def last_cycle(history_csv, frequency_hz, cycles):
    rows = read_csv(history_csv)
    start = (cycles - 1) / frequency_hz
    t = [number(r["t_s"]) for r in rows]
    keep = [i for i, ti in enumerate(t) if ti >= start - 1e-12]
    return [(t[i] - start) * frequency_hz for i in keep], [number(rows[i]["lift_N"]) for i in keep]


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(argv) >= 2 else 1
    folder = argv[1]
    for name in ("optimum.toml", "report.md", "evaluations.csv"):
        if not os.path.isfile(os.path.join(folder, name)):
            print("plot_optimize.py: %s has no %s: not a flapsim optimize folder" % (folder, name), file=sys.stderr)
            return 2
    out = argv[2] if len(argv) > 2 else os.path.join(folder, "plots")
    os.makedirs(out, exist_ok=True)
    objective, optimum_hash, keys = problem(folder)
    rows = read_csv(os.path.join(folder, "evaluations.csv"))
    rows.sort(key=lambda r: int(r["evaluation"]))
    ok = [r for r in rows if r["status"] == "ok"]
    n = [int(r["evaluation"]) for r in ok]
    values = [number(r[objective]) for r in ok]

    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(n, values, "o", label=objective)
    best, so_far = -math.inf, []
    for v in values:
        best = max(best, v)
        so_far.append(best)
    ax.step(n, so_far, where="post", label="best so far")
    ax.set_xlabel("evaluation")
    ax.set_ylabel(objective)
    ax.legend()
    save(fig, out, "optimize_objective")

    optimum = next(r for r in rows if r["inputs_hash"] == optimum_hash)
    start_values = [k[3] for k in keys]

    def is_start(r):
        return all(abs(number(r[k[0]]) - k[3]) <= 1e-9 * max(1.0, abs(k[3])) for k in keys)

    start = next((r for r in rows if is_start(r)), rows[0])
    fig, ax = plt.subplots(figsize=(6, 4))
    if len(keys) == 1:
        name, lo, hi, _ = keys[0]
        ax.plot([int(r["evaluation"]) for r in rows], [number(r[name]) for r in rows], "o-")
        ax.axhline(number(optimum[name]), color="C3", ls="--", label="optimum")
        ax.axhline(start_values[0], color="C2", ls=":", label="start")
        ax.set_xlabel("evaluation")
        ax.set_ylabel(name)
        ax.set_ylim(lo, hi)
    else:
        (kx, xlo, xhi, _), (ky, ylo, yhi, _) = keys[0], keys[1]
        ax.plot([number(r[kx]) for r in rows], [number(r[ky]) for r in rows], "o-", ms=4)
        ax.plot(number(start[kx]), number(start[ky]), "s", color="C2", label="start")
        ax.plot(number(optimum[kx]), number(optimum[ky]), "*", color="C3", ms=14, label="optimum")
        ax.set_xlim(xlo, xhi)
        ax.set_ylim(ylo, yhi)
        ax.set_xlabel(kx)
        ax.set_ylabel(ky)
    ax.legend()
    save(fig, out, "optimize_path")

    fig, ax = plt.subplots(figsize=(6, 4))
    for r, label in ((start, "start"), (optimum, "optimum")):
        history = os.path.join(folder, "runs", r["inputs_hash"], "history.csv")
        if os.path.exists(history):
            s, lift = last_cycle(history, number(r["frequency_hz"]), int(r["cycles"]))
            ax.plot(s, lift, label="%s (mean %s N)" % (label, r["mean_lift_N"][:8]))
    ax.set_xlabel("phase in the last cycle, t f")
    ax.set_ylabel("lift [N]")
    ax.legend()
    save(fig, out, "optimize_lift_cycle")
    print("plots in %s" % out)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
