#!/usr/bin/python3
"""Figures of any flapsim sweep (docs/sweeps.md, "Plotting a sweep"): for each varied key
of a sweep.csv, the mean lift against that key — and the mean aerodynamic power, when the
table has a power column — with one line per combination of the other varied keys.

  sweep_<key>.png, sweep_<key>.pdf   one figure per varied key (PNG 200 dpi, PDF vector)

The varied keys are the leading columns of sweep.csv: case keys and wing keys are dotted
(kinematics.rotation_phase, wing.membrane.thickness), spring_scale and wing (the wing
files, named on the axis by their file names); result columns are not. Cases whose status is not "ok" are left out (and counted on the figure).

Usage: plot_sweep.py SWEEP.csv [OUTPUT_DIR]   (default OUTPUT_DIR: plots/ next to SWEEP.csv;
Debian's python3-matplotlib)
"""
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from si_prefix import si_scale  # noqa: E402


def varied_keys(header):
    keys = []
    for name in header:
        if "." in name or name in ("spring_scale", "wing"):
            keys.append(name)
        else:
            break
    return keys


def power_column(header):
    # The mean aerodynamic power, once the results have it (a column such as mean_power_W).
    for name in header:
        if name.startswith("mean_") and "power" in name:
            return name
    return None


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def order(text):
    """Sort key of a cell: numbers by value, then words (a text key's values: none, shed) by name."""
    x = number(text)
    return (1, 0.0, text) if math.isnan(x) else (0, x, "")


def label(name):
    return name.rsplit(".", 1)[-1].replace("_", " ")


# Axis names of the keys users sweep most, with the factor from the file's value to the axis:
# the rotation phase in % of the period, as the phase-study figures show it.
AXES = {
    "kinematics.rotation_phase": ("rotation phase δψ [% of the period]", 100.0),
    "kinematics.frequency_hz": ("wingbeat frequency [Hz]", 1.0),
    "spring_scale": ("joint spring factor [-]", 1.0),
    "wing": ("wing", 1.0),
}


def tick(key, value):
    """A value as the axis names it: a wing file by its name (wings/hawkmoth.toml: hawkmoth)."""
    return os.path.splitext(os.path.basename(value))[0] if key == "wing" else value


def axis(key):
    return AXES.get(key, (key, 1.0))


def run_title(table, rows):
    """The case and its structure (rigid wing, chain file, ...) from the cases' summary.json: one
    structure if every case has it, else each (a sweep of structure.kind: rigid, chain, fem),
    in the order of the table; the first case's alone named every case's structure before."""
    case, structures = None, []
    for r in rows:
        try:
            with open(os.path.join(os.path.dirname(os.path.abspath(table)), r["folder"], "summary.json")) as f:
                s = json.load(f)
        except (OSError, KeyError, ValueError):
            continue
        case = case or s.get("case", "?")
        structure = s.get("structure", "?")
        if structure not in structures:
            structures.append(structure)
    if case is None:
        return ""
    return "%s: %s" % (case, structures[0] if len(structures) == 1 else "structures " + ", ".join(structures))


def plot_key(rows, key, others, power, out_path, failed, title_text=""):
    lift_scale, lift_unit = si_scale([number(r["mean_lift_N"]) for r in rows], "N")
    panels = [("mean_lift_N", "mean lift [%s]" % lift_unit, lift_scale)]
    if power:
        unit = power.rsplit("_", 1)[-1] if "_" in power else ""
        scale, shown = si_scale([number(r[power]) for r in rows], unit) if unit == "W" else (1.0, unit)
        panels.append((power, "mean power [%s]" % shown, scale))
    fig, axes = plt.subplots(len(panels), 1, figsize=(6.0, 3.2 * len(panels)), sharex=True, squeeze=False)
    groups = {}
    for r in rows:
        groups.setdefault(tuple(r[o] for o in others), []).append(r)
    # A key of words (numerics.leading_edge = none, separated, shed) is drawn at evenly spaced
    # positions in the order the sweep gave them, each named on the axis.
    words = [v for v in dict.fromkeys(r[key] for r in rows) if math.isnan(number(v))]
    position = {v: i for i, v in enumerate(dict.fromkeys(r[key] for r in rows))} if words else {}
    for (column, title, scale), ax in zip(panels, axes[:, 0]):
        for group, members in sorted(groups.items(), key=lambda g: tuple(order(v) for v in g[0])):
            if position:
                members = sorted(members, key=lambda r: position[r[key]])
                x = [position[r[key]] for r in members]
            else:
                members = sorted(members, key=lambda r: number(r[key]))
                x = [number(r[key]) * axis(key)[1] for r in members]
            y = [number(r[column]) * scale for r in members]
            name = ", ".join("%s = %s" % (label(o), tick(o, v)) for o, v in zip(others, group))
            ax.plot(x, y, "o-", ms=4, label=name or None)
        ax.set_ylabel(title)
        ax.grid(True, alpha=0.3)
        if others and len(groups) <= 12:
            ax.legend(fontsize=7)
    if position:
        axes[-1, 0].set_xticks(list(position.values()), [tick(key, v) for v in position.keys()])
    axes[-1, 0].set_xlabel(axis(key)[0])
    heading = [t for t in (title_text, "%d case(s) not ok, left out" % failed if failed else "") if t]
    if heading:
        axes[0, 0].set_title("\n".join(heading), fontsize=8)
    fig.tight_layout()
    fig.savefig(out_path, dpi=200)
    fig.savefig(os.path.splitext(out_path)[0] + ".pdf")
    plt.close(fig)


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(argv) >= 2 else 1
    table = argv[1]
    out_dir = argv[2] if len(argv) > 2 else os.path.join(os.path.dirname(os.path.abspath(table)), "plots")
    with open(table, newline="") as f:
        reader = csv.DictReader(f)
        header = reader.fieldnames or []
        all_rows = list(reader)
    keys = varied_keys(header)
    if not keys or "mean_lift_N" not in header:
        print("plot_sweep: %s is not a flapsim sweep.csv (no varied key or no mean_lift_N)" % table, file=sys.stderr)
        return 2
    rows = [r for r in all_rows if r.get("status", "ok") == "ok"]
    failed = len(all_rows) - len(rows)
    power = power_column(header)
    os.makedirs(out_dir, exist_ok=True)
    for key in keys:
        others = [k for k in keys if k != key]
        path = os.path.join(out_dir, "sweep_%s.png" % key.replace(".", "_"))
        plot_key(rows, key, others, power, path, failed, run_title(table, rows))
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
