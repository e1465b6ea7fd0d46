#!/usr/bin/python3
"""Verifies that VTK's own XML readers read flotsam's output as written.

Reads the samples of tests/scripts/write_vtk_samples.cpp from the folder given as the only
argument and checks, against the formulas and the body table written out below (keep them in
step with write_vtk_samples.cpp):
  * flow_*.vtu: node and cell counts of the 3 x 2 rectangle, every cell VTK_QUADRATIC_TRIANGLE
    (22), f = x + 2y, g = 3x - y + 1 and u = (y, -x, 0) at every point to 1e-12, the cell field
    equal to the cell index, TimeValue; and VTK's own P2 interpolation of q = x^2 at an interior
    point of every cell equal to x^2 there to 1e-12, which holds only if VTK reads the six nodes
    in the order we meant;
  * flow.pvd: XML with the two datasets and their times, each file present;
  * boundary.vtp: 10 three-point polylines through their mid node, with their group;
  * bodies.vtp: ids, states, corners of every polygon, velocities, the extra "drag [N]" array.
Exits 1 with a message naming the file, the item and both values on the first mismatch.
Run with /usr/bin/python3 (Debian's python3-vtk9).
"""
import math
import os
import sys
import xml.etree.ElementTree as ElementTree

import vtk

TOLERANCE = 1e-12


def fail(message):
    print(f"check_vtk: FAILED: {message}", file=sys.stderr)
    sys.exit(1)


def expect(condition, message):
    if not condition:
        fail(message)


def expect_close(actual, expected, what, tolerance=TOLERANCE):
    if not abs(actual - expected) <= tolerance * max(1.0, abs(expected)):
        fail(f"{what}: read {actual!r}, expected {expected!r} (tolerance {tolerance})")


def read(reader_class, path):
    expect(os.path.isfile(path), f"{path} is missing")
    reader = reader_class()
    reader.SetFileName(path)
    errors = []  # VTK reports a bad file through ErrorEvent, not by raising
    reader.AddObserver("ErrorEvent", lambda caller, event: errors.append(event))
    reader.Update()
    expect(not errors, f"{path}: VTK's {reader_class.__name__} reported an error (see above)")
    return reader.GetOutput()


def array(data, name, path):
    a = data.GetArray(name)
    expect(a is not None, f"{path}: no array '{name}'")
    return a


def time_value(dataset, path, expected):
    t = dataset.GetFieldData().GetArray("TimeValue")
    expect(t is not None, f"{path}: no FieldData TimeValue")
    expect_close(t.GetValue(0), expected, f"{path}: TimeValue")


