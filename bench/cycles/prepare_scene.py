#!/usr/bin/env python3
"""Reads a veduta scene file and writes what bench/cycles_compare.sh needs to render the same
scene with veduta and with Blender Cycles:

  OUT/scene.xml   the scene for veduta: the input with every relative path made absolute and a
                  sun placed by date and time replaced by the azimuth and elevation computed here
                  (so that both renderers get the very same direction, and the sky that
                  `veduta cubemap` bakes for Blender is the one veduta renders with);
  OUT/scene.json  camera, sun, environment, render settings and every material of the scene
                  (with its maps as absolute paths), for bench/cycles/cycles_build.py.

Usage: prepare_scene.py SCENE.xml OUT_DIR

Only the standard library: it runs under the system python3 and under Blender's.
"""

import json
import math
import os
import sys
import xml.etree.ElementTree as ET
from datetime import date as Date

# Attributes that name files, resolved against the folder of the file they are in.
PATH_ATTRIBUTES = {"file", "rules", "cubemap", "diffuse_map", "specular_map", "normal_map", "reflection_map",
                   "opacity_map", "mesh", "path", "src", "materials", "heightmap", "dgm", "osm", "atkis",
                   "citygml", "ortho", "texture"}


def numbers(text):
    return [float(v) for v in text.replace(",", " ").split()]


def colour(text):
    v = numbers(text)
    return v * 3 if len(v) == 1 else v


# --- NOAA's solar position (the NOAA solar calculator's spreadsheet), as veduta's
# src/scene/sun_position.h follows it: apparent elevation with refraction, azimuth against true
# north. Used only to turn a date and time into an azimuth and elevation that BOTH renderers are
# then given, so a small difference to veduta's own computation changes nothing in the comparison.
def noaa_sun(day, clock, utc_offset, latitude, longitude):
    y, mo, d = (int(v) for v in day.split("-"))
    parts = [int(v) for v in clock.split(":")]
    while len(parts) < 3:
        parts.append(0)
    local_minutes = parts[0] * 60 + parts[1] + parts[2] / 60.0
    if utc_offset in ("Z", "z"):
        tz = 0.0
    else:
        sign = -1.0 if utc_offset[0] == "-" else 1.0
        hh, mm = utc_offset[1:].split(":")
        tz = sign * (int(hh) + int(mm) / 60.0)
    jd = Date(y, mo, d).toordinal() + 1721424.5 + (local_minutes / 60.0 - tz) / 24.0
    t = (jd - 2451545.0) / 36525.0
    l0 = (280.46646 + t * (36000.76983 + t * 0.0003032)) % 360
    m = 357.52911 + t * (35999.05029 - 0.0001537 * t)
    e = 0.016708634 - t * (0.000042037 + 0.0000001267 * t)
    mr = math.radians(m)
    c = (math.sin(mr) * (1.914602 - t * (0.004817 + 0.000014 * t)) + math.sin(2 * mr) * (0.019993 - 0.000101 * t)
         + math.sin(3 * mr) * 0.000289)
    true_long = l0 + c
    omega = 125.04 - 1934.136 * t
    app_long = true_long - 0.00569 - 0.00478 * math.sin(math.radians(omega))
    eps0 = 23 + (26 + (21.448 - t * (46.815 + t * (0.00059 - t * 0.001813))) / 60) / 60
    eps = eps0 + 0.00256 * math.cos(math.radians(omega))
    decl = math.degrees(math.asin(math.sin(math.radians(eps)) * math.sin(math.radians(app_long))))
    var_y = math.tan(math.radians(eps / 2)) ** 2
    l0r = math.radians(l0)
    eot = 4 * math.degrees(var_y * math.sin(2 * l0r) - 2 * e * math.sin(mr) + 4 * e * var_y * math.sin(mr) * math.cos(2 * l0r)
                           - 0.5 * var_y * var_y * math.sin(4 * l0r) - 1.25 * e * e * math.sin(2 * mr))
    tst = (local_minutes + eot + 4 * longitude - 60 * tz) % 1440
    ha = tst / 4 + 180 if tst / 4 < 0 else tst / 4 - 180
    lat, dr, har = math.radians(latitude), math.radians(decl), math.radians(ha)
    cz = math.sin(lat) * math.sin(dr) + math.cos(lat) * math.cos(dr) * math.cos(har)
    zen = math.degrees(math.acos(max(-1.0, min(1.0, cz))))
    s = math.cos(lat) * math.sin(math.radians(zen))
    if abs(s) < 1e-12:
        az = 180.0
    else:
        a = math.degrees(math.acos(max(-1.0, min(1.0, (math.sin(lat) * math.cos(math.radians(zen)) - math.sin(dr)) / s))))
        az = (a + 180) % 360 if ha > 0 else (540 - a) % 360
    el = 90 - zen
    if el > 85:
        refr = 0.0
    else:
        te = math.tan(math.radians(el))
        if el > 5:
            refr = 58.1 / te - 0.07 / te ** 3 + 0.000086 / te ** 5
        elif el > -0.575:
            refr = 1735 + el * (-518.2 + el * (103.4 + el * (-12.79 + el * 0.711)))
        else:
            refr = -20.772 / te
        refr /= 3600
    return az, el + refr


