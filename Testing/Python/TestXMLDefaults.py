"""pvpython test: every ParaView property's default (the XML) is the VTK class's default.

Run as
    PYTHONPATH=<build>/lib/python3.11/site-packages \\
        xvfb-run -a pvpython TestXMLDefaults.py --plugin ShapeSplines.so

For each ShapeSplines proxy, each property with a Set command is compared with
Get<Name>() of a new instance of the wrapped class (from the shapesplines
package, without the plugin's XML): a C++ user and a ParaView user start from
the same settings. A string array property's "None" equals a null name. A
deprecated old name (an empty, hidden property that sets the same thing as a
visible one) has no default of its own: it must be hidden, empty, and share
its command with a visible property.
"""
import argparse
import math
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin
import shapesplines

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--plugin", required=True, help="path of ShapeSplines.so")
args = parser.parse_args()
LoadPlugin(args.plugin, remote=False)

PROXIES = ("CubicSpline", "GeneralizedCubicSpline", "TensionQuinticSpline", "VariableDegreeSpline",
           "QQRSpline", "PolylineShapeAnalysis", "CurvatureComb")
failures, compared, aliases = [], 0, 0
pxm = servermanager.ProxyManager()
for name in PROXIES:
    proxy = pxm.SMProxyManager.NewProxy("filters", name)
    fresh = getattr(shapesplines, proxy.GetVTKClassName())()
    iterator = proxy.NewPropertyIterator()
    iterator.Begin()
    properties = []
    while not iterator.IsAtEnd():
        properties.append(iterator.GetProperty())
        iterator.Next()
    visible_commands = {p.GetCommand() for p in properties if p.GetPanelVisibility() != "never"}
    for prop in properties:
        command = prop.GetCommand()
        if not command or not command.startswith("Set") or prop.IsA("vtkSMInputProperty") \
                or prop.GetInformationOnly():
            continue
        if prop.GetPanelVisibility() == "never" and prop.GetRepeatable():
            aliases += 1
            if prop.GetNumberOfElements() != 0 or command not in visible_commands:
                failures.append("%s.%s: an old name must be empty and set what a visible property sets"
                                " (%d elements, %s)" % (name, prop.GetXMLName(), prop.GetNumberOfElements(),
                                                       command))
            continue
        getter = getattr(fresh, "Get" + command[3:], None)
        if getter is None:
            failures.append("%s.%s: no Get%s in %s" % (name, prop.GetXMLName(), command[3:],
                                                       fresh.GetClassName()))
            continue
        expected = getter()
        # A new proxy's values are its XML defaults (no input: no domain changed them).
        xml = prop.GetElement(0)
        if prop.IsA("vtkSMStringVectorProperty"):
            same = (expected or "None") == (xml or "None")
        else:
            same = xml == expected or (isinstance(expected, float)
                                       and math.isclose(xml, expected, rel_tol=1e-12, abs_tol=0.0))
        compared += 1
        if not same:
            failures.append("%s.%s: XML default %r, %s::%s() %r" % (
                name, prop.GetXMLName(), xml, fresh.GetClassName(), "Get" + command[3:], expected))
if failures:
    print("%d of %d defaults differ:" % (len(failures), compared))
    for f in failures:
        print("  - " + f)
    sys.exit(1)
print("All %d property defaults of %d proxies equal the C++ defaults (%d old names checked empty)."
      % (compared, len(PROXIES), aliases))
