"""The runs of `make reproduce` (tools/reproduce.py): case files derived from the shipped
cases with a few keys changed, `flapsim run` and `flapsim reduce` in a pool of worker
threads (one OpenMP thread per process), each with an optional wall-clock limit, and the
results read back (summary.json, history.csv).

A derived case is the shipped case's text with keys replaced inside their [section]
(or added to it), its relative `wing` and `chain` paths made absolute, written atomically
into the output folder. Nothing here reads anything outside the source tree and the output
folder.
"""
import concurrent.futures
import csv
import json
import os
import re
import signal
import subprocess
import sys
import threading
import time
import tomllib


class ReproduceError(Exception):
    """A failure that stops `make reproduce` (exit 2), with a message naming the file."""


def write_atomic(path, text, mode="w"):
    """Writes `text` to `path` through a temporary name in the same folder and a rename."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    tmp = "%s.tmp.%d" % (path, os.getpid())
    with open(tmp, mode) as f:
        f.write(text)
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)


def derive_case(source_case, dest, overrides):
    """Writes `source_case` to `dest` with `overrides` {"section.key": toml_value_text}
    ("key" alone for a top-level key) and its relative wing/chain paths made absolute."""
    try:
        with open(source_case) as f:
            lines = f.read().split("\n")
    except OSError as e:
        raise ReproduceError("%s: %s" % (source_case, e.strerror))
    base = os.path.dirname(os.path.abspath(source_case))
    pending = dict(overrides)
    section = ""
    out = []
    sections_seen = set()

    def flush_section(sec):
        # keys of this section not found in it: add them at its end
        for k in [k for k in pending if k.rsplit(".", 1)[0] == sec and "." in k]:
            out.append("%s = %s" % (k.rsplit(".", 1)[1], pending.pop(k)))

    for line in lines:
        m = re.match(r"^\s*\[([A-Za-z0-9_.]+)\]\s*(#.*)?$", line)
        if m:
            flush_section(section)
            section = m.group(1)
            sections_seen.add(section)
            out.append(line)
            continue
        m = re.match(r"^(\s*)([A-Za-z0-9_]+)(\s*=\s*)(.*)$", line)
        if m:
            key = m.group(2) if not section else section + "." + m.group(2)
            if key in pending:
                out.append("%s%s%s%s" % (m.group(1), m.group(2), m.group(3), pending.pop(key)))
                continue
            if not section and m.group(2) in ("wing", "chain"):
                value = re.match(r'\s*"([^"]*)"', m.group(4))
                if value and not os.path.isabs(value.group(1)):
                    out.append('%s = "%s"' % (m.group(2), os.path.normpath(os.path.join(base, value.group(1)))))
                    continue
        out.append(line)
    flush_section(section)
    top = [k for k in pending if "." not in k]
    for k in top:
        out.insert(0, "%s = %s" % (k, pending.pop(k)))
    for k in list(pending):
        sec, key = k.rsplit(".", 1)
        out.append("[%s]" % sec if sec not in sections_seen else "")
        out.append("%s = %s" % (key, pending.pop(k)))
        sections_seen.add(sec)
    write_atomic(dest, "\n".join(out))
    return dest


class Run:
    """One command of the reproduction: its argv, its folder and what it gave."""

    def __init__(self, name, argv, folder, timeout=None, env=None, kind="run"):
        self.name = name
        self.argv = argv
        self.folder = folder
        self.timeout = timeout
        self.env = env
        self.kind = kind
        self.returncode = None
        self.timed_out = False
        self.seconds = 0.0
        self.output = ""

    def command_line(self, root):
        """The command as a user would type it from the source tree."""
        parts = []
        for a in self.argv:
            a = os.path.relpath(a, root) if os.path.isabs(a) and a.startswith(root) else a
            parts.append(a)
        return "OMP_NUM_THREADS=1 " + " ".join(parts)

    def summary(self):
        path = os.path.join(self.folder, "summary.json")
        try:
            with open(path) as f:
                return json.load(f)
        except (OSError, ValueError):
            return None


def execute(run):
    """Runs one command; on its time limit sends SIGTERM (flapsim finishes the step and writes
    summary.json "interrupted") and, 30 s later, SIGKILL."""
    env = dict(os.environ, OMP_NUM_THREADS="1", FLAPSIM_QUIET="1")
    env.update(run.env or {})
    start = time.monotonic()
    p = subprocess.Popen(run.argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    try:
        out, _ = p.communicate(timeout=run.timeout)
    except subprocess.TimeoutExpired:
        run.timed_out = True
        p.send_signal(signal.SIGTERM)
        try:
            out, _ = p.communicate(timeout=30)
        except subprocess.TimeoutExpired:
            p.kill()
            out, _ = p.communicate()
    run.seconds = time.monotonic() - start
    run.returncode = p.returncode
    run.output = out or ""
    save_record(run)
    return run


def record_path(run):
    return run.folder.rstrip("/") + ".run.json"


def save_record(run):
    """What a run gave, beside its folder, for `reproduce.py --report-only`."""
    write_atomic(record_path(run), json.dumps({"argv": run.argv, "returncode": run.returncode,
                                               "timed_out": run.timed_out, "seconds": run.seconds,
                                               "output": run.output[-20000:]}, indent=1))


def load_record(run):
    """Fills a Run from the record of an earlier execution; ReproduceError if there is none."""
    path = record_path(run)
    try:
        with open(path) as f:
            d = json.load(f)
    except (OSError, ValueError):
        raise ReproduceError("%s: no record of this run (run reproduce.py without --report-only first)" % path)
    run.returncode, run.timed_out, run.seconds, run.output = d["returncode"], d["timed_out"], d["seconds"], d["output"]
    return run


def run_all(runs, jobs, log=sys.stdout):
    """Runs every Run on `jobs` worker threads, longest expected first (the order given);
    prints one line per finished run."""
    lock = threading.Lock()
    done = [0]

    def one(r):
        execute(r)
        with lock:
            done[0] += 1
            state = "ok" if r.returncode == 0 else ("time limit" if r.timed_out else "exit %d" % r.returncode)
            print("[%d/%d] %-48s %6.1f s  %s" % (done[0], len(runs), r.name, r.seconds, state), file=log, flush=True)
        return r

    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        list(pool.map(one, runs))
    return runs


def read_history(folder, columns=None):
    """history.csv of a run as {column: [floats]} (all columns, or those named)."""
    path = os.path.join(folder, "history.csv")
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        names = columns or reader.fieldnames
        data = {c: [] for c in names}
        for row in reader:
            for c in names:
                try:
                    data[c].append(float(row[c]))
                except (TypeError, ValueError):
                    data[c].append(float("nan"))
    return data


def last_cycle(hist, frequency_hz):
    """Indices of the samples of the last whole cycle of a history."""
    t = hist["t_s"]
    t_end = t[-1]
    t0 = t_end - 1.0 / frequency_hz
    return [k for k, s in enumerate(t) if s >= t0 - 1e-12]


def read_chain(path):
    """A chain.toml as its list of bodies (length [m], mass [kg], inertia 3x3 [kg m^2])."""
    try:
        with open(path, "rb") as f:
            data = tomllib.load(f)
    except (OSError, tomllib.TOMLDecodeError) as e:
        raise ReproduceError("%s: %s" % (path, e))
    unit = {"m": 1.0, "mm": 1e-3, "cm": 1e-2}[data.get("length_unit", "m")]
    return [{"length": b["length"] * unit, "mass": b["mass"], "inertia": b["inertia"]} for b in data["bodies"]]


def read_json(path):
    """A JSON file, or ReproduceError naming it."""
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        raise ReproduceError("%s: %s" % (path, e))
