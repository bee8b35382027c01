"""Render the snake swallowing an apple (prm/apple_snake.prm) with ParaView.

    xvfb-run -a pvpython contrib/render_apple_snake.py output/apple_snake/apple.pvd doc/figures

Writes apple_snake_<percent>.png at the start and at a quarter, half, three
quarters and the whole of the apple's path: above, the snake seen from above
(along z), coloured by the von Mises stress; below, the same step seen
cut open at the snake's mid-plane z = 0 (its upper half removed), the apple
in red inside the lumen (what the lowest row of Fig. 50 shows by
transparency). Stops with a non-zero exit status if ParaView reports a warning or
error (under xvfb-run, ParaView 5.11 from Debian 12 sometimes aborts at start
with a GLX error; running it again works).
"""

import argparse
import os

from paraview.simple import (Clip, ColorBy, Hide, Render, SaveScreenshot,
                             Show, Threshold)

from pv_series import WarningCounter, nearest_step, open_series


def body(warp, material_id):
    """The cells of one body (material id) of the warped series."""
    part = Threshold(Input=warp, Scalars=["CELLS", "material_id"])
    part.LowerThreshold = material_id
    part.UpperThreshold = material_id
    return part


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pvd")
    parser.add_argument("figures")
    args = parser.parse_args()
    os.makedirs(args.figures, exist_ok=True)
    counter = WarningCounter()
    times, warp, view = open_series(args.pvd, 900)
    snake_cells = body(warp, 1)
    snake = Show(snake_cells, view)
    ColorBy(snake, ("CELLS", "von_mises"))
    half = Clip(Input=snake_cells)
    half.ClipType = "Plane"
    half.ClipType.Origin = [0.0, 0.0, 0.0]
    half.ClipType.Normal = [0.0, 0.0, 1.0]
    cut = Show(half, view)
    ColorBy(cut, ("CELLS", "von_mises"))
    apple = Show(body(warp, 2), view)
    apple.ColorArrayName = ["POINTS", ""]
    apple.AmbientColor = apple.DiffuseColor = [0.8, 0.1, 0.1]
    for fraction in (0.0, 0.25, 0.5, 0.75, 1.0):
        t = nearest_step(times, fraction * times[-1])
        view.ViewTime = t
        snake.RescaleTransferFunctionToDataRange(False, True)
        for name, whole in (("", True), ("_inside", False)):
            (Show if whole else Hide)(snake_cells, view)
            (Hide if whole else Show)(half, view)
            Render(view)  # before the camera: Show() may reset it
            view.CameraPosition = [0.3, 0.0, 1.5]
            view.CameraFocalPoint = [0.3, 0.0, 0.0]
            view.CameraViewUp = [0.0, 1.0, 0.0]
            view.CameraParallelProjection = 1
            view.ResetCamera()
            view.CameraParallelScale = 0.14
            Render(view)
            SaveScreenshot(os.path.join(args.figures, "apple_snake_%03d%s.png"
                                        % (round(100 * t), name)), view,
                           ImageResolution=[900, 360])
    counter.exit_on_messages()


if __name__ == "__main__":
    main()
