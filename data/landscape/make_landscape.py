#!/usr/bin/env python3
"""Writes the synthetic landscape of scenes/landscape.xml: a DGM as an ESRI ASCII grid (the
format of ../shared/data/dgm/dem_window.asc, whose real heights may not be copied into the
repository) and ATKIS-style vector layers as GeoJSON with OBJART codes, all in ETRS89 / UTM 32
(EPSG:25832) near the Heuneburg. Deterministic: the same file every run.

    python3 data/landscape/make_landscape.py data/landscape
"""
import json
import math
import os
import sys

WEST, SOUTH = 530000.0, 5326000.0  # the south-west DGM node
SPACING = 10.0
COLUMNS, ROWS = 241, 161            # 2.4 km x 1.6 km


def hash01(i, j, seed):
    h = (i * 374761393 + j * 668265263 + seed * 2147483647) & 0xFFFFFFFF
    h = ((h ^ (h >> 13)) * 1274126177) & 0xFFFFFFFF
    return ((h ^ (h >> 16)) & 0xFFFFFF) / float(0x1000000)


def value_noise(x, y, seed):
    i, j = math.floor(x), math.floor(y)
    fx, fy = x - i, y - j
    sx, sy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)
    a, b = hash01(i, j, seed), hash01(i + 1, j, seed)
    c, d = hash01(i, j + 1, seed), hash01(i + 1, j + 1, seed)
    return (a + (b - a) * sx) * (1 - sy) + (c + (d - c) * sx) * sy


def fbm(x, y):
    total, amplitude, frequency = 0.0, 1.0, 1.0 / 600.0
    for octave in range(5):
        total += amplitude * (value_noise(x * frequency, y * frequency, octave + 1) - 0.5)
        amplitude *= 0.5
        frequency *= 2.0
    return total


def river_y(x):
    """The valley's thalweg, local metres from the south-west node."""
    return 560.0 + 90.0 * math.sin(x / 420.0) + 30.0 * math.sin(x / 150.0 + 1.0)


def height(x, y):
    hills = 580.0 + 130.0 * fbm(x, y) + 0.03 * (y - 560.0)
    valley = 45.0 * math.exp(-((y - river_y(x)) / 240.0) ** 2)
    ridge = 45.0 * math.exp(-((x - 1750.0) / 260.0) ** 2 - ((y - 1250.0) / 300.0) ** 2)
    return hills - valley + ridge


def write_dgm(folder):
    with open(os.path.join(folder, "dgm.asc"), "w") as f:
        f.write(f"ncols {COLUMNS}\nnrows {ROWS}\n")
        f.write(f"xllcorner {WEST - SPACING / 2:.3f}\nyllcorner {SOUTH - SPACING / 2:.3f}\n")
        f.write(f"cellsize {SPACING:.3f}\nNODATA_value -99999\n")
        for row in range(ROWS - 1, -1, -1):  # north to south
            y = row * SPACING
            f.write(" ".join(f"{height(c * SPACING, y):.3f}" for c in range(COLUMNS)) + "\n")
    with open(os.path.join(folder, "dgm.prj"), "w") as f:
        f.write('PROJCS["ETRS_1989_UTM_Zone_32N",GEOGCS["GCS_ETRS_1989",DATUM["D_ETRS_1989",'
                'SPHEROID["GRS_1980",6378137.0,298.257222101]],PRIMEM["Greenwich",0.0],'
                'UNIT["Degree",0.0174532925199433]],PROJECTION["Transverse_Mercator"],'
                'PARAMETER["False_Easting",500000.0],PARAMETER["False_Northing",0.0],'
                'PARAMETER["Central_Meridian",9.0],PARAMETER["Scale_Factor",0.9996],'
                'PARAMETER["Latitude_Of_Origin",0.0],UNIT["Meter",1.0]]')


def to_map(points):
    return [[round(WEST + x, 3), round(SOUTH + y, 3)] for x, y in points]


