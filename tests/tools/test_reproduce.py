#!/usr/bin/python3
"""tools/reproduce.py --quick (2 cycles of 40 steps on a 3 x 5 lattice, 1 vacuum cycle, four
flexible and three rigid phases; no sensitivity study): every claim row of the report is filled
for every leading-edge model, the figures are written, and two numbers that do not depend on
the shortened numerics are right: RP Table 2's area (815.3 mm^2, the wing file scales to it)
and the base's measured rotation phase in the Fig. 15 table, which reproduces each case's dpsi
(eq. 8, the base motion is prescribed). A missing build exits 2 and writes no report."""
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import tool_test_args  # noqa: E402

args, work = tool_test_args.arguments("source", "build", "work")
check = tool_test_args.Checks()
tool = os.path.join(args.source, "tools", "reproduce.py")
doc = os.path.join(work, "reproduction.md")
figs = os.path.join(work, "figures")
p = subprocess.run([sys.executable, tool, "--quick", "--no-sensitivity", "--build", args.build, "--out",
                    os.path.join(work, "out"), "--doc", doc, "--figures", figs, "--jobs", "2"],
                   capture_output=True, text=True, env=tool_test_args.RUN_ENV)
print(p.stdout[-3000:], p.stderr[-3000:])
check(p.returncode == 0, "reproduce.py --quick exited %d" % p.returncode)
text = open(doc).read() if os.path.exists(doc) else ""


def table_after(heading):
    """Rows (lists of cells) of the first table after a heading."""
    part = text.split(heading, 1)[1] if heading in text else ""
    rows = []
    for line in part.splitlines():
        if line.startswith("|"):
            rows.append([c.strip() for c in re.split(r"(?<!\\)\|", line.strip())[1:-1]])
        elif rows:
            break
    return rows[0] if rows else [], rows[2:]


# The claims of issue 31's list, each a row of one of the two tables.
head, structure = table_after("## Structure and vacuum")
head_air, air = table_after("## In air: each leading-edge model")
claims = {
    "MB 3-body check": "3-body chain against a second multibody code",
    "MB 10-body distribution": "10-body chain: mass and stiffness distribution",
    "MB vacuum flapping, 33.8 mg": "vacuum flapping at 26.1 Hz, ±54°, 33.8 mg",
    "MB vacuum flapping, 43.4 mg": "vacuum flapping at 26.1 Hz, ±54°, 43.4 mg",
    "RP Table 1 masses": "3-body chain, masses",
    "RP Table 1 inertia": "3-body chain, torsional inertia",
    "RP Table 1 length": "3-body chain, body length",
    "RP eqs. 5-6": "3-body chain under eqs. 5–6",
    "RP Table 2": "the paper's wing: mass, area, span, mean chord",
    "RP eq. 7 CL": "eq. 7 (Lua et al.'s kinematics), rigid wing: mean CL",
    "RP eq. 7 in Lua's definition": "eq. 7: mean CL in Lua et al.'s definition",
    "RP eq. 8 rigid": "rigid wing, eq. 8",
    "RP eq. 8 flexible 33.8 mg": "flexible 33.8 mg wing, eq. 8",
    "RP eq. 8 flexible 43.4 mg": "flexible 43.4 mg wing (RP Table 2), eq. 8",
    "RP Fig. 14 at -0.05": "Fig. 14: base vs tip Euler angles, flexible 33.8 mg wing, δψ = -0.05",
    "RP Fig. 14 at +0.05": "Fig. 14: base vs tip Euler angles, flexible 33.8 mg wing, δψ = +0.05",
    "RP Fig. 15 at -0.10": "Fig. 15: tip rotation phase at δψ = -0.10, flexible 33.8 mg",
    "RP Fig. 15 at +0.10": "Fig. 15: tip rotation phase at δψ = +0.10, flexible 33.8 mg",
    "RP Fig. 15 at +0.10, 43.4 mg": "Fig. 15: tip rotation phase at δψ = +0.10, flexible 43.4 mg",
}
for name, title in claims.items():
    rows = [r for r in structure + air if r and r[0].startswith(title)]
    check(len(rows) >= 1, "%s: no row starting %r" % (name, title))
check(len(head) == 7 and len(head_air) == 8, "table heads %r / %r" % (head, head_air))
for r in structure:
    check(len(r) == 7 and all(r), "structure row not filled: %r" % r)
for r in air:
    # claim, source, paper, none, separated, shed, why, command: all filled; `none` and
    # `separated` with a value, never 'not run' (shed may say where it stops).
    check(len(r) == 8 and all(r), "air row not filled: %r" % r)
    check(len(r) == 8 and not any(c.startswith("not run") for c in r[3:6]), "air row not run: %r" % r)
# RP Table 2's area is the wing file's (firm): 815.3 mm^2.
t2 = [r for r in structure if r[0].startswith("the paper's wing")]
check(t2 and "815.3 mm²" in t2[0][3], "Table 2 row: %r" % (t2[0][3] if t2 else None))
# The base's measured phase is the case's dpsi (eq. 8: prescribed), to 1e-3 of the period.
_, fig15 = table_after("## Fig. 15: rotation phase at the tip")
measured = 0
for r in fig15:
    if len(r) > 4 and r[1] in ("none", "separated"):
        check(abs(float(r[3]) - float(r[2])) < 1e-3, "base phase %s for dpsi %s" % (r[3], r[2]))
        measured += 1
check(measured == 16, "%d none/separated rows with a measured base phase (want 2 wings x 2 models x 4 phases)" % measured)
for name in ("lift_cycle", "euler_angles", "tip_phase", "lua_cl"):
    for ext in ("pdf", "png"):
        f = os.path.join(figs, "reproduction_%s.%s" % (name, ext))
        check(os.path.exists(f) and os.path.getsize(f) > 1000, "figure %s" % f)
check(not [f for f in os.listdir(work) if ".tmp." in f], "temporary files left in %s" % work)

# A build without flapsim: exit 2 naming it, no report.
bad_doc = os.path.join(work, "bad.md")
p = subprocess.run([sys.executable, tool, "--quick", "--build", os.path.join(work, "no_build"), "--out",
                    os.path.join(work, "bad"), "--doc", bad_doc, "--figures", os.path.join(work, "bad_figs")],
                   capture_output=True, text=True)
check(p.returncode == 2 and "no_build/flapsim" in p.stderr and not os.path.exists(bad_doc),
      "missing build: exit %d, %r" % (p.returncode, p.stderr))
sys.exit(1 if check.failures else 0)
