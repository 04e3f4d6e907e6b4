#!/usr/bin/python3
"""Pictures of a flapsim run without opening ParaView: PNG snapshots of the wing
(coloured by the pressure jump), its wake (by circulation) and the bar chain at chosen
phases of the last wingbeat, rendered offscreen with VTK's Python (python3-vtk9). A run
of the wing's FEM (structure kind "fem", fem.pvd) shows the FEM's deformed surface
instead, coloured by its displacement beyond the base's rigid motion (its twist and
camber), with the veins drawn dark.

    xvfb-run -a tools/render_run.py out/hover_flexible                 # phases 0, 0.25, 0.5, 0.75
    xvfb-run -a tools/render_run.py out/hover_flexible --phases 0.25 -o preview.png

VTK's render window needs an X display: on a machine without one, run the script under
xvfb-run (Debian packages xvfb, xauth; tools/install_deps.sh installs them). The phase is
t/T of the run's kinematics (t = 0 at the start of the run, where the case's
phase-0 angles hold), taken within the last complete wingbeat written. Each picture is
titled with t/T, t and the lift of its frame. Exit status 0, or 2 on bad input (a folder
without chain.pvd or fem.pvd, a phase outside [0, 1)). docs/fsi.md, "Pictures".
"""
import argparse
import json
import math
import os
import sys
import xml.etree.ElementTree as ET

import vtk

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from si_prefix import run_force_scale  # noqa: E402


def fail(message):
    print(f"render_run: error: {message}", file=sys.stderr)
    sys.exit(2)


def read_pvd(path):
    """[(time, absolute data file)] of a .pvd collection, files relative to it."""
    root = ET.parse(path).getroot()
    folder = os.path.dirname(os.path.abspath(path))
    return [(float(d.get("timestep")), os.path.join(folder, d.get("file")))
            for d in root.iter("DataSet")]


def read_vtp(path):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = vtk.vtkPolyData()
    data.DeepCopy(reader.GetOutput())
    return data


def field(data, name, default=float("nan")):
    a = data.GetFieldData().GetArray(name)
    return a.GetTuple1(0) if a is not None else default


def diverging(range_):
    """ParaView's "Cool to Warm" over [-range, range]."""
    ctf = vtk.vtkColorTransferFunction()
    ctf.SetColorSpaceToDiverging()
    ctf.AddRGBPoint(-range_, 0.231373, 0.298039, 0.752941)
    ctf.AddRGBPoint(0.0, 0.865003, 0.865003, 0.865003)
    ctf.AddRGBPoint(range_, 0.705882, 0.0156863, 0.14902)
    return ctf


def cell_range(data, name):
    a = data.GetCellData().GetArray(name)
    if a is None or a.GetNumberOfTuples() == 0:
        return 0.0
    lo, hi = a.GetRange()
    return max(abs(lo), abs(hi))


def normalized(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v] if n > 0 else [0.0, 0.0, 1.0]


def face_normal(wing):
    """The wing's mean panel normal, pointing up (unit), or None for no panels."""
    if wing is None or wing.GetNumberOfCells() == 0:
        return None
    normals = vtk.vtkPolyDataNormals()
    normals.SetInputData(wing)
    normals.ComputeCellNormalsOn()
    normals.ComputePointNormalsOff()
    normals.SplittingOff()
    normals.ConsistencyOff()
    normals.Update()
    cell = normals.GetOutput().GetCellData().GetNormals()
    n = [0.0, 0.0, 0.0]
    for i in range(cell.GetNumberOfTuples()):
        t = cell.GetTuple3(i)
        n = [a + b for a, b in zip(n, t)]
    n = normalized(n)
    return [-x for x in n] if n[2] < 0 else n


