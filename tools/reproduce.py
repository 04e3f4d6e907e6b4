#!/usr/bin/python3
"""`make reproduce`: every quantitative claim of the two papers flapsim follows (the
multibody paper, MB, and the rotation-phase paper, RP; docs/references.md) beside what
flapsim computes, for each leading-edge model (none, separated, shed), regenerated from
scratch into docs/reproduction.md and its figures (docs/figures/reproduction_*.pdf/png).

The papers' numbers are those the project's docs quote with their section, figure or
table (docs/hawkmoth_reference_data.md, docs/multibody.md, docs/uvlm.md,
docs/validation.md); they are written in tools/reproduce_report.py. Every run is a shipped
case with a few keys changed (tools/reproduce_runs.py), run by build/flapsim with one
OpenMP thread, --jobs at a time. A run that stops (exit 3: `shed` on a flapping wing) or
passes its time limit is reported where it stopped; the table regenerates when it runs.

Usage: reproduce.py [--build build] [--out out/reproduce] [--doc docs/reproduction.md]
                    [--figures docs/figures] [--jobs 2] [--quick] [--no-sensitivity]
Runs of `shed` stop at --shed-limit seconds of wall clock (default 900) and run more cycles
(Lua et al.'s case 30, the phase studies 12): on a flapping wing their cycles do not repeat, and
their result is the mean over the cycles from the second on (summary.json settled_mean_CL).
--quick: 2 cycles of 40 steps on a 3 x 5 lattice, 1 vacuum cycle, fewer phases, shed
limited to 20 s a run: every row filled in a few tens of seconds, numbers not converged
(the test tools.Reproduce.*). Exit 0 when the report is written (runs that stop are
results); 2 when an input or the build is missing; the report is then not written.
"""
import argparse
import json
import os
import re
import resource
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import reproduce_runs as rr  # noqa: E402
from reproduce_runs import ReproduceError  # noqa: E402

MODELS = ("none", "separated", "shed")
WINGS = {"mb": "wings/hawkmoth.toml", "rp": "wings/hawkmoth_rp.toml"}
# First bending 85 Hz instead of the calibrated chain's 90.8 Hz: springs scale with f^2
# (docs/hawkmoth_reference_data.md, criterion 4: "near the roughly 85 Hz").
SPRINGS_85HZ = (85.0 / 90.8) ** 2


def frange(spec):
    lo, step, hi = (float(v) for v in spec.split(":"))
    n = int(round((hi - lo) / step))
    return [round(lo + k * step, 10) for k in range(n + 1)]


def settings(quick):
    if quick:
        return {"rigid": [-0.15, -0.10, 0.05], "flexible": [-0.10, -0.05, 0.05, 0.10],
                "numerics": {"numerics.cycles": "2", "numerics.steps_per_cycle": "40",
                             "numerics.chordwise_panels": "3", "numerics.spanwise_panels": "5"},
                "fine_lattice": {"numerics.chordwise_panels": "6", "numerics.spanwise_panels": "10"},
                "vacuum": {"numerics.cycles": "1", "numerics.steps_per_cycle": "200"},
                "shed_limit": 20.0, "run_limit": 120.0}
    return {"rigid": frange("-0.20:0.05:0.10"), "flexible": frange("-0.10:0.05:0.10"), "numerics": {},
            "fine_lattice": {"numerics.chordwise_panels": "12", "numerics.spanwise_panels": "20"},
            "vacuum": {}, "shed_limit": 900.0, "run_limit": 900.0,
            # `shed` on a flapping wing: its cycles do not repeat, its result is the mean over
            # many (summary.json settled_mean_CL; docs/uvlm.md, "Lua et al.'s hover over many cycles")
            "shed_cycles": {"lua": "30", "phase": "12"}}


