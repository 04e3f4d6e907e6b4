"""Figures of `make reproduce` (tools/reproduce.py), drawn like the rotation-phase paper's:
lift over the last wingbeat for dpsi = -0.15 / -0.10 / +0.05 (RP Figs. 12b, 13b), base
against tip Euler angles at dpsi = -0.05 / +0.05 (Fig. 14), the tip's rotation phase against
the base's (Fig. 15, both definitions), and eq. 7's CL over a cycle per leading-edge model.
PDF and PNG of each, written through a temporary name and renamed (matplotlib, Agg).
Time axes: t/T from the start of the run's last whole wingbeat (t_end - T).
"""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import reproduce_runs as rr  # noqa: E402
import rotation_phase  # noqa: E402

MODELS = ("none", "separated", "shed")
COLORS = {-0.15: "tab:blue", -0.10: "tab:orange", -0.05: "tab:purple", 0.0: "tab:gray", 0.05: "tab:green",
          0.10: "tab:red"}


def last_wingbeat(plan, key, columns):
    """(t/T, {column: values}) over the last whole wingbeat of a run that finished, else None."""
    r = plan.runs.get(key)
    s = r.summary() if r else None
    if not s or s.get("status") != "ok":
        return None
    h = rr.read_history(r.folder, ["t_s"] + columns)
    f = s["frequency_hz"]
    idx = rr.last_cycle(h, f)
    t0 = h["t_s"][-1] - 1.0 / f
    return [(h["t_s"][k] - t0) * f for k in idx], {c: [h[c][k] for k in idx] for c in columns}


def save(fig, folder, name):
    fig.tight_layout()
    os.makedirs(folder, exist_ok=True)
    for ext in ("pdf", "png"):
        path = os.path.join(folder, "%s.%s" % (name, ext))
        tmp = "%s.tmp.%d.%s" % (path, os.getpid(), ext)
        fig.savefig(tmp, format=ext, dpi=130 if ext == "png" else None)
        os.replace(tmp, path)
    plt.close(fig)


def stopped(ax, text):
    ax.text(0.5, 0.5, text, ha="center", va="center", transform=ax.transAxes, fontsize=8, wrap=True)


def lift_cycle(plan, folder, name):
    rows = (("rigid", "rigid:%s:%+.2f", plan.s["rigid"]), ("flexible, 33.8 mg", "flex:mb:%s:%+.2f", plan.s["flexible"]),
            ("flexible, 43.4 mg", "flex:rp:%s:%+.2f", plan.s["flexible"]))
    fig, axes = plt.subplots(len(rows), len(MODELS), figsize=(12, 9), sharex=True, squeeze=False)
    for i, (label, pattern, grid) in enumerate(rows):
        for j, m in enumerate(MODELS):
            ax = axes[i][j]
            drawn = 0
            for d in (-0.15, -0.10, 0.05):
                if d not in grid:
                    continue
                w = last_wingbeat(plan, pattern % (m, d), ["lift_N"])
                if w:
                    ax.plot(w[0], [v * 1e3 for v in w[1]["lift_N"]], color=COLORS[d], label="δψ = %+.2f" % d)
                    drawn += 1
            if not drawn:
                stopped(ax, "no run of this model finished\n(where each stops: the tables)")
            ax.set_title("%s, leading edge `%s`" % (label, m), fontsize=9)
            ax.axhline(0, color="k", lw=0.5)
            if j == 0:
                ax.set_ylabel("lift [mN]")
            if i == len(rows) - 1:
                ax.set_xlabel("t/T of the last wingbeat")
            if drawn:
                ax.legend(fontsize=7)
    fig.suptitle("Lift over the last wingbeat (RP Figs. 12b, 13b); flexible studies have no δψ = −0.15", fontsize=10)
    save(fig, folder, name)
    return name, "Lift over the last wingbeat for δψ = −0.15 / −0.10 / +0.05, each leading-edge model (RP Figs. 12b, 13b)"


