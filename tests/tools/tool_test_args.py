"""Command line shared by the tools tests (tests/tools/CMakeLists.txt passes the options):
the named path options, all required, and a fresh, empty --work folder; and XVFB_RUN, the
xvfb-run command line of the tests that render."""
import argparse
import os
import shutil
import subprocess

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


# The environment of the tests' own flapsim runs: no progress line, one thread each.
RUN_ENV = dict(os.environ, FLAPSIM_QUIET="1", OMP_NUM_THREADS="1")


def write_flapping_plate_case(source, path, name="plate", steps_per_cycle=12, cycles=1, vtk_every=3):
    """Writes the rigid flat plate (wings/flat_plate.toml) flapped at 26.1 Hz, sweep 10° ± 50°,
    rotation 90° − 45° sin, on a 3 × 4 lattice, to `path`; returns `path`."""
    with open(path, "w") as f:
        f.write(f'name = "{name}"\nwing = "{source}/wings/flat_plate.toml"\n'
                "[kinematics]\nfrequency_hz = 26.1\n"
                "sweep = { mean_deg = 10.0, cos_deg = [50.0] }\n"
                "rotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
                '[structure]\nkind = "rigid"\n'
                f"[numerics]\nsteps_per_cycle = {steps_per_cycle}\ncycles = {cycles}\n"
                "chordwise_panels = 3\nspanwise_panels = 4\n"
                f"core_radius = 0.2\n[output]\nvtk_every = {vtk_every}\n")
    return path


def run_case(flapsim, case, run):
    """`flapsim run case -o run -q`; a failure fails the test. Returns `run`."""
    subprocess.run([flapsim, "run", case, "-o", run, "-q"], check=True, env=RUN_ENV)
    return run


def make_run(source, build, out, case):
    """`make run CASE=case` of the source tree with BUILD and OUT given, one OpenMP thread;
    prints the end of its output and returns the CompletedProcess (stdout, stderr as text)."""
    r = subprocess.run(["make", "-C", source, "--no-print-directory", f"BUILD={build}", f"OUT={out}", "run",
                        f"CASE={case}"], capture_output=True, text=True, env=dict(os.environ, OMP_NUM_THREADS="1"))
    print(r.stdout[-3000:], r.stderr[-3000:])
    return r


class Checks:
    """check(ok, message): records and prints a failed check; `failures` lists them."""

    def __init__(self):
        self.failures = []

    def __call__(self, ok, message):
        if not ok:
            self.failures.append(message)
            print("FAIL:", message)


def read_png_rgb(path):
    """The picture at `path` as an (h, w, 3) array of RGB in [0, 1], rows as VTK stores them
    (the first row at the bottom)."""
    import vtk  # the rendering tests' module only: the other tools tests run without it
    from vtk.util.numpy_support import vtk_to_numpy
    reader = vtk.vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3] / 255.0
