#!/usr/bin/python3
"""The rotation phase of a run's tip as the rotation-phase paper defines it (RP Figs. 10
and 15), read from the run's history.csv.

RP Fig. 10 starts the wingbeat cycle when the (base's) sweep angle phi is at its maximum
and puts point A where the rotation angle alpha passes 90 deg; the rotation phase dpsi is
A's time after that start, as a fraction of the period (negative: the wing rotates before
the stroke reverses). Fig. 15 gives the same measure at the tip. Here, over one whole
cycle (the last one the run completed):

  t0        the base's sweep maximum that starts the cycle (the stroke reversal of
            the falling alpha = 90 deg crossing); r1 = t0 + T/2 the adjacent sweep minimum
            (the rising crossing's; t0 - T/2 if the run ends before t0 + T);
  base      the base's falling alpha = 90 deg crossing within half a period of t0 and
            its rising one within half a period of r1: (crossing - reversal) / T, mean of
            the two; reproduces the case's dpsi;
  rp_phase  the same for a wing section (the tip, or the outer body): ITS crossings of
            the SAME cycle (the same windows) minus the BASE's reversals: the paper's
            tip rotation phase of Fig. 15 (read as: the tip's point A on the cycle that
            Fig. 10 starts at the base's sweep maximum);
  rp_lead   rp_phase - base: the section's crossings minus the base's, same cycle
            (negative: the section rotates earlier);
  own_phase the section's crossings minus ITS OWN sweep reversals (its own phi maximum
            before the falling crossing, minimum before the rising one): the definition
            of summary.json's tip_rotation_phase (pipeline/fsi/phase_analysis.hpp), on
            this tool's wingbeat, where summary.json takes the run's last period: they
            differ by a fraction of a step where the wingbeats differ (docs/fsi.md).

Usage: rotation_phase.py RUN_DIR [--section tip|outer] [--json]
prints base, rp_phase, rp_lead, own_phase for the section (fractions of the period).
Exit 2 if history.csv is missing, lacks a column or has no complete cycle.
"""
import argparse
import csv
import json
import math
import os
import sys


class PhaseError(Exception):
    """A history.csv that cannot give a phase (names the file and what is missing)."""


def read_history(path, columns):
    """Columns of history.csv as lists of floats (t_s always)."""
    try:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            names = reader.fieldnames or []
            missing = [c for c in ["t_s"] + columns if c not in names]
            if missing:
                raise PhaseError("%s: no column %s" % (path, ", ".join(missing)))
            data = {c: [] for c in ["t_s"] + columns}
            for line, row in enumerate(reader, start=2):
                try:
                    for c in data:
                        data[c].append(float(row[c]))
                except (TypeError, ValueError):
                    raise PhaseError("%s, line %d: not a number in %s" % (path, line, c))
    except OSError as e:
        raise PhaseError("%s: %s" % (path, e.strerror))
    return data


def crossings(t, x, level, direction):
    """Times where x crosses level (linear interpolation); direction +1 rising, -1 falling."""
    out = []
    for k in range(1, len(t)):
        a, b = x[k - 1] - level, x[k] - level
        if direction < 0 and a > 0 >= b or direction > 0 and a < 0 <= b:
            out.append(t[k - 1] + (t[k] - t[k - 1]) * a / (a - b))
    return out


def extrema(t, x, sign):
    """Times of the local maxima (sign +1) or minima (sign -1) of x, refined by the parabola
    through the sample and its two neighbours."""
    out = []
    for k in range(1, len(t) - 1):
        a, b, c = sign * x[k - 1], sign * x[k], sign * x[k + 1]
        if b > a and b >= c:
            den = a - 2 * b + c
            shift = 0.5 * (a - c) / den if den != 0 else 0.0
            out.append(t[k] + shift * 0.5 * (t[k + 1] - t[k - 1]))
    return out


def first_in(times, lo, hi):
    inside = [s for s in times if lo <= s < hi]
    return inside[0] if inside else None


