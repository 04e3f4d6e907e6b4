"""Command line shared by the tools tests (tests/tools/CMakeLists.txt passes the options):
the named path options, all required, and a fresh, empty --work folder; and XVFB_RUN, the
xvfb-run command line of the tests that render."""
import argparse
import os
import shutil

# xvfb-run with its own X display: -a alone starts its search at :99, so two tests started
# at once (ctest -j, or another build's tests on the machine) took the same display, and
# the one whose server went first lost it ("bad X server connection", exit 134). The search
# starts at a number drawn from the process id instead. -noreset: Xvfb otherwise resets
# when its last client leaves, and a render window opened during the reset fails the same way.
XVFB_RUN = ["xvfb-run", "-a", "-n", str(100 + os.getpid() % 800), "-s", "-screen 0 1024x768x24 -noreset"]


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
