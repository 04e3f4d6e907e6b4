#!/usr/bin/python3
"""Convergence study of a case: `make convergence CASE=cases/x.toml` (docs/uvlm.md,
"Convergence study").

Runs the case at 3 or 4 lattice levels (chordwise x spanwise panels, each level the
last times a constant ratio r) and at 3 or 4 time-step levels (steps_per_cycle), each
study with the other resolution at the case's own, through `flapsim sweep --cases`
(so every level is checked as `flapsim run` checks it), and reports for each study the
mean lift of every level, the observed order of convergence from the last three,

    p = ln((f1 - f2) / (f2 - f3)) / ln r          (f3 the finest)

and the Richardson-extrapolated mean lift f3 + (f3 - f2) / (r^p - 1) with the finest
level's estimated error (Roache 1998, "Verification and Validation in Computational
Science and Engineering", ch. 5). When the differences change sign (oscillatory
convergence) or do not shrink, no order is claimed and no extrapolation made.

Writes DIR/convergence.csv (study, level, chordwise, spanwise, steps, mean lift) and
DIR/convergence.md (the tables), DIR/lattice/ and DIR/steps/ the sweeps' folders.
Exit status: 0 ok, 1 bad arguments, 2 bad input (from flapsim), 3 a level failed, 4 out of
memory (from flapsim), 130/143 interrupted by SIGINT/SIGTERM: the signal is passed on to the
sweep under way, which ends its levels' runs as `flapsim sweep` does; the same command again
runs only the levels not completed (with --force, all of them).
"""
import argparse
import csv
import math
import os
import re
import signal
import subprocess
import sys
import tempfile
import tomllib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from si_prefix import si_scale  # noqa: E402


def case_numerics(case):
    """The case's numerics keys that set the resolution (defaults of docs/case_file.md), read
    as TOML (tomllib): a line-by-line reading missed `numerics.steps_per_cycle = 30` written as
    a dotted key, an inline table or `1_000`, and labelled the levels with the defaults while
    the runs used the case's values."""
    values = {"chordwise_panels": 6, "spanwise_panels": 10, "steps_per_cycle": 100}
    try:
        with open(case, "rb") as f:
            numerics = tomllib.load(f).get("numerics", {})
    except (OSError, tomllib.TOMLDecodeError) as e:
        raise ValueError(f"{case}: {e}") from e
    for key in values:
        if isinstance(numerics.get(key), int) and not isinstance(numerics.get(key), bool):
            values[key] = numerics[key]
    return values


def levels_of(text, base, ratio, count, kind):
    """Levels given as "6x10,12x20,24x40" (lattice) or "50,100,200" (steps), or base * ratio^k."""
    if text:
        out = []
        for item in text.split(","):
            if kind == "lattice":
                m = re.match(r"^\s*(\d+)\s*[xX]\s*(\d+)\s*$", item)
                if not m:
                    raise ValueError(f"--lattice: '{item}' is not NCxNS (e.g. 6x10)")
                out.append((int(m.group(1)), int(m.group(2))))
            else:
                if not item.strip().isdigit():
                    raise ValueError(f"--steps: '{item}' is not a whole number")
                out.append(int(item))
        return out
    if kind == "lattice":
        return [(base[0] * ratio**k, base[1] * ratio**k) for k in range(count)]
    return [base * ratio**k for k in range(count)]


def refinement_ratio(sizes):
    """The constant ratio of successive levels (sizes: panel or step counts, coarse first)."""
    ratios = [b / a for a, b in zip(sizes, sizes[1:])]
    if any(r <= 1.0 for r in ratios):
        raise ValueError("levels must be listed coarse to fine, each finer than the last")
    if max(ratios) - min(ratios) > 1e-9 * max(ratios):
        raise ValueError(f"levels must refine by one constant ratio (got {', '.join(f'{r:g}' for r in ratios)})")
    return ratios[0]


def observed_order(f, r):
    """Observed order and Richardson extrapolation from the last three values of f (coarse
    to fine) at refinement ratio r: (p, extrapolated, error of the finest) or Nones."""
    if len(f) < 3 or any(math.isnan(x) for x in f[-3:]):
        return None, None, None
    f1, f2, f3 = f[-3:]
    d12, d23 = f1 - f2, f2 - f3
    if d23 == 0.0:
        return math.inf, f3, 0.0
    q = d12 / d23
    if q <= 1.0:  # differences that change sign or do not shrink: no asymptotic range
        return None, None, None
    p = math.log(q) / math.log(r)
    ext = f3 + (f3 - f2) / (r**p - 1.0)
    return p, ext, f3 - ext


