"""Runs inside the ParaView GUI (paraview --script=ParaViewGUI.py), as a new
user would click it: open the aorta centerline, clean it, apply the Cubic
Spline filter (shown coloured by Torsion without being asked) and leave the
filter selected so that its panel shows. The plugin's auto-start
(Plugin/pqShapeSplinesTorsionColors.h) centres the Torsion map on zero over
the output's TorsionColorRange; this script checks that it does, that it wins
over ParaView's own rescale after an Apply, and that it keeps a range the user
locked. Paths come from the environment: SHAPESPLINES_PLUGIN, SHAPESPLINES_DATA,
SHAPESPLINES_READY (written when the scene is ready for the screenshot: "ready"
and what was checked, or "failed" and why).
"""
import math
import os
import traceback

from paraview.modules.vtkRemotingViews import vtkSMTransferFunctionManager
from paraview.simple import *  # noqa: F401,F403

LoadPlugin(os.environ["SHAPESPLINES_PLUGIN"], remote=False, ns=globals())
reader = XMLPolyDataReader(registrationName="aorta-centerline.vtp",
                           FileName=[os.path.join(os.environ["SHAPESPLINES_DATA"], "aorta-centerline.vtp")])
# Clean, as users often do first (the centerline's repeated point would otherwise be
# merged by the filter and counted in MergedPoints).
clean = Clean(registrationName="Clean1", Input=reader)
curve = CubicSpline(registrationName="CubicSpline1", Input=clean)
view = GetActiveViewOrCreate("RenderView")
# No ColorBy: the filter's output has Torsion as active scalars, so ParaView colours by it
# on its own, as a user sees it after Apply.
display = Show(curve, view)
display.SetScalarBarVisibility(view, True)
display.LineWidth = 4.0
display.RenderLinesAsTubes = 1
ResetCamera(view)
SetActiveSource(curve)
Render(view)

colors = GetColorTransferFunction("Torsion")
opacities = GetOpacityTransferFunction("Torsion")
report = []


def finish(status, lines):
    with open(os.environ["SHAPESPLINES_READY"], "w") as ready:
        ready.write("\n".join([status] + lines) + "\n")


class NotYet(AssertionError):
    """A range the auto-start has not set yet: checked again a little later."""


def later(step, attempts=40):
    """Runs step once the GUI's event loop has run again: the auto-start acts
    there, after the script's or an Apply's updates (a one-shot timer of the
    render view's Qt interactor). A loaded machine can run the timer before
    the auto-start's pass: a range not yet as expected is checked again every
    quarter second, up to 10 s, before it fails."""
    interactor = view.GetInteractor()

    def fire(caller, event):
        caller.RemoveObserver(observer)
        written = len(report)
        try:
            step()
        except NotYet:
            if attempts > 1:
                del report[written:]  # what the attempt that came too early wrote
                later(step, attempts - 1)
            else:
                finish("failed", report + [traceback.format_exc()])
        except Exception:
            finish("failed", report + [traceback.format_exc()])

    observer = interactor.AddObserver("TimerEvent", fire)
    interactor.CreateOneShotTimer(250)


def apply(**properties):
    """What the GUI's Apply does once a filter's properties changed
    (pqApplyBehavior::applied): update the view, where the representations
    say their data changed, then rescale every unlocked map to the data
    (growing it), then render."""
    for name, value in properties.items():
        setattr(curve, name, value)
    view.Update()
    vtkSMTransferFunctionManager().ResetAllTransferFunctionRangesUsingCurrentData(
        servermanager.ActiveConnection.Session.GetSessionProxyManager(), False)
    Render(view)


def map_range(function):
    """The first and last control points' values (4 numbers a point in both functions)."""
    points = function.RGBPoints if function is colors else function.Points
    return points[0], points[-4]


def check(what, function, expected):
    found = map_range(function)
    report.append("%s range [%.6g, %.6g], expected [%.6g, %.6g]" % (what, *found, *expected))
    if not all(math.isclose(f, e, rel_tol=1e-9) for f, e in zip(found, expected)):
        raise NotYet("%s range [%.6g, %.6g] is not [%.6g, %.6g]" % (what, *found, *expected))


def robust_range():
    """(-m, m) from the output's field data TorsionColorRange."""
    return tuple(curve.FieldData["TorsionColorRange"].GetRange(0))


def torsion_range():
    return tuple(curve.PointData["Torsion"].GetRange(0))


def shown():
    """After Show: the map and the opacity function over [-m, m], m far below
    the spikes of the noisy cubic. Then the user locks a range of their own
    and changes the filter."""
    m = robust_range()[1]
    low, high = torsion_range()
    report.append("TorsionColorRange m = %.6g; Torsion over [%.6g, %.6g]" % (m, low, high))
    check("shown: colour map", colors, (-m, m))
    check("shown: opacity function", opacities, (-m, m))
    # The aorta's cubic: m near 30 where the spikes reach 222.
    if not 0 < m < max(-low, high) / 5:
        raise AssertionError("m = %g is not far below the largest |torsion| %g" % (m, max(-low, high)))
    # As Rescale to Custom Range > Rescale and disable automatic rescaling does.
    colors.AutomaticRescaleRangeMode = "Never"
    colors.RescaleTransferFunction(-5.0, 5.0)
    apply(NumberOfSubdivisions=20)
    later(locked)


def locked():
    """The locked range is the user's. Unlocked again, the next Apply grows
    the map over the data's range (checked right away) and the auto-start
    brings it back to [-m, m] (checked in applied)."""
    check("locked, after an Apply: colour map", colors, (-5.0, 5.0))
    colors.AutomaticRescaleRangeMode = "Grow and update on 'Apply'"
    apply(NumberOfSubdivisions=10)
    low, high = torsion_range()
    found = map_range(colors)
    report.append("unlocked, ParaView's own rescale at the end of the Apply: [%.6g, %.6g]" % found)
    slack = 1e-9 * (high - low)  # rescaling the control points rounds
    if not (found[0] <= low + slack and found[1] >= high - slack):
        raise AssertionError("ParaView's Apply did not grow the map over the data: [%g, %g]" % found)
    later(applied)


def applied():
    m = robust_range()[1]
    check("unlocked, after an Apply: colour map", colors, (-m, m))
    check("unlocked, after an Apply: opacity function", opacities, (-m, m))
    finish("ready", report)


later(shown)