def euler_angles(plan, folder, name):
    fig, axes = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
    cols = ["phi_base_deg", "alpha_base_deg", "phi_tip_deg", "alpha_tip_deg"]
    for j, d in enumerate((-0.05, 0.05)):
        for w, style, label in (("mb", "--", "tip, 33.8 mg"), ("rp", ":", "tip, 43.4 mg")):
            r = last_wingbeat(plan, "flex:%s:separated:%+.2f" % (w, d), cols)
            if not r:
                continue
            t, v = r
            if w == "mb":
                axes[0][j].plot(t, v["phi_base_deg"], "k-", label="base")
                axes[1][j].plot(t, v["alpha_base_deg"], "k-", label="base")
            axes[0][j].plot(t, v["phi_tip_deg"], style, color="tab:red", label=label)
            axes[1][j].plot(t, v["alpha_tip_deg"], style, color="tab:blue", label=label)
        axes[0][j].set_title("δψ = %+.2f, flexible wing, `separated`" % d, fontsize=9)
        axes[0][j].set_ylabel("sweep φ [°]")
        axes[1][j].set_ylabel("rotation α [°]")
        axes[1][j].axhline(90, color="k", lw=0.5)
        axes[1][j].set_xlabel("t/T of the last wingbeat")
        for ax in (axes[0][j], axes[1][j]):
            ax.legend(fontsize=7)
    fig.suptitle("Base and tip Euler angles (RP Fig. 14)", fontsize=10)
    save(fig, folder, name)
    return name, "Base and tip Euler angles of the flexible wing at δψ = −0.05 and +0.05 (RP Fig. 14)"


def tip_phase(plan, folder, name):
    fig, ax = plt.subplots(figsize=(7, 5))
    grid = plan.s["flexible"]
    ax.plot(grid, grid, "k-", lw=0.8, label="base (tip = base)")
    ax.plot([-0.10, 0.10], [-0.15, -0.03], "ks", ms=8, label="paper (Fig. 15 text)")
    styles = {("mb", "none"): "tab:blue", ("mb", "separated"): "tab:orange", ("rp", "separated"): "tab:green",
              ("rp", "none"): "tab:cyan"}
    for (w, m), color in styles.items():
        pts = []
        for d in grid:
            try:
                pts.append((d, rotation_phase.run_phases(plan.runs["flex:%s:%s:%+.2f" % (w, m, d)].folder, "tip")))
            except (rotation_phase.PhaseError, KeyError):
                pass
        if pts:
            label = "%s, `%s`" % ("33.8 mg" if w == "mb" else "43.4 mg", m)
            ax.plot([d for d, _ in pts], [p["rp_phase"] for _, p in pts], "o-", color=color, label=label + ", RP def.")
            ax.plot([d for d, _ in pts], [p["own_phase"] for _, p in pts], "x--", color=color,
                    label=label + ", own reversal")
    ax.set_xlabel("rotation phase at the base δψ [period]")
    ax.set_ylabel("rotation phase at the tip [period]")
    ax.legend(fontsize=7)
    ax.set_title("Tip against base rotation phase (RP Fig. 15)", fontsize=10)
    save(fig, folder, name)
    return name, ("Rotation phase at the tip against the base (RP Fig. 15): RP def. = tip crossing minus the base's "
                  "reversal (same cycle), own reversal = summary.json's tip_rotation_phase")


def lua_cl(plan, folder, name):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for m, color in zip(MODELS, ("tab:blue", "tab:orange", "tab:green")):
        w = last_wingbeat(plan, "lua:%s" % m, ["CL"])
        if w:
            ax.plot(w[0], w[1]["CL"], color=color, label="`%s`" % m)
    ax.axhline(2.06, color="k", ls="--", lw=0.8, label="RP mean 2.06")
    ax.axhline(2.08, color="k", ls=":", lw=0.8, label="measured mean 2.08")
    ax.set_xlabel("t/T of the last wingbeat")
    ax.set_ylabel("CL (U: cycle-mean speed at r2)")
    ax.set_title("Eq. 7 (Lua et al.'s kinematics), rigid wing", fontsize=10)
    ax.legend(fontsize=7)
    save(fig, folder, name)
    return name, "CL over the last wingbeat of eq. 7's rigid wing, each leading-edge model, with RP's and the measured means"


def write_figures(plan, folder, prefix):
    return [lift_cycle(plan, folder, prefix + "lift_cycle"), euler_angles(plan, folder, prefix + "euler_angles"),
            tip_phase(plan, folder, prefix + "tip_phase"), lua_cl(plan, folder, prefix + "lua_cl")]
