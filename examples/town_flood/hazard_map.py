#!/usr/bin/python3
"""Draws the town flood's hazard map: the Australian hazard classes H1-H6 (docs/model.md "Flood
hazard") that flotsam wrote as a GeoTIFF, over a hillshade of the terrain, as a PNG.

    /usr/bin/python3 examples/town_flood/hazard_map.py out/town_flood hazard.png

Reads <run>/town_flood_australian_hazard_class.tif and examples/town_flood/data/valley_dem.tif
(make_inputs.py); Debian's python3-gdal and python3-numpy.
"""
import os
import sys

import numpy as np
from osgeo import gdal

gdal.UseExceptions()

# H1 ... H6: from green (generally safe) to dark red (all buildings vulnerable to failure)
COLOURS = np.array([[26, 150, 65], [166, 217, 106], [255, 255, 140],
                    [253, 174, 97], [215, 25, 28], [120, 0, 30]], dtype=float)
OPACITY = 0.8


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    run, png = sys.argv[1], sys.argv[2]
    classes = gdal.Open(os.path.join(run, "town_flood_australian_hazard_class.tif"))
    dem = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "valley_dem.tif")
    x0, dx, _, y0, _, dy = classes.GetGeoTransform()
    width, height = classes.RasterXSize, classes.RasterYSize
    # The terrain on the classes' grid, then its hillshade (light from the north-west).
    terrain = gdal.Warp("", dem, format="MEM", width=width, height=height,
                        outputBounds=(x0, y0 + dy * height, x0 + dx * width, y0),
                        resampleAlg="bilinear")
    shade = gdal.DEMProcessing("", terrain, "hillshade", format="MEM", zFactor=3.0)
    grey = shade.ReadAsArray().astype(float)
    grey = 0.35 * 255 + 0.65 * grey  # lighter, so that the colours read
    band = classes.GetRasterBand(1)
    h = band.ReadAsArray()
    wet = (h != band.GetNoDataValue()) & (h >= 1)
    rgb = np.repeat(grey[:, :, None], 3, axis=2)
    colour = COLOURS[np.clip(h.astype(int), 1, 6) - 1]
    rgb[wet] = (1 - OPACITY) * rgb[wet] + OPACITY * colour[wet]
    out = gdal.GetDriverByName("MEM").Create("", width, height, 3, gdal.GDT_Byte)
    for k in range(3):
        out.GetRasterBand(k + 1).WriteArray(np.clip(rgb[:, :, k], 0, 255).astype(np.uint8))
    gdal.GetDriverByName("PNG").CreateCopy(png, out)
    counts = [int(((h == c) & wet).sum()) for c in range(1, 7)]
    pixel = abs(dx * dy)  # [m^2]
    print(f"wrote {png}: area per class H1-H6 [m^2] "
          + ", ".join(f"H{c} {n * pixel:.0f}" for c, n in enumerate(counts, 1)))


if __name__ == "__main__":
    main()