class Plan:
    """The runs of the reproduction, by key, and where their results go."""

    def __init__(self, a):
        self.root = os.path.abspath(a.source)
        self.out = os.path.abspath(a.out)
        self.flapsim = os.path.abspath(os.path.join(a.build, "flapsim"))
        self.test_mbd = os.path.abspath(os.path.join(a.build, "tests", "mbd", "test_mbd"))
        self.s = settings(a.quick)
        if a.shed_limit is not None:
            self.s["shed_limit"] = a.shed_limit
        self.quick = a.quick
        self.sensitivity = not a.no_sensitivity
        self.runs = {}
        self.models = {}

    def path(self, *p):
        return os.path.join(self.out, *p)

    def src(self, *p):
        return os.path.join(self.root, *p)

    def model(self, key, wing, bodies):
        folder = self.path("models", key)
        self.models[key] = {"wing": wing, "bodies": bodies, "folder": folder}
        self.runs["model:" + key] = rr.Run("reduce %s --bodies %d" % (wing, bodies),
                                           [self.flapsim, "reduce", self.src(wing), "-o", folder, "--bodies", str(bodies)],
                                           folder, timeout=self.s["run_limit"], kind="reduce")

    def case(self, key, case, overrides, chain=None, spring_scale=None, limit=None):
        folder = self.path("runs", key.replace(":", "_"))
        derived = rr.derive_case(self.src(case), self.path("cases", key.replace(":", "_") + ".toml"), overrides)
        argv = [self.flapsim, "run", derived, "-o", folder, "-q", "--vtk-every", "0"]
        if chain:
            argv += ["--chain", os.path.join(self.models[chain]["folder"], "chain.toml")]
        if spring_scale is not None:
            argv += ["--spring-scale", "%.6g" % spring_scale]
        r = rr.Run(key, argv, folder, timeout=limit or self.s["run_limit"])
        r.case = case
        r.overrides = overrides
        r.chain = chain
        self.runs[key] = r
        return r

    def air(self, model, extra=None, study="phase"):
        o = dict(self.s["numerics"])
        o["numerics.leading_edge"] = '"%s"' % model
        if model == "shed" and "shed_cycles" in self.s:
            o["numerics.cycles"] = self.s["shed_cycles"][study]
        o.update(extra or {})
        return o

    def limit(self, model):
        return self.s["shed_limit"] if model == "shed" else None

    def build_runs(self):
        s = self.s
        self.model("mb10", WINGS["mb"], 10)
        self.model("rp10", WINGS["rp"], 10)
        self.model("mb3", WINGS["mb"], 3)
        self.model("rp3", WINGS["rp"], 3)
        if self.sensitivity:
            self.model("thin10", "wings/hawkmoth_thin_membrane.toml", 10)
        self.runs["model:mesh"] = rr.Run("mesh wings/hawkmoth.toml", [self.flapsim, "mesh", self.src(WINGS["mb"]), "-o",
                                         self.path("models", "mesh")], self.path("models", "mesh"), kind="mesh")
        self.runs["model:check_rp"] = rr.Run("check wings/hawkmoth_rp.toml", [self.flapsim, "check", self.src(WINGS["rp"])],
                                             self.path("models", "check_rp"), kind="check")
        # Vacuum: RP eqs. 5-6 (three bodies), MB sec. 4 (the reduced chains at 26.1 Hz, +-54 deg).
        self.case("three_body", "cases/three_body.toml", dict(s["vacuum"]))
        for w in ("mb", "rp"):
            self.case("vacuum:%s" % w, "cases/vacuum_flapping.toml", dict(s["vacuum"]), chain=w + "10")
        for m in MODELS:
            self.case("lua:%s" % m, "cases/lua_rigid.toml", self.air(m, study="lua"), limit=self.limit(m))
            for d in s["rigid"]:
                self.case("rigid:%s:%+.2f" % (m, d), "cases/rotation_phase_rigid_coupled.toml",
                          self.air(m, {"kinematics.rotation_phase": "%.4f" % d}), limit=self.limit(m))
            for w in ("mb", "rp"):
                for d in s["flexible"]:
                    self.case("flex:%s:%s:%+.2f" % (w, m, d), "cases/rotation_phase_flexible.toml",
                              self.air(m, {"kinematics.rotation_phase": "%.4f" % d}), chain=w + "10",
                              limit=self.limit(m))
        if self.sensitivity:
            for d in s["flexible"]:
                ph = {"kinematics.rotation_phase": "%.4f" % d}
                self.case("sens:springs85:%+.2f" % d, "cases/rotation_phase_flexible.toml",
                          self.air("separated", ph), chain="mb10", spring_scale=SPRINGS_85HZ)
                self.case("sens:thin:%+.2f" % d, "cases/rotation_phase_flexible.toml",
                          self.air("separated", ph), chain="thin10")
                self.case("sens:truncated:%+.2f" % d, "cases/rotation_phase_flexible.toml",
                          self.air("separated", dict(ph, **{"numerics.far_wake_cycles": "0",
                                                            "numerics.wake_max_rows": "50"})), chain="mb10")
                self.case("sens:lattice:%+.2f" % d, "cases/rotation_phase_flexible.toml",
                          self.air("separated", dict(ph, **s["fine_lattice"])), chain="mb10")

    def mesh_info(self):
        """FEM node count of `flapsim mesh` and the RP wing's area, span, S/R of `flapsim check`."""
        m = re.search(r"(\d+) nodes", self.runs["model:mesh"].output)
        out = self.runs["model:check_rp"].output
        get = lambda key: float(re.search(key + r"\s+([0-9.]+)", out).group(1))
        try:
            check = {"area": get("area S"), "span": get("span R"), "chord": get("mean chord S/R")}
        except AttributeError:
            raise ReproduceError("flapsim check %s: no area, span or mean chord in its output" % WINGS["rp"])
        return (int(m.group(1)) if m else None), check

    def simbody_info(self):
        """(percent of amplitude, amplitude [mm], joint-angle percent) of the Simbody test, or None."""
        r = self.runs.get("simbody")
        if r is None or r.returncode != 0:
            return None
        a = re.search(r"amplitude of A ([0-9.]+) mm.*= ([0-9.e+-]+) % of amplitude", r.output)
        q = re.search(r"largest joint angle .*\(([0-9.]+) %\)", r.output)
        if not a or not q:
            return None
        return ("%.3f" % float(a.group(2)), "%.1f" % float(a.group(1)), "%.2f" % float(q.group(1)))

    def load(self):
        """The results of an earlier execution into the same --out (--report-only)."""
        for r in self.runs.values():
            rr.load_record(r)
        test = rr.Run("test_mbd SimbodyThreeBody", [], self.path("simbody"), kind="test")
        try:
            self.runs["simbody"] = rr.load_record(test)
        except ReproduceError:
            pass

    def execute(self, jobs):
        for exe in (self.flapsim,):
            if not os.access(exe, os.X_OK):
                raise ReproduceError("%s: not built (make build)" % exe)
        models = [r for k, r in self.runs.items() if k.startswith("model:")]
        cases = [r for k, r in self.runs.items() if not k.startswith("model:")]
        rr.run_all(models, jobs)
        for r in models:
            if r.returncode != 0:
                raise ReproduceError("%s failed (exit %s): %s" % (r.name, r.returncode, r.output.strip()[-400:]))
        # Longest first: the shed runs (to their limit), the fine lattice, then the rest.
        rank = lambda r: (0 if ":shed" in r.name else 1 if "lattice" in r.name else 2 if r.name.startswith("lua") else 3)
        extra = []
        if os.access(self.test_mbd, os.X_OK):
            self.runs["simbody"] = rr.Run("test_mbd SimbodyThreeBody", [self.test_mbd,
                                          "--gtest_filter=SimbodyThreeBody.TipTrajectoryAgreesWithSimbodyOverThreeCycles"],
                                          self.path("simbody"), timeout=self.s["run_limit"], kind="test")
            extra.append(self.runs["simbody"])
        rr.run_all(sorted(cases, key=rank) + extra, jobs)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap.add_argument("--source", default=here, help="the source tree (default: this tool's)")
    ap.add_argument("--build", default=os.path.join(here, "build"))
    ap.add_argument("--out", default=os.path.join(here, "out", "reproduce"))
    ap.add_argument("--doc", default=os.path.join(here, "docs", "reproduction.md"))
    ap.add_argument("--figures", default=os.path.join(here, "docs", "figures"))
    ap.add_argument("--jobs", "-j", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--no-sensitivity", action="store_true")
    ap.add_argument("--shed-limit", type=float, default=None,
                    help="wall-clock limit of each `shed` run [s] (default 900; --quick 20)")
    ap.add_argument("--report-only", action="store_true",
                    help="write the report and figures from the runs of an earlier reproduce.py into the same --out")
    a = ap.parse_args(argv)
    if a.jobs < 1:
        ap.error("--jobs must be at least 1")
    start = time.monotonic()
    try:
        import reproduce_report
        plan = Plan(a)
        plan.build_runs()
        if a.report_only:
            plan.load()
            wall = sum(r.seconds for r in plan.runs.values()) / a.jobs
        else:
            plan.execute(a.jobs)
            wall = time.monotonic() - start
        ru = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = None if a.report_only else ru.ru_utime + ru.ru_stime
        if not a.report_only:
            plan.load = os.getloadavg()[0]
            rr.write_atomic(plan.path("timing.json"), json.dumps({"wall_s": wall, "cpu_s": cpu, "jobs": a.jobs,
                                                                  "load_average": plan.load}))
        else:
            try:
                t = rr.read_json(plan.path("timing.json"))
                wall, cpu, plan.load = t["wall_s"], t["cpu_s"], t.get("load_average")
            except ReproduceError:
                pass
        reproduce_report.write(plan, a, wall, cpu)
    except ReproduceError as e:
        print("reproduce.py: %s" % e, file=sys.stderr)
        return 2
    print("reproduce: %.0f s wall; %s and its figures in %s" % (time.monotonic() - start, a.doc, a.figures))
    return 0


if __name__ == "__main__":
    sys.exit(main())
