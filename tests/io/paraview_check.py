"""Run by ParaView's own Python (pvpython, under xvfb-run) from test_paraview.py: opens a run's
two XDMF sidecars with ParaView's XDMF3 reader and prints what ParaView sees as one JSON line
(time steps; per block its points, cells, cell arrays and field data at the last step), then
renders the hinge network coloured by the plastic field to a PNG.

usage: pvpython paraview_check.py RUN.xdmf RUN.cycles.xdmf OUT.png
"""
import json
import os
import sys

from paraview import servermanager
from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetColorTransferFunction, Render,
                             SaveScreenshot, Show, Threshold, Xdmf3ReaderS)


def blocks(reader, time):
    reader.UpdatePipeline(time)
    data = servermanager.Fetch(reader)
    out = []
    it = data.NewIterator()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        b = it.GetCurrentDataObject()
        cd, fd = b.GetCellData(), b.GetFieldData()
        out.append({
            "points": b.GetNumberOfPoints(), "cells": b.GetNumberOfCells(),
            "cell_arrays": sorted(cd.GetArrayName(i) for i in range(cd.GetNumberOfArrays())),
            "point_arrays": sorted(b.GetPointData().GetArrayName(i)
                                   for i in range(b.GetPointData().GetNumberOfArrays())),
            "field": {fd.GetArrayName(i): fd.GetArray(i).GetValue(0)
                      for i in range(fd.GetNumberOfArrays())},
            "p_range": list(cd.GetArray("p").GetRange()) if cd.GetArray("p") else None,
            "creased": (sum(cd.GetArray("crease").GetValue(k) for k in range(b.GetNumberOfCells()))
                        if cd.GetArray("crease") else None),
        })
        it.GoToNextItem()
    return out


def main():
    frames_path, cycles_path, png = (os.path.abspath(a) for a in sys.argv[1:4])
    report = {}
    for name, path in (("frames", frames_path), ("cycles", cycles_path)):
        r = Xdmf3ReaderS(FileName=[path])
        times = list(r.TimestepValues)
        report[name] = {"times": times, "last": blocks(r, times[-1])}
        if name == "cycles":
            view = GetActiveViewOrCreate("RenderView")
            view.ViewSize = [400, 400]
            view.ViewTime = times[-1]
            sheet = Show(r, view)
            ColorBy(sheet, None)
            sheet.DiffuseColor = [0.85, 0.85, 0.85]
            # The creased hinges only (the crease mask), coloured by the plastic field.
            creases = Threshold(Input=r, Scalars=["CELLS", "crease"], LowerThreshold=0.5,
                                UpperThreshold=1.5)
            lines = Show(creases, view)
            ColorBy(lines, ("CELLS", "p"))
            lines.LineWidth = 2.0
            lut = GetColorTransferFunction("p")
            lut.ApplyPreset("Cool to Warm", True)
            lines.RescaleTransferFunctionToDataRange(True)
            lines.SetScalarBarVisibility(view, True)
            view.ResetCamera()
            Render(view)
            SaveScreenshot(png, view, ImageResolution=[400, 400])
    print("PARAVIEW " + json.dumps(report))


if __name__ == "__main__":
    main()
