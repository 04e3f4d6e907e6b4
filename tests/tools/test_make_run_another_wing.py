#!/usr/bin/python3
"""ctest tools.MakeRun.AnotherWingFliesTheCaseWithItsOwnModel: `make run WING=x.toml` makes
that wing's model in out/<wing>/ and runs the case with `--wing x.toml --chain
out/<wing>/chain.toml` into out/<case name>_<wing>/; `make phase-study WING=x.toml` passes
--wing to both sweeps, into out/phase_study_<wing>/. Before: `make run WING=...` made the
wing's model but ran the case's own wing with that chain. Checked with `make -n` (what make
would run, nothing run)."""
import os
import subprocess
import sys

import tool_test_args

a, work = tool_test_args.arguments("source", "build", "work")
out = os.path.join(work, "out")
wing = os.path.join(a.source, "wings", "hawkmoth_rp.toml")
failures = []


def make_n(*goal_and_vars):
    r = subprocess.run(["make", "-n", "-C", a.source, "--no-print-directory", f"BUILD={a.build}", f"OUT={out}",
                        *goal_and_vars], capture_output=True, text=True)
    if r.returncode != 0:
        failures.append(f"make -n {' '.join(goal_and_vars)}: exit {r.returncode}\n{r.stderr[-2000:]}")
    return [line.split() for line in r.stdout.replace("\\\n", " ").splitlines()]


def commands(lines, command):
    """The words of every `flapsim COMMAND ...` (a recipe line may hold several, joined by ';' or '&')."""
    found = []
    for words in lines:
        starts = [i for i, x in enumerate(words) if x.endswith("/flapsim")]
        for i, j in zip(starts, starts[1:] + [len(words)]):
            if i + 1 < len(words) and words[i + 1] == command:
                found.append(words[i:j])
    return found


def option(words, name):
    return words[words.index(name) + 1] if name in words else None


run = make_n("run", f"WING={wing}")
reduce = commands(run, "reduce")
if [option(w, "-o") for w in reduce] != [os.path.join(out, "hawkmoth_rp")]:
    failures.append(f"the wing's model is not made in out/hawkmoth_rp: {reduce}")
runs = commands(run, "run")
if len(runs) != 1:
    failures.append(f"not one flapsim run: {runs}")
else:
    w = runs[0]
    if option(w, "--wing") != wing:
        failures.append(f"flapsim run without --wing {wing}: {w}")
    if option(w, "--chain") != os.path.join(out, "hawkmoth_rp", "chain.toml"):
        failures.append(f"flapsim run without the wing's chain: {w}")
    if option(w, "-o") != os.path.join(out, "hover_flexible_hawkmoth_rp"):
        failures.append(f"flapsim run not into out/hover_flexible_hawkmoth_rp: {w}")
checks = commands(run, "check")
if not checks or option(checks[0], "--wing") != wing:
    failures.append(f"flapsim check without --wing: {checks}")

study = commands(make_n("phase-study", f"WING={wing}"), "sweep")
if len(study) != 2 or any(option(w, "--wing") != wing for w in study):
    failures.append(f"the phase study's sweeps do not fly the wing: {study}")
if sorted(option(w, "-o") for w in study) != [os.path.join(out, "phase_study_hawkmoth_rp", k)
                                              for k in ("flexible", "rigid")]:
    failures.append(f"the phase study not into out/phase_study_hawkmoth_rp: {[option(w, '-o') for w in study]}")

# Without WING, the case's own wing: no --wing anywhere.
plain = commands(make_n("run"), "run")
if any("--wing" in w for w in plain) or [option(w, "-o") for w in plain] != [os.path.join(out, "hover_flexible")]:
    failures.append(f"make run without WING: {plain}")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
