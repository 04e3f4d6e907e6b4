#!/usr/bin/python3
"""ctest tools.PlotSweep.TheTitleNamesEveryStructureOfASweepOverStructureKind: plot_sweep's
title names the case and its structure from the cases' summary.json; a sweep of
structure.kind (rigid, chain, fem) named the first case's structure for all of them until
4 Dec 2026 ("hover: rigid wing" over a chain's and a FEM's lift). The folders here hold
summary.json files of made-up runs with the keys flapsim writes (case, structure)."""
import json
import os
import sys

import tool_test_args

a, work = tool_test_args.arguments("source", "work")
sys.path.insert(0, os.path.join(a.source, "tools"))
import plot_sweep  # noqa: E402

failures = []
table = os.path.join(work, "sweep.csv")
os.makedirs(work, exist_ok=True)
rows = []
structures = ["rigid wing (one body welded to the base)", "wing reduced in process (FEM + reduction, 10 bodies)",
              "the wing's FEM (geometrically nonlinear shells and veins)"]
for i, structure in enumerate(structures + structures[:1]):
    folder = "%02d_structure.kind" % i
    os.makedirs(os.path.join(work, folder), exist_ok=True)
    with open(os.path.join(work, folder, "summary.json"), "w") as f:
        json.dump({"case": "hover", "structure": structure}, f)
    rows.append({"folder": folder})
title = plot_sweep.run_title(table, rows)
expected = "hover: structures " + ", ".join(structures)
if title != expected:
    failures.append(f"title {title!r}, expected {expected!r}")
one = plot_sweep.run_title(table, [rows[0], rows[3]])
if one != "hover: " + structures[0]:
    failures.append(f"one structure: {one!r}")
if plot_sweep.run_title(table, [{"folder": "missing"}]) != "":
    failures.append("a folder without summary.json gives a title")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
