"""Render the coiling snake (prm/coiling_snake.prm) with ParaView.

    xvfb-run -a pvpython contrib/render_snake.py output/coiling_snake/snake.pvd doc/figures

Writes coiling_snake_<angle>.png, views from above (along z) of the deformed
snake at a quarter, half, three quarters and the whole of the head's turn,
coloured by the von Mises stress. Stops with a non-zero exit status if
ParaView reports a warning or error (under xvfb-run, ParaView 5.11 from Debian
12 sometimes aborts at start with a GLX error; running it again works).
"""

import argparse
import os

from paraview.simple import ColorBy, Render, SaveScreenshot, Show

from pv_series import WarningCounter, nearest_step, open_series


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pvd")
    parser.add_argument("figures")
    args = parser.parse_args()
    os.makedirs(args.figures, exist_ok=True)
    counter = WarningCounter()
    times, warp, view = open_series(args.pvd, 800)
    display = Show(warp, view)
    ColorBy(display, ("CELLS", "von_mises"))
    for fraction in (0.25, 0.5, 0.75, 1.0):
        t = nearest_step(times, fraction * times[-1])
        view.ViewTime = t
        display.RescaleTransferFunctionToDataRange(False, True)
        view.CameraPosition = [0.2, 0.1, 1.5]
        view.CameraFocalPoint = [0.2, 0.1, 0.0]
        view.CameraViewUp = [0.0, 1.0, 0.0]
        view.CameraParallelProjection = 1
        view.ResetCamera()
        Render(view)
        SaveScreenshot(os.path.join(args.figures, "coiling_snake_%03d.png"
                                    % round(360 * t)), view,
                       ImageResolution=[800, 800])
    counter.exit_on_messages()


if __name__ == "__main__":
    main()
