#!/usr/bin/python3
"""ctest tools.MakeRun.ACaseNamedAsItsWingRunsBesideItsModel: `make run CASE=x.toml` for a
flexible case whose name is its wing's (cases/mav_film_wing.toml on wings/mav_film_wing.toml)
makes the wing's model in out/<wing>/ and runs into out/<case name>_run/. Before: both went to
out/mav_film_wing/, and flapsim run refused to replace the summary.json of flapsim reduce
(exit 4). A case with another name still runs into out/<case name>/. Checked with `make -n`
(what make would run, nothing run)."""
import os
import subprocess
import sys

import tool_test_args

a, work = tool_test_args.arguments("source", "build", "work")
out = os.path.join(work, "out")
failures = []


def make_n_run(case):
    r = subprocess.run(["make", "-n", "-C", a.source, "--no-print-directory", f"BUILD={a.build}", f"OUT={out}", "run",
                        f"CASE={case}"], capture_output=True, text=True)
    if r.returncode != 0:
        failures.append(f"make -n run CASE={case}: exit {r.returncode}\n{r.stderr[-2000:]}")
    return r.stdout


def output_folders(text, command):
    """The -o folder of every `flapsim COMMAND` line make would run (continued lines joined)."""
    folders = []
    for line in text.replace("\\\n", " ").splitlines():
        words = line.split()
        if command in words and "-o" in words:
            folders.append(words[words.index("-o") + 1])
    return folders


same = make_n_run(os.path.join(a.source, "cases", "mav_film_wing.toml"))
print(same)
if output_folders(same, "reduce") != [os.path.join(out, "mav_film_wing")]:
    failures.append(f"the wing's model is not made in out/mav_film_wing: {output_folders(same, 'reduce')}")
if output_folders(same, "run") != [os.path.join(out, "mav_film_wing_run")]:
    failures.append(f"the case does not run into out/mav_film_wing_run: {output_folders(same, 'run')}")

other = make_n_run(os.path.join(a.source, "cases", "hover_flexible.toml"))  # wing: hawkmoth
if output_folders(other, "run") != [os.path.join(out, "hover_flexible")]:
    failures.append(f"hover_flexible does not run into out/hover_flexible: {output_folders(other, 'run')}")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
