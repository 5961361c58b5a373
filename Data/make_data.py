#!/usr/bin/env python3
"""Regenerate the synthetic sample curves in this folder.

Run with a Python that has VTK's ``vtkmodules`` (e.g. Debian's python3-paraview):

    /usr/bin/python3 Data/make_data.py

Every file is a VTK XML PolyData (.vtp) file holding one polyline cell with
double-precision points, written as ASCII. aorta-centerline.vtp is real data
copied from VMTK's test data and is not generated here (see README.md).
"""
import math
from pathlib import Path

from vtkmodules.vtkCommonCore import VTK_DOUBLE, vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

HERE = Path(__file__).resolve().parent


def write_polyline(name, xyz, point_arrays=None):
    """Write the points xyz as one polyline to HERE/name; point_arrays: {name: values}."""
    points = vtkPoints()
    points.SetDataTypeToDouble()
    for p in xyz:
        points.InsertNextPoint(*p)
    lines = vtkCellArray()
    lines.InsertNextCell(len(xyz))
    for i in range(len(xyz)):
        lines.InsertCellPoint(i)
    poly = vtkPolyData()
    poly.SetPoints(points)
    poly.SetLines(lines)
    for array_name, values in (point_arrays or {}).items():
        assert len(values) == len(xyz), array_name
        array = vtkDoubleArray()
        array.SetName(array_name)
        for v in values:
            array.InsertNextValue(v)
        poly.GetPointData().AddArray(array)
    assert poly.GetPoints().GetDataType() == VTK_DOUBLE
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(str(HERE / name))
    writer.SetInputData(poly)
    writer.SetDataModeToAscii()
    if not writer.Write():
        raise RuntimeError(f"failed to write {name}")


def planar(xs, ys):
    assert len(xs) == len(ys)
    return [(x, y, 0.0) for x, y in zip(xs, ys)]


def main():
    # Circular helix (a cos t, a sin t, b t), a = 2, b = 1: 4 turns, 8 points
    # per turn, t in [0, 8 pi] inclusive. Curvature a/(a^2+b^2) = 0.4,
    # torsion b/(a^2+b^2) = 0.2.
    a, b, n = 2.0, 1.0, 4 * 8 + 1
    ts = [8.0 * math.pi * i / (n - 1) for i in range(n)]
    write_polyline("helix.vtp",
                   [(a * math.cos(t), a * math.sin(t), b * t) for t in ts],
                   {"Radius": [2.0] * n})

    # Akima (1970), J. ACM 17(4).
    write_polyline("akima.vtp", planar(
        [0, 2, 3, 5, 6, 8, 9, 11, 12, 14, 15],
        [10, 10, 10, 10, 10, 10, 10.5, 15, 50, 60, 85]))

    # RPN 15A, Fritsch & Carlson (1980), SIAM J. Numer. Anal. 17(2).
    write_polyline("rpn15a.vtp", planar(
        [7.99, 8.09, 8.19, 8.7, 9.2, 10, 12, 15, 20],
        [0, 2.76429e-5, 4.37498e-2, 0.169183, 0.469428, 0.943740,
         0.998636, 0.999919, 0.999994]))

    # Titanium heat data, de Boor, A Practical Guide to Splines (pppack titand).
    ti_y = [.644, .622, .638, .649, .652, .639, .646, .657, .652, .655,
            .644, .663, .663, .668, .676, .676, .686, .679, .678, .683,
            .694, .699, .710, .730, .763, .812, .907, 1.044, 1.336, 1.881,
            2.169, 2.075, 1.598, 1.211, .916, .746, .672, .627, .615, .607,
            .606, .609, .603, .601, .603, .601, .611, .601, .608]
    assert len(ti_y) == 49
    write_polyline("titanium.vtp", planar(range(595, 1076, 10), ti_y))


if __name__ == "__main__":
    main()