def check_vtu(path, time):
    nx, ny = 3, 2  # the rectangle [0.5, 3.5] x [-1, 1] of write_vtk_samples.cpp
    vertices = (nx + 1) * (ny + 1)
    cells = 2 * nx * ny
    edges = vertices + cells - 1  # Euler: V - E + F = 1 for a disc
    grid = read(vtk.vtkXMLUnstructuredGridReader, path)
    expect(grid.GetNumberOfPoints() == vertices + edges,
           f"{path}: {grid.GetNumberOfPoints()} points, expected {vertices + edges} (P2 nodes)")
    expect(grid.GetNumberOfCells() == cells,
           f"{path}: {grid.GetNumberOfCells()} cells, expected {cells}")
    time_value(grid, path, time)

    point_data = grid.GetPointData()
    f = array(point_data, "f [m]", path)
    g = array(point_data, "g [m]", path)
    q = array(point_data, "q [m^2]", path)
    u = array(point_data, "u [m/s]", path)
    expect(u.GetNumberOfComponents() == 3, f"{path}: u has {u.GetNumberOfComponents()} components")
    for p in range(grid.GetNumberOfPoints()):
        x, y, z = grid.GetPoint(p)
        expect(z == 0.0, f"{path}: point {p} has z = {z}")
        expect(0.5 <= x <= 3.5 and -1.0 <= y <= 1.0, f"{path}: point {p} = ({x}, {y}) outside")
        expect_close(f.GetValue(p), x + 2 * y, f"{path}: f at point {p} ({x}, {y})")
        expect_close(g.GetValue(p), 3 * x - y + 1, f"{path}: g (P1) at point {p} ({x}, {y})")
        expect_close(q.GetValue(p), x * x, f"{path}: q at point {p} ({x}, {y})")
        ux, uy, uz = u.GetTuple3(p)
        expect_close(ux, y, f"{path}: u_x at point {p}")
        expect_close(uy, -x, f"{path}: u_y at point {p}")
        expect(uz == 0.0, f"{path}: u_z at point {p} is {uz}")

    element = array(grid.GetCellData(), "element", path)
    pcoords = [0.2, 0.3, 0.0]  # an interior point, off the symmetry lines
    for c in range(cells):
        cell = grid.GetCell(c)
        expect(cell.GetCellType() == vtk.VTK_QUADRATIC_TRIANGLE,
               f"{path}: cell {c} has type {cell.GetCellType()}, expected 22")
        expect_close(element.GetValue(c), c, f"{path}: cell field at cell {c}")
        # VTK's quadratic interpolation of q = x^2 is exact when the nodes are in VTK's order.
        location = [0.0, 0.0, 0.0]
        weights = [0.0] * 6
        cell.EvaluateLocation(vtk.reference(0), pcoords, location, weights)
        interpolated = sum(weights[k] * q.GetValue(cell.GetPointId(k)) for k in range(6))
        expect_close(interpolated, location[0] ** 2, f"{path}: VTK's P2 interpolation of x^2 "
                     f"in cell {c} at ({location[0]}, {location[1]})")
        # Counter-clockwise corners: positive signed area.
        (x0, y0, _), (x1, y1, _), (x2, y2, _) = (grid.GetPoint(cell.GetPointId(k))
                                                 for k in range(3))
        expect((x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0) > 0,
               f"{path}: cell {c} is clockwise")


def check_pvd(folder):
    path = os.path.join(folder, "flow.pvd")
    expect(os.path.isfile(path), f"{path} is missing")
    root = ElementTree.parse(path).getroot()
    expect(root.tag == "VTKFile" and root.get("type") == "Collection",
           f"{path}: root is <{root.tag} type={root.get('type')}>, expected a VTKFile Collection")
    datasets = root.findall("./Collection/DataSet")
    expected = [(0.0, "flow_000000.vtu"), (7.5, "flow_000001.vtu")]
    expect(len(datasets) == len(expected), f"{path}: {len(datasets)} datasets, expected 2")
    for dataset, (time, file) in zip(datasets, expected):
        expect_close(float(dataset.get("timestep")), time, f"{path}: timestep of {file}")
        expect(dataset.get("file") == file, f"{path}: file {dataset.get('file')}, expected {file}")
        check_vtu(os.path.join(folder, file), time)


def check_boundary(folder):
    path = os.path.join(folder, "boundary.vtp")
    lines = read(vtk.vtkXMLPolyDataReader, path)
    expect(lines.GetNumberOfLines() == 10, f"{path}: {lines.GetNumberOfLines()} lines, expected 10")
    names_array = lines.GetFieldData().GetAbstractArray("group_names")
    expect(names_array is not None, f"{path}: no FieldData group_names")
    names = [names_array.GetValue(k) for k in range(names_array.GetNumberOfValues())]
    expect(sorted(names) == ["bottom", "left", "right", "top"], f"{path}: group names {names}")
    group = array(lines.GetCellData(), "group", path)
    on_side = {"bottom": lambda x, y: y == -1.0, "top": lambda x, y: y == 1.0,
               "left": lambda x, y: x == 0.5, "right": lambda x, y: x == 3.5}
    for c in range(lines.GetNumberOfCells()):
        cell = lines.GetCell(c)
        expect(cell.GetCellType() == vtk.VTK_POLY_LINE and cell.GetNumberOfPoints() == 3,
               f"{path}: line {c} is type {cell.GetCellType()} with {cell.GetNumberOfPoints()} "
               "points, expected a 3-point polyline")
        a, m, b = (lines.GetPoint(cell.GetPointId(k)) for k in range(3))
        for i in range(2):
            expect_close(m[i], 0.5 * (a[i] + b[i]), f"{path}: mid node of line {c}")
        name = names[int(group.GetValue(c))]
        expect(on_side[name](*a[:2]) and on_side[name](*b[:2]),
               f"{path}: line {c} from {a} to {b} is not on side '{name}'")


