#!/usr/bin/python3
"""Verifies that a result file of src/io/ugrid_writer.hpp reads as UGRID-1.0 / CF with the
layout QGIS 3.22's MDAL 0.9.4 needs (../shared/notes/qgis-ugrid-hazard.md), through netCDF4 and
xarray:
  * a classic-format file (CDF-1, -2 or -5), which cannot hold the NC_STRING attributes MDAL
    rejects;
  * the mesh variable: cf_role "mesh_topology", topology_dimension 2, node_coordinates,
    face_node_connectivity and face_dimension naming what exists; the connectivity with
    start_index (0 or 1) and every node index in range;
  * a dimension and a variable named exactly "time", units "seconds since YYYY-MM-DD hh:mm:ss"
    (a space before the clock time), calendar standard, times increasing, and xarray's decoded
    datetime64 times equal to the origin plus the seconds;
  * when node_x names a grid_mapping: that variable with an int epsg, EPSG_code "EPSG:<epsg>"
    and the WKT as wkt and crs_wkt;
  * each data variable (with a "mesh" attribute): on (time, node|face) or (node|face), with a
    unique long_name, units and _FillValue; vector components ("<stem>, x-component" /
    "<stem>, y-component") in timed pairs on one location, never static.
Then the expectations given: --expect-nodes N, --expect-faces N, --expect-times K, and
--value VAR TIME_INDEX INDEX EXPECTED (repeatable; TIME_INDEX is "-" for a static variable;
EXPECTED "nan" for a fill value), to a relative tolerance of 1e-12.
Prints a short summary; exits 1 with a message naming the file, the item and both values on the
first failure. Run with /usr/bin/python3 (Debian's python3-netcdf4 and python3-xarray):

    /usr/bin/python3 tests/scripts/check_ugrid.py out/case/case.nc --expect-faces 4468 \\
        --expect-times 31 --value depth 30 17 0.8125
"""
import argparse
import math
import re
import sys

import netCDF4
import numpy as np
import xarray

TOLERANCE = 1e-12  # relative
ORIGIN = re.compile(r"^seconds since (\d{4}-\d{2}-\d{2}) (\d{2}:\d{2}:\d{2})$")
COMPONENT = re.compile(r"^(.*), ([xy])-component(.*)$")


def fail(path, message):
    print(f"check_ugrid: {path}: FAILED: {message}", file=sys.stderr)
    sys.exit(1)


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("file")
    parser.add_argument("--expect-nodes", type=int)
    parser.add_argument("--expect-faces", type=int)
    parser.add_argument("--expect-times", type=int)
    parser.add_argument("--value", nargs=4, action="append", default=[],
                        metavar=("VAR", "TIME_INDEX", "INDEX", "EXPECTED"))
    return parser.parse_args()


def mesh_variable(path, ds):
    meshes = [v for v in ds.variables.values() if getattr(v, "cf_role", None) == "mesh_topology"]
    if len(meshes) != 1:
        fail(path, f"{len(meshes)} variables with cf_role 'mesh_topology', expected 1")
    mesh = meshes[0]
    if getattr(mesh, "topology_dimension", None) != 2:
        fail(path, f"'{mesh.name}': topology_dimension is "
                   f"{getattr(mesh, 'topology_dimension', None)!r}, expected 2")
    for attribute in ("node_coordinates", "face_node_connectivity", "face_dimension"):
        if not isinstance(getattr(mesh, attribute, None), str):
            fail(path, f"'{mesh.name}' has no text attribute {attribute}")
    return mesh


def check_topology(path, ds, mesh):
    """(node dimension, face dimension, node count, face count)"""
    names = mesh.node_coordinates.split()
    if len(names) != 2 or any(n not in ds.variables for n in names):
        fail(path, f"node_coordinates '{mesh.node_coordinates}' does not name two variables")
    node_dim = ds.variables[names[0]].dimensions[0]
    face_dim = mesh.face_dimension
    if face_dim not in ds.dimensions:
        fail(path, f"face_dimension '{face_dim}' is not a dimension")
    connectivity = ds.variables.get(mesh.face_node_connectivity)
    if connectivity is None or connectivity.dimensions[0] != face_dim:
        fail(path, f"face_node_connectivity '{mesh.face_node_connectivity}' is not ({face_dim}, n)")
    if "start_index" not in connectivity.ncattrs():
        fail(path, f"'{connectivity.name}' has no start_index (MDAL 0.9.4 cannot load it)")
    start = int(connectivity.start_index)
    if start not in (0, 1):
        fail(path, f"'{connectivity.name}': start_index {start}, expected 0 or 1")
    nodes, faces = len(ds.dimensions[node_dim]), len(ds.dimensions[face_dim])
    corners = connectivity[:]  # netCDF4 masks the _FillValue
    used = np.ma.getdata(corners)[~np.ma.getmaskarray(corners)] - start
    if used.size and (used.min() < 0 or used.max() >= nodes):
        fail(path, f"'{connectivity.name}' names nodes {used.min() + start}..{used.max() + start}"
                   f" with start_index {start} and {nodes} nodes")
    return node_dim, face_dim, nodes, faces


