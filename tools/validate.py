#!/usr/bin/python3
"""`make validate`: every validation case of flapsim with its reference value and what
flapsim computes, as one table.

 1. the verification and validation tests of each module (GoogleTest executables in
    BUILD/tests/<module>/, run with a filter); each asserts its numbers against the
    reference written next to it, so the table shows the reference and PASS/FAIL;
 2. the rotation-phase study (outputs of `make phase-study`): the phase of maximum mean
    lift of the rigid and of the flexible wing, and the rotation phase at the tip;
 3. the hawkmoth-like wing with eq. 7 kinematics (cases/lua_rigid.toml) through the
    coupled path: its last-cycle mean CL against 2.06 (paper) and 2.08 (Lua et al.).

Usage: validate.py --build BUILD --out OUT
"""
import argparse
import csv
import json
import os
import subprocess
import sys

TESTS = [
    # (module, gtest filter, what, reference)
    ("uvlm", "SteadyWing.*", "flat wing AR 4 at 5 deg; CL_alpha for AR 1..10", "CL 0.316; 1.54/2.54/4.24/4.86 per rad"),
    ("uvlm", "ImpulsiveStart.*", "impulsive start AR 4; very high AR", "CL/CL_ss 0.88/0.93/0.98; Wagner (Jones) 2 %"),
    ("mbd", "SimbodyThreeBody.*", "3-body chain of the rotation-phase paper", "Simbody, 0.5 % of amplitude"),
    ("mbd", "ChainEnergy.*", "energy balance, eigenfrequencies", "1e-6 relative; eig(K, M)"),
    ("mbd", "HenckyCantilever.*", "Hencky chain 4/8/16 bodies", "-3.9/-1.0/-0.25 % first mode"),
    ("fem", "*CantileverPlate*", "square cantilever plate (Leissa)", "3.492 8.525 21.43 27.33 31.11"),
    ("fem", "SquarePlateUniformLoad.*", "uniform-load square plates", "0.00406 / 0.00126 qa^4/D"),
    ("fem", "ShellBenchmarks.*", "Scordelis-Lo roof, twisted beam", "0.3024; 0.005424/0.001754"),
    ("fem", "CantileverBeam.*", "cantilever beam frequencies", "beta L 1.8751 4.6941 7.8548"),
    ("reduction", "*", "plate strip EI, GJ, elastic axis, strip masses", "2 %, 1 % chord, round-off"),
    ("fsi", "Fsi*", "FSI: load transfer, rigid = lattice, stiff chain = rigid", "round-off; round-off; 0.5 %"),
]


