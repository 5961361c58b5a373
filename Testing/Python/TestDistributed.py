"""Distributed pvbatch: run as
    mpirun -np N pvbatch --symmetric TestDistributed.py --plugin P --data D --temp T
Rank 0 writes a partitioned input (.pvtp, 5 pieces of curves from Data/, each
line tagged by a LineId cell array); the reader spreads the pieces over the
ranks; every rank fits its lines with the CubicSpline proxy and compares them
with a serial fit of the whole input, line by line: points and every array
must be identical. Together the ranks must hold each line exactly once.
"""
import argparse
import os
import sys

import numpy as np
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIntArray
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersCore import vtkAppendPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter
from vtkmodules.vtkParallelCore import vtkMultiProcessController

import shapesplines

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--data", required=True)
parser.add_argument("--temp", required=True)
args = parser.parse_args()

controller = vtkMultiProcessController.GetGlobalController()
rank, size = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
folder = os.path.join(args.temp, "distributed-%d" % size)
PIECES = 5


def read(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def tagged_input():
    """All lines of the sample data in one poly data, with a LineId cell array."""
    append = vtkAppendPolyData()
    for name in ("aorta-centerline.vtp", "helix.vtp", "akima.vtp", "rpn15a.vtp", "titanium.vtp"):
        data = read(os.path.join(args.data, name))
        stripped = vtkPolyData()
        stripped.SetPoints(data.GetPoints())
        stripped.SetLines(data.GetLines())
        append.AddInputData(stripped)
    append.Update()
    data = append.GetOutput()
    ids = vtkIntArray()
    ids.SetName("LineId")
    for k in range(data.GetNumberOfCells()):
        ids.InsertNextValue(k)
    data.GetCellData().AddArray(ids)
    return data


def lines_of(data):
    offsets = vtk_to_numpy(data.GetLines().GetOffsetsArray())
    connectivity = vtk_to_numpy(data.GetLines().GetConnectivityArray())
    return [connectivity[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)]


def line_values(data, cell, ids):
    """Points and every point array of one output line, and its cell arrays."""
    values = {"points": vtk_to_numpy(data.GetPoints().GetData())[ids]}
    pd, cd = data.GetPointData(), data.GetCellData()
    for a in range(pd.GetNumberOfArrays()):
        values[pd.GetArrayName(a)] = vtk_to_numpy(pd.GetArray(a))[ids]
    for a in range(cd.GetNumberOfArrays()):
        values["cell " + cd.GetArrayName(a)] = vtk_to_numpy(cd.GetArray(a))[cell]
    return values


whole = tagged_input()
if rank == 0:
    os.makedirs(folder, exist_ok=True)
    line_ids = [ids for ids in lines_of(whole)]
    with open(os.path.join(folder, "lines.pvtp"), "w") as pvtp:
        pvtp.write('<?xml version="1.0"?>\n<VTKFile type="PPolyData" version="0.1" byte_order="LittleEndian">\n'
                   '  <PPolyData GhostLevel="0">\n    <PCellData><PDataArray type="Int32" Name="LineId"/></PCellData>\n'
                   '    <PPoints><PDataArray type="Float64" NumberOfComponents="3"/></PPoints>\n')
        for piece in range(PIECES):
            cells = [k for k in range(len(line_ids)) if k % PIECES == piece]
            part = vtkPolyData()
            points = whole.GetPoints().NewInstance()
            points.SetDataTypeToDouble()
            lines = whole.GetLines().NewInstance()
            ids = vtkIntArray()
            ids.SetName("LineId")
            for k in cells:
                start = points.GetNumberOfPoints()
                for i in line_ids[k]:
                    points.InsertNextPoint(whole.GetPoint(i))
                lines.InsertNextCell(len(line_ids[k]), range(start, start + len(line_ids[k])))
                ids.InsertNextValue(k)
            part.SetPoints(points)
            part.SetLines(lines)
            part.GetCellData().AddArray(ids)
            writer = vtkXMLPolyDataWriter()
            writer.SetFileName(os.path.join(folder, "piece%d.vtp" % piece))
            writer.SetInputData(part)
            writer.Write()
            pvtp.write('    <Piece Source="piece%d.vtp"/>\n' % piece)
        pvtp.write("  </PPolyData>\n</VTKFile>\n")
controller.Barrier()

# The serial reference: the wrapped filter on the whole input, on this rank alone
# (before LoadPlugin: loaded after it, the wrapped class is shadowed by the plugin's).
serial_filter = shapesplines.vtkCubicSplineFilter()
serial_filter.SetNumberOfSubdivisions(7)
serial_filter.SetInputData(whole)
serial_filter.Update()
serial = serial_filter.GetOutput()
serial_lines = lines_of(serial)
serial_ids = vtk_to_numpy(serial.GetCellData().GetArray("LineId"))

# The distributed pipeline, through the plugin's proxy.
LoadPlugin(args.plugin, remote=False, ns=globals())
reader = XMLPartitionedPolydataReader(FileName=[os.path.join(folder, "lines.pvtp")])
spline = CubicSpline(Input=reader, NumberOfSubdivisions=7)
spline.UpdatePipeline()
local = spline.GetClientSideObject().GetOutputDataObject(0)

failures = []
local_ids = []
if local.GetNumberOfCells() > 0:
    local_ids = list(vtk_to_numpy(local.GetCellData().GetArray("LineId")))
for cell, ids in enumerate(lines_of(local)):
    line = local_ids[cell]
    reference = int(np.nonzero(serial_ids == line)[0][0])
    mine = line_values(local, cell, ids)
    theirs = line_values(serial, reference, serial_lines[reference])
    if set(mine) != set(theirs):
        failures.append("line %d: arrays %s vs %s" % (line, sorted(mine), sorted(theirs)))
        continue
    for name in mine:
        if not np.array_equal(mine[name], theirs[name]):
            failures.append("line %d: %s differs from the serial output" % (line, name))
print("rank %d of %d: %d lines %s, %d differences" % (rank, size, len(local_ids), local_ids, len(failures)))

# Each line on exactly one rank.
with open(os.path.join(folder, "rank%d.txt" % rank), "w") as f:
    f.write(" ".join(str(i) for i in local_ids))
controller.Barrier()
if rank == 0:
    held = []
    for r in range(size):
        with open(os.path.join(folder, "rank%d.txt" % r)) as f:
            held += [int(w) for w in f.read().split()]
    expected = list(range(whole.GetNumberOfCells()))
    if sorted(held) != expected:
        failures.append("lines held by the ranks %s, expected each of %s once" % (sorted(held), expected))
    with open(os.path.join(folder, "rank0.txt")) as f:
        first = f.read().split()
    if len(first) == len(expected):
        failures.append("rank 0 holds every line: the input was not distributed")
for f in failures:
    print("FAIL rank %d: %s" % (rank, f))
# A script that ends normally lets pvbatch finalize MPI; only a failure exits early.
if failures:
    sys.exit(1)
