#!/usr/bin/env python3
"""Makes the textures of materials/seed000.xml: small procedural stand-ins for the photos and
Shader Map Pro maps of seed 000's texture folders (facade, roof, materials, door, wall, window,
reflection), so that the repository carries no third-party images.

Run from anywhere: python3 materials/textures/make_textures.py. Pure Python (no numpy), so it
needs nothing beyond Debian's python3; the output is deterministic.

Conventions: colour maps are 8-bit sRGB; data maps (normal, specular, reflection, opacity) are
linear ("Non-Color"). Normal maps are tangent space, OpenGL style: red = +u (right), green = +v
(up in the image), blue = out of the surface.
"""
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def write_png(name, width, height, channels, pixel):
    """pixel(x, y) -> tuple of `channels` floats in [0, 1]; row 0 is the top."""
    rows = bytearray()
    for y in range(height):
        rows.append(0)
        for x in range(width):
            for v in pixel(x, y):
                rows.append(max(0, min(255, int(round(v * 255)))))
    color_type = {1: 0, 3: 2, 4: 6}[channels]

    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, color_type, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(bytes(rows), 9)) + chunk(b"IEND", b"")
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(png)


def hash01(*values):
    h = 0x9E3779B9
    for v in values:
        h ^= (v * 0x85EBCA6B) & 0xFFFFFFFF
        h = ((h << 13) | (h >> 19)) & 0xFFFFFFFF
        h = (h * 5 + 0xE6546B64) & 0xFFFFFFFF
    h ^= h >> 16
    h = (h * 0x7FEB352D) & 0xFFFFFFFF
    h ^= h >> 15
    return h / 4294967296.0


def value_noise(x, y, period, seed):
    """Smooth periodic noise in [0, 1]; (x, y) in cells, period in cells."""
    x0, y0 = int(math.floor(x)), int(math.floor(y))
    fx, fy = x - x0, y - y0
    sx, sy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)

    def corner(i, j):
        return hash01((x0 + i) % period, (y0 + j) % period, seed)

    top = corner(0, 0) * (1 - sx) + corner(1, 0) * sx
    bottom = corner(0, 1) * (1 - sx) + corner(1, 1) * sx
    return top * (1 - sy) + bottom * sy


def fbm(x, y, size, seed, octaves=4, base=8):
    """Tileable fractal noise over an image of `size` pixels, in [0, 1]."""
    total, amplitude, norm = 0.0, 1.0, 0.0
    for o in range(octaves):
        cells = base << o
        total += amplitude * value_noise(x * cells / size, y * cells / size, cells, seed + o)
        norm += amplitude
        amplitude *= 0.5
    return total / norm


def normal_map(height, size, strength):
    """Tangent-space normals from a height function h(x, y) (periodic), OpenGL convention."""
    def pixel(x, y):
        dhdx = (height((x + 1) % size, y) - height((x - 1) % size, y)) * 0.5
        # Image y grows downwards, v upwards.
        dhdv = (height(x, (y - 1) % size) - height(x, (y + 1) % size)) * 0.5
        nx, ny, nz = -dhdx * strength, -dhdv * strength, 1.0
        length = math.sqrt(nx * nx + ny * ny + nz * nz)
        return (nx / length * 0.5 + 0.5, ny / length * 0.5 + 0.5, nz / length * 0.5 + 0.5)
    return pixel


def cached(function, size):
    table = [[function(x, y) for x in range(size)] for y in range(size)]
    return lambda x, y: table[y][x]


# --- Brick wall (category wall): running bond, 4 courses and 2 bricks per course per tile ---
S = 256
COURSES, BRICKS, MORTAR = 8, 4, 0.07  # mortar as a fraction of a course


def brick_cell(x, y):
    course = y * COURSES // S
    shift = 0.5 if course % 2 else 0.0
    u = (x / S * BRICKS + shift) % BRICKS
    brick = int(u)
    fu, fv = u - brick, (y * COURSES / S) - course
    # Distance to the brick's edge, in course heights (bricks are 2 courses... long: scale u).
    edge = min(fu * (COURSES / BRICKS), (1 - fu) * (COURSES / BRICKS), fv, 1 - fv)
    return course, brick, edge


