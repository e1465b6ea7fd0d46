"""check_png.py FILE WIDTH HEIGHT: the PNG has that size and is not one flat colour.

Read with VTK's own PNG reader (python3-vtk9), so no other Python package is needed."""
import sys

import vtk


def main() -> int:
    path, width, height = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    reader = vtk.vtkPNGReader()
    if not reader.CanReadFile(path):
        print(f"{path}: not a PNG file VTK can read")
        return 1
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    nx, ny, _ = image.GetDimensions()
    if (nx, ny) != (width, height):
        print(f"{path}: {nx}x{ny} pixels, expected {width}x{height}")
        return 1
    scalars = image.GetPointData().GetScalars()
    count = scalars.GetNumberOfTuples()
    step = max(1, count // 20000)
    colours = {tuple(scalars.GetTuple(i)[:3]) for i in range(0, count, step)}
    if len(colours) < 20:
        print(f"{path}: only {len(colours)} distinct colours; expected a picture")
        return 1
    print(f"{path}: {nx}x{ny}, {len(colours)} colours in the sample")
    return 0


if __name__ == "__main__":
    sys.exit(main())