def view_direction(wings, chain):
    """Unit vector from the wing toward the camera: the mean of the wing's face normals
    (pointing up) at mid-downstroke and mid-upstroke, plus 0.4 of the vertical; for a chain
    alone, horizontal across its span, 30° up. Until 3 Dec only mid-downstroke's face was
    looked at, and a hover's wing, turned through 90° about its span by mid-upstroke, showed
    there edge-on (0.0 % of the picture)."""
    faces = [n for n in (face_normal(w) for w in wings) if n is not None]
    if faces:
        n = normalized([sum(f[i] for f in faces) for i in range(3)])
        return normalized([n[0], n[1], n[2] + 0.4])
    p0, p1 = chain.GetPoint(0), chain.GetPoint(chain.GetNumberOfPoints() - 1)
    span = normalized([b - a for a, b in zip(p0, p1)])
    across = normalized([-span[1], span[0], 0.0])
    return normalized([across[0], across[1], 0.58])


def frame_at(series, frequency, phase):
    """The entry of the series closest to the last t/T at the given phase. A run that
    stopped before reaching that phase in its first wingbeat (interrupted, diverged) shows
    its last frame, the nearest it has: the target used to be clamped to t = 0, and a run
    stopped at t/T 0.2 showed its start (no wake, no lift) at phases 0.25, 0.5 and 0.75."""
    last = series[-1][0] * frequency
    start = math.floor(last - phase + 1e-9) + phase if last >= phase else phase
    target = start if start <= last + 1e-9 else start - 1.0
    if target < 0.0:
        target = last
    return min(series, key=lambda e: abs(e[0] * frequency - target))


def shared_view(run):
    """The one camera of a run's pictures: the bounds of the wing (or the chain) over the
    frames of the last wingbeat written, and the direction toward the camera from the wing's
    faces at mid-downstroke and mid-upstroke (phases 0.25, 0.75) of that wingbeat
    (view_direction). Every picture
    then shows the wing from the same point: its positions over the stroke compare."""
    wing_series, _, chain_series, frequency = run
    series = wing_series if wing_series else chain_series
    last = series[-1][0] * frequency
    frames = [e for e in series if e[0] * frequency >= last - 1.0 - 1e-9] or [series[-1]]
    bounds = [math.inf, -math.inf] * 3
    for _, path in frames:
        b = read_vtp(path).GetBounds()
        for i in range(3):
            bounds[2 * i] = min(bounds[2 * i], b[2 * i])
            bounds[2 * i + 1] = max(bounds[2 * i + 1], b[2 * i + 1])
    faces = [chain_series.index(frame_at(chain_series, frequency, phase)) for phase in (0.25, 0.75)]
    wings = [read_vtp(wing_series[i][1]) for i in faces] if wing_series else []
    return tuple(bounds), view_direction(wings, read_vtp(chain_series[faces[0]][1]))


def frame_title(t, frequency, phase, lift, force_scale=(1e3, "mN")):
    """The picture's title: t/T, the phase of the frame shown (and the phase asked for when
    no frame lies there: with vtk_every 4 of 40 steps per cycle, 0.25 shows the frame at
    0.30, which the title called "phase 0.25"), t and the lift in force_scale's unit
    (si_prefix.run_force_scale: the run's own, so a fruit fly's reads uN)."""
    s = t * frequency
    shown = max(0.0, s - math.floor(s + 1e-9))
    where = f"phase {shown:.2f}"
    if abs(shown - phase) > 5e-3 and abs(abs(shown - phase) - 1.0) > 5e-3:
        where += f", the frame nearest to {phase:.2f}"
    factor, unit = force_scale
    return f"t/T = {s:.3f} ({where})   t = {t * 1e3:.2f} ms   lift = {lift * factor:.4g} {unit}"