def brick_height(x, y):
    course, brick, edge = brick_cell(x, y)
    if edge < MORTAR * 0.5:
        return -0.6 + 0.2 * fbm(x, y, S, 5, 3, 32)
    bevel = min(1.0, (edge - MORTAR * 0.5) / 0.06)
    return bevel * 0.5 + 0.25 * fbm(x, y, S, 9, 3, 32) - 0.25


brick_h = cached(brick_height, S)


def brick_diffuse(x, y):
    course, brick, edge = brick_cell(x, y)
    n = fbm(x, y, S, 3, 4, 16)
    if edge < MORTAR * 0.5:
        g = 0.62 + 0.1 * n
        return (g, g * 0.97, g * 0.9)
    tone = hash01(course, brick, 1)
    r = 0.55 + 0.2 * tone + 0.12 * (n - 0.5)
    return (r, r * (0.42 + 0.1 * hash01(course, brick, 2)), r * 0.3)


def brick_specular(x, y):
    course, brick, edge = brick_cell(x, y)
    if edge < MORTAR * 0.5:
        return (0.1,)
    return (0.35 + 0.4 * fbm(x, y, S, 21, 3, 16),)


write_png("brick_diffuse.png", S, S, 3, brick_diffuse)
write_png("brick_normal.png", S, S, 3, normal_map(brick_h, S, 6.0))
write_png("brick_specular.png", S, S, 1, brick_specular)

# --- Roof tiles (category roof): rows of rounded clay tiles, overlapping downwards ---
ROWS, TILES = 8, 6


def roof_height(x, y):
    row = y * ROWS // S
    fv = (y * ROWS / S) - row
    u = (x / S * TILES + (0.5 if row % 2 else 0)) % 1.0
    arch = math.sin(math.pi * u) ** 0.6
    return 0.6 * arch + 0.5 * fv + 0.1 * fbm(x, y, S, 31, 3, 16)


roof_h = cached(roof_height, S)


def roof_diffuse(x, y):
    row = y * ROWS // S
    tile = int((x / S * TILES + (0.5 if row % 2 else 0)) % TILES)
    tone = hash01(row, tile, 7)
    n = fbm(x, y, S, 37, 4, 16)
    shade = 0.75 + 0.25 * ((y * ROWS / S) % 1.0)
    r = (0.5 + 0.15 * tone + 0.1 * (n - 0.5)) * shade
    return (r, r * 0.38, r * 0.25)


write_png("roof_diffuse.png", S, S, 3, roof_diffuse)
write_png("roof_normal.png", S, S, 3, normal_map(roof_h, S, 5.0))

# --- Plaster (category facade) ---


def plaster_diffuse(x, y):
    n = fbm(x, y, S, 41, 5, 8)
    g = 0.78 + 0.12 * (n - 0.5)
    return (g, g * 0.93, g * 0.8)


plaster_h = cached(lambda x, y: fbm(x, y, S, 43, 4, 32), S)
write_png("plaster_diffuse.png", S, S, 3, plaster_diffuse)
write_png("plaster_normal.png", S, S, 3, normal_map(plaster_h, S, 1.5))

# --- Sandstone (category material: cornices, sills) ---


def sandstone_diffuse(x, y):
    n = fbm(x, y, S, 51, 5, 8)
    layers = 0.5 + 0.5 * math.sin(y / S * 2 * math.pi * 12 + 3 * n)
    g = 0.62 + 0.1 * layers + 0.08 * (n - 0.5)
    return (g, g * 0.82, g * 0.62)


sandstone_h = cached(lambda x, y: fbm(x, y, S, 53, 4, 16), S)
write_png("sandstone_diffuse.png", S, S, 3, sandstone_diffuse)
write_png("sandstone_normal.png", S, S, 3, normal_map(sandstone_h, S, 2.0))
write_png("sandstone_specular.png", S, S, 1, lambda x, y: (0.3 + 0.4 * sandstone_h(x, y),))

# --- Wooden door planks (category door): vertical planks with grain ---
PLANKS = 5


def wood_height(x, y):
    u = x / S * PLANKS
    fu = u - int(u)
    groove = min(fu, 1 - fu)
    g = fbm(x * 0.25, y * 2.0, S, 61 + int(u), 3, 8)
    return (0.0 if groove < 0.03 else 0.5) + 0.15 * g


wood_h = cached(wood_height, S)


