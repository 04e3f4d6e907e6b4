#!/usr/bin/python3
"""Figures of the rotation-phase study (the rotation-phase paper's Figs. 12-15) from the
outputs of `make phase-study`:

  fig12a_mean_lift_vs_phase.png   mean lift against the rotation phase, rigid and flexible
  fig12b_rigid_lift_cycle.png     lift over the last cycle, rigid wing, three phases
  fig13b_flexible_lift_cycle.png  lift over the last cycle, flexible wing, three phases
  fig14_euler_angles.png          base, tip and outer-body Euler angles of the flexible wing (dpsi = -0.05, +0.05)
  fig15_tip_base_phase.png        tip rotation phase and tip-minus-base rotation lag

Usage: plot_phase_study.py PHASE_STUDY_DIR OUTPUT_DIR   (Debian's python3-matplotlib)
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


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


def last_cycle(h, frequency=26.1):
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


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    study, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    rigid = read_sweep(os.path.join(study, "rigid", "sweep.csv"))
    flexible = read_sweep(os.path.join(study, "flexible", "sweep.csv"))
    written = []

    # Fig. 12a / 13a: mean lift against the rotation phase.
    fig, ax = plt.subplots(figsize=(6, 4))
    for rows, label, marker in ((rigid, "rigid", "o"), (flexible, "flexible", "s")):
        ok = [r for r in rows if r["status"] == "ok"]
        ax.plot([100 * r["value"] for r in ok], [1e3 * r["lift"] for r in ok], marker=marker, label=label)
    ax.axvline(-10, color="C0", ls=":", lw=1, label="paper: rigid max (-10 %)")
    ax.axvspan(5, 7, color="C1", alpha=0.15, label="paper: flexible max (+5...7 %)")
    ax.set_xlabel("rotation phase δψ [% of the period]")
    ax.set_ylabel("mean lift, last cycle [mN]")
    ax.set_title("Mean lift against rotation phase (hawkmoth, 26.1 Hz)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    written.append(os.path.join(out, "fig12a_mean_lift_vs_phase.png"))
    fig.savefig(written[-1], dpi=120)
    plt.close(fig)

    # Fig. 12b / 13b: lift over the last cycle for three phases.
    for rows, values, name, title in (
            (rigid, (-0.15, -0.10, 0.05), "fig12b_rigid_lift_cycle.png", "rigid wing"),
            (flexible, (-0.10, 0.0, 0.10), "fig13b_flexible_lift_cycle.png", "flexible wing")):
        fig, ax = plt.subplots(figsize=(6, 4))
        for v in values:
            r = pick(rows, v)
            if r is None:
                continue
            h = read_history(os.path.join(case_dir(os.path.join(study, "rigid" if rows is rigid else "flexible"), r),
                                          "history.csv"))
            keep, s = last_cycle(h)
            ax.plot(s, 1e3 * h["lift_N"][keep], label="δψ = %+.0f %%" % (100 * v))
        ax.set_xlabel("t / T (last cycle)")
        ax.set_ylabel("lift [mN]")
        ax.set_title("Lift over a cycle, " + title)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        written.append(os.path.join(out, name))
        fig.savefig(written[-1], dpi=120)
        plt.close(fig)

    # Fig. 14: base and tip Euler angles of the flexible wing.
    fig, axes = plt.subplots(1, 2, figsize=(10, 4), sharey=True)
    for ax, v in zip(axes, (-0.05, 0.05)):
        r = pick(flexible, v)
        if r is None:
            continue
        h = read_history(os.path.join(study, "flexible", r["folder"], "history.csv"))
        keep, s = last_cycle(h)
        for col, label, style in (("phi_base_deg", "φ_b", "C0-"), ("phi_tip_deg", "φ_t", "C0--"),
                                  ("alpha_base_deg", "α_b", "C1-"), ("alpha_tip_deg", "α_t", "C1--"),
                                  ("phi_outer_deg", "φ outer", "C0:"), ("alpha_outer_deg", "α outer", "C1:"),
                                  ("theta_tip_deg", "θ_t", "C2--")):
            y = h[col][keep]
            if col.startswith("alpha"):  # a twisting tip may pass ±180°: draw it continuous
                y = np.degrees(np.unwrap(np.radians(y)))
            ax.plot(s, y, style, label=label)
        ax.set_title("flexible wing, δψ = %+.0f %%" % (100 * v))
        ax.set_xlabel("t / T (last cycle)")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("angle [deg]")
    axes[0].legend(fontsize=8, ncol=2)
    fig.tight_layout()
    written.append(os.path.join(out, "fig14_euler_angles.png"))
    fig.savefig(written[-1], dpi=120)
    plt.close(fig)

    # Fig. 15: rotation phase at the tip against the base.
    fig, ax = plt.subplots(figsize=(6, 4))
    ok = [r for r in flexible if r["status"] == "ok"]
    x = [100 * r["value"] for r in ok]
    ax.plot(x, x, "k:", label="base (= δψ)")
    ax.plot(x, [100 * r["tip_phase"] for r in ok], "s-", label="tip rotation phase (α_t = 90° vs φ_t reversal)")
    ax.plot(x, [100 * r["tip_lag"] for r in ok], "o--", label="tip − base α = 90° crossing")
    ax.plot(x, [100 * r["outer_phase"] for r in ok], "^-", label="outer body (5/6 span) rotation phase")
    ax.plot(x, [100 * r["outer_lag"] for r in ok], "v--", label="outer − base α = 90° crossing")
    ax.plot([-10, 10], [-15, -3], "x", color="C3", ms=9, label="paper: tip phase at δψ = ∓10 %")
    ax.set_xlabel("base rotation phase δψ [%]")
    ax.set_ylabel("[% of the period]")
    ax.set_title("Rotation phase at the tip, flexible wing")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    written.append(os.path.join(out, "fig15_tip_base_phase.png"))
    fig.savefig(written[-1], dpi=120)
    plt.close(fig)

    for w in written:
        print("wrote", w)


if __name__ == "__main__":
    main()