def add_fem_surface(renderer, fem):
    """The FEM's deformed triangles coloured by |displacement_m| (white at rest to dark
    blue at the frame's largest), its veins (lines) left to the tubes of the caller."""
    magnitude = vtk.vtkArrayCalculator()
    magnitude.SetInputData(fem)
    magnitude.SetAttributeTypeToPointData()
    magnitude.AddVectorArrayName("displacement_m")
    magnitude.SetFunction("mag(displacement_m)")
    magnitude.SetResultArrayName("displacement_magnitude_m")
    magnitude.Update()
    surface = magnitude.GetOutput()
    top = max(surface.GetPointData().GetArray("displacement_magnitude_m").GetRange()[1], 1e-12)
    lut = vtk.vtkLookupTable()
    lut.SetTableRange(0.0, top)
    lut.SetHueRange(0.6, 0.6)
    lut.SetSaturationRange(0.0, 1.0)
    lut.SetValueRange(1.0, 0.55)
    lut.Build()
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(surface)
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("displacement_magnitude_m")
    mapper.SetLookupTable(lut)
    mapper.SetScalarRange(0.0, top)
    mapper.SetColorModeToMapScalars()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetAmbient(0.3)
    actor.GetProperty().SetDiffuse(0.7)
    renderer.AddActor(actor)


