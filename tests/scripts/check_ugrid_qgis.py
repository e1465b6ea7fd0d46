#!/usr/bin/python3
"""Loads flotsam's UGRID NetCDF result in QGIS itself (python3-qgis, headless) as a mesh layer
and checks it against the file as netCDF4 reads it: the layer is valid, its CRS is the expected
EPSG code, its extent is the nodes' bounding box, its dataset groups are the file's variables
(scalars and the velocity as one vector group) on faces or vertices as the file says, its times are the file's (QGIS counts
hours from the time origin, which it reads as the reference time), and the values at a few faces
and times are those written (1e-12 relative; the fill value reads back as NaN in both).

    check_ugrid_qgis.py RESULT.nc --epsg 32633 --origin "2024-06-01 06:30:00"
Exit 1 with a message on any mismatch; exit 2 when QGIS cannot be imported.
"""
import argparse
import math
import os
import sys
import tempfile

import netCDF4


def fail(message):
    print(f"check_ugrid_qgis: {message}", file=sys.stderr)
    sys.exit(1)


def same(a, b):
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    return abs(a - b) <= 1e-12 * max(1.0, abs(b))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("file")
    parser.add_argument("--epsg", type=int, required=True)
    parser.add_argument("--origin", required=True, help="YYYY-MM-DD hh:mm:ss, the time of t = 0")
    args = parser.parse_args()

    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    os.environ["HOME"] = tempfile.mkdtemp()  # QGIS writes a profile there
    try:
        from qgis.core import (Qgis, QgsApplication, QgsMeshDatasetGroupMetadata,
                               QgsMeshDatasetIndex,
                               QgsMeshLayer, QgsProviderRegistry)
        from qgis.PyQt.QtCore import QDateTime, Qt
    except ImportError as error:
        print(f"check_ugrid_qgis: QGIS cannot be imported ({error}); install python3-qgis",
              file=sys.stderr)
        sys.exit(2)

    nc = netCDF4.Dataset(args.file)
    nc.set_auto_mask(False)
    x, y = nc["node_x"][:], nc["node_y"][:]
    times = nc["time"][:]
    faces = nc.dimensions["face"].size
    file_vars = {name: v for name, v in nc.variables.items()
                 if "location" in v.ncattrs() and name not in ("node_z",)}

    QgsApplication.setPrefixPath("/usr", True)
    app = QgsApplication([], False)
    app.initQgis()
    try:
        if "mdal" not in QgsProviderRegistry.instance().providerList():
            fail("QGIS has no MDAL provider")
        layer = QgsMeshLayer(args.file, "flotsam", "mdal")
        if not layer.isValid():
            fail(f"QGIS does not open {args.file} as a mesh layer: {layer.error().summary()}")
        if layer.crs().authid() != f"EPSG:{args.epsg}":
            fail(f"CRS {layer.crs().authid()!r}, expected EPSG:{args.epsg}")
        provider = layer.dataProvider()
        if provider.faceCount() != faces or provider.vertexCount() != len(x):
            fail(f"{provider.vertexCount()} vertices and {provider.faceCount()} faces, the file "
                 f"has {len(x)} and {faces}")
        extent = layer.extent()
        for got, want, name in ((extent.xMinimum(), x.min(), "x min"),
                                (extent.xMaximum(), x.max(), "x max"),
                                (extent.yMinimum(), y.min(), "y min"),
                                (extent.yMaximum(), y.max(), "y max")):
            if not same(got, float(want)):
                fail(f"extent {name} {got}, the nodes' {want}")
        reference = provider.temporalCapabilities().referenceTime()
        want_reference = QDateTime.fromString(args.origin, "yyyy-MM-dd HH:mm:ss")
        want_reference.setTimeSpec(Qt.UTC)
        if reference.toMSecsSinceEpoch() != want_reference.toMSecsSinceEpoch():
            fail(f"reference time {reference.toString(Qt.ISODate)}, expected {args.origin} UTC")

        groups = {}
        for g in range(provider.datasetGroupCount()):
            meta = provider.datasetGroupMetadata(g)
            groups[meta.name()] = (g, meta)
        checked = 0
        for name, var in file_vars.items():
            long_name = var.long_name
            vector = long_name.endswith(", x-component") or long_name.endswith(", y-component")
            group_name = long_name.rsplit(",", 1)[0] if vector else long_name
            if group_name not in groups:
                fail(f"no dataset group {group_name!r} (variable {name}); QGIS has "
                     f"{sorted(groups)}")
            g, meta = groups[group_name]
            on_faces = var.location == "face"
            want_type = (QgsMeshDatasetGroupMetadata.DataOnFaces if on_faces
                         else QgsMeshDatasetGroupMetadata.DataOnVertices)
            if meta.dataType() != want_type:
                fail(f"group {group_name!r} is not on the {var.location}s")
            count = faces if on_faces else len(x)
            if meta.isScalar() == vector:
                fail(f"group {group_name!r}: {'scalar' if meta.isScalar() else 'vector'}, "
                     f"expected {'vector' if vector else 'scalar'}")
            timed = "time" in var.dimensions
            steps = provider.datasetCount(g)
            if steps != (len(times) if timed else 1):
                fail(f"group {group_name!r} has {steps} datasets, the file {len(times)} times")
            for step in ([0, len(times) // 2, len(times) - 1] if timed else [0]):
                index = QgsMeshDatasetIndex(g, step)
                if timed:
                    hours = provider.datasetMetadata(index).time()
                    if not same(hours * 3600.0, float(times[step])):
                        fail(f"{group_name!r} step {step}: {hours} h, the file "
                             f"{times[step]} s")
                block = provider.datasetValues(index, 0, count)
                data = var[step] if timed else var[:]
                for k in sorted({0, count // 3, count // 2, count - 1}):
                    value = block.value(k)
                    got = value.scalar() if not vector else (
                        value.x() if long_name.endswith("x-component") else value.y())
                    want = float(data[k])
                    want = math.nan if want == float(var._FillValue) else want
                    if not same(got, want):
                        fail(f"{name} at {var.location} {k}, step {step}: QGIS {got}, "
                             f"the file {want}")
                    checked += 1
        print(f"QGIS {Qgis.version()} opened {args.file}: EPSG:{args.epsg}, "
              f"{len(x)} vertices, {faces} faces, {len(groups)} dataset groups, "
              f"{len(times)} times from {args.origin}; {checked} values equal to the file's")
    finally:
        app.exitQgis()


if __name__ == "__main__":
    main()