def buffer_line(points, half_width):
    """The outline of a band round a polyline (left side, then the right side back)."""
    left, right = [], []
    for k, (x, y) in enumerate(points):
        a = points[max(k - 1, 0)]
        b = points[min(k + 1, len(points) - 1)]
        dx, dy = b[0] - a[0], b[1] - a[1]
        n = math.hypot(dx, dy)
        nx, ny = -dy / n, dx / n
        left.append((x + nx * half_width, y + ny * half_width))
        right.append((x - nx * half_width, y - ny * half_width))
    return left + right[::-1]


def blob(cx, cy, rx, ry, seed, count=28):
    """A wobbly closed outline round (cx, cy)."""
    points = []
    for k in range(count):
        t = 2 * math.pi * k / count
        r = 1.0 + 0.18 * (value_noise(math.cos(t) * 2 + 5, math.sin(t) * 2 + 5, seed) - 0.5) * 2
        points.append((cx + rx * r * math.cos(t), cy + ry * r * math.sin(t)))
    return points


def feature(objart, geometry_type, coordinates, **attributes):
    properties = {"OBJART": objart}
    properties.update(attributes)
    return {"type": "Feature", "properties": properties,
            "geometry": {"type": geometry_type, "coordinates": coordinates}}


def area(objart, outline, **attributes):
    ring = to_map(outline)
    return feature(objart, "Polygon", [ring + [ring[0]]], **attributes)


def line(objart, points, **attributes):
    return feature(objart, "LineString", to_map(points), **attributes)


def write_layer(folder, name, features):
    collection = {"type": "FeatureCollection", "name": name,
                  "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::25832"}},
                  "features": features}
    with open(os.path.join(folder, name + ".geojson"), "w") as f:
        json.dump(collection, f, indent=1)
        f.write("\n")


def main(folder):
    write_dgm(folder)
    river = [(x, river_y(x)) for x in range(0, 2401, 40)]
    water = [area(5101, buffer_line(river, 9.0), OBJID="DEBWW001"),
             area(5112, blob(1900, river_y(1900) + 55, 95, 45, 7), OBJID="DEBWW002")]
    cover = [
        area(4107, blob(520, 1300, 430, 230, 1), VEG="2000", OBJID="DEBWV001"),   # spruce on the north hill
        area(4107, blob(1750, 1280, 420, 220, 2), VEG="1000", OBJID="DEBWV002"),  # beech on the ridge
        area(4107, blob(1950, 200, 330, 150, 3), VEG="3000", OBJID="DEBWV003"),   # mixed, south-east
        area(4108, blob(1350, 330, 120, 70, 4), OBJID="DEBWV004"),
        area(4108, blob(250, 250, 110, 80, 5), OBJID="DEBWV005"),
        area(4101, [(300, 80), (900, 60), (930, 330), (320, 380)], OBJID="DEBWV006"),
        area(4101, [(1000, 950), (1300, 930), (1320, 1150), (1010, 1180)], OBJID="DEBWV007"),
        area(4102, buffer_line(river, 120.0), OBJID="DEBWV008"),
        area(2111, [(640, 700), (1120, 690), (1130, 900), (650, 920)], OBJID="DEBWS001"),
    ]
    village_road = [(0, 760), (300, 780), (600, 790), (900, 800), (1200, 790), (1500, 760), (1800, 700), (2100, 690), (2400, 720)]
    hill_road = [(900, 800), (950, 950), (1050, 1080), (1150, 1230), (1200, 1450), (1250, 1600)]
    forest_track = [(600, 790), (560, 1000), (480, 1200), (420, 1450)]
    rail = [(0, 420), (500, 430), (1000, 400), (1500, 360), (2000, 330), (2400, 330)]
    traffic = [
        line(3101, village_road, WDM="1305", BRF="0065", OBJID="DEBWT001"),
        line(3101, hill_road, WDM="1307", BRF="0055", OFM="Pflaster", OBJID="DEBWT002"),
        line(3102, forest_track, OBJID="DEBWT003"),
        line(3201, rail, GLS="1000", OBJID="DEBWT004"),
        line(4202, [(1230, 797), (1500, 770), (1790, 713)], OBJID="DEBWV009"),  # 10 m north of the road
    ]
    write_layer(folder, "water", water)
    write_layer(folder, "landcover", cover)
    write_layer(folder, "traffic", traffic)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__)))
