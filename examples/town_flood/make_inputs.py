#!/usr/bin/env python3
"""Writes the geodata of examples/town_flood/town_flood.yaml into examples/town_flood/data/.

A synthetic valley, nothing downloaded, the same files at every run:

  valley_dem.tif  terrain model (GeoTIFF, Float32, 2 m pixels, EPSG:32633): a valley 1.6 km long
                  falling 2.5 m per km towards the east, a river channel 22 m wide and 2.8 m deep
                  meandering gently down it, a floodplain, a terrace on the north bank where a
                  small town stands around a road bridge (its deck is not in the terrain: the
                  water passes under it, between its piers)
  town.gpkg       GeoPackage, same coordinate system, layers:
                    domain      the outline of the modelled valley (one polygon)
                    boundaries  lines along the outline, attribute name: inflow (west end),
                                outflow (east end)
                    buildings   32 footprints in eight blocks, streets between them, a few turned
                    piers       the bridge's three circular piers as polygons (for the map; the
                                case gives them as circles, mesh.region.piers)
                    bridges     the road bridge's axis (a line from its right abutment to its
                                left one, looking downstream), attribute name (the case's bridges)
                    landuse     attribute manning_n: channel 0.03, floodplain grass 0.05, town
                                streets 0.015 (for flow.friction zones)
                    parking     the parking lanes of the streets, attribute count: the cars the
                                case parks there (bodies.release zones)

Run it with Debian's python3 (packages python3-gdal, python3-numpy; `make deps` installs them):

    python3 examples/town_flood/make_inputs.py [--out DIR]

The coordinates are EPSG:32633 (UTM zone 33 N); the script works in local metres (x east, y
north) from the point E 500000 m, N 5100000 m (X0, Y0) and adds it when writing.
"""

import argparse
import math
import os
import sys

try:
    import numpy as np
    from osgeo import gdal, ogr, osr
except ImportError as missing:
    sys.exit(f"{missing}: this script needs numpy and GDAL's Python bindings, Debian's packages "
             "python3-numpy and python3-gdal (`make deps` installs them); run it with Debian's "
             "python3 (/usr/bin/python3), which finds them")

gdal.UseExceptions()
ogr.UseExceptions()
# the GeoPackage stamps its tables with this date instead of now: the same bytes at every run
gdal.SetConfigOption("OGR_CURRENT_DATE", "2026-11-24T00:00:00Z")

EPSG = 32633
X0, Y0 = 500000.0, 5100000.0  # [m] false origin of the local coordinates

LENGTH = 1600.0  # [m] of the modelled valley, west (x = 0) to east
PIXEL = 2.0      # [m] terrain model resolution
MARGIN = 20.0    # [m] the terrain model reaches this far beyond the outline

# The valley: its floor falls 2.5 m per km towards the east (z = 100 m at x = 0); the
# floodplain rises 5 mm per m away from the valley axis y = 200 m, up to 180 m north of it and
# 140 m south of it; the valley sides beyond rise at 7 %.
Z_UPSTREAM = 100.0   # [m] valley floor on the axis at x = 0
VALLEY_SLOPE = 0.0025
AXIS_Y = 200.0       # [m]
FLOODPLAIN_SLOPE = 0.005
SIDE_SLOPE = 0.07
FLOODPLAIN_NORTH, FLOODPLAIN_SOUTH = 180.0, 140.0  # [m] from the axis

# The river: its centre line swings 35 m either side of the axis with a wavelength of 800 m
# (a bend towards the town at the bridge, x = 1000 m); a parabolic section 22 m wide at the
# top and 2.8 m deep below the valley floor.
MEANDER_AMPLITUDE = 35.0     # [m]
MEANDER_WAVELENGTH = 800.0   # [m]
CHANNEL_HALF_WIDTH = 11.0    # [m]
CHANNEL_DEPTH = 2.8          # [m]

BRIDGE_X = 1000.0            # [m] the road bridge, across the river's northern bend
PIER_RADIUS = 1.5            # [m]

# The town's terrace: x in [820, 1200] m, rising 0.8 % northwards from 50 m off the axis, so
# that its riverside street lies 0.25-0.4 m above the valley floor and its northern edge 1.8 m.
TOWN = (820.0, 1200.0, 250.0, 372.0)  # [m] x_min, x_max, y_min, y_max
TERRACE_SLOPE = 0.008
TERRACE_FROM = 50.0                   # [m] north of the axis
TERRACE_TAPER = 80.0                  # [m] along x outside the town