class Reader:
    def __init__(self):
        self.camera = {"position": [0, -10, 2], "look_at": [0, 0, 2], "up": [0, 0, 1], "fov": 45.0,
                       "resolution": [640, 360]}
        self.sun = {"azimuth": 135.0, "elevation": 45.0, "irradiance": [3.0, 3.0, 3.0], "angular_diameter": 0.53}
        self.environment = {"kind": "radiance", "radiance": [0.0, 0.0, 0.0], "intensity": 1.0, "rotation": 0.0}
        self.render = {"spp": 16, "max_depth": 8, "seed": 0, "filter": "blackman-harris", "filter_width": None,
                       "light_sampling": "mis"}
        self.materials = {}
        self.unsupported = []

    def absolutise(self, element, folder):
        for k, v in list(element.attrib.items()):
            if k in PATH_ATTRIBUTES and v and not os.path.isabs(v):
                element.set(k, os.path.normpath(os.path.join(folder, v)))
        for child in element:
            self.absolutise(child, folder)

    def material(self, e):
        a = e.attrib
        m = {"name": a["name"]}
        m["glass"] = a.get("glass", "false") in ("true", "1")
        if m["glass"]:
            m["ior"] = float(a.get("ior", 1.5))
            m["tint"] = colour(a.get("tint", "1"))
        else:
            m["diffuse_map"] = a.get("diffuse_map")
            m["diffuse"] = colour(a["diffuse"]) if "diffuse" in a else ([1, 1, 1] if m["diffuse_map"] else [0.8] * 3)
            m["specular"] = colour(a.get("specular", "1 1 0.85"))
            m["specular_map"] = a.get("specular_map")
            m["specular_intensity"] = float(a.get("specular_intensity", 1 if m["specular_map"] else 0))
            m["shininess"] = float(a.get("shininess", 32))
            m["normal_map"] = a.get("normal_map")
            m["normal_strength"] = float(a.get("normal_strength", 1))
            m["reflection_map"] = a.get("reflection_map")
            m["reflectivity"] = colour(a["reflectivity"]) if "reflectivity" in a else (
                [1, 1, 1] if m["reflection_map"] else [0, 0, 0])
            m["opacity_map"] = a.get("opacity_map")
            for k in ("diffuse_map", "specular_map", "normal_map", "reflection_map", "opacity_map"):
                m[k + "_colorspace"] = a.get(k + "_colorspace", "" if k == "diffuse_map" else "Non-Color")
        self.materials[m["name"]] = m

    def materials_file(self, path):
        root = ET.parse(path).getroot()
        for e in root:
            if e.tag == "material":
                self.absolutise(e, os.path.dirname(path))
                self.material(e)

    def read(self, path):
        tree = ET.parse(path)
        root = tree.getroot()
        folder = os.path.dirname(os.path.abspath(path))
        self.absolutise(root, folder)
        for e in root:
            a = e.attrib
            if e.tag == "camera":
                for k in ("position", "look_at", "up"):
                    if k in a:
                        self.camera[k] = numbers(a[k])
                if "fov" in a:
                    self.camera["fov"] = float(a["fov"])
                if "resolution" in a:
                    self.camera["resolution"] = [int(v) for v in numbers(a["resolution"])]
            elif e.tag == "sun":
                if "direction" in a:
                    d = numbers(a["direction"])
                    n = math.sqrt(sum(v * v for v in d))
                    d = [v / n for v in d]
                    self.sun["azimuth"] = math.degrees(math.atan2(d[0], d[1])) % 360
                    self.sun["elevation"] = math.degrees(math.asin(max(-1, min(1, d[2]))))
                if "azimuth" in a:
                    self.sun["azimuth"], self.sun["elevation"] = float(a["azimuth"]), float(a["elevation"])
                if "date" in a:
                    if "latitude" not in a:
                        sys.exit("prepare_scene.py: a sun placed by date needs latitude/longitude here "
                                 "(a <georeference> origin is not converted)")
                    self.sun["azimuth"], self.sun["elevation"] = noaa_sun(
                        a["date"], a["time"], a["utc_offset"], float(a["latitude"]), float(a["longitude"]))
                    self.sun["from_date"] = "%s %s %s" % (a["date"], a["time"], a["utc_offset"])
                    if self.sun["elevation"] < -self.sun["angular_diameter"] / 2:
                        self.sun["irradiance"] = [0.0, 0.0, 0.0]  # set: veduta's sun lights nothing
                if "irradiance" in a:
                    self.sun["irradiance"] = colour(a["irradiance"])
                if "angular_diameter" in a:
                    self.sun["angular_diameter"] = float(a["angular_diameter"])
                # Rewrite the element for veduta: the direction as azimuth and elevation.
                for k in ("direction", "date", "time", "utc_offset", "latitude", "longitude", "azimuth", "elevation"):
                    a.pop(k, None)
                a["azimuth"] = "%.9g" % self.sun["azimuth"]
                a["elevation"] = "%.9g" % self.sun["elevation"]
                a["irradiance"] = " ".join("%.9g" % v for v in self.sun["irradiance"])
            elif e.tag == "environment":
                if "radiance" in a:
                    self.environment.update(kind="radiance", radiance=colour(a["radiance"]))
                if "cubemap" in a:
                    self.environment.update(kind="map", source=a["cubemap"])
                if "sky" in a:
                    self.environment.update(kind="map", source="sky:" + a["sky"])
                if "intensity" in a:
                    self.environment["intensity"] = float(a["intensity"])
                if "rotation" in a:
                    self.environment["rotation"] = float(a["rotation"])
            elif e.tag == "render":
                for k in ("spp", "max_depth", "seed"):
                    if k in a:
                        self.render[k] = int(a[k])
                for k in ("filter", "light_sampling"):
                    if k in a:
                        self.render[k] = a[k]
                if "filter_width" in a:
                    self.render["filter_width"] = float(a["filter_width"])
            elif e.tag == "material":
                self.material(e)
            elif e.tag == "materials":
                self.materials_file(a["file"])
            elif e.tag in ("georeference", "terrain", "landscape", "city", "vegetation", "trees"):
                self.unsupported.append(e.tag)
        if self.render["filter_width"] is None:
            self.render["filter_width"] = 1.0 if self.render["filter"] == "box" else 1.5
        return tree


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    src, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    r = Reader()
    tree = r.read(src)
    tree.write(os.path.join(out, "scene.xml"), encoding="UTF-8", xml_declaration=True)
    az, el = math.radians(r.sun["azimuth"]), math.radians(r.sun["elevation"])
    r.sun["direction"] = [math.sin(az) * math.cos(el), math.cos(az) * math.cos(el), math.sin(el)]
    data = {"source": os.path.abspath(src), "camera": r.camera, "sun": r.sun, "environment": r.environment,
            "render": r.render, "materials": r.materials}
    with open(os.path.join(out, "scene.json"), "w") as f:
        json.dump(data, f, indent=1)
    note = " (from %s)" % r.sun["from_date"] if "from_date" in r.sun else ""
    print("prepared %s: %dx%d, sun azimuth %.3f elevation %.3f%s, environment %s, %d materials" % (
        src, r.camera["resolution"][0], r.camera["resolution"][1], r.sun["azimuth"], r.sun["elevation"], note,
        r.environment.get("source", "constant"), len(r.materials)))


if __name__ == "__main__":
    main()
