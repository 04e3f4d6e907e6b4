"""Command line shared by the tools tests (tests/tools/CMakeLists.txt passes the options):
the named path options, all required, and a fresh, empty --work folder."""
import argparse
import os
import shutil


def arguments(*names):
    """Parses --<name> for each name; if "work" is among them, empties that folder.
    Returns (args, absolute work folder or None)."""
    p = argparse.ArgumentParser()
    for n in names:
        p.add_argument("--" + n, required=True)
    a = p.parse_args()
    if "work" not in names:
        return a, None
    work = os.path.abspath(a.work)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    return a, work