def wood_diffuse(x, y):
    plank = int(x / S * PLANKS)
    grain = fbm(x * 4.0, y * 0.25, S, 67 + plank, 4, 8)
    r = 0.33 + 0.1 * hash01(plank, 3) + 0.12 * (grain - 0.5)
    return (r, r * 0.62, r * 0.38)


write_png("wood_diffuse.png", S, S, 3, wood_diffuse)
write_png("wood_normal.png", S, S, 3, normal_map(wood_h, S, 4.0))
write_png("wood_specular.png", S, S, 1, lambda x, y: (0.3 + 0.5 * wood_h(x, y),))

# --- Reflection maps (categories window, reflection): weathering streaks running down ---


def streaks(seed, base, spread):
    def pixel(x, y):
        column = fbm(x * 1.0, y * 0.02, S, seed, 3, 16)
        spots = fbm(x, y, S, seed + 1, 4, 16)
        return (max(0.0, min(1.0, base + spread * (column - 0.5) - 0.25 * max(0.0, spots - 0.6))),)
    return pixel


write_png("metal_reflection.png", S, S, 1, streaks(71, 0.75, 0.5))
write_png("window_reflection.png", S, S, 1, streaks(73, 0.85, 0.3))


def metal_diffuse(x, y):
    n = fbm(x * 1.0, y * 0.05, S, 77, 4, 16)
    g = 0.45 + 0.15 * (n - 0.5)
    return (g, g * 1.02, g * 1.05)


write_png("metal_diffuse.png", S, S, 3, metal_diffuse)

# --- Foliage (cut-out): leaves with alpha ---
LEAVES = 60
leaf_centres = [(hash01(i, 1) * S, hash01(i, 2) * S, 10 + 14 * hash01(i, 3), hash01(i, 4) * math.pi)
                for i in range(LEAVES)]


def leaf_pixel(x, y):
    for cx, cy, r, angle in leaf_centres:
        dx, dy = (x - cx + S / 2) % S - S / 2, (y - cy + S / 2) % S - S / 2
        a = dx * math.cos(angle) + dy * math.sin(angle)
        b = -dx * math.sin(angle) + dy * math.cos(angle)
        if (a / r) ** 2 + (b / (0.45 * r)) ** 2 < 1:
            shade = 0.75 + 0.25 * hash01(int(cx), int(cy), 5)
            vein = 0.85 if abs(b) < 0.6 else 1.0
            return (0.2 * shade * vein, 0.42 * shade * vein, 0.1 * shade, 1.0)
    return (0.0, 0.0, 0.0, 0.0)


write_png("leaves.png", S, S, 4, leaf_pixel)

# --- Slate (category roof, rules/gruenderzeit): rows of rectangular slates, overlapping ---
SLATE_ROWS, SLATES = 10, 5


def slate_cell(x, y):
    row = y * SLATE_ROWS // S
    u = x / S * SLATES + (0.5 if row % 2 else 0)
    return row, int(u) % SLATES, u % 1.0, (y * SLATE_ROWS / S) % 1.0


def slate_height(x, y):
    row, slate, fu, fv = slate_cell(x, y)
    gap = 0.0 if min(fu, 1 - fu) < 0.02 else 1.0
    return gap * (0.4 + 0.5 * fv) + 0.1 * fbm(x, y, S, 81, 3, 32)


slate_h = cached(slate_height, S)


def slate_diffuse(x, y):
    row, slate, fu, fv = slate_cell(x, y)
    g = 0.2 + 0.06 * hash01(row, slate, 83) + 0.05 * (fbm(x, y, S, 85, 4, 16) - 0.5)
    return (g, g * 1.04, g * 1.12)


write_png("slate_diffuse.png", S, S, 3, slate_diffuse)
write_png("slate_normal.png", S, S, 3, normal_map(slate_h, S, 5.0))

# --- Stucco ornaments (rules/gruenderzeit: miscNormal\OrnamentBorder0081_S.jpg and
# miscNormal\OrnamentBorder0093_2_S.jpg). Only their normal maps carry the relief (L2442). ---
O = 128


def fillets(v):
    """Raised bands along the top and bottom edge that frame a frieze; v in [0, 1]."""
    return 1.0 if v < 0.1 or v > 0.9 else 0.0