def run_interruptible(cmd, env):
    """Runs cmd; SIGINT and SIGTERM sent to this script go on to it (so no sweep is left
    running, ppid 1, when the script is stopped); returns its exit status, 128 + N for a
    child ended by signal N."""
    proc = subprocess.Popen(cmd, env=env)

    def forward(signum, _frame):
        if proc.poll() is None:
            proc.send_signal(signum)

    old = {s: signal.signal(s, forward) for s in (signal.SIGINT, signal.SIGTERM)}
    try:
        code = proc.wait()
    finally:
        for s, h in old.items():
            signal.signal(s, h)
    return 128 - code if code < 0 else code


def run_sweep(flapsim, case, rows, columns, out, chain, wing, jobs, threads, force=False):
    os.makedirs(out, exist_ok=True)
    table = os.path.join(out, "levels.csv")
    with open(table, "w", newline="", encoding="utf-8") as t:
        w = csv.writer(t)
        w.writerow(columns)
        w.writerows(rows)
    cmd = [flapsim, "sweep", case, "--cases", table, "-o", out] + (["--force"] if force else [])
    if chain:
        cmd += ["--chain", chain]
    if wing:
        cmd += ["--wing", wing]
    if jobs:
        cmd += ["-j", str(jobs)]
    if threads:
        cmd += ["--threads", str(threads)]
    env = dict(os.environ)
    env.setdefault("FLAPSIM_QUIET", "1")
    code = run_interruptible(cmd, env)
    if code in (130, 143):
        print(f"convergence: interrupted; the same command again runs the levels not completed ({out})",
              file=sys.stderr)
    if code != 0:
        sys.exit(code if code in (2, 4, 130, 143) else 3)
    lift = []
    with open(os.path.join(out, "sweep.csv"), newline="", encoding="utf-8") as f:
        for row in csv.DictReader(f):
            if row.get("status") != "ok":
                print(f"convergence: the level {row.get('folder')} {row.get('status')}: {row.get('message')}",
                      file=sys.stderr)
                sys.exit(3)
            lift.append(float(row["mean_lift_N"]))
    return lift


