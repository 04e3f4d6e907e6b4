#!/usr/bin/python3
"""Figures of the rotation-phase study (the rotation-phase paper's Figs. 12-15) from the
outputs of `make phase-study`, each as PDF (vector, for papers) and PNG (200 dpi), with
the numbers it draws beside it as CSV (one row per point: panel, series, x, y):

  fig12a_mean_lift_vs_phase       mean lift against the rotation phase, rigid and flexible
  fig12b_rigid_lift_cycle         lift over the last cycle, rigid wing, three phases
  fig13b_flexible_lift_cycle      lift over the last cycle, flexible wing, three phases
  fig14_euler_angles              base, tip and outer-body Euler angles of the flexible wing (dpsi = -0.05, +0.05)
  fig15_tip_base_phase            tip rotation phase and tip-minus-base rotation lag

Time axes are t/T of the last computed wingbeat: t = 0 is the start of the run, where the
kinematics are at phase 0 (eq. 8: phi = 10 deg + 50 deg cos 2 pi (f t + dpsi)), so the
base downstroke (phi decreasing) is 0 < t/T + dpsi < 0.5; it is shaded grey.

Usage: plot_phase_study.py PHASE_STUDY_DIR OUTPUT_DIR [--prefix P]   (Debian's python3-matplotlib)
"""
import argparse
import csv
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

plt.rcParams.update({"font.size": 10, "axes.titlesize": 10, "legend.fontsize": 8,
                     "savefig.bbox": "tight", "pdf.fonttype": 42})


def read_sweep(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    key = list(rows[0].keys())[0] if rows else "value"
    out = []
    for r in rows:
        out.append({"value": float(r[key]), "lift": float(r["mean_lift_N"]), "cl": float(r["mean_CL"]),
                    "tip_phase": float(r["tip_rotation_phase"]), "tip_lag": float(r["tip_rotation_lag"]),
                    "outer_phase": float(r.get("outer_rotation_phase", "nan")),
                    "outer_lag": float(r.get("outer_rotation_lag", "nan")),
                    "folder": r["folder"], "status": r["status"]})
    return sorted(out, key=lambda r: r["value"])


def read_history(path):
    data = np.genfromtxt(path, delimiter=",", names=True)
    return data


def case_frequency(folder):
    """The case's flapping frequency [Hz] from its summary.json (the study's cases run at
    26.1 Hz; a study of cases edited to another frequency cut the wrong wingbeat)."""
    with open(os.path.join(folder, "summary.json")) as f:
        return float(json.load(f)["frequency_hz"])


def last_cycle(h, frequency):
    t = h["t_s"]
    period = 1.0 / frequency
    keep = t >= t[-1] - period - 1e-12
    return keep, (t[keep] - (t[-1] - period)) / period


def case_dir(study, row):
    return os.path.join(study, row["folder"])


def pick(rows, value):
    for r in rows:
        if abs(r["value"] - value) < 1e-9 and r["status"] == "ok":
            return r
    return None


def shade_strokes(ax, dpsi=0.0):
    """Grey band over the base downstroke (0 < t/T + dpsi < 0.5 modulo 1) of a last-cycle axis."""
    start = (-dpsi) % 1.0
    for lo in (start - 1.0, start):
        ax.axvspan(max(lo, 0.0), min(lo + 0.5, 1.0), color="0.9", zorder=0, lw=0)
    ax.set_xlim(0.0, 1.0)


def legend_below(ax, ncol=3):
    """The legend under the axes, where it hides no data."""
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=ncol, frameon=False)


def save_plotted_data(fig, path):
    """The points of every labelled line of the figure: what a reader can re-plot or check."""
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["panel", "series", "x", "y"])
        for i, ax in enumerate(fig.axes):
            for line in ax.get_lines():
                label = line.get_label()
                if label.startswith("_"):  # unlabelled helpers (axis lines, shading edges)
                    continue
                for x, y in zip(np.asarray(line.get_xdata(), float), np.asarray(line.get_ydata(), float)):
                    w.writerow([i, label, repr(float(x)), repr(float(y))])


def save(fig, out, prefix, name, written):
    for ext, kw in (("pdf", {}), ("png", {"dpi": 200})):
        path = os.path.join(out, f"{prefix}{name}.{ext}")
        fig.savefig(path, **kw)
        written.append(path)
    data = os.path.join(out, f"{prefix}{name}.csv")
    save_plotted_data(fig, data)
    written.append(data)
    plt.close(fig)


