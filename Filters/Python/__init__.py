"""ShapeSplines: shape-preserving spline curves with curvature and torsion (VTK filters)."""
try:
    import vtkmodules.vtkCommonExecutionModel  # the base classes come first
except ImportError as error:
    # Typically a virtualenv's or pyenv's python3 first on PATH: it lacks the
    # VTK the filters were built against, ParaView's.
    import sys

    raise ImportError(
        "shapesplines needs ParaView's VTK (the vtkmodules package), which this Python "
        "(%s) cannot import: %s. Run it with Debian's /usr/bin/python3 (with the package "
        "python3-paraview installed) or with pvpython." % (sys.executable, error)) from error

from .ShapeSplinesFilters import *  # noqa: E402,F401,F403