def render(run, time_index, phase, args, output, view):
    wing_series, wake_series, chain_series, frequency = run
    fem_run = read_vtp(chain_series[time_index][1]).GetPointData().GetArray("displacement_m") is not None
    if fem_run and not args.wing_color:
        wing_series = []  # the FEM's own surface shows the wing (the lattice lies on it)
    t, chain_file = chain_series[time_index]
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(1.0, 1.0, 1.0)
    renderer.TwoSidedLightingOn()
    lift = float("nan")
    wing = None
    if wing_series:
        wing = read_vtp(wing_series[time_index][1])
        lift = field(wing, "lift_N")
        mapper = vtk.vtkPolyDataMapper()
        mapper.SetInputData(wing)
        if args.wing_color:
            mapper.ScalarVisibilityOff()
        else:
            mapper.SetScalarModeToUseCellFieldData()
            mapper.SelectColorArray("pressure_jump_Pa")
            mapper.SetLookupTable(diverging(max(cell_range(wing, "pressure_jump_Pa"), 1e-12)))
            mapper.SetColorModeToMapScalars()
        actor = vtk.vtkActor()
        actor.SetMapper(mapper)
        if args.wing_color:
            actor.GetProperty().SetColor(*args.wing_color)
        actor.GetProperty().SetAmbient(0.25)
        actor.GetProperty().SetDiffuse(0.75)
        actor.GetProperty().SetSpecular(0.0)
        actor.GetProperty().EdgeVisibilityOn()
        actor.GetProperty().SetEdgeColor(0.2, 0.2, 0.2)
        renderer.AddActor(actor)
    # The wake whatever shows the wing (an FEM run in air draws its own surface, not the
    # lattice's, and its pictures had no wake).
    if wake_series and not args.no_wake:
        wake = read_vtp(wake_series[time_index][1])
        if wake.GetNumberOfCells() > 0:
            wm = vtk.vtkPolyDataMapper()
            wm.SetInputData(wake)
            wm.SetScalarModeToUseCellFieldData()
            wm.SelectColorArray("circulation_m2_s")
            wm.SetLookupTable(diverging(max(cell_range(wake, "circulation_m2_s"), 1e-12)))
            wa = vtk.vtkActor()
            wa.SetMapper(wm)
            wa.GetProperty().SetOpacity(0.15)
            renderer.AddActor(wa)
    chain = read_vtp(chain_file)
    if math.isnan(lift):
        lift = field(chain, "lift_N")
    if chain.GetPointData().GetArray("displacement_m") is not None:
        add_fem_surface(renderer, chain)
    tubes = vtk.vtkTubeFilter()
    tubes.SetInputData(chain)
    bounds = (wing if wing is not None else chain).GetBounds()
    size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4], 1e-6)
    tubes.SetRadius(0.008 * size)
    tubes.SetNumberOfSides(12)
    cm = vtk.vtkPolyDataMapper()
    cm.SetInputConnection(tubes.GetOutputPort())
    cm.ScalarVisibilityOff()
    ca = vtk.vtkActor()
    ca.SetMapper(cm)
    ca.GetProperty().SetColor(0.05, 0.05, 0.05)
    renderer.AddActor(ca)

    # One camera for every picture of the run (shared_view): the frames compare.
    view_bounds, direction = view
    cx, cy, cz = [(view_bounds[2 * i] + view_bounds[2 * i + 1]) / 2 for i in range(3)]
    view_size = max(view_bounds[1] - view_bounds[0], view_bounds[3] - view_bounds[2],
                    view_bounds[5] - view_bounds[4], 1e-6)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(cx, cy, cz)
    camera.SetPosition(*[c + 3.0 * view_size * d for c, d in zip((cx, cy, cz), direction)])
    camera.SetViewUp(0, 0, 1) if abs(direction[2]) < 0.95 else camera.SetViewUp(0, 1, 0)
    renderer.ResetCamera(view_bounds)
    camera.Zoom(1.2)  # ResetCamera fits the bounds' sphere, loose around a flat stroke's box
    renderer.ResetCameraClippingRange()

    text = vtk.vtkTextActor()
    text.SetInput(frame_title(t, frequency, phase, lift, run_force_scale(args.run, lift)))
    text.GetTextProperty().SetColor(0, 0, 0)
    text.GetTextProperty().SetFontSize(max(12, args.size[1] // 40))
    text.SetDisplayPosition(10, 10)
    renderer.AddViewProp(text)

    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(*args.size)
    window.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    tmp = output + f".tmp.{os.getpid()}"
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(tmp)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    os.replace(tmp, output)  # atomic: a reader never sees half a picture
    print(f"wrote {output}")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("run", help="the output folder of 'flapsim run'")
    p.add_argument("--phases", type=float, nargs="+", default=[0.0, 0.25, 0.5, 0.75],
                   help="phases t/T of the last wingbeat, in [0, 1) (default 0 0.25 0.5 0.75)")
    p.add_argument("-o", "--output", help="PNG file (one phase) or folder (default: RUN/snapshots)")
    p.add_argument("--size", type=int, nargs=2, default=[1200, 800], metavar=("W", "H"))
    p.add_argument("--wing-color", type=float, nargs=3, metavar=("R", "G", "B"),
                   help="one colour for the wing instead of the pressure jump")
    p.add_argument("--no-wake", action="store_true", help="leave the wake out")
    args = p.parse_args()

    chain_pvd = os.path.join(args.run, "chain.pvd")
    if not os.path.isfile(chain_pvd):
        chain_pvd = os.path.join(args.run, "fem.pvd")  # a run of the wing's FEM
    if not os.path.isfile(chain_pvd):
        fail(f"{args.run}: no chain.pvd nor fem.pvd (a run with [output] vtk_every = 0 writes no pictures)")
    for ph in args.phases:
        if not 0.0 <= ph < 1.0:
            fail(f"--phases: {ph} is outside [0, 1)")
    summary = os.path.join(args.run, "summary.json")
    frequency = json.load(open(summary))["frequency_hz"] if os.path.isfile(summary) else None
    chain_series = read_pvd(chain_pvd)
    if not chain_series:
        fail(f"{chain_pvd}: no frames")
    wing_pvd, wake_pvd = os.path.join(args.run, "wing.pvd"), os.path.join(args.run, "wake.pvd")
    wing_series = read_pvd(wing_pvd) if os.path.isfile(wing_pvd) else []
    wake_series = read_pvd(wake_pvd) if os.path.isfile(wake_pvd) else []
    if frequency is None:  # a run still going: t/T of the frames themselves
        first = read_vtp(chain_series[-1][1])
        t_over_T, t = field(first, "t_over_T"), chain_series[-1][0]
        frequency = t_over_T / t if t > 0 else 1.0
    run = (wing_series, wake_series, chain_series, frequency)

    single = len(args.phases) == 1 and args.output and args.output.endswith(".png")
    folder = os.path.dirname(args.output) if single else (args.output or os.path.join(args.run, "snapshots"))
    if folder:
        os.makedirs(folder, exist_ok=True)
    view = shared_view(run)
    for phase in args.phases:
        entry = frame_at(chain_series, frequency, phase)
        index = chain_series.index(entry)
        output = args.output if single else os.path.join(folder, f"phase_{phase:.2f}.png")
        render(run, index, phase, args, output, view)


if __name__ == "__main__":
    main()