T_LABEL = "t/T, last wingbeat (t = 0: run start; grey: downstroke)"


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("study")
    p.add_argument("out")
    p.add_argument("--prefix", default="", help="prefix of the file names (docs/figures: phase_)")
    a = p.parse_args()
    study, out, prefix = a.study, a.out, a.prefix
    os.makedirs(out, exist_ok=True)
    rigid = read_sweep(os.path.join(study, "rigid", "sweep.csv"))
    flexible = read_sweep(os.path.join(study, "flexible", "sweep.csv"))
    written = []

    # Fig. 12a / 13a: mean lift against the rotation phase.
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    for rows, label, marker in ((rigid, "rigid wing", "o"), (flexible, "flexible wing", "s")):
        ok = [r for r in rows if r["status"] == "ok"]
        ax.plot([100 * r["value"] for r in ok], [1e3 * r["lift"] for r in ok], marker=marker, label=label, zorder=3)
    ax.axvline(-10, color="C0", ls=":", lw=1, label="paper: rigid maximum (δψ = −10 %)")
    ax.axvspan(5, 7, color="C1", alpha=0.15, label="paper: flexible maximum (δψ = +5 … 7 %)")
    ax.set_xlabel("rotation phase δψ [% of the period]")
    ax.set_ylabel("mean lift over the last wingbeat [mN]")
    some = [(sub, r) for sub, rows in (("rigid", rigid), ("flexible", flexible)) for r in rows if r["status"] == "ok"]
    hz = case_frequency(case_dir(os.path.join(study, some[0][0]), some[0][1])) if some else float("nan")
    ax.set_title("Mean lift against rotation phase (hawkmoth, %.3g Hz)" % hz)
    ax.grid(alpha=0.3)
    legend_below(ax, ncol=2)
    save(fig, out, prefix, "fig12a_mean_lift_vs_phase", written)

    # Fig. 12b / 13b: lift over the last cycle for three phases.
    for rows, sub, values, name, title in (
            (rigid, "rigid", (-0.15, -0.10, 0.05), "fig12b_rigid_lift_cycle", "rigid wing"),
            (flexible, "flexible", (-0.10, 0.0, 0.10), "fig13b_flexible_lift_cycle", "flexible wing")):
        fig, ax = plt.subplots(figsize=(6.5, 4.2))
        shade_strokes(ax)
        for v in values:
            r = pick(rows, v)
            if r is None:
                continue
            folder = case_dir(os.path.join(study, sub), r)
            h = read_history(os.path.join(folder, "history.csv"))
            keep, s = last_cycle(h, case_frequency(folder))
            ax.plot(s, 1e3 * h["lift_N"][keep], label="δψ = %+.0f %%" % (100 * v), zorder=3)
        ax.set_xlabel(T_LABEL + ", shown for δψ = 0")
        ax.set_ylabel("lift [mN]")
        ax.set_title("Lift over a wingbeat, " + title)
        ax.grid(alpha=0.3)
        legend_below(ax)
        save(fig, out, prefix, name, written)

    # Fig. 14: base and tip Euler angles of the flexible wing.
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.4), sharey=True)
    for ax, v in zip(axes, (-0.05, 0.05)):
        shade_strokes(ax, v)
        r = pick(flexible, v)
        if r is None:
            continue
        folder = os.path.join(study, "flexible", r["folder"])
        h = read_history(os.path.join(folder, "history.csv"))
        keep, s = last_cycle(h, case_frequency(folder))
        # Base and tip drawn bold; the outer body's thin dotted lines on top of them (drawn
        # beneath, they vanished wherever they ran along the tip's lines), thin enough to
        # leave the bold lines readable through their gaps.
        for col, label, style, lw, z in (
                ("phi_base_deg", r"$\varphi_\mathrm{base}$", "C0-", 2.0, 3),
                ("phi_tip_deg", r"$\varphi_\mathrm{tip}$", "C0--", 2.0, 4),
                ("alpha_base_deg", r"$\alpha_\mathrm{base}$", "C1-", 2.0, 3),
                ("alpha_tip_deg", r"$\alpha_\mathrm{tip}$", "C1--", 2.0, 4),
                ("theta_tip_deg", r"$\theta_\mathrm{tip}$", "C2--", 1.5, 4),
                ("phi_outer_deg", r"$\varphi_\mathrm{outer\ body}$", "C0:", 1.2, 5),
                ("alpha_outer_deg", r"$\alpha_\mathrm{outer\ body}$", "C1:", 1.2, 5)):
            if col not in h.dtype.names:
                continue
            y = h[col][keep]
            if col.startswith("alpha"):  # a twisting tip may pass ±180°: draw it continuous
                y = np.degrees(np.unwrap(np.radians(y)))
            ax.plot(s, y, style, label=label, lw=lw, zorder=z)
        ax.set_title("flexible wing, δψ = %+.0f %%" % (100 * v))
        ax.set_xlabel(T_LABEL)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("Euler angle [deg]")
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=7, frameon=False, bbox_to_anchor=(0.5, -0.06))
    save(fig, out, prefix, "fig14_euler_angles", written)

    # Fig. 15: rotation phase at the tip against the base.
    fig, ax = plt.subplots(figsize=(6.5, 4.6))
    ok = [r for r in flexible if r["status"] == "ok"]
    x = [100 * r["value"] for r in ok]
    ax.plot(x, x, "k:", label="base (= δψ)")
    ax.plot(x, [100 * r["tip_phase"] for r in ok], "s-", label="tip rotation phase (α = 90° vs φ reversal)", zorder=3)
    ax.plot(x, [100 * r["tip_lag"] for r in ok], "o--", label="tip − base lag of the α = 90° crossing", zorder=3)
    ax.plot(x, [100 * r["outer_phase"] for r in ok], "^-", lw=1, ms=4, label="outer body (5/6 span) rotation phase")
    ax.plot(x, [100 * r["outer_lag"] for r in ok], "v--", lw=1, ms=4, label="outer − base lag of the α = 90° crossing")
    ax.plot([-10, 10], [-15, -3], "x", color="C3", ms=9, label="paper: tip phase at δψ = ∓10 %")
    ax.set_xlabel("base rotation phase δψ [% of the period]")
    ax.set_ylabel("rotation phase or lag [% of the period]")
    ax.set_title("Rotation phase at the tip, flexible wing")
    ax.grid(alpha=0.3)
    legend_below(ax, ncol=2)
    save(fig, out, prefix, "fig15_tip_base_phase", written)

    for w in written:
        print("wrote", w)


if __name__ == "__main__":
    main()
