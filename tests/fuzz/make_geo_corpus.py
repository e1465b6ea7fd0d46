#!/usr/bin/python3
"""Writes the raster and vector fuzzers' seed corpus (tests/fuzz/corpus/raster, .../vector):
small GeoTIFFs and GeoPackage/GeoJSON layers of the kinds a case reads. Run once; the files are
kept in the repository (a few kilobytes each, the GeoPackages about 100 KB).

    /usr/bin/python3 tests/fuzz/make_geo_corpus.py
"""
import os

import numpy as np
from osgeo import gdal, ogr, osr

gdal.UseExceptions()
here = os.path.dirname(os.path.abspath(__file__))
rasters, vectors = (os.path.join(here, "corpus", k) for k in ("raster", "vector"))
os.makedirs(rasters, exist_ok=True)
os.makedirs(vectors, exist_ok=True)
utm = osr.SpatialReference()
utm.ImportFromEPSG(32633)

def geotiff(name, dtype, options=(), georeferenced=True, nodata=None):
    path = os.path.join(rasters, name)
    d = gdal.GetDriverByName("GTiff").Create(path, 6, 4, 1, dtype, list(options))
    if georeferenced:
        d.SetGeoTransform((500000.0, 2.0, 0.0, 5000008.0, 0.0, -2.0))
        d.SetProjection(utm.ExportToWkt())
    band = d.GetRasterBand(1)
    if nodata is not None:
        band.SetNoDataValue(nodata)
    band.WriteArray((np.arange(24).reshape(4, 6) * 0.5 + 100.0).astype(float))
    d = None

geotiff("float32_nodata.tif", gdal.GDT_Float32, nodata=-9999.0)
geotiff("int16.tif", gdal.GDT_Int16)
geotiff("deflate_float64.tif", gdal.GDT_Float64, options=("COMPRESS=DEFLATE",))
geotiff("no_georeference.tif", gdal.GDT_Float32, georeferenced=False)

def layer(path, driver, name, geometry, features):
    ds = ogr.GetDriverByName(driver).CreateDataSource(path)
    lyr = ds.CreateLayer(name, utm, geometry)
    lyr.CreateField(ogr.FieldDefn("n", ogr.OFTReal))
    lyr.CreateField(ogr.FieldDefn("name", ogr.OFTString))
    for wkt, n, label in features:
        f = ogr.Feature(lyr.GetLayerDefn())
        f.SetGeometry(ogr.CreateGeometryFromWkt(wkt))
        f.SetField("n", n)
        f.SetField("name", label)
        lyr.CreateFeature(f)
    ds = None

polygons = [("POLYGON ((0 0,10 0,10 10,0 10,0 0),(2 2,2 4,4 4,4 2,2 2))", 0.03, "a"),
            ("MULTIPOLYGON (((20 0,30 0,30 10,20 0)),((40 0,50 0,50 10,40 0)))", 0.05, "b")]
lines = [("LINESTRING (0 0,0 10)", 0.0, "inflow"), ("LINESTRING (50 0,50 10)", 0.0, "outflow")]
for name, driver, extension in (("GPKG", "GPKG", "gpkg"), ("GeoJSON", "GeoJSON", "geojson")):
    layer(os.path.join(vectors, f"polygons.{extension}"), driver, "zones", ogr.wkbPolygon,
          polygons[:1])
    layer(os.path.join(vectors, f"multipolygons.{extension}"), driver, "zones",
          ogr.wkbMultiPolygon, polygons[1:])
    layer(os.path.join(vectors, f"lines.{extension}"), driver, "boundaries", ogr.wkbLineString,
          lines)
print("wrote", sorted(os.listdir(rasters)), sorted(os.listdir(vectors)))
