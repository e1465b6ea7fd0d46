#!/usr/bin/python3
"""Opens flotsam's UGRID NetCDF result with xarray and checks it against the ParaView files of the
same run (VTK's own reader): the times decode to origin + t and are the .pvd's; at every output
the depth, water level and velocity per face are the .vtu's cell values (1e-12 relative; dry
cells, H = 0 in the .vtu, are missing in the NetCDF file); the static envelopes and hazard are
the last .vtu's (classes missing where the water never came, 0 in the .vtu).

    compare_ugrid_vtk.py RUN_FOLDER NAME --origin "2024-06-01 06:30:00"
"""
import argparse
import math
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np
import xarray as xr
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader


def fail(message):
    print(f"compare_ugrid_vtk: {message}", file=sys.stderr)
    sys.exit(1)


def cell_array(grid, name):
    array = grid.GetCellData().GetArray(name)
    if array is None:
        fail(f"the .vtu has no cell array {name!r}")
    return vtk_to_numpy(array)


def expect_equal(what, got, want, missing_where=None):
    """got (NetCDF, NaN for missing) against want (.vtu); missing exactly where asked."""
    got, want = np.asarray(got, float), np.asarray(want, float)
    missing = np.isnan(got)
    if missing_where is not None and not np.array_equal(missing, missing_where):
        k = int(np.argmax(missing != missing_where))
        fail(f"{what}: face {k} is {'missing' if missing[k] else got[k]} in the NetCDF file, "
             f"{want[k]} in the .vtu")
    ok = ~missing
    scale = np.maximum(1.0, np.abs(want[ok]))
    err = np.abs(got[ok] - want[ok]) / scale
    if err.size and err.max() > 1e-12:
        k = int(np.flatnonzero(ok)[np.argmax(err)])
        fail(f"{what}: face {k} holds {got[k]} in the NetCDF file, {want[k]} in the .vtu")
    return int(ok.sum())


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("folder")
    parser.add_argument("name")
    parser.add_argument("--origin", required=True)
    args = parser.parse_args()

    ds = xr.open_dataset(os.path.join(args.folder, args.name + ".nc"))
    pvd = ET.parse(os.path.join(args.folder, args.name + ".pvd")).getroot()
    outputs = [(float(d.get("timestep")), d.get("file")) for d in pvd.iter("DataSet")]
    if ds.sizes["time"] != len(outputs):
        fail(f"{ds.sizes['time']} times in the NetCDF file, {len(outputs)} in the .pvd")
    origin = np.datetime64(args.origin.replace(" ", "T"))
    compared = 0
    for k, (t, file) in enumerate(outputs):
        want_time = origin + np.timedelta64(round(t * 1e9), "ns")
        if ds.time.values[k] != want_time:
            fail(f"time {k}: {ds.time.values[k]}, expected {want_time} (t = {t} s)")
        reader = vtkXMLUnstructuredGridReader()
        reader.SetFileName(os.path.join(args.folder, file))
        reader.Update()
        grid = reader.GetOutput()
        if grid.GetNumberOfCells() != ds.sizes["face"]:
            fail(f"{file}: {grid.GetNumberOfCells()} cells, {ds.sizes['face']} faces in .nc")
        H = cell_array(grid, "H [m]")
        u = cell_array(grid, "u [m/s]")
        snap = ds.isel(time=k)
        dry = np.isnan(snap.depth.values)
        if np.any(u[dry] != 0.0) or np.any(H[dry] > 0.01):  # dry in the .vtu: no velocity
            fail(f"{file}: a cell missing from the NetCDF file at time {k} is wet in the .vtu")
        compared += expect_equal(f"depth at {t} s", snap.depth.values, H, dry)
        compared += expect_equal(f"water level at {t} s", snap.water_level.values,
                                 cell_array(grid, "eta [m]"), dry)
        compared += expect_equal(f"ux at {t} s", snap.ux.values, u[:, 0], dry)
        compared += expect_equal(f"uy at {t} s", snap.uy.values, u[:, 1], dry)
        if k == len(outputs) - 1:
            never = np.isnan(cell_array(grid, "arrival time [s]"))
            for var, array, only_wet in (
                    ("bed", "z_b [m]", False), ("max_depth", "max H [m]", False),
                    ("max_speed", "max |u| [m/s]", False),
                    ("max_unit_discharge", "max H|u| [m^2/s]", False),
                    ("arrival_time", "arrival time [s]", True),
                    ("wet_duration", "wet duration [s]", False),
                    ("hazard_rating", "max hazard rating HR [-]", False),
                    ("hazard_rating_class", "hazard rating class (1-4)", True),
                    ("australian_hazard_class", "Australian hazard class (H1-H6)", True),
                    ("vehicle_class", "vehicles unstable (0-3)", True)):
                compared += expect_equal(var, ds[var].values, cell_array(grid, array),
                                         never if only_wet else np.zeros_like(never))
    mesh = ds["mesh"].attrs
    if mesh.get("cf_role") != "mesh_topology" or int(mesh.get("topology_dimension")) != 2:
        fail(f"the mesh variable's attributes: {mesh}")
    if int(ds["face_nodes"].attrs.get("start_index", -1)) != 0:
        fail("face_nodes has no start_index 0")
    print(f"xarray read {ds.sizes['face']} faces x {len(outputs)} times from "
          f"{args.name}.nc: {compared} values equal to the .vtu files'")


if __name__ == "__main__":
    main()