def last_cycle(t, phi_base, period):
    """The last whole wingbeat of the run: (t0, r1), t0 a base sweep maximum and r1 the
    adjacent sweep minimum (t0 + T/2, or t0 - T/2 when the run ends too soon after t0), with
    a whole period around them in the run: each crossing is sought within half a period of
    its reversal, so the windows cover [min(t0, r1) - T/2, max(t0, r1) + T/2]."""
    tol = 1e-12 * period
    for t0 in reversed(extrema(t, phi_base, +1)):
        for r1 in (t0 + 0.5 * period, t0 - 0.5 * period):
            if min(t0, r1) - 0.5 * period >= t[0] - tol and max(t0, r1) + 0.5 * period <= t[-1] + tol:
                return t0, r1
    raise PhaseError("no complete wingbeat (a base sweep maximum and the adjacent minimum, each with half "
                     "a period on either side)")


def section_phases(hist, section, period):
    """base, rp_phase, rp_lead, own_phase of a section ('tip' or 'outer') over the last
    complete cycle, fractions of the period; None where a crossing is missing."""
    t = hist["t_s"]
    t0, r1 = last_cycle(t, hist["phi_base_deg"], period)
    # falling crossing: reversal at the sweep maximum; rising: at the sweep minimum
    windows = {-1: t0, +1: r1}
    base, sec, own = [], [], []
    phi_sec = hist["phi_%s_deg" % section]
    for direction, reversal in windows.items():
        lo, hi = reversal - 0.5 * period, reversal + 0.5 * period
        tb = first_in(crossings(t, hist["alpha_base_deg"], 90.0, direction), lo, hi)
        ts = first_in(crossings(t, hist["alpha_%s_deg" % section], 90.0, direction), lo, hi)
        if tb is None or ts is None:
            return None
        base.append((tb - reversal) / period)
        sec.append((ts - reversal) / period)
        # The section's own reversal: its sweep extremum (max before falling, min before
        # rising) nearest the base's reversal, within half a period.
        own_rev = [s for s in extrema(t, phi_sec, -direction) if abs(s - reversal) < 0.5 * period]
        if own_rev:
            r = min(own_rev, key=lambda s: abs(s - reversal))
            own.append((ts - r) / period)
    b = sum(base) / 2
    p = sum(sec) / 2
    return {"cycle_start_s": t0, "base": b, "rp_phase": p, "rp_lead": p - b,
            "own_phase": sum(own) / len(own) if len(own) == 2 else None,
            "half_strokes": {"falling": {"base": base[0], "rp_phase": sec[0]},
                             "rising": {"base": base[1], "rp_phase": sec[1]}}}


def run_phases(run_dir, section="tip", frequency_hz=None):
    """Phases of a run folder (history.csv, and summary.json for the frequency)."""
    if frequency_hz is None:
        try:
            with open(os.path.join(run_dir, "summary.json")) as f:
                frequency_hz = float(json.load(f)["frequency_hz"])
        except (OSError, KeyError, ValueError) as e:
            raise PhaseError("%s: no frequency_hz (%s)" % (os.path.join(run_dir, "summary.json"), e))
    cols = ["phi_base_deg", "alpha_base_deg", "phi_%s_deg" % section, "alpha_%s_deg" % section]
    path = os.path.join(run_dir, "history.csv")
    hist = read_history(path, cols)
    try:
        r = section_phases(hist, section, 1.0 / frequency_hz)
    except PhaseError as e:
        raise PhaseError("%s: %s" % (path, e))
    if r is None:
        raise PhaseError("%s: no alpha = 90 deg crossing of the %s in the last complete cycle" % (path, section))
    return r


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("run_dir")
    ap.add_argument("--section", choices=("tip", "outer"), default="tip")
    ap.add_argument("--json", action="store_true")
    a = ap.parse_args(argv)
    try:
        r = run_phases(a.run_dir, a.section)
    except PhaseError as e:
        print("rotation_phase.py: %s" % e, file=sys.stderr)
        return 2
    if a.json:
        print(json.dumps(r, indent=1))
    else:
        fmt = lambda v: "none" if v is None or (isinstance(v, float) and math.isnan(v)) else "%+.4f" % v
        print("base %s  %s_rp_phase %s  %s_rp_lead %s  %s_own_phase %s" % (
            fmt(r["base"]), a.section, fmt(r["rp_phase"]), a.section, fmt(r["rp_lead"]), a.section,
            fmt(r["own_phase"])))
    return 0


if __name__ == "__main__":
    sys.exit(main())