def check_bodies(folder):
    path = os.path.join(folder, "bodies.vtp")
    # id, x, y, angle [rad], L, l, state; body 13 is gone and must be absent.
    table = [(7, 10.0, 5.0, 0.0, 20.0, 1.0, 0),
             (11, -3.0, 2.0, math.pi / 2, 4.0, 2.0, 1),
             (42, 1.0, -1.0, math.pi / 6, 2.0, 1.0, 0)]
    polys = read(vtk.vtkXMLPolyDataReader, path)
    expect(polys.GetNumberOfPolys() == len(table),
           f"{path}: {polys.GetNumberOfPolys()} polygons, expected {len(table)}")
    time_value(polys, path, 7.5)
    cell_data = polys.GetCellData()
    ids, states = array(cell_data, "id", path), array(cell_data, "state", path)
    velocity, drag = array(cell_data, "velocity [m/s]", path), array(cell_data, "drag [N]", path)
    omega = array(cell_data, "angular_velocity [rad/s]", path)
    for c, (body, gx, gy, angle, length, width, state) in enumerate(table):
        expect(ids.GetValue(c) == body, f"{path}: polygon {c} has id {ids.GetValue(c)}, "
               f"expected {body}")
        expect(states.GetValue(c) == state, f"{path}: body {body} state {states.GetValue(c)}")
        expect_close(velocity.GetTuple3(c)[0], 0.5 * body, f"{path}: body {body} u_x")
        expect_close(velocity.GetTuple3(c)[1], -0.25 * body, f"{path}: body {body} u_y")
        expect_close(omega.GetValue(c), 0.01 * body, f"{path}: body {body} omega")
        expect_close(drag.GetValue(c), 100.0 * body, f"{path}: body {body} drag")
        cell = polys.GetCell(c)
        # vtkPolyData hands out a 4-point polygon as a VTK_QUAD.
        expect(cell.GetCellType() in (vtk.VTK_QUAD, vtk.VTK_POLYGON)
               and cell.GetNumberOfPoints() == 4,
               f"{path}: body {body} is type {cell.GetCellType()} with "
               f"{cell.GetNumberOfPoints()} points, expected a 4-point polygon")
        ax, ay = math.cos(angle), math.sin(angle)  # long axis; short axis (-ay, ax)
        corners = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
        for k, (sa, sn) in enumerate(corners):
            ex = gx + sa * 0.5 * length * ax - sn * 0.5 * width * ay
            ey = gy + sa * 0.5 * length * ay + sn * 0.5 * width * ax
            x, y, _ = polys.GetPoint(cell.GetPointId(k))
            expect_close(x, ex, f"{path}: body {body} corner {k} x")
            expect_close(y, ey, f"{path}: body {body} corner {k} y")


def main():
    if len(sys.argv) != 2:
        fail("usage: check_vtk.py <folder written by write_vtk_samples>")
    folder = sys.argv[1]
    check_pvd(folder)
    check_boundary(folder)
    check_bodies(folder)
    print(f"check_vtk: VTK {vtk.vtkVersion.GetVTKVersion()} read every sample in {folder}")


if __name__ == "__main__":
    main()