def egg_and_dart_height(x, y):
    """Four eggs across, each in a sunken shell, with a dart between neighbours."""
    u, v = (x + 0.5) / O * 4 % 1.0, (y + 0.5) / O
    a, b = (u - 0.5) / 0.34, (v - 0.5) / 0.36
    egg = max(0.0, 1 - a * a - b * b) ** 0.5
    shell = 1.0 if 0.34 ** 2 < (u - 0.5) ** 2 + ((v - 0.5) * 0.34 / 0.36) ** 2 < 0.42 ** 2 else 0.0
    dart = max(0.0, 1 - abs(u if u < 0.5 else u - 1.0) / 0.06 - abs(v - 0.45) / 0.35)
    return max(0.8 * egg, 0.5 * shell, 0.7 * dart, 0.6 * fillets(v))


def rosette_height(x, y):
    """A rosette of eight petals in a round frame, once per texture (uv tiles it)."""
    dx, dy = (x + 0.5) / O - 0.5, (y + 0.5) / O - 0.5
    r, angle = math.hypot(dx, dy), math.atan2(dy, dx)
    petals = 0.32 * (0.55 + 0.45 * abs(math.cos(4 * angle)))
    petal = max(0.0, 1 - r / petals) if r < petals else 0.0
    ring = 0.6 if 0.38 < r < 0.44 else 0.0
    return max(petal, ring, 0.7 if r < 0.06 else 0.0, 0.5 * fillets((y + 0.5) / O))


write_png("ornament_egg_and_dart_normal.png", O, O, 3, normal_map(cached(egg_and_dart_height, O), O, 6.0))
write_png("ornament_rosette_normal.png", O, O, 3, normal_map(cached(rosette_height, O), O, 6.0))

# --- Facades of the futuristic city's prisms (rules/futuristic/materials.xml) ---
# Each image is one bay of 3 m by one storey of 3.5 m (texture_size="3 3.5"); the prisms repeat
# it a whole number of times along and up each wall, so no pane is cut at a corner.


def frame_distance(x, y):
    """How far (0 … 0.5) a pixel lies from the tile's edge, as a fraction of the tile."""
    u, v = (x + 0.5) / S, (y + 0.5) / S
    return min(u, 1 - u, v, 1 - v)


def curtain_diffuse(x, y):
    v = (y + 0.5) / S
    if frame_distance(x, y) < 0.03 or abs((x + 0.5) / S - 0.5) < 0.012:
        return (0.72, 0.74, 0.77)  # anodised aluminium mullions and transoms
    if v > 0.78:
        return (0.1, 0.11, 0.13)  # the spandrel panel in front of the slab
    g = 0.1 + 0.06 * (1 - v) + 0.03 * (fbm(x, y, S, 81, 3, 16) - 0.5)
    return (g * 0.85, g, g * 1.2)


def curtain_reflection(x, y):
    v = (y + 0.5) / S
    if frame_distance(x, y) < 0.03 or abs((x + 0.5) / S - 0.5) < 0.012:
        return (0.3,)
    return (0.35,) if v > 0.78 else (0.8,)


def ribbon_diffuse(x, y):
    v = (y + 0.5) / S
    if 0.12 < v < 0.6:
        if abs((x + 0.5) / S - 0.5) < 0.008 or frame_distance(x, y) < 0.008:
            return (0.2, 0.21, 0.23)  # the thin frames between the panes
        g = 0.12 + 0.05 * (0.6 - v) + 0.02 * (fbm(x, y, S, 83, 3, 16) - 0.5)
        return (g * 0.9, g, g * 1.15)
    joint = abs(v - 0.8) < 0.006 or abs((x + 0.5) / S - 0.25) < 0.004 or abs((x + 0.5) / S - 0.75) < 0.004
    g = 0.78 + 0.04 * (fbm(x, y, S, 84, 3, 16) - 0.5)
    return (g * 0.6,) * 3 if joint else (g, g * 0.99, g * 0.96)  # white composite panels


def ribbon_reflection(x, y):
    v = (y + 0.5) / S
    return (0.75,) if 0.12 < v < 0.6 else (0.15,)


write_png("facade_curtain_diffuse.png", S, S, 3, curtain_diffuse)
write_png("facade_curtain_reflection.png", S, S, 1, curtain_reflection)
write_png("facade_ribbon_diffuse.png", S, S, 3, ribbon_diffuse)
write_png("facade_ribbon_reflection.png", S, S, 1, ribbon_reflection)