def check_time(path, ds):
    """(raw seconds, origin as numpy datetime64)"""
    if "time" not in ds.dimensions or "time" not in ds.variables:
        fail(path, "no dimension and variable named exactly 'time' (MDAL drops timed data)")
    time = ds.variables["time"]
    match = ORIGIN.match(getattr(time, "units", ""))
    if not match:
        fail(path, f"time units {getattr(time, 'units', None)!r}, expected "
                   "'seconds since YYYY-MM-DD hh:mm:ss'")
    if getattr(time, "calendar", "standard") not in ("standard", "gregorian"):
        fail(path, f"time calendar {time.calendar!r}, expected 'standard'")
    seconds = np.asarray(time[:], dtype=float)
    if seconds.size > 1 and not np.all(np.diff(seconds) > 0):
        fail(path, f"times do not increase: {seconds.tolist()}")
    return seconds, np.datetime64(f"{match.group(1)}T{match.group(2)}", "ns")


def check_decoded_times(path, decoded, seconds, origin):
    if decoded.dtype.kind != "M":
        fail(path, f"xarray decodes time as {decoded.dtype}, not datetime64")
    expected = origin + np.round(seconds * 1e9).astype("timedelta64[ns]")
    if not np.array_equal(decoded.astype("datetime64[ns]"), expected):
        fail(path, f"xarray decodes the times as {decoded}, expected {expected}")


def check_crs(path, ds, mesh):
    """The EPSG code, or None when the file has no coordinate system."""
    x = ds.variables[mesh.node_coordinates.split()[0]]
    name = getattr(x, "grid_mapping", None)
    if name is None:
        return None
    crs = ds.variables.get(name)
    if crs is None:
        fail(path, f"'{x.name}' has grid_mapping '{name}', which is not a variable")
    wkt = getattr(crs, "wkt", "")
    if not wkt or wkt != getattr(crs, "crs_wkt", None):
        fail(path, f"'{name}' has no wkt equal to its crs_wkt")
    if "epsg" not in crs.ncattrs():
        return 0
    epsg = crs.epsg
    if not isinstance(epsg, (int, np.integer)):
        fail(path, f"'{name}': epsg {epsg!r} is not an integer")
    if getattr(crs, "EPSG_code", None) != f"EPSG:{epsg}":
        fail(path, f"'{name}': EPSG_code {getattr(crs, 'EPSG_code', None)!r}, "
                   f"expected 'EPSG:{epsg}'")
    return int(epsg)


def check_no_stray_variables(path, ds, mesh, node_dim, face_dim):
    """MDAL shows every variable on the nodes or faces as a dataset group, except the ones the
    mesh names (node_coordinates, face_coordinates, the connectivity) and its bed elevation."""
    named = set(mesh.node_coordinates.split()) | set(getattr(mesh, "face_coordinates", "").split())
    named.add(mesh.face_node_connectivity)
    for var in ds.variables.values():
        on_mesh = var.dimensions and var.dimensions[-1] in (node_dim, face_dim)
        if on_mesh and var.name not in named and getattr(var, "mesh", None) != mesh.name:
            fail(path, f"'{var.name}' is on {var.dimensions} but neither a data variable (mesh = "
                       f"'{mesh.name}') nor named by the mesh: QGIS would show it as a dataset")


