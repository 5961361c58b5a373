"""Compares a PNG a script wrote with its baseline, as VTK's image tests do.

Run as
    python3 CompareImage.py --image build/Testing/Temporary/demo/headline.png \
        --baseline Testing/Data/Baseline/DemoHeadline.png [--threshold 10]

vtkImageDifference's thresholded error (the measure
paraview.vtk.test.Testing.compareImage uses, which needs a render window) must
not exceed the threshold, and the sizes must match. On a mismatch the
difference image is written next to the image, as <name>.diff.png.
"""
import argparse
import os
import sys

from vtkmodules.vtkImagingCore import vtkImageDifference
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--image", required=True, help="the PNG written by the test")
parser.add_argument("--baseline", required=True, help="the baseline PNG")
parser.add_argument("--threshold", type=float, default=10.0, help="largest thresholded error (default 10)")
args = parser.parse_args()

for path in (args.image, args.baseline):
    if not os.path.isfile(path):
        sys.exit("missing: %s (inspect the produced image, then copy it to the baseline folder)" % path)


def read(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return reader


image, baseline = read(args.image), read(args.baseline)
sizes = [r.GetOutput().GetDimensions()[:2] for r in (image, baseline)]
if sizes[0] != sizes[1]:
    sys.exit("size %s differs from the baseline's %s" % (sizes[0], sizes[1]))
difference = vtkImageDifference()
difference.SetInputConnection(image.GetOutputPort())
difference.SetImageConnection(baseline.GetOutputPort())
difference.Update()
error = difference.GetThresholdedError()
if error > args.threshold:
    writer = vtkPNGWriter()
    writer.SetFileName(os.path.splitext(args.image)[0] + ".diff.png")
    writer.SetInputConnection(difference.GetOutputPort())
    writer.Write()
    sys.exit("%s differs from %s: thresholded error %.3g > %.3g" % (args.image, args.baseline, error,
                                                                       args.threshold))
print("%s matches %s: thresholded error %.3g (threshold %.3g)" % (args.image, args.baseline, error,
                                                                  args.threshold))