def run_tests(build):
    rows = []
    for module, pattern, what, ref in TESTS:
        exe = os.path.join(build, "tests", module, "test_" + module)
        if not os.path.exists(exe):
            rows.append((what, ref, "(test_%s not built)" % module, "-"))
            continue
        p = subprocess.run([exe, "--gtest_filter=" + pattern, "--gtest_brief=1"],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        passed = [l for l in p.stdout.splitlines() if "PASSED" in l]
        count = passed[0].split("]")[1].strip() if passed else ""
        ran = bool(passed) and not count.startswith("0 ")
        status = "FAIL" if p.returncode != 0 else ("PASS" if ran else "NO TESTS")
        rows.append((what, ref, "test_%s %s %s" % (module, pattern, count), status))
    return rows


def read_sweep(path):
    with open(path) as f:
        rows = [r for r in csv.DictReader(f)]
    key = list(rows[0].keys())[0]
    return sorted(({"v": float(r[key]), "lift": float(r["mean_lift_N"]), "phase": float(r["tip_rotation_phase"]),
                    "lag": float(r["tip_rotation_lag"]), "outer": float(r.get("outer_rotation_phase", "nan")),
                    "outer_lag": float(r.get("outer_rotation_lag", "nan")), "ok": r["status"] == "ok"} for r in rows),
                  key=lambda r: r["v"])


def argmax_phase(rows):
    ok = [r for r in rows if r["ok"]]
    if not ok:
        return float("nan"), float("nan")
    best = max(range(len(ok)), key=lambda i: ok[i]["lift"])
    refined = ok[best]["v"]
    if 0 < best < len(ok) - 1:  # vertex of the parabola through the three best points
        x = [ok[best + k]["v"] for k in (-1, 0, 1)]
        y = [ok[best + k]["lift"] for k in (-1, 0, 1)]
        den = (x[0] - x[1]) * (x[0] - x[2]) * (x[1] - x[2])
        a = (x[2] * (y[1] - y[0]) + x[1] * (y[0] - y[2]) + x[0] * (y[2] - y[1])) / den
        b = (x[2] ** 2 * (y[0] - y[1]) + x[1] ** 2 * (y[2] - y[0]) + x[0] ** 2 * (y[1] - y[2])) / den
        if a < 0:
            refined = -b / (2 * a)
    return ok[best]["v"], refined


def phase_rows(out):
    rows = []
    study = os.path.join(out, "phase_study")
    try:
        rigid = read_sweep(os.path.join(study, "rigid", "sweep.csv"))
        flexible = read_sweep(os.path.join(study, "flexible", "sweep.csv"))
    except (OSError, IndexError):
        return [("rotation-phase study", "", "(run make phase-study)", "-")]
    g, r = argmax_phase(rigid)
    rows.append(("rigid wing: dpsi of max mean lift", "-10 % (paper Fig. 12a)",
                 "%+.0f %% (grid), %+.1f %% (parabola)" % (100 * g, 100 * r), "%+.1f %%" % (100 * (g + 0.10))))
    g, r = argmax_phase(flexible)
    rows.append(("flexible wing: dpsi of max mean lift", "+5...7 % (paper Fig. 13a)",
                 "%+.0f %% (grid), %+.1f %% (parabola)" % (100 * g, 100 * r),
                 "%+.1f %%" % (100 * (g - 0.06))))
    paper_tip = {-0.10: -0.15, 0.10: -0.03}
    for rr in flexible:
        if not rr["ok"]:
            continue
        ref = paper_tip.get(round(rr["v"], 2))
        rows.append(("flexible, dpsi %+.0f %%: rotation phase tip; outer body (lag vs base)" % (100 * rr["v"]),
                     ("tip %+.0f %% (paper Fig. 15)" % (100 * ref)) if ref is not None else "-",
                     "%+.1f %% (%+.1f %%); %+.1f %% (%+.1f %%)" % (100 * rr["phase"], 100 * rr["lag"],
                                                            100 * rr["outer"], 100 * rr["outer_lag"]), "-"))
    return rows


def lua_row(build, out):
    case = "cases/lua_rigid.toml"
    if not os.path.exists(case):
        return []
    dest = os.path.join(out, "validate", "lua_rigid")
    p = subprocess.run([os.path.join(build, "flapsim"), "run", case, "-o", dest, "--vtk-every", "0", "-q"],
                       env=dict(os.environ, OMP_NUM_THREADS="1"))
    if p.returncode != 0:
        return [("eq. 7 hawkmoth-like wing, rigid: mean CL", "2.06 sim. / 2.08 exp.", "run failed (%d)" % p.returncode, "-")]
    with open(os.path.join(dest, "summary.json")) as f:
        s = json.load(f)
    cl = s["mean_CL"]
    return [("eq. 7 hawkmoth-like wing, rigid: mean CL", "2.06 sim. / 2.08 exp. (Lua et al.)",
             "%.3f" % cl, "%+.1f %%" % (100 * (cl / 2.06 - 1)))]


def reduction_row(out):
    """Hawkmoth chain vs FEM from `make hawkmoth-model` (out/hawkmoth/summary.json)."""
    path = os.path.join(out, "hawkmoth", "summary.json")
    if not os.path.exists(path):
        return [("hawkmoth chain vs FEM", "5 % (issue 7)", "(run make hawkmoth-model)", "-")]
    with open(path) as f:
        s = json.load(f)
    errs = [s["bending_relative_error"], s["torsion_relative_error"], s["tip_deflection_relative_error"]]
    return [("hawkmoth chain vs FEM (%d bodies): bending, torsion, tip deflection" % s["num_bodies"],
             "within 5 % (issue 7)", " / ".join("%+.1f %%" % (100 * e) for e in errs),
             "met" if all(abs(e) <= 0.05 for e in errs) else "NOT MET")]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="out")
    a = ap.parse_args()
    rows = run_tests(a.build) + reduction_row(a.out) + phase_rows(a.out) + lua_row(a.build, a.out)
    head = ("case", "reference", "computed", "status / difference")
    widths = [max(len(str(r[i])) for r in rows + [head]) for i in range(4)]
    line = "  ".join("%-*s" % (widths[i], head[i]) for i in range(4))
    print(line)
    print("-" * len(line))
    for r in rows:
        print("  ".join("%-*s" % (widths[i], r[i]) for i in range(4)))
    sys.exit(1 if any(r[3] == "FAIL" for r in rows) else 0)


if __name__ == "__main__":
    main()
