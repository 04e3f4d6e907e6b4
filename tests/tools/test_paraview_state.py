#!/usr/bin/python3
"""ctest tools.ParaViewState.TheRunStateReadsAtAGlance: a small flapsim run (flat plate,
rigid, 3 x 4 panels, 24 steps a wingbeat, 2 wingbeats, a frame every 2 steps); its
run.pvsm loaded the documented headless way (tools/paraview_state.py, VTK's Python, no
ParaView) must say:
- the chart draws exactly lift_N and CL: ParaView draws every column of the table not
  named hidden, and the table's columns are the frames' field data (read here from the
  frames with VTK) and Time;
- every coloured representation of each 3-D view has a visible scalar bar of its colour map;
- the wing's colour map is symmetric, ±R, with R the 98th percentile (nearest rank) of
  |Cp| (|pressure_jump_Pa| where the frames have no Cp) over every panel of every frame
  after t = 0, computed here with numpy (method "inverted_cdf": the nearest-rank rule);
- `make snapshot` writes the front and side views at phases 0, 0.25, 0.5, 0.75, and with
  the wing drawn in one flat colour (magenta) it covers at least 10 % of the front view's
  picture at each of the 4 phases (the issue's rule for a view that frames the wing).
A state that does not exist is bad input (exit status 2)."""
import glob
import os
import subprocess
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

import tool_test_args

a, work = tool_test_args.arguments("flapsim", "source", "work")
sys.path.insert(0, os.path.join(a.source, "tools"))
import paraview_state  # noqa: E402

case = tool_test_args.write_flapping_plate_case(a.source, os.path.join(work, "case.toml"), "plate", 24, 2, 2)
run = os.path.join(work, "run")
tool_test_args.run_case(a.flapsim, case, run)
check = tool_test_args.Checks()
failures = check.failures


def frames(pvd):
    return [read(path) for _, path in paraview_state.read_pvd(os.path.join(run, pvd))]


def read(path):
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    return r.GetOutput()


state = paraview_state.State(os.path.join(run, "run.pvsm"))
wing_frames = frames("wing.pvd")

# 1. The chart: exactly lift_N and CL.
fd = wing_frames[-1].GetFieldData()
columns = {fd.GetArrayName(i) for i in range(fd.GetNumberOfArrays())} | {"Time"}
visible = paraview_state.chart_visible_series(state, sorted(columns))
print(f"chart columns {sorted(columns)}, drawn {visible}")
check(visible == ["CL", "lift_N"], f"the chart draws {visible}, expected exactly CL and lift_N")
chart = state.of_type("XYChartRepresentation")[0]
check(chart.one("XArrayName") == "t_over_T", f"the chart's x axis is {chart.one('XArrayName')}, expected t_over_T")

# 2. A scalar bar for every coloured representation, in each 3-D view.
views = state.render_views()
check(len(views) == 2, f"{len(views)} 3-D views, expected 2 (front and side)")
for view, name in views:
    reps = state.representations(view)
    bars = {r.get("LookupTable")[0] for r in reps
            if r.type == "ScalarBarWidgetRepresentation" and r.one("Visibility") == "1"}
    coloured = [r for r in reps if r.type == "GeometryRepresentation" and r.one("Visibility") == "1"
                and r.get("ColorArrayName", ["", "", "", "", ""])[4]]
    check(len(coloured) == 2, f"{name}: {len(coloured)} coloured representations, expected 2 (wing, wake)")
    for r in coloured:
        check(r.get("LookupTable")[0] in bars,
              f"{name}: {r.get('ColorArrayName')[4]} of {state.reader_file(r.get('Input')[0])} has no scalar bar")

# 3. The wing's range: symmetric, the 98th percentile of |field| over the frames after t = 0.
wing_reps = [r for v, _ in views for r in state.representations(v)
             if r.type == "GeometryRepresentation" and state.reader_file(r.get("Input")[0]) == "wing.pvd"]
has_cp = wing_frames[-1].GetCellData().GetArray("Cp") is not None
expected_field = "Cp" if has_cp else "pressure_jump_Pa"
values = np.concatenate([np.abs(vtk_to_numpy(f.GetCellData().GetArray(expected_field)))
                         for f in wing_frames if f.GetFieldData().GetArray("step").GetValue(0) > 0])
p98 = float(np.percentile(values, 98.0, method="inverted_cdf"))
for r in wing_reps:
    check(r.get("ColorArrayName")[4] == expected_field,
          f"the wing is coloured by {r.get('ColorArrayName')[4]}, expected {expected_field}")
    points = state.proxies[r.get("LookupTable")[0]].numbers("RGBPoints")
    lo, hi = points[0], points[-4]
    print(f"wing range [{lo:.6g}, {hi:.6g}] {expected_field}; 98th percentile {p98:.6g}, largest {values.max():.6g}")
    check(abs(lo + hi) <= 1e-12 * abs(hi), f"the wing's range [{lo}, {hi}] is not symmetric")
    check(abs(hi - p98) <= 1e-9 * p98, f"the wing's range {hi} is not the 98th percentile {p98}")

# 4. make snapshot: 4 phases x 2 views; the wing covers >= 10 % of the front view.
xvfb = tool_test_args.XVFB_RUN
r = subprocess.run(["make", "-C", a.source, "--no-print-directory", "snapshot", f"RUN={run}"],
                   capture_output=True, text=True)
print(r.stdout[-1500:], r.stderr[-1500:])
check(r.returncode == 0, f"make snapshot exited {r.returncode}")
shots = sorted(os.path.basename(p) for p in glob.glob(os.path.join(run, "snapshots", "*.png")))
expected = sorted(f"{v}_phase_{p}.png" for v in ("front", "side") for p in ("0.00", "0.25", "0.50", "0.75"))
check(shots == expected, f"make snapshot wrote {shots}, expected {expected}")
flat = os.path.join(work, "flat")
subprocess.run(xvfb + ["/usr/bin/python3", os.path.join(a.source, "tools", "paraview_state.py"),
                       os.path.join(run, "run.pvsm"), "-o", flat, "--wing-colour", "1", "0", "1"], check=True)
for phase in ("0.00", "0.25", "0.50", "0.75"):
    rgb = tool_test_args.read_png_rgb(os.path.join(flat, f"front_phase_{phase}.png"))
    h, w, _ = rgb.shape
    magenta = (rgb[:, :, 0] > 0.5) & (rgb[:, :, 2] > 0.5) & (rgb[:, :, 1] < 0.5 * np.minimum(rgb[:, :, 0], rgb[:, :, 2]))
    share = magenta.mean()
    print(f"phase {phase}: the wing covers {100 * share:.1f} % of the front view ({w} x {h})")
    check(share >= 0.10, f"phase {phase}: the wing covers {100 * share:.1f} % of the front view, expected >= 10 %")

# 5. Bad input.
status = subprocess.run(xvfb + ["/usr/bin/python3", os.path.join(a.source, "tools", "paraview_state.py"),
                                os.path.join(work, "none.pvsm")], capture_output=True).returncode
check(status == 2, f"a missing state gave exit status {status}, expected 2")
sys.exit(1 if failures else 0)