# The town's streets (local metres): a riverside street along y in [250, 262], a cross street
# along y in [306, 318], the bridge road (main street) along x in [990, 1010], lanes at
# x in [900, 910] and [1090, 1100]. The buildings fill the eight blocks between them.
BLOCKS = [  # x_min, x_max, y_min, y_max [m]
    (830.0, 898.0, 266.0, 302.0), (912.0, 986.0, 266.0, 302.0),
    (1014.0, 1088.0, 266.0, 302.0), (1102.0, 1190.0, 266.0, 302.0),
    (830.0, 898.0, 322.0, 366.0), (912.0, 986.0, 322.0, 366.0),
    (1014.0, 1088.0, 322.0, 366.0), (1102.0, 1190.0, 322.0, 366.0),
]

# Parking lanes (local metres) and the cars parked in each: cars stand along the riverside
# and cross streets, and across the main street's east side; the case's bodies.release zones
# are these polygons.
PARKING = [  # name, x_min, x_max, y_min, y_max, count
    ("riverside_west", 838.0, 984.0, 253.0, 258.0, 10),
    ("riverside_east", 1016.0, 1184.0, 253.0, 258.0, 10),
    ("cross_west", 838.0, 984.0, 308.0, 313.0, 8),
    ("cross_east", 1016.0, 1184.0, 308.0, 313.0, 8),
    ("main_street", 1001.0, 1008.0, 268.0, 300.0, 5),
]

# The outline: the valley between its sides, west to east along the south, back along the north.
OUTLINE = [(0.0, 10.0), (400.0, 0.0), (800.0, 15.0), (1200.0, 5.0), (LENGTH, 10.0),
           (LENGTH, 430.0), (1200.0, 440.0), (800.0, 430.0), (400.0, 440.0), (0.0, 430.0)]


def river_centre(x):
    """y of the river's centre line at x [m]: the northern bend at the bridge."""
    return AXIS_Y + MEANDER_AMPLITUDE * np.cos(2 * np.pi * (x - BRIDGE_X) / MEANDER_WAVELENGTH)


def river_direction(x):
    """Unit vector along the river at x, downstream."""
    dy = -MEANDER_AMPLITUDE * 2 * np.pi / MEANDER_WAVELENGTH * np.sin(
        2 * np.pi * (x - BRIDGE_X) / MEANDER_WAVELENGTH)
    n = np.hypot(1.0, dy)
    return 1.0 / n, dy / n


def smoothstep(t):
    t = np.clip(t, 0.0, 1.0)
    return t * t * (3 - 2 * t)


def terrain(x, y):
    """Bed elevation [m] at local x, y [m] (arrays)."""
    floor = Z_UPSTREAM - VALLEY_SLOPE * x
    d = y - AXIS_Y
    north = FLOODPLAIN_SLOPE * np.minimum(d, FLOODPLAIN_NORTH) + SIDE_SLOPE * np.maximum(
        d - FLOODPLAIN_NORTH, 0.0)
    south = FLOODPLAIN_SLOPE * np.minimum(-d, FLOODPLAIN_SOUTH) + SIDE_SLOPE * np.maximum(
        -d - FLOODPLAIN_SOUTH, 0.0)
    z = floor + np.where(d >= 0, north, south)
    # the town's terrace, tapered to nothing over TERRACE_TAPER metres beyond the town's ends
    x0, x1 = TOWN[0], TOWN[1]
    along = smoothstep((x - (x0 - TERRACE_TAPER)) / TERRACE_TAPER) * smoothstep(
        ((x1 + TERRACE_TAPER) - x) / TERRACE_TAPER)
    z += along * TERRACE_SLOPE * np.clip(d - TERRACE_FROM, 0.0, FLOODPLAIN_NORTH - TERRACE_FROM)
    # the river: a parabolic section below the valley floor, measured across the centre line
    # (the distance along y scaled by the centre line's direction)
    ux, _ = river_direction(x)
    across = np.abs(y - river_centre(x)) * ux
    channel = floor - CHANNEL_DEPTH * (1.0 - (across / CHANNEL_HALF_WIDTH) ** 2)
    return np.minimum(z, channel)