def study_table(title, header, rows, lift, r):
    p, ext, err = observed_order(lift, r)
    scale, unit = si_scale(lift, "N")  # a fruit fly's uN, not 0.0032 mN with changes of +0.0000
    lines = [f"### {title}", "", "| " + " | ".join(header + [f"mean lift [{unit}]", f"change [{unit}]"]) + " |",
             "|" + "---|" * (len(header) + 2)]
    for k, (row, f) in enumerate(zip(rows, lift)):
        change = "" if k == 0 else f"{scale * (f - lift[k - 1]):+.4f}"
        lines.append("| " + " | ".join(str(v) for v in row) + f" | {scale * f:.4f} | {change} |")
    lines.append("")
    if p is None:
        # Two cases: the changes change sign (oscillating), or keep it and do not shrink.
        d12, d23 = (lift[-3] - lift[-2], lift[-2] - lift[-1]) if len(lift) >= 3 else (0.0, 0.0)
        why = ("the changes do not shrink (the levels are not yet in their asymptotic range)"
               if d12 * d23 > 0.0 else "the changes change sign (the levels oscillate)")
        lines.append(f"Refinement ratio {r:g}: over the last three levels {why}: no observed order, "
                     "no extrapolation.")
    elif math.isinf(p):
        lines.append(f"Refinement ratio {r:g}: the last two levels agree exactly.")
    else:
        lines.append(f"Refinement ratio {r:g}: observed order p = {p:.2f}; Richardson-extrapolated mean lift "
                     f"{scale * ext:.4f} {unit}; the finest level {100 * err / ext:+.2f} % from it, the coarsest "
                     f"{100 * (lift[0] - ext) / ext:+.2f} %.")
    lines.append("")
    return lines, p, ext


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("case")
    ap.add_argument("-o", "--output", help="output folder (default out/convergence/<case name>)")
    ap.add_argument("--levels", type=int, default=3, help="levels per study, 3 or 4 (default 3)")
    ap.add_argument("--ratio", type=int, default=2, help="refinement ratio between levels (default 2)")
    ap.add_argument("--lattice", help="lattice levels instead, e.g. 6x10,12x20,24x40")
    ap.add_argument("--steps", help="steps_per_cycle levels instead, e.g. 50,100,200")
    ap.add_argument("--study", choices=["both", "lattice", "steps"], default="both")
    ap.add_argument("--chain", help="chain file (as flapsim run --chain)")
    ap.add_argument("--wing", help="wing file flown instead of the case's (as flapsim run --wing)")
    ap.add_argument("--flapsim", default="build/flapsim")
    ap.add_argument("-j", "--jobs", type=int, default=0, help="levels run at once (flapsim sweep -j)")
    ap.add_argument("--threads", type=int, default=0, help="flapsim sweep --threads")
    ap.add_argument("--force", action="store_true",
                    help="run every level again (flapsim sweep --force); else levels an earlier study completed "
                         "with the same inputs are kept")
    a = ap.parse_args()
    try:
        if not 3 <= a.levels <= 4:
            raise ValueError("--levels must be 3 or 4")
        if a.ratio < 2:
            raise ValueError("--ratio must be at least 2")
        if not os.path.isfile(a.case):
            raise ValueError(f"no case file {a.case}")
        base = case_numerics(a.case)
        lattice = levels_of(a.lattice, (base["chordwise_panels"], base["spanwise_panels"]), a.ratio, a.levels,
                            "lattice")
        steps = levels_of(a.steps, base["steps_per_cycle"], a.ratio, a.levels, "steps")
        if a.study != "steps" and len(lattice) < 3:
            raise ValueError("--lattice needs at least 3 levels")
        if a.study != "lattice" and len(steps) < 3:
            raise ValueError("--steps needs at least 3 levels")
        r_lattice = refinement_ratio([nc * ns for nc, ns in lattice]) ** 0.5 if a.study != "steps" else None
        r_steps = refinement_ratio(steps) if a.study != "lattice" else None
        if r_lattice is not None:
            for (c0, s0), (c1, s1) in zip(lattice, lattice[1:]):
                if abs(c1 / c0 - s1 / s0) > 1e-9:
                    raise ValueError("--lattice: refine both directions by the same ratio (e.g. 6x10,12x20,24x40)")
    except ValueError as e:
        print(f"convergence: {e}", file=sys.stderr)
        return 1
    name = os.path.splitext(os.path.basename(a.case))[0]
    if a.wing:
        name += "_" + os.path.splitext(os.path.basename(a.wing))[0]
    out = a.output or os.path.join("out", "convergence", name)
    os.makedirs(out, exist_ok=True)
    md = [f"# Convergence of {a.case}" + (f" with the wing {a.wing}" if a.wing else ""), ""]
    rows_csv = []
    if a.study != "steps":
        rows = [(nc, ns, base["steps_per_cycle"]) for nc, ns in lattice]
        lift = run_sweep(a.flapsim, a.case, [(nc, ns) for nc, ns in lattice],
                         ["numerics.chordwise_panels", "numerics.spanwise_panels"], os.path.join(out, "lattice"),
                         a.chain, a.wing, a.jobs, a.threads, a.force)
        lines, _, _ = study_table("Lattice (steps_per_cycle " + str(base["steps_per_cycle"]) + ")",
                                  ["chordwise", "spanwise", "steps"], rows, lift, r_lattice)
        md += lines
        rows_csv += [("lattice", k, *row, f) for k, (row, f) in enumerate(zip(rows, lift))]
    if a.study != "lattice":
        rows = [(base["chordwise_panels"], base["spanwise_panels"], s) for s in steps]
        lift = run_sweep(a.flapsim, a.case, [(s,) for s in steps], ["numerics.steps_per_cycle"],
                         os.path.join(out, "steps"), a.chain, a.wing, a.jobs, a.threads, a.force)
        lines, _, _ = study_table(f"Time step (lattice {base['chordwise_panels']} x {base['spanwise_panels']})",
                                  ["chordwise", "spanwise", "steps"], rows, lift, r_steps)
        md += lines
        rows_csv += [("steps", k, *row, f) for k, (row, f) in enumerate(zip(rows, lift))]
    for fname, write in (("convergence.csv", "csv"), ("convergence.md", "md")):
        path = os.path.join(out, fname)
        fd, tmp = tempfile.mkstemp(dir=out, prefix=fname + ".tmp.")
        with os.fdopen(fd, "w", newline="", encoding="utf-8") as f:
            if write == "csv":
                w = csv.writer(f)
                w.writerow(["study", "level", "chordwise", "spanwise", "steps_per_cycle", "mean_lift_N"])
                w.writerows([(s, k, c, n, st, f"{v:.9g}") for s, k, c, n, st, v in rows_csv])
            else:
                f.write("\n".join(md))
        os.replace(tmp, path)
    print("\n".join(md))
    print(f"wrote {os.path.join(out, 'convergence.md')}, {os.path.join(out, 'convergence.csv')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
