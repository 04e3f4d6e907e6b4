#!/usr/bin/python3
"""A run's ParaView state (run.pvsm) rendered without ParaView: the project's own reader
of the state's objects (PVD readers, the representations of each 3-D view with their
colour maps, scalar bars and opacity, the views' cameras, the chart's series), drawn
offscreen with VTK's Python (python3-vtk9). Debian 12's ParaView has no Python without
python3-paraview, which conflicts with python3-vtk9 (README, "ParaView"); this reads the
same file ParaView's GUI loads, so what it draws is what the state says.

    xvfb-run -a tools/paraview_state.py out/hover_flexible/run.pvsm           # 4 phases
    xvfb-run -a tools/paraview_state.py out/hover_flexible/run.pvsm --movie out/hover_flexible/movie.mp4

Snapshots: for each phase t/T of the last complete wingbeat written (default 0, 0.25,
0.5, 0.75) and each 3-D view of the state (front, side), a PNG
RUN/snapshots/<view>_phase_<phase>.png, captioned with t/T and the lift. Movie: the
state's first 3-D view at every frame of the last wingbeat, one camera (the state's),
encoded as H.264 MP4 by ffmpeg (Debian package ffmpeg). VTK's render window needs an X
display: run under xvfb-run (packages xvfb, xauth). Exit status 0, 2 on bad input (no
state, a state naming a missing file, a phase outside [0, 1), no ffmpeg for a movie).
docs/fsi.md, "Rendering the state headless".
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import vtk

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from render_run import frame_at, read_pvd, read_vtp  # noqa: E402
from si_prefix import run_force_scale  # noqa: E402


class StateError(Exception):
    pass


class Proxy:
    """One <Proxy> of the state: group, type, id and its properties, each a list of
    element values (strings) or of referenced proxy ids (ints)."""

    def __init__(self, element):
        self.group, self.type, self.id = element.get("group"), element.get("type"), int(element.get("id"))
        self.properties = {}
        for p in element.findall("Property"):
            refs = p.findall("Proxy")
            if refs:
                self.properties[p.get("name")] = [int(r.get("value")) for r in refs]
            else:
                self.properties[p.get("name")] = [e.get("value") for e in p.findall("Element")]

    def get(self, name, default=None):
        return self.properties.get(name, default)

    def one(self, name, default=None):
        v = self.properties.get(name)
        return v[0] if v else default

    def numbers(self, name, default=None):
        v = self.properties.get(name)
        return [float(x) for x in v] if v else default


class State:
    """The objects of a .pvsm file, its readers' files resolved against its folder (as
    `cd RUN && paraview --state=run.pvsm` does)."""

    def __init__(self, path):
        if not os.path.isfile(path):
            raise StateError(f"{path}: no such state file")
        try:
            root = ET.parse(path).getroot()
        except ET.ParseError as e:
            raise StateError(f"{path}: not XML: {e}")
        self.path, self.folder = path, os.path.dirname(os.path.abspath(path))
        self.proxies = {}
        for e in root.iter("Proxy"):
            if e.get("group") is not None:
                p = Proxy(e)
                self.proxies[p.id] = p
        self.collections = {c.get("name"): {int(i.get("id")): i.get("name") for i in c.findall("Item")}
                            for c in root.iter("ProxyCollection")}
        self.series = {}  # reader id -> [(time, file)]
        for p in self.of_type("PVDReader"):
            pvd = os.path.join(self.folder, p.one("FileName"))
            if not os.path.isfile(pvd):
                raise StateError(f"{path}: reader {p.id} names {p.one('FileName')}, which does not exist")
            self.series[p.id] = read_pvd(pvd)

    def of_type(self, kind):
        return [p for p in self.proxies.values() if p.type == kind]

    def render_views(self):
        """The 3-D views in the order of the "views" collection, with their names."""
        names = self.collections.get("views", {})
        return [(self.proxies[i], n) for i, n in names.items() if self.proxies[i].type == "RenderView"]

    def representations(self, view):
        return [self.proxies[i] for i in view.get("Representations", [])]

    def reader_file(self, reader_id):
        return self.proxies[reader_id].one("FileName")

    def timed_reader(self):
        """The reader whose field data the chart plots (the input of ExtractFieldDataOverTime)."""
        over_time = self.of_type("ExtractFieldDataOverTime")
        if not over_time:
            raise StateError(f"{self.path}: no ExtractFieldDataOverTime (the lift chart)")
        return over_time[0].get("Input")[0]


def chart_visible_series(state, columns):
    """The series ParaView's line chart draws from a table of these columns: every column
    but the X array, except those SeriesVisibility sets to 0 (a column the state does not
    name is drawn: ParaView's default)."""
    rep = state.of_type("XYChartRepresentation")[0]
    pairs = rep.get("SeriesVisibility", [])
    listed = {pairs[i]: pairs[i + 1] == "1" for i in range(0, len(pairs) - 1, 2)}
    x = rep.one("XArrayName")
    return sorted(c for c in columns if c != x and listed.get(c, True))


def chart_columns(state):
    """The columns of "Plot Global Variables Over Time" on the chart's reader: the field
    data of its frames and ParaView's Time."""
    frame = read_vtp(state.series[state.timed_reader()][-1][1])
    fd = frame.GetFieldData()
    return sorted({fd.GetArrayName(i) for i in range(fd.GetNumberOfArrays())} | {"Time"})


def lookup_table(proxy):
    """A vtkColorTransferFunction of a PVLookupTable's RGBPoints (x, r, g, b …)."""
    points = proxy.numbers("RGBPoints")
    ctf = vtk.vtkColorTransferFunction()
    if proxy.one("ColorSpace") == "3":
        ctf.SetColorSpaceToDiverging()
    for i in range(0, len(points), 4):
        ctf.AddRGBPoint(*points[i:i + 4])
    ctf.ClampingOn()
    return ctf


def nearest_frame(series, t):
    return min(series, key=lambda e: abs(e[0] - t))[1]


def field(data, name, default=float("nan")):
    a = data.GetFieldData().GetArray(name)
    return a.GetTuple1(0) if a is not None else default


def build_renderer(state, view, t, solid=None):
    """A vtkRenderer of the 3-D view (a RenderView proxy) at time t [s]: its
    representations, scalar bars and camera. solid: {pvd file name: (r, g, b)} draws
    that series in one flat colour instead (for measuring what a picture shows)."""
    solid = solid or {}
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(*(view.numbers("Background") or [1.0, 1.0, 1.0]))
    renderer.TwoSidedLightingOn()
    for rep in state.representations(view):
        if rep.one("Visibility", "1") != "1":
            continue
        if rep.type == "ScalarBarWidgetRepresentation":
            bar = vtk.vtkScalarBarActor()
            bar.SetLookupTable(lookup_table(state.proxies[rep.get("LookupTable")[0]]))
            # A long title ("circulation [m^2/s]") breaks before its unit: centred over a bar
            # at the view's right edge, one line ran off the picture.
            bar.SetTitle(re.sub(r" ([\[(])", r"\n\1", rep.one("Title", ""), count=1))
            bar.SetOrientationToVertical()
            bar.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
            x, y = rep.numbers("Position") or [0.89, 0.05]
            bar.GetPositionCoordinate().SetValue(x, y)
            bar.SetWidth(0.1)
            bar.SetHeight(rep.numbers("ScalarBarLength", [0.33])[0])
            bar.SetNumberOfLabels(5)
            # Fixed font sizes: fitted to the bar's width, a short title ("Cp") was drawn
            # taller than the bar's labels by five.
            bar.UnconstrainedFontSizeOn()
            bar.SetVerticalTitleSeparation(8)  # [px] between the title and the top label
            for text, size in ((bar.GetTitleTextProperty(), 16), (bar.GetLabelTextProperty(), 14)):
                text.SetColor(0, 0, 0)
                text.SetFontSize(size)
                text.ShadowOff()
                text.ItalicOff()
            renderer.AddViewProp(bar)
            continue
        if rep.type != "GeometryRepresentation":
            continue
        reader = rep.get("Input")[0]
        data = read_vtp(nearest_frame(state.series[reader], t))
        if data.GetNumberOfCells() == 0:
            continue
        mapper = vtk.vtkPolyDataMapper()
        mapper.SetInputData(data)
        colour = rep.get("ColorArrayName", ["", "", "", "0", ""])
        actor = vtk.vtkActor()
        prop = actor.GetProperty()
        flat = solid.get(state.reader_file(reader))
        if flat is not None:
            mapper.ScalarVisibilityOff()
            prop.SetColor(*flat)
            prop.LightingOff()
        elif colour[4]:
            mapper.SetScalarModeToUseCellFieldData() if colour[3] == "1" else mapper.SetScalarModeToUsePointFieldData()
            mapper.SelectColorArray(colour[4])
            mapper.SetLookupTable(lookup_table(state.proxies[rep.get("LookupTable")[0]]))
            mapper.UseLookupTableScalarRangeOn()
            mapper.SetColorModeToMapScalars()
        else:
            mapper.ScalarVisibilityOff()
            prop.SetColor(*(rep.numbers("DiffuseColor") or [1.0, 1.0, 1.0]))
        # Some light on faces seen edge-on (ParaView's light kit is softer than one light).
        prop.SetAmbient(rep.numbers("Ambient", [0.2])[0])
        prop.SetDiffuse(rep.numbers("Diffuse", [0.8])[0])
        kind = rep.one("Representation", "Surface")
        if kind == "Wireframe":
            prop.SetRepresentationToWireframe()
        elif kind == "Points":
            prop.SetRepresentationToPoints()
        if kind == "Surface With Edges" and flat is None:
            prop.EdgeVisibilityOn()
            prop.SetEdgeColor(0.0, 0.0, 0.5)
        prop.SetOpacity(rep.numbers("Opacity", [1.0])[0])
        prop.SetLineWidth(rep.numbers("LineWidth", [1.0])[0])
        actor.SetMapper(mapper)
        renderer.AddActor(actor)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(*view.numbers("CameraPosition"))
    camera.SetFocalPoint(*view.numbers("CameraFocalPoint"))
    camera.SetViewUp(*view.numbers("CameraViewUp"))
    camera.SetParallelProjection(view.one("CameraParallelProjection", "0") == "1")
    if view.numbers("CameraParallelScale"):
        camera.SetParallelScale(view.numbers("CameraParallelScale")[0])
    renderer.ResetCameraClippingRange()
    return renderer


def view_size(view, size=None):
    return size or [int(float(v)) for v in (view.get("ViewSize") or [800, 600])]


def caption(state, t):
    """t/T and the lift of the chart's frame nearest to time t."""
    frame = read_vtp(nearest_frame(state.series[state.timed_reader()], t))
    lift = field(frame, 'lift_N')
    # One unit for the whole movie, read once: the run's (a fruit fly's in uN).
    if getattr(state, "force_scale", None) is None:
        state.force_scale = run_force_scale(state.folder, lift)
    factor, unit = state.force_scale
    return (f"t/T = {field(frame, 't_over_T'):.3f}   t = {t * 1e3:.2f} ms   "
            f"lift = {lift * factor:.4g} {unit}")


def render(state, view, t, size=None, solid=None, title=True, window=None):
    """The picture of the 3-D view at time t, as a vtkImageData (RGB); drawn in window (a
    vtkRenderWindow kept over several pictures: one X connection) or in a new one."""
    renderer = build_renderer(state, view, t, solid)
    w, h = view_size(view, size)
    if title:
        text = vtk.vtkTextActor()
        text.SetInput(caption(state, t))
        text.GetTextProperty().SetColor(0, 0, 0)
        text.GetTextProperty().SetFontSize(max(10, h // 40))
        text.SetDisplayPosition(8, 8)
        renderer.AddViewProp(text)
    own = window is None
    if own:
        window = vtk.vtkRenderWindow()
        window.SetOffScreenRendering(1)
    window.GetRenderers().RemoveAllItems()
    window.AddRenderer(renderer)
    window.SetSize(w, h)
    window.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.SetInputBufferTypeToRGB()
    grab.Update()
    image = vtk.vtkImageData()
    image.DeepCopy(grab.GetOutput())
    window.RemoveRenderer(renderer)
    if own:
        window.Finalize()
    return image


def write_png(image, path):
    tmp = path + f".tmp.{os.getpid()}.png"
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(tmp)
    writer.SetInputData(image)
    writer.Write()
    os.replace(tmp, path)  # atomic: a reader never sees half a picture


def wingbeat_frequency(state):
    """1/T from the chart reader's last frame (t_over_T / t)."""
    t, path = state.series[state.timed_reader()][-1]
    s = field(read_vtp(path), "t_over_T")
    if not (t > 0 and s > 0):
        raise StateError(f"{state.path}: the last frame has no t/T to find the wingbeat by")
    return s / t


def last_wingbeat_times(state):
    """The times of the chart reader's frames within the last wingbeat written (t/T from
    the last frame's minus 1 to it, both ends)."""
    f = wingbeat_frequency(state)
    series = state.series[state.timed_reader()]
    last = series[-1][0] * f
    return [t for t, _ in series if t * f >= last - 1.0 - 1e-9]


def snapshots(state, phases, folder, size=None, solid=None):
    os.makedirs(folder, exist_ok=True)
    f = wingbeat_frequency(state)
    series = state.series[state.timed_reader()]
    written = []
    window = vtk.vtkRenderWindow()  # one X connection for every picture
    window.SetOffScreenRendering(1)
    for phase in phases:
        t = frame_at(series, f, phase)[0]
        for view, name in state.render_views():
            label = "front" if name == "RenderView1" else "side" if name == "RenderView2" else name
            path = os.path.join(folder, f"{label}_phase_{phase:.2f}.png")
            write_png(render(state, view, t, size, solid, window=window), path)
            written.append(path)
            print(f"wrote {path}")
    window.Finalize()
    return written


def movie(state, output, size=None, fps=25):
    """The state's first 3-D view at every frame of the last wingbeat, as an MP4."""
    ffmpeg = shutil.which("ffmpeg")
    if ffmpeg is None:
        raise StateError("no ffmpeg to encode the movie: apt-get install ffmpeg (tools/install_deps.sh)")
    view = state.render_views()[0][0]
    w, h = view_size(view, size)
    w, h = w - w % 2, h - h % 2  # H.264 with yuv420p takes even sizes
    times = last_wingbeat_times(state)
    folder = os.path.dirname(os.path.abspath(output))
    os.makedirs(folder, exist_ok=True)
    window = vtk.vtkRenderWindow()  # one for every frame
    window.SetOffScreenRendering(1)
    with tempfile.TemporaryDirectory(prefix=".movie-", dir=folder) as frames:
        for k, t in enumerate(times):
            write_png(render(state, view, t, [w, h], window=window), os.path.join(frames, f"frame_{k:05d}.png"))
        window.Finalize()
        tmp = os.path.join(frames, "movie.mp4")
        r = subprocess.run([ffmpeg, "-loglevel", "error", "-y", "-framerate", str(fps), "-i",
                            os.path.join(frames, "frame_%05d.png"), "-c:v", "libx264", "-pix_fmt", "yuv420p",
                            tmp], capture_output=True, text=True)
        if r.returncode != 0:
            raise StateError(f"ffmpeg failed: {r.stderr.strip()}")
        os.replace(tmp, output)
    print(f"wrote {output} ({len(times)} frames, {w} x {h}, {fps} per second: the last wingbeat)")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("state", help="a run's run.pvsm")
    p.add_argument("--phases", type=float, nargs="+", default=[0.0, 0.25, 0.5, 0.75],
                   help="phases t/T of the last wingbeat, in [0, 1) (default 0 0.25 0.5 0.75)")
    p.add_argument("-o", "--output", help="folder of the snapshots (default: the state's folder/snapshots)")
    p.add_argument("--movie", metavar="MP4", help="write a movie of the last wingbeat instead")
    p.add_argument("--fps", type=int, default=25, help="frames per second of the movie (default 25)")
    p.add_argument("--size", type=int, nargs=2, metavar=("W", "H"), help="pixels (default: the state's ViewSize)")
    p.add_argument("--wing-colour", type=float, nargs=3, metavar=("R", "G", "B"),
                   help="the wing (wing.pvd) in one flat colour, to measure where it is in the picture")
    args = p.parse_args()
    try:
        for ph in args.phases:
            if not 0.0 <= ph < 1.0:
                raise StateError(f"--phases: {ph} is outside [0, 1)")
        state = State(args.state)
        if args.movie:
            movie(state, args.movie, args.size, args.fps)
        else:
            solid = {"wing.pvd": tuple(args.wing_colour)} if args.wing_colour else None
            snapshots(state, args.phases, args.output or os.path.join(state.folder, "snapshots"), args.size, solid)
    except StateError as e:
        print(f"paraview_state: error: {e}", file=sys.stderr)
        sys.exit(2)


if __name__ == "__main__":
    main()
