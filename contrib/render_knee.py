"""Render the knee flexion scene (prm/knee_flexion.prm) with ParaView.

Run with ParaView's Python under a virtual display:

    xvfb-run -a pvpython contrib/render_knee.py output/knee_flexion/knee.pvd doc/figures

Writes, from the PVD series of a run:
  knee_flexion_<angle>.png  side views (along the knee axis) of the deformed
                            leg at 0 degrees, the last step and evenly spaced
                            steps between, coloured by body;
  knee_skin_depth.png       the skin-fat layer at the last step, coloured by
                            material depth (the fold behind the knee);
  knee_cutaway.png          the last step cut at x = 0 (the mid-plane):
                            femur, patella on the condyles, ligament, tendon.
The flexion angle of a step is its load factor (the PVD time) times the
angle given with --angle (default 150 degrees).
Stops with a non-zero exit status if ParaView reports a warning or error.
(Under xvfb-run, ParaView 5.11 from Debian 12 sometimes aborts at start with a
GLX error of the virtual display; running it again works.)
"""

import argparse
import os

from paraview.simple import (
    Clip,
    ColorBy,
    GetActiveViewOrCreate,
    GetColorTransferFunction,
    GetScalarBar,
    Hide,
    Render,
    SaveScreenshot,
    Show,
    Threshold,
)

from pv_series import WarningCounter, nearest_step, open_series


BODY_COLOURS = [  # material id 1..7
    (0.93, 0.90, 0.80),  # femur
    (0.85, 0.82, 0.70),  # tibia
    (0.95, 0.85, 0.55),  # patella
    (0.45, 0.65, 0.85),  # patellar ligament
    (0.35, 0.55, 0.80),  # quadriceps tendon
    (0.80, 0.30, 0.30),  # quadriceps muscle
    (0.95, 0.75, 0.65),  # skin-fat
]


def side_camera(view):
    view.CameraPosition = [1.0, 0.0, 0.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraParallelProjection = 1
    view.ResetCamera()
    view.CameraParallelScale = 0.24


def colour_by_body(display):
    ColorBy(display, ("CELLS", "material_id"))
    lut = GetColorTransferFunction("material_id")
    lut.InterpretValuesAsCategories = 1
    lut.Annotations = sum(
        ([str(i + 1), name] for i, name in enumerate(
            ["femur", "tibia", "patella", "ligament", "tendon", "muscle",
             "skin-fat"])), [])
    lut.IndexedColors = [c for rgb in BODY_COLOURS for c in rgb]
    display.SetScalarBarVisibility(GetActiveViewOrCreate("RenderView"), False)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pvd")
    parser.add_argument("figures")
    parser.add_argument("--angle", type=float, default=150.0,
                        help="flexion angle at load factor 1, degrees")
    parser.add_argument("--frames", type=int, default=4)
    args = parser.parse_args()
    os.makedirs(args.figures, exist_ok=True)
    counter = WarningCounter()

    times, warp, view = open_series(args.pvd, 900)

    # the flexion sequence
    display = Show(warp, view)
    colour_by_body(display)
    # the steps nearest to evenly spaced angles (cut-back steps are uneven)
    n = max(args.frames, 2)
    picks = sorted({nearest_step(times, i * times[-1] / (n - 1))
                    for i in range(n)})
    for t in picks:
        view.ViewTime = t
        side_camera(view)
        Render(view)
        angle = round(t * args.angle)
        SaveScreenshot(os.path.join(args.figures,
                                    "knee_flexion_%03d.png" % angle), view,
                       ImageResolution=[900, 900])
    view.ViewTime = times[-1]

    # the skin-fat layer at the last step, coloured by material depth
    Hide(warp, view)
    skin = Threshold(Input=warp, Scalars=["CELLS", "material_id"])
    skin.LowerThreshold = 7
    skin.UpperThreshold = 7
    skin_display = Show(skin, view)
    ColorBy(skin_display, ("POINTS", "material_depth"))
    skin_display.RescaleTransferFunctionToDataRange(True, False)
    skin_display.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(GetColorTransferFunction("material_depth"), view)
    bar.Title = "material depth (m)"
    bar.ComponentTitle = ""
    bar.TitleColor = [0.0, 0.0, 0.0]
    bar.LabelColor = [0.0, 0.0, 0.0]
    side_camera(view)
    view.CameraPosition = [0.6, -0.8, 0.0]  # from behind and the side
    view.ResetCamera()
    view.CameraParallelScale = 0.24
    Render(view)
    SaveScreenshot(os.path.join(args.figures, "knee_skin_depth.png"), view,
                   ImageResolution=[900, 900])
    Hide(skin, view)

    # a cut-away at the mid-plane x = 0
    clip = Clip(Input=warp)
    clip.ClipType = "Plane"
    clip.ClipType.Origin = [0.0, 0.0, 0.0]
    clip.ClipType.Normal = [1.0, 0.0, 0.0]
    clip.Crinkleclip = 0
    clip_display = Show(clip, view)
    colour_by_body(clip_display)
    side_camera(view)
    Render(view)
    SaveScreenshot(os.path.join(args.figures, "knee_cutaway.png"), view,
                   ImageResolution=[900, 900])

    counter.exit_on_messages()
    print("wrote %d flexion views, the skin's depth and a cut-away to %s"
          % (len(picks), args.figures))


if __name__ == "__main__":
    main()