def data_variables(path, ds, mesh, node_dim, face_dim):
    """{name: (location, timed, long_name, units)} of the variables on the mesh."""
    found, long_names = {}, {}
    for var in ds.variables.values():
        if getattr(var, "mesh", None) != mesh.name or var.name == "node_z":
            continue
        dims = var.dimensions
        timed = len(dims) == 2 and dims[0] == "time"
        location = dims[-1] if dims else None
        if location not in (node_dim, face_dim) or len(dims) != (2 if timed else 1):
            fail(path, f"'{var.name}' is on {dims}, expected (time, {node_dim}|{face_dim}) or "
                       f"({node_dim}|{face_dim})")
        for attribute in ("long_name", "units", "_FillValue"):
            if attribute not in var.ncattrs():
                fail(path, f"'{var.name}' has no {attribute}")
        if var.long_name in long_names:
            fail(path, f"'{var.name}' and '{long_names[var.long_name]}' share the long_name "
                       f"'{var.long_name}' (MDAL merges them)")
        long_names[var.long_name] = var.name
        found[var.name] = (location, timed, var.long_name, var.units)
    for name, (location, timed, long_name, _) in found.items():
        match = COMPONENT.match(long_name)
        if not match:
            continue
        if not timed:
            fail(path, f"'{name}' is a static vector component (MDAL 0.9.4 reads its y as x)")
        other = "y" if match.group(2) == "x" else "x"
        pair = f"{match.group(1)}, {other}-component{match.group(3)}"
        partner = long_names.get(pair)
        if partner is None or found[partner][:2] != (location, timed):
            fail(path, f"'{name}' ({long_name}) has no timed '{pair}' on {location}")
    return found


def check_values(path, xr_ds, variables, requests):
    for name, time_text, index_text, expected_text in requests:
        if name not in variables:
            fail(path, f"--value: no data variable '{name}'")
        timed = variables[name][1]
        values = xr_ds[name].values
        try:
            index = int(index_text)
            expected = float(expected_text)
            got = values[int(time_text), index] if timed else values[index]
        except (ValueError, IndexError) as error:
            fail(path, f"--value {name} {time_text} {index_text} {expected_text}: {error}")
        what = f"{name}[{time_text if timed else '-'}, {index}]"
        if math.isnan(expected):
            if not math.isnan(got):
                fail(path, f"{what}: read {got!r}, expected the fill value (NaN)")
        elif not abs(got - expected) <= TOLERANCE * abs(expected):
            fail(path, f"{what}: read {got!r}, expected {expected!r} "
                       f"(relative tolerance {TOLERANCE})")


def main():
    args = parse_arguments()
    path = args.file
    try:
        ds = netCDF4.Dataset(path)
    except OSError as error:
        fail(path, f"not a NetCDF file netCDF4 can open ({error})")
    with ds:
        if not ds.data_model.startswith("NETCDF3"):
            fail(path, f"format {ds.data_model}, expected a classic one (NETCDF3_*)")
        mesh = mesh_variable(path, ds)
        node_dim, face_dim, nodes, faces = check_topology(path, ds, mesh)
        seconds, origin = check_time(path, ds)
        epsg = check_crs(path, ds, mesh)
        check_no_stray_variables(path, ds, mesh, node_dim, face_dim)
        variables = data_variables(path, ds, mesh, node_dim, face_dim)
        data_model, mesh_name = ds.data_model, mesh.name
    with xarray.open_dataset(path, engine="netcdf4") as xr_ds:
        check_decoded_times(path, xr_ds["time"].values, seconds, origin)
        check_values(path, xr_ds, variables, args.value)
    for option, actual in (("nodes", nodes), ("faces", faces), ("times", len(seconds))):
        expected = getattr(args, f"expect_{option}")
        if expected is not None and expected != actual:
            fail(path, f"{actual} {option}, expected {expected}")

    print(f"{path}: UGRID-1.0 mesh '{mesh_name}', {nodes} nodes, {faces} faces, {data_model}")
    def date(s):
        return np.datetime_as_string(origin + np.timedelta64(int(round(s * 1e9)), "ns"), "auto")

    span = f"{date(seconds[0])} .. {date(seconds[-1])}" if seconds.size else "none"
    print(f"  {len(seconds)} times ({span}), seconds since {date(0.0)}")
    print(f"  coordinate system: {'none' if epsg is None else f'EPSG:{epsg}' if epsg else 'WKT only'}")
    for name, (location, timed, long_name, units) in variables.items():
        kind = "timed" if timed else "static"
        print(f"  {name:16s} {location:5s} {kind:6s} [{units}] {long_name}")
    print(f"check_ugrid: {len(args.value)} values checked, OK")


if __name__ == "__main__":
    main()