def write_dem(path, srs):
    x_min, x_max = -MARGIN, LENGTH + MARGIN
    y_min, y_max = -MARGIN, max(p[1] for p in OUTLINE) + MARGIN
    nx, ny = int(round((x_max - x_min) / PIXEL)), int(round((y_max - y_min) / PIXEL))
    xc = x_min + PIXEL * (np.arange(nx) + 0.5)
    yc = y_max - PIXEL * (np.arange(ny) + 0.5)  # north-up: row 0 is the northern edge
    z = terrain(xc[np.newaxis, :], yc[:, np.newaxis]).astype(np.float32)
    driver = gdal.GetDriverByName("GTiff")
    ds = driver.Create(path, nx, ny, 1, gdal.GDT_Float32,
                       options=["COMPRESS=DEFLATE", "PREDICTOR=3", "TILED=YES"])
    ds.SetGeoTransform((X0 + x_min, PIXEL, 0.0, Y0 + y_max, 0.0, -PIXEL))
    ds.SetProjection(srs.ExportToWkt())
    band = ds.GetRasterBand(1)
    band.WriteArray(z)
    band.SetDescription("bed elevation [m]")
    ds = None
    return nx, ny, float(z.min()), float(z.max())


def absolute(points):
    return [(X0 + x, Y0 + y) for x, y in points]


def polygon(points, holes=()):
    g = ogr.Geometry(ogr.wkbPolygon)
    for ring_points in [points, *holes]:
        ring = ogr.Geometry(ogr.wkbLinearRing)
        for x, y in absolute(ring_points):
            ring.AddPoint_2D(x, y)
        ring.CloseRings()
        g.AddGeometry(ring)
    return g


def line(points):
    g = ogr.Geometry(ogr.wkbLineString)
    for x, y in absolute(points):
        g.AddPoint_2D(x, y)
    return g


def rectangle(cx, cy, length, width, angle_deg=0.0):
    """Corners of a length x width rectangle centred on (cx, cy), turned by angle_deg."""
    c, s = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg))
    half = [(-length / 2, -width / 2), (length / 2, -width / 2), (length / 2, width / 2),
            (-length / 2, width / 2)]
    return [(round(cx + c * a - s * b, 2), round(cy + s * a + c * b, 2)) for a, b in half]


def circle(cx, cy, r, n=32):
    return [(cx + r * math.cos(2 * math.pi * k / n), cy + r * math.sin(2 * math.pi * k / n))
            for k in range(n)]


def buildings():
    """Footprints in the blocks: four a block, along the block with gaps of 4-7 m for yards and
    passages, each on the street side of its block; one in four turned by 8-20 degrees."""
    rng = np.random.RandomState(16)  # the legacy generator: the same numbers on every numpy
    footprints = []
    for b, (x0, x1, y0, y1) in enumerate(BLOCKS):
        slots = 4
        slot = (x1 - x0) / slots
        for k in range(slots):
            length = rng.uniform(0.62, 0.78) * slot         # [m] along the street
            depth = rng.uniform(10.0, 17.0)                 # [m] back from the street
            turned = rng.uniform() < 0.25
            angle = rng.uniform(8.0, 20.0) * rng.choice([-1, 1]) if turned else 0.0
            if turned:  # smaller, so that its turned corners stay in the slot
                length, depth = 0.7 * length, min(0.8 * depth, 0.7 * slot)
            cx = x0 + slot * (k + 0.5)
            # 2 m back from the street on the block's south side (the riverside street for the
            # southern blocks, the cross street for the northern ones)
            margin = 2.0 + 0.5 * (length * abs(math.sin(math.radians(angle))))
            footprints.append(rectangle(cx, y0 + margin + depth / 2, length, depth, angle))
    check_apart(footprints)
    return footprints


def check_apart(footprints, gap=3.0):
    """Every footprint inside its block and at least `gap` metres from every other."""
    shapes = [polygon(c) for c in footprints]
    blocks = [polygon([(x0, y0), (x1, y0), (x1, y1), (x0, y1)]) for x0, x1, y0, y1 in BLOCKS]
    for i, a in enumerate(shapes):
        assert any(b.Contains(a) for b in blocks), f"building {i + 1} leaves its block"
        for j in range(i):
            assert a.Distance(shapes[j]) >= gap, f"buildings {j + 1} and {i + 1} are too close"


def landuse_parts(domain):
    """The channel (its banks offset 11 m either side of the centre line), the town's streets
    (the town's terrace; the buildings are holes in the mesh anyway), and the floodplain: the rest
    of the domain."""
    xs = np.arange(-20.0, LENGTH + 20.0 + 1e-9, 10.0)
    ux, uy = river_direction(xs)
    yc = river_centre(xs)
    left = [(x - uy_ * CHANNEL_HALF_WIDTH, y + ux_ * CHANNEL_HALF_WIDTH)
            for x, y, ux_, uy_ in zip(xs, yc, ux, uy)]
    right = [(x + uy_ * CHANNEL_HALF_WIDTH, y - ux_ * CHANNEL_HALF_WIDTH)
             for x, y, ux_, uy_ in zip(xs, yc, ux, uy)]
    channel = polygon(right + left[::-1]).Intersection(domain)
    x0, x1, y0, y1 = TOWN
    town = polygon([(x0, y0), (x1, y0), (x1, y1), (x0, y1)]).Difference(channel)
    floodplain = domain.Difference(channel).Difference(town)
    return [("channel", 0.03, channel), ("town_streets", 0.015, town),
            ("floodplain_grass", 0.05, floodplain)]


