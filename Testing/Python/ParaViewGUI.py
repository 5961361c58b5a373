"""Runs inside the ParaView GUI (paraview --script=ParaViewGUI.py), as a new
user would click it: open the aorta centerline, clean it, apply the Cubic
Spline filter (shown coloured by Torsion without being asked), centre the
diverging map on zero, and leave the filter selected so that its panel shows. Paths come from
the environment: SHAPESPLINES_PLUGIN, SHAPESPLINES_DATA, SHAPESPLINES_READY
(a file written when the scene is ready for the screenshot).
"""
import os

from paraview.simple import *  # noqa: F401,F403

LoadPlugin(os.environ["SHAPESPLINES_PLUGIN"], remote=False, ns=globals())
reader = XMLPolyDataReader(registrationName="aorta-centerline.vtp",
                           FileName=[os.path.join(os.environ["SHAPESPLINES_DATA"], "aorta-centerline.vtp")])
# The centerline repeats a point; Clean merges it (the spline filter would say so in a warning).
clean = Clean(registrationName="Clean1", Input=reader)
curve = CubicSpline(registrationName="CubicSpline1", Input=clean)
view = GetActiveViewOrCreate("RenderView")
display = Show(curve, view)
# No ColorBy: the filter's output has Torsion as active scalars, so ParaView colours by it
# on its own, as a user sees it after Apply. Centre the diverging map on zero, as the
# README advises (the noisy cubic's extremes would squash it).
GetColorTransferFunction("Torsion").RescaleTransferFunction(-2.0, 2.0)
display.SetScalarBarVisibility(view, True)
display.LineWidth = 4.0
display.RenderLinesAsTubes = 1
ResetCamera(view)
SetActiveSource(curve)
Render(view)
with open(os.environ["SHAPESPLINES_READY"], "w") as ready:
    ready.write("ready\n")
