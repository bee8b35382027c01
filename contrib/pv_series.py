"""What contrib/render_knee.py and contrib/render_snake.py share: a PVD
series warped by its displacement in a white render view, the step nearest
a given time, and a count of ParaView's warnings and errors.
Imported by pvpython scripts in this folder."""

import sys

from paraview.simple import GetActiveViewOrCreate, PVDReader, WarpByVector
import paraview.vtk as vtk


class WarningCounter:
    """Counts the messages VTK's output window receives (warnings, errors)."""

    def __init__(self):
        self.messages = []
        window = vtk.vtkOutputWindow.GetInstance()
        window.AddObserver("WarningEvent", self.collect)
        window.AddObserver("ErrorEvent", self.collect)

    def collect(self, obj, event):
        self.messages.append(event)

    def exit_on_messages(self):
        if self.messages:
            sys.exit("ParaView reported %d warning(s) or error(s)"
                     % len(self.messages))


def open_series(pvd, size):
    """(times, warped source, view) of the PVD series @p pvd: every field is
    point data on points duplicated per cell (the material id too, constant
    on each cell), the mesh moved by the point data 'displacement', shown in
    a white size x size view without orientation axes."""
    reader = PVDReader(FileName=pvd)
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues)
    if not times:
        sys.exit("no time steps in " + pvd)
    warp = WarpByVector(Input=reader, Vectors=["POINTS", "displacement"])
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [size, size]
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 0
    return times, warp, view


def nearest_step(times, t):
    """The step of @p times nearest to @p t (cut-back steps are uneven)."""
    return min(times, key=lambda s: abs(s - t))
