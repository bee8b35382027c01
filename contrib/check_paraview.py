#!/usr/bin/env pvpython
"""Load a TissueContact result series in ParaView and fail on any warning.

    xvfb-run -a pvpython contrib/check_paraview.py output/solution.pvd

Needs Debian's `paraview` (pvpython) and, without a display, `xvfb`. For
every state of the series (and of <base>-surface.pvd when it exists): the
reader's arrays are checked (displacement a 3-vector, cauchy_stress a
6-component symmetric tensor as cell data, the contact fields on the
surface), then Warp By Vector, Extract Surface and (on the volume) Cell Data to
Point Data with Tensor Glyph on the stress run on it; any VTK warning or error, a missing array or an
empty output makes the script exit with status 1. Not part of the ctest
suite (ParaView is a large dependency); doc/users/output.md describes it.
"""
import os
import sys

from paraview import simple, servermanager
from paraview import vtk as pvvtk  # noqa: F401 (loads the VTK modules)
from vtkmodules.vtkCommonCore import vtkCommand, vtkOutputWindow

problems = []


def install_catcher():
    window = vtkOutputWindow.GetInstance()

    def on_message(obj, event, *args):
        problems.append(event)

    for event in (vtkCommand.WarningEvent, vtkCommand.ErrorEvent):
        window.AddObserver(event, on_message)
    window.SetDisplayModeToAlwaysStdErr()


def check_series(pvd, surface):
    reader = simple.PVDReader(FileName=pvd)
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    for t in times:
        reader.UpdatePipeline(t)
        data = servermanager.Fetch(reader)
        points, cells = data.GetPointData(), data.GetCellData()
        need_points = {"displacement": 3}
        need_cells = {"body": 1} if surface else {"cauchy_stress": 6, "J": 1}
        if surface:
            need_points.update(contact_pressure=1, contact_traction=3,
                               penetration=1)
        for name, n in need_points.items():
            a = points.GetArray(name)
            if a is None or a.GetNumberOfComponents() != n:
                problems.append(f"{pvd} t={t}: point array {name} "
                                f"({n} components) missing")
        for name, n in need_cells.items():
            a = cells.GetArray(name)
            if a is None or a.GetNumberOfComponents() != n:
                problems.append(f"{pvd} t={t}: cell array {name} "
                                f"({n} components) missing")
        warped = simple.WarpByVector(Input=reader, Vectors=["POINTS",
                                                            "displacement"])
        outer = simple.ExtractSurface(Input=warped)
        outer.UpdatePipeline(t)
        n_faces = servermanager.Fetch(outer).GetNumberOfCells()
        if n_faces == 0:
            problems.append(f"{pvd} t={t}: Extract Surface gave no faces")
        if not surface:
            # the stress read as a symmetric tensor: glyphs oriented by its
            # eigenvectors at the points
            at_points = simple.CellDatatoPointData(Input=warped)
            glyphs = simple.TensorGlyph(Input=at_points,
                                        GlyphType="Sphere")
            glyphs.Tensors = ["POINTS", "cauchy_stress"]
            glyphs.ScaleFactor = 1e-3
            glyphs.UpdatePipeline(t)
            if servermanager.Fetch(glyphs).GetNumberOfPoints() == 0:
                problems.append(f"{pvd} t={t}: no stress tensor glyphs")
            simple.Delete(glyphs)
            simple.Delete(at_points)
        simple.Delete(outer)
        simple.Delete(warped)
    print(f"{pvd}: {len(times)} states, {data.GetNumberOfPoints()} points, "
          f"{data.GetNumberOfCells()} cells")


def main():
    if len(sys.argv) != 2 or not sys.argv[1].endswith(".pvd"):
        print(__doc__)
        return 2
    install_catcher()
    pvd = sys.argv[1]
    check_series(pvd, surface=False)
    surface = pvd[:-4] + "-surface.pvd"
    if os.path.exists(surface):
        check_series(surface, surface=True)
    if problems:
        print("ParaView reported problems:")
        for p in problems:
            print("  ", p)
        return 1
    print("ParaView read every file without a warning")
    return 0


if __name__ == "__main__":
    sys.exit(main())
