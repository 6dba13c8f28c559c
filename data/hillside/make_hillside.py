#!/usr/bin/env python3
"""Writes the synthetic town on a hillside of scenes/hillside-town.xml: a DGM as an ESRI ASCII
grid (dgm.asc, 5 m), an OpenStreetMap extract of the same place (town.osm: streets, two
residential blocks, houses) and ATKIS-style areas (areas.geojson: a forest and a meadow, both
running over streets), in ETRS89 / UTM 32 (EPSG:25832) on the zone's central meridian. The
OSM nodes are the UTM points converted to WGS 84 with PROJ's cs2cs (apt-get install proj-bin),
to 1e-7 degrees. Deterministic: the same files every run.

    python3 data/hillside/make_hillside.py data/hillside
"""
import json
import math
import os
import subprocess
import sys

ORIGIN_E, ORIGIN_N = 500000.0, 5330150.0  # the scene's origin: the centre of the town's box
HALF = 150.0                              # the DGM reaches this far from the origin
SPACING = 5.0
NODES = int(2 * HALF / SPACING) + 1       # 61 x 61


def height(x, y):
    """The hillside, local metres: rising 13 % to the north, with a spur and a hollow."""
    return (540.0 + 0.13 * y + 3.5 * math.sin(x / 40.0 + 0.5)
            + 1.5 * math.sin(y / 23.0) * math.cos(x / 31.0))


def write_dgm(folder):
    west, south = ORIGIN_E - HALF, ORIGIN_N - HALF
    with open(os.path.join(folder, "dgm.asc"), "w") as f:
        f.write(f"ncols {NODES}\nnrows {NODES}\n")
        f.write(f"xllcorner {west - SPACING / 2:.3f}\nyllcorner {south - SPACING / 2:.3f}\n")
        f.write(f"cellsize {SPACING:.3f}\nNODATA_value -99999\n")
        for row in range(NODES - 1, -1, -1):  # north to south
            y = row * SPACING - HALF
            f.write(" ".join(f"{height(c * SPACING - HALF, y):.3f}" for c in range(NODES)) + "\n")


# The town, local metres from the origin; its box is symmetric about it, so that an OSM frame
# centred on the data's box lies on the scene's.
STREETS = [  # (highway, points)
    ("residential", [(-130, -70), (-60, -68), (0, -66), (60, -64), (130, -62)]),  # the main street
    ("residential", [(-60, -68), (-57, 0), (-54, 66)]),                           # up the hill, west
    ("residential", [(60, -64), (63, 2), (66, 70)]),                              # and east
    ("residential", [(-130, -2), (-57, 0), (63, 2), (130, 4)]),                   # along the slope
    ("service", [(-54, 66), (6, 68), (66, 70)]),                                  # the top lane, in the forest
]
BLOCKS = [  # residential areas on the streets' centrelines
    [(-60, -68), (0, -66), (60, -64), (63, 2), (-57, 0)],  # with the houses below
    [(-130, -70), (-60, -68), (-57, 0), (-130, -2)],       # without: perimeter lots
]


def houses():
    """Two rows of houses in the first block, set back behind the sidewalks."""
    result = []
    for i in range(6):
        x0 = -52 + 17 * i
        front = -67 + (x0 + 6.5) / 30  # the main street's centreline there
        result.append(([(x0, front + 7), (x0 + 13, front + 7), (x0 + 13, front + 18), (x0, front + 18)], 3 + i % 2))
        back = (x0 + 6.5 + 57) / 60  # the upper street's
        result.append(([(x0, back - 18), (x0 + 13, back - 18), (x0 + 13, back - 7), (x0, back - 7)], 3 + (i + 1) % 2))
    return result


def to_wgs84(points):
    """UTM 32 (local + origin) to WGS 84 latitude and longitude with cs2cs."""
    text = "".join(f"{ORIGIN_E + x:.3f} {ORIGIN_N + y:.3f}\n" for x, y in points)
    out = subprocess.run(["cs2cs", "-f", "%.9f", "EPSG:25832", "EPSG:4326"], input=text, capture_output=True,
                         text=True, check=True).stdout
    return [(float(line.split()[0]), float(line.split()[1])) for line in out.splitlines()]


def write_osm(folder):
    nodes = {}  # local point -> node id; ways that share a point share its node

    def node_ids(points):
        ids = []
        for p in points:
            if p not in nodes:
                nodes[p] = 1000 + len(nodes)
            ids.append(nodes[p])
        return ids

    ways = []
    for highway, points in STREETS:
        ways.append((node_ids(points), {"highway": highway}))
    for ring in BLOCKS:
        ids = node_ids(ring)
        ways.append((ids + ids[:1], {"landuse": "residential"}))
    for outline, levels in houses():
        ids = node_ids(outline)
        ways.append((ids + ids[:1], {"building": "house", "building:levels": str(levels), "roof:shape": "gabled"}))
    points = sorted(nodes, key=nodes.get)
    coordinates = to_wgs84(points)
    lines = ['<?xml version="1.0" encoding="UTF-8"?>',
             "<!-- veduta scene data (scenes/hillside-town.xml), written by data/hillside/make_hillside.py: a",
             "     made-up town, not OpenStreetMap data, on the synthetic hillside of dgm.asc. -->",
             '<osm version="0.6" generator="make_hillside.py">']
    for p, (lat, lon) in zip(points, coordinates):
        lines.append(f'  <node id="{nodes[p]}" version="1" lat="{lat:.7f}" lon="{lon:.7f}"/>')
    for k, (ids, tags) in enumerate(ways):
        lines.append(f'  <way id="{2000 + k}" version="1">')
        lines.extend(f'    <nd ref="{i}"/>' for i in ids)
        lines.extend(f'    <tag k="{key}" v="{value}"/>' for key, value in tags.items())
        lines.append("  </way>")
    lines.append("</osm>")
    with open(os.path.join(folder, "town.osm"), "w") as f:
        f.write("\n".join(lines) + "\n")


def write_areas(folder):
    def area(objart, object_id, x0, y0, x1, y1):
        ring = [[ORIGIN_E + x, ORIGIN_N + y] for x, y in [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)]]
        return {"type": "Feature", "properties": {"OBJART": objart, "OBJID": object_id},
                "geometry": {"type": "Polygon", "coordinates": [ring]}}

    collection = {"type": "FeatureCollection", "name": "areas",
                  "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::25832"}},
                  "features": [area(4107, "DEBWHILLF1", -150, 40, 150, 150),     # forest over the top lane
                               area(4102, "DEBWHILLM1", -150, -150, 150, -58)]}  # meadow over the main street
    with open(os.path.join(folder, "areas.geojson"), "w") as f:
        json.dump(collection, f, indent=1)
        f.write("\n")


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    os.makedirs(folder, exist_ok=True)
    write_dgm(folder)
    write_osm(folder)
    write_areas(folder)


if __name__ == "__main__":
    main()
