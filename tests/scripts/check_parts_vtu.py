#!/usr/bin/python3
"""Verifies the parts `flotsam info MESH --parts N --parts-vtu FILE` writes for ParaView.

Usage: check_parts_vtu.py FILE N REPORT. Reads FILE with VTK's own XML reader and checks that
its cell array "part" holds only whole numbers 0 .. N-1, each of them, and that the smallest
and largest number of cells in a part equal the "cells  min / mean / max" line of REPORT (the
command's printed summary, exact). Exits 1 with a message naming what differs.
Run with /usr/bin/python3 (Debian's python3-vtk9).
"""
import re
import sys

import vtk


def fail(message):
    print(f"check_parts_vtu: FAILED: {message}", file=sys.stderr)
    sys.exit(1)


def main():
    path, parts, report = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    array = grid.GetCellData().GetArray("part")
    if array is None:
        fail(f"{path}: no cell array 'part'")
    counts = [0] * parts
    for k in range(grid.GetNumberOfCells()):
        value = array.GetValue(k)
        if value != int(value) or not 0 <= value < parts:
            fail(f"{path}: cell {k} has part {value}, expected a whole number in 0 .. {parts - 1}")
        counts[int(value)] += 1
    if min(counts) == 0:
        fail(f"{path}: a part has no cell: {counts}")
    match = re.search(r"^  cells +(\d+) / \d+ / (\d+)$", open(report).read(), re.MULTILINE)
    if not match:
        fail(f"{report}: no line 'cells  min / mean / max'")
    printed = (int(match.group(1)), int(match.group(2)))
    if printed != (min(counts), max(counts)):
        fail(f"{path}: parts of {min(counts)} .. {max(counts)} cells, the report says {printed}")
    print(f"check_parts_vtu: {grid.GetNumberOfCells()} cells in {parts} parts of {counts}")


main()
