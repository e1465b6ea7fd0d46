#!/usr/bin/python3
"""check_debris_gpkg.py FILE --layer LAYER --expect-features N --expect-epsg CODE [--require-qgis]

Checks a run's debris GeoPackage (`<name>_debris.gpkg`, src/geo/debris_layers.hpp) as a user
would open it: with GDAL's Python bindings (python3-gdal), the layer exists, holds N features
and is in EPSG:CODE; then, when QGIS's Python bindings are there (python3-qgis), QGIS loads the
layer as a valid vector layer with the same coordinate system and count, and reads its `time`
field as a date-time (what the temporal controller needs). Without QGIS that part is skipped
(exit 0, saying so) unless --require-qgis is given.

Prints what was checked; exits 1 with a message naming the file and layer on a mismatch.
Run it with the system interpreter (/usr/bin/python3): Debian's osgeo and qgis modules live
there, not in a pyenv python3.
"""
import argparse
import os
import sys
import tempfile


def check_with_gdal(path: str, layer: str, features: int, epsg: int) -> list[str]:
    """The problems GDAL finds; an empty list when the layer is as expected."""
    from osgeo import gdal, osr

    gdal.UseExceptions()
    try:
        dataset = gdal.OpenEx(path, gdal.OF_VECTOR | gdal.OF_READONLY)
    except RuntimeError as error:
        return [f"{path}: GDAL cannot open it as a vector file ({error})"]
    found = dataset.GetLayerByName(layer)
    if found is None:
        names = [dataset.GetLayer(k).GetName() for k in range(dataset.GetLayerCount())]
        return [f"{path}: no layer '{layer}'; its layers: {', '.join(names) or 'none'}"]
    problems = []
    count = found.GetFeatureCount()
    if count != features:
        problems.append(f"{path}, layer '{layer}': {count} features (GDAL), expected {features}")
    expected = osr.SpatialReference()
    expected.ImportFromEPSG(epsg)
    srs = found.GetSpatialRef()
    if srs is None or not srs.IsSame(expected):
        name = srs.GetName() if srs is not None else "none"
        problems.append(f"{path}, layer '{layer}': coordinate system '{name}' (GDAL), "
                        f"expected EPSG:{epsg} ({expected.GetName()})")
    if not problems:
        print(f"{path}, layer '{layer}': GDAL reads {count} features in EPSG:{epsg}")
    return problems


def check_with_qgis(path: str, layer: str, features: int, epsg: int) -> list[str] | None:
    """The problems QGIS finds, or None when QGIS's Python bindings are not installed."""
    os.environ["QT_QPA_PLATFORM"] = "offscreen"  # no display needed
    home = tempfile.TemporaryDirectory(prefix="check_debris_gpkg_home_")
    os.environ["HOME"] = home.name  # QGIS writes its profile there, not in the user's home
    os.environ.setdefault("XDG_RUNTIME_DIR", home.name)  # Qt wants one (mode 0700)
    try:
        from qgis.core import QgsApplication, QgsVectorLayer
        from qgis.PyQt.QtCore import QVariant
    except ImportError:
        return None
    QgsApplication.setPrefixPath("/usr", True)
    app = QgsApplication([], False)
    app.initQgis()
    problems = []
    try:
        loaded = QgsVectorLayer(f"{path}|layername={layer}", layer, "ogr")
        if not loaded.isValid():
            problems.append(f"{path}, layer '{layer}': QGIS cannot load it as a vector layer")
        else:
            authid = loaded.crs().authid()
            count = loaded.featureCount()
            if authid != f"EPSG:{epsg}":
                problems.append(f"{path}, layer '{layer}': QGIS reads the coordinate system "
                                f"'{authid or 'none'}', expected EPSG:{epsg}")
            if count != features:
                problems.append(f"{path}, layer '{layer}': {count} features (QGIS), "
                                f"expected {features}")
            time_field = loaded.fields().indexOf("time")
            if time_field >= 0 and loaded.fields().at(time_field).type() != QVariant.DateTime:
                problems.append(f"{path}, layer '{layer}': QGIS reads 'time' as "
                                f"{loaded.fields().at(time_field).typeName()}, not a date-time")
            if not problems:
                print(f"{path}, layer '{layer}': QGIS loads it (valid, {authid}, {count} features"
                      f"{', time a date-time' if time_field >= 0 else ''})")
        del loaded
    finally:
        app.exitQgis()
        home.cleanup()
    return problems


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("file")
    parser.add_argument("--layer", required=True, help="tracks or jams")
    parser.add_argument("--expect-features", type=int, required=True, metavar="N")
    parser.add_argument("--expect-epsg", type=int, required=True, metavar="CODE")
    parser.add_argument("--require-qgis", action="store_true",
                        help="a missing QGIS is an error, not a skipped check")
    args = parser.parse_args()
    if not os.path.isfile(args.file):
        print(f"{args.file}: no such file")
        return 1
    try:
        problems = check_with_gdal(args.file, args.layer, args.expect_features, args.expect_epsg)
    except ImportError:
        print("GDAL's Python bindings (osgeo) are missing: install python3-gdal and run this "
              "script with /usr/bin/python3")
        return 1
    qgis_problems = check_with_qgis(args.file, args.layer, args.expect_features, args.expect_epsg)
    if qgis_problems is None:
        if args.require_qgis:
            problems.append("QGIS not available (import qgis.core failed) and --require-qgis "
                            "given: install python3-qgis and run with /usr/bin/python3")
        else:
            print("QGIS not available: skipped the QGIS check")
    else:
        problems += qgis_problems
    for problem in problems:
        print(problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
