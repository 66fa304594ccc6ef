#!/usr/bin/env python3
"""Reads FILE with VTK's own readers (python3-vtk9) and prints what it holds as JSON:
{"points", "cells", "polys", "bounds", "dims", "range", "arrays"}. The reader is chosen by
the file's extension, as ParaView would; fest's code is not involved.

  vtk_read.py FILE
"""
import json
import sys

# Only the reader modules: `import vtk` would also load the MPI modules, whose factory
# replaces vtkNrrdReader by a parallel reader that fails without an MPI controller.
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
from vtkmodules.vtkIOImage import vtkMetaImageReader, vtkNrrdReader
from vtkmodules.vtkIOLegacy import vtkGenericDataObjectReader
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import (vtkXMLImageDataReader, vtkXMLPolyDataReader,
                                 vtkXMLStructuredGridReader, vtkXMLUnstructuredGridReader)

READERS = {
    ".ply": vtkPLYReader, ".stl": vtkSTLReader, ".obj": vtkOBJReader,
    ".vtu": vtkXMLUnstructuredGridReader, ".vti": vtkXMLImageDataReader,
    ".vtp": vtkXMLPolyDataReader, ".vts": vtkXMLStructuredGridReader,
    ".vtk": vtkGenericDataObjectReader, ".nrrd": vtkNrrdReader,
    ".mha": vtkMetaImageReader, ".mhd": vtkMetaImageReader,
}


def main(path):
    ext = "." + path.rsplit(".", 1)[-1].lower()
    if ext not in READERS:
        sys.exit(f"vtk_read.py: no VTK reader for {ext}")
    reader = READERS[ext]()
    reader.SetFileName(path)
    if not isinstance(reader, vtkGenericDataObjectReader) and hasattr(reader, "CanReadFile"):
        if not reader.CanReadFile(path):
            sys.exit(f"vtk_read.py: VTK cannot read {path}")
    reader.Update()
    data = reader.GetOutputDataObject(0)
    if data is None or data.GetNumberOfPoints() == 0:
        sys.exit(f"vtk_read.py: VTK read no points from {path}")
    out = {"points": data.GetNumberOfPoints(), "cells": data.GetNumberOfCells(),
           "bounds": list(data.GetBounds()), "arrays": {}}
    if hasattr(data, "GetNumberOfPolys"):
        out["polys"] = data.GetNumberOfPolys()
    if hasattr(data, "GetDimensions"):
        out["dims"] = list(data.GetDimensions())
    scalars = data.GetPointData().GetScalars()
    if scalars is not None:
        out["range"] = list(scalars.GetRange())
    for where, attrs in (("point", data.GetPointData()), ("cell", data.GetCellData())):
        for i in range(attrs.GetNumberOfArrays()):
            a = attrs.GetArray(i)
            if a is not None:
                out["arrays"][f"{where}:{a.GetName()}"] = {
                    "components": a.GetNumberOfComponents(), "tuples": a.GetNumberOfTuples()}
    print(json.dumps(out))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