def write_layers(path, srs):
    driver = ogr.GetDriverByName("GPKG")
    if os.path.exists(path):
        driver.DeleteDataSource(path)
    ds = driver.CreateDataSource(path)

    def layer(name, geometry_type, fields):
        lyr = ds.CreateLayer(name, srs, geometry_type)
        for field_name, field_type in fields:
            lyr.CreateField(ogr.FieldDefn(field_name, field_type))
        return lyr

    def add(lyr, geometry, **values):
        f = ogr.Feature(lyr.GetLayerDefn())
        for k, v in values.items():
            f.SetField(k, v)
        f.SetGeometry(geometry)
        lyr.CreateFeature(f)

    domain = polygon(OUTLINE)
    add(layer("domain", ogr.wkbPolygon, [("name", ogr.OFTString)]), domain, name="valley")

    lines = layer("boundaries", ogr.wkbLineString, [("name", ogr.OFTString)])
    add(lines, line([OUTLINE[-1], OUTLINE[0]]), name="inflow")   # x = 0, the west end
    add(lines, line([OUTLINE[4], OUTLINE[5]]), name="outflow")   # x = LENGTH, the east end

    footprints = buildings()
    lyr = layer("buildings", ogr.wkbPolygon, [("id", ogr.OFTInteger)])
    for k, corners in enumerate(footprints):
        add(lyr, polygon(corners), id=k + 1)

    lyr = layer("piers", ogr.wkbPolygon, [("id", ogr.OFTInteger), ("radius", ogr.OFTReal)])
    for k, (x, y) in enumerate(pier_centres()):
        add(lyr, polygon(circle(x, y, PIER_RADIUS)), id=k + 1, radius=PIER_RADIUS)

    lyr = layer("bridges", ogr.wkbLineString, [("name", ogr.OFTString)])
    add(lyr, line(bridge_axis()), name="road_bridge")

    lyr = layer("landuse", ogr.wkbMultiPolygon,
                [("name", ogr.OFTString), ("manning_n", ogr.OFTReal)])
    for name, n, g in landuse_parts(domain):
        add(lyr, ogr.ForceToMultiPolygon(g), name=name, manning_n=n)

    lyr = layer("parking", ogr.wkbPolygon, [("name", ogr.OFTString), ("count", ogr.OFTInteger)])
    for name, x0, x1, y0, y1, count in PARKING:
        add(lyr, polygon([(x0, y0), (x1, y0), (x1, y1), (x0, y1)]), name=name, count=count)
    ds = None
    return footprints


def pier_centres():
    """Three piers across the river at the bridge, 8 m apart, the middle one on its centre line."""
    yc = float(river_centre(BRIDGE_X))
    return [(BRIDGE_X, yc - 8.0), (BRIDGE_X, yc), (BRIDGE_X, yc + 8.0)]


def bridge_axis():
    """The road bridge's axis, from its right (south) abutment to its left (north) one: across the
    river 22 m wide and 4 m of floodplain on either side."""
    yc = float(river_centre(BRIDGE_X))
    return [(BRIDGE_X, yc - CHANNEL_HALF_WIDTH - 4.0), (BRIDGE_X, yc + CHANNEL_HALF_WIDTH + 4.0)]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default=os.path.join(here, "data"),
                        help="folder for valley_dem.tif and town.gpkg (default: %(default)s)")
    out = parser.parse_args().out
    os.makedirs(out, exist_ok=True)
    srs = osr.SpatialReference()
    srs.ImportFromEPSG(EPSG)
    srs.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)  # x = easting, y = northing

    dem = os.path.join(out, "valley_dem.tif")
    nx, ny, z_min, z_max = write_dem(dem, srs)
    print(f"wrote {dem}: {nx} x {ny} pixels of {PIXEL:g} m, bed {z_min:.2f} .. {z_max:.2f} m")
    gpkg = os.path.join(out, "town.gpkg")
    footprints = write_layers(gpkg, srs)
    print(f"wrote {gpkg}: layers domain, boundaries, buildings ({len(footprints)}), piers "
          f"({len(pier_centres())}), bridges (1), landuse, parking ({sum(p[5] for p in PARKING)} cars in "
          f"{len(PARKING)} lanes)")


if __name__ == "__main__":
    main()
