"""Builds the Blender (Cycles) twin of a veduta scene and saves it as a .blend file.

Run by bench/cycles_compare.sh (Blender 3.4, Debian 12):
  blender -b --factory-startup --python bench/cycles/cycles_build.py -- \
      --json OUT/scene.json --obj OUT/scene.obj [--sky OUT/sky.exr] --blend OUT/scene.blend

scene.json comes from bench/cycles/prepare_scene.py, scene.obj from `veduta export`, sky.exr from
`veduta cubemap SCENE --to latlong`. Render settings (samples, depth, resolution, seed) are set
per render by bench/cycles/cycles_render.py; this script sets everything that is the scene.

Conventions, veduta -> Blender (docs/cycles-compare.md has the whole list):
* Axes: veduta is Z up, x east, y north, metres; so is Blender. The OBJ is written in veduta's
  own frame, so it is imported with forward +Y and up +Z, which is the identity (Blender's
  default, forward -Z / up Y, would turn it by 90 degrees about x).
* Camera: veduta's `fov` is the VERTICAL field of view for any aspect ratio. Blender's lens
  angle depends on sensor_fit; with sensor_fit = VERTICAL the angle is measured across
  sensor_height, so lens = (sensor_height / 2) / tan(fov / 2) gives exactly veduta's frustum.
  veduta's camera right is normalize(cross(forward, up)) and its up cross(right, forward); a
  Blender camera looks along its local -Z with local +Y up, so its matrix has the columns
  (right, up, -forward). Clipping: Blender clips at clip_end (100 m by default); veduta never
  clips, so clip_start/clip_end are set to 1 mm / 1e6 m.
* Sun: veduta's `irradiance` is W/m^2 on a surface facing the sun, per channel, and its disc has
  the radiance E / (pi sin^2(d/2)). A Blender sun's `energy` (strength) is also irradiance in
  W/m^2 (a white diffuse plane facing it has radiance strength/pi), times its colour; `angle` is
  the full angular diameter in RADIANS. So energy = the largest channel, colour = irradiance /
  energy, angle = radians(angular_diameter). A Blender sun shines along its local -Z: the object
  is turned so that its +Z is veduta's direction towards the sun.
* Environment: a constant `radiance` is the world Background colour with strength 1. A map
  (cubemap file or baked sky) is written by `veduta cubemap SCENE --to latlong`, whose lat-long
  layout is Blender's own (u = 0.5 - atan2(y, x) / 2pi, v from the zenith; centre looks +x), with
  rotation and intensity already applied, so it goes into an Environment Texture node
  (equirectangular, linear, not colour-managed) with strength 1.
* Materials: see build_phong / build_glass below.
"""

import json
import math
import os
import sys

import bpy
from mathutils import Matrix, Vector


def args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    out = {"sky": None}
    i = 0
    while i < len(argv):
        out[argv[i].lstrip("-")] = argv[i + 1]
        i += 2
    return out


def clear_scene():
    for o in list(bpy.data.objects):
        bpy.data.objects.remove(o, do_unlink=True)
    for coll in (bpy.data.meshes, bpy.data.materials, bpy.data.lights, bpy.data.cameras, bpy.data.images):
        for b in list(coll):
            coll.remove(b)


def import_obj(path):
    # Blender 3.4's C++ importer; 3.x before 3.3 had only the Python one (import_scene.obj).
    if hasattr(bpy.ops.wm, "obj_import"):
        bpy.ops.wm.obj_import(filepath=path, forward_axis="Y", up_axis="Z", validate_meshes=False)
    else:
        bpy.ops.import_scene.obj(filepath=path, axis_forward="Y", axis_up="Z", use_split_objects=True,
                                 use_split_groups=False, use_image_search=False)
    lo = Vector((1e30, 1e30, 1e30))
    hi = -lo
    for o in bpy.context.scene.objects:
        if o.type != "MESH":
            continue
        # No shadow-terminator offset: veduta offsets shadow rays only by its epsilon.
        for attr in ("shadow_terminator_geometry_offset", "shadow_terminator_shading_offset"):
            if hasattr(o, attr):
                setattr(o, attr, 0.0)
        for v in o.data.vertices:
            w = o.matrix_world @ v.co
            lo = Vector(map(min, lo, w))
            hi = Vector(map(max, hi, w))
    return lo, hi


def read_mtl(path):
    """The .mtl beside the OBJ: Kd, Ks, Ns (and glass: Ni, Tf) for materials that no scene or
    material file defines (veduta's built-in `default` and the generator's fallbacks)."""
    mats, cur = {}, None
    if not os.path.exists(path):
        return mats
    for line in open(path):
        p = line.split()
        if not p:
            continue
        if p[0] == "newmtl":
            cur = mats.setdefault(" ".join(p[1:]), {})
        elif cur is not None and p[0] in ("Kd", "Ks", "Tf"):
            cur[p[0]] = [float(v) for v in p[1:4]]
        elif cur is not None and p[0] in ("Ns", "Ni", "d"):
            cur[p[0]] = float(p[1])
    return mats


def from_mtl(name, m):
    if "Tf" in m and "Ni" in m:
        return {"name": name, "glass": True, "ior": m["Ni"], "tint": m["Tf"]}
    ks = m.get("Ks", [0, 0, 0])
    return {"name": name, "glass": False, "diffuse": m.get("Kd", [0.8] * 3), "diffuse_map": None,
            "specular": ks, "specular_intensity": 1.0, "specular_map": None, "shininess": m.get("Ns", 32),
            "normal_map": None, "normal_strength": 1.0, "reflectivity": [0, 0, 0], "reflection_map": None,
            "opacity_map": None}


class Nodes:
    def __init__(self, mat):
        mat.use_nodes = True
        self.tree = mat.node_tree
        self.tree.nodes.clear()
        self.x = 0

    def new(self, kind, **inputs):
        n = self.tree.nodes.new(kind)
        n.location = (self.x, 0)
        self.x += 200
        for k, v in inputs.items():
            if isinstance(v, bpy.types.NodeSocket):
                self.tree.links.new(v, n.inputs[k])
            else:
                n.inputs[k].default_value = v
        return n

    def link(self, a, b):
        self.tree.links.new(a, b)

    def math(self, op, a, b=None):
        n = self.new("ShaderNodeMath")
        n.operation = op
        for i, v in enumerate((a, b)):
            if v is None:
                continue
            if isinstance(v, bpy.types.NodeSocket):
                self.link(v, n.inputs[i])
            else:
                n.inputs[i].default_value = v
        return n.outputs[0]

    def vmath(self, op, a, b):
        n = self.new("ShaderNodeVectorMath")
        n.operation = op
        for i, v in enumerate((a, b)):
            if isinstance(v, bpy.types.NodeSocket):
                self.link(v, n.inputs[i])
            else:
                n.inputs[i].default_value = v
        return n.outputs[0]

    def scale(self, v, k):
        n = self.new("ShaderNodeVectorMath")
        n.operation = "SCALE"
        if isinstance(v, bpy.types.NodeSocket):
            self.link(v, n.inputs[0])
        else:
            n.inputs[0].default_value = v
        if isinstance(k, bpy.types.NodeSocket):
            self.link(k, n.inputs["Scale"])
        else:
            n.inputs["Scale"].default_value = k
        return n.outputs[0]

    def image(self, path, colorspace):
        img = bpy.data.images.load(path, check_existing=True)
        # veduta's default for a diffuse map is the file's own colour space (sRGB for 8- and
        # 16-bit integer images, linear for float ones), for the data maps Non-Color; the names
        # are those of Blender's OCIO configuration.
        if colorspace:
            img.colorspace_settings.name = colorspace
        elif img.is_float:
            img.colorspace_settings.name = "Linear"
        else:
            img.colorspace_settings.name = "sRGB"
        n = self.new("ShaderNodeTexImage")
        n.image = img
        # Bilinear, repeat. veduta filters by the ray's footprint (mip-maps, ray cones) where
        # Cycles on the CPU has no mip-maps: the same mean, differently distributed noise.
        n.interpolation = "Linear"
        n.extension = "REPEAT"
        return n


def rgb(c):
    return (c[0], c[1], c[2], 1.0)


def build_phong(mat, m):
    """veduta's normalised Phong: f = kd/pi + ks (n+2)/(2pi) cos^n(alpha) + ks f_ms, plus a
    mirror lobe of weight `reflectivity`; kd + ks <= 1 per texel (both scaled down by
    max(kd + ks) when it exceeds 1) and kd, ks then times (1 - reflectivity).
    Cycles: Diffuse BSDF (kd) + Glossy BSDF, Multiscatter GGX (ks) + Glossy BSDF, Sharp (mirror),
    added. The Phong lobe has no Cycles equivalent: GGX with roughness (2/(n+2))^(1/4) (the
    Walter et al. 2007 match of a Phong exponent, the roughness veduta's glTF export writes;
    Blender's roughness is sqrt(alpha)) has the same width but a longer tail; Multiscatter GGX
    stands in for veduta's Kulla-Conty compensation lobe f_ms (both keep a white lobe white).
    Neither Glossy BSDF has a Fresnel term, as veduta's Phong has none."""
    n = Nodes(mat)
    tex = n.new("ShaderNodeTexCoord").outputs["UV"]
    kd = tuple(m["diffuse"])
    kd_sock = None
    if m.get("diffuse_map"):
        t = n.image(m["diffuse_map"], m.get("diffuse_map_colorspace", ""))
        n.link(tex, t.inputs["Vector"])
        kd_sock = n.vmath("MULTIPLY", t.outputs["Color"], kd)
    ks_base = tuple(s * m["specular_intensity"] for s in m["specular"])
    ks_sock = None
    if m.get("specular_map"):
        t = n.image(m["specular_map"], m.get("specular_map_colorspace", "Non-Color"))
        n.link(tex, t.inputs["Vector"])
        sep = n.new("ShaderNodeSeparateColor", Color=t.outputs["Color"])  # the first channel
        ks_sock = n.scale(ks_base, sep.outputs[0])
    refl = tuple(m["reflectivity"])
    refl_sock = None
    if m.get("reflection_map"):
        t = n.image(m["reflection_map"], m.get("reflection_map_colorspace", "Non-Color"))
        n.link(tex, t.inputs["Vector"])
        sep = n.new("ShaderNodeSeparateColor", Color=t.outputs["Color"])
        refl_sock = n.scale(refl, sep.outputs[0])
    kd_v = kd_sock if kd_sock else kd
    ks_v = ks_sock if ks_sock else ks_base
    refl_v = refl_sock if refl_sock else refl
    # kd + ks <= 1: s = max(1, max channel of kd + ks); kd /= s, ks /= s.
    total = n.vmath("ADD", kd_v, ks_v)
    sep = n.new("ShaderNodeSeparateXYZ", Vector=total)
    s = n.math("MAXIMUM", n.math("MAXIMUM", sep.outputs[0], sep.outputs[1]), sep.outputs[2])
    s = n.math("MAXIMUM", s, 1.0)
    inv = n.math("DIVIDE", 1.0, s)
    rest = n.vmath("SUBTRACT", (1.0, 1.0, 1.0), refl_v)
    kd_f = n.vmath("MULTIPLY", n.scale(kd_v, inv), rest)
    ks_f = n.vmath("MULTIPLY", n.scale(ks_v, inv), rest)
    normal = None
    if m.get("normal_map"):
        # Tangent space, OpenGL convention (green = +v), as Blender's Normal Map node; strength
        # as veduta's normal_strength. veduta folds the part of the diffuse lobe below the
        # real surface back up; Cycles 3.4 does not (it bends only glossy reflections back
        # above the surface, as veduta's "valid reflection" does).
        t = n.image(m["normal_map"], m.get("normal_map_colorspace", "Non-Color"))
        n.link(tex, t.inputs["Vector"])
        nm = n.new("ShaderNodeNormalMap", Strength=m["normal_strength"], Color=t.outputs["Color"])
        nm.space = "TANGENT"
        normal = nm.outputs["Normal"]
    shininess = min(max(m["shininess"], 1.0), 1e4)  # veduta clamps the exponent to 1 ... 10^4
    roughness = (2.0 / (shininess + 2.0)) ** 0.25
    diffuse = n.new("ShaderNodeBsdfDiffuse", Roughness=0.0)
    n.link(kd_f, diffuse.inputs["Color"])
    glossy = n.new("ShaderNodeBsdfGlossy", Roughness=roughness)
    glossy.distribution = "MULTI_GGX"
    n.link(ks_f, glossy.inputs["Color"])
    mirror = n.new("ShaderNodeBsdfGlossy", Roughness=0.0)
    mirror.distribution = "SHARP"
    if isinstance(refl_v, tuple):
        mirror.inputs["Color"].default_value = rgb(refl_v)
    else:
        n.link(refl_v, mirror.inputs["Color"])
    if normal is not None:
        for b in (diffuse, glossy, mirror):
            n.link(normal, b.inputs["Normal"])
    add = n.new("ShaderNodeAddShader")
    n.link(diffuse.outputs[0], add.inputs[0])
    n.link(glossy.outputs[0], add.inputs[1])
    shader = add.outputs[0]
    if max(refl) > 0:
        add2 = n.new("ShaderNodeAddShader")
        n.link(shader, add2.inputs[0])
        n.link(mirror.outputs[0], add2.inputs[1])
        shader = add2.outputs[0]
    if m.get("opacity_map"):
        # veduta: a cut-out where the map (its alpha, if it has one) is below 0.5.
        t = n.image(m["opacity_map"], m.get("opacity_map_colorspace", "Non-Color"))
        n.link(tex, t.inputs["Vector"])
        ch = t.image.channels
        alpha = t.outputs["Alpha"] if ch in (2, 4) else n.new("ShaderNodeSeparateColor",
                                                              Color=t.outputs["Color"]).outputs[0]
        keep = n.math("GREATER_THAN", alpha, 0.49999)
        transparent = n.new("ShaderNodeBsdfTransparent")
        mix = n.new("ShaderNodeMixShader", Fac=keep)
        n.link(transparent.outputs[0], mix.inputs[1])
        n.link(shader, mix.inputs[2])
        shader = mix.outputs[0]
    out = n.new("ShaderNodeOutputMaterial")
    n.link(shader, out.inputs["Surface"])


def build_glass(mat, m):
    """veduta's thin glass: a pane of zero thickness. Fresnel reflectance R (the mean of s and p,
    from air, on either side) at the face, the slab's total R' = R + T^2 R/(1 - R^2) = 2R/(1 + R)
    reflected as a mirror (white), T' = tint (1 - R') passed straight through, undeviated; shadow
    rays pass with T' too. Cycles: Mix Shader of a Transparent BSDF (colour tint) and a sharp
    Glossy BSDF (white) with Fac = 2F/(1 + F), F from the Fresnel node. Cycles' Fresnel node
    inverts the IOR on back faces (a solid's inside), which for a pane would give total internal
    reflection; so the IOR fed to it is 1/ior on back faces, which it inverts back to ior.
    Transparent passes count as transparent bounces in Cycles (transparent_max_bounces, set
    high), not as surface bounces, as in veduta, where a pass-through is no path vertex.
    Cycles evaluates the Fresnel node with the shading normal (panes are flat: the same)."""
    n = Nodes(mat)
    geo = n.new("ShaderNodeNewGeometry")
    ior = m["ior"]
    eff = n.math("ADD", ior, n.math("MULTIPLY", geo.outputs["Backfacing"], 1.0 / ior - ior))
    fres = n.new("ShaderNodeFresnel", IOR=eff)
    fac = n.math("DIVIDE", n.math("MULTIPLY", fres.outputs[0], 2.0), n.math("ADD", fres.outputs[0], 1.0))
    transparent = n.new("ShaderNodeBsdfTransparent", Color=rgb(m["tint"]))
    mirror = n.new("ShaderNodeBsdfGlossy", Roughness=0.0, Color=(1, 1, 1, 1))
    mirror.distribution = "SHARP"
    mix = n.new("ShaderNodeMixShader", Fac=fac)
    n.link(transparent.outputs[0], mix.inputs[1])
    n.link(mirror.outputs[0], mix.inputs[2])
    out = n.new("ShaderNodeOutputMaterial")
    n.link(mix.outputs[0], out.inputs["Surface"])


def set_materials(scene_materials, mtl):
    made, from_file = [], []
    for mat in list(bpy.data.materials):
        name = mat.name
        m = scene_materials.get(name)
        if m is None and name in mtl:
            m = from_mtl(name, mtl[name])
            from_file.append(name)
        if m is None:
            m = from_mtl(name, {})
            from_file.append(name + " (not found: veduta's default grey)")
        (build_glass if m["glass"] else build_phong)(mat, m)
        made.append(name)
    return made, from_file


def set_camera(scene, c):
    cam_data = bpy.data.cameras.new("veduta_camera")
    cam_data.type = "PERSP"
    cam_data.sensor_fit = "VERTICAL"
    cam_data.sensor_height = 24.0
    cam_data.lens = (cam_data.sensor_height / 2.0) / math.tan(math.radians(c["fov"]) / 2.0)
    cam_data.clip_start = 1e-3
    cam_data.clip_end = 1e6
    cam = bpy.data.objects.new("veduta_camera", cam_data)
    scene.collection.objects.link(cam)
    pos, at, up = Vector(c["position"]), Vector(c["look_at"]), Vector(c["up"])
    f = (at - pos).normalized()
    r = f.cross(up).normalized()
    u = r.cross(f)
    m = Matrix.Identity(4)
    for i in range(3):
        m[i][0], m[i][1], m[i][2], m[i][3] = r[i], u[i], -f[i], pos[i]
    cam.matrix_world = m
    scene.camera = cam


def set_sun(scene, s):
    e = s["irradiance"]
    peak = max(e)
    if peak <= 0:
        return
    light = bpy.data.lights.new("veduta_sun", type="SUN")
    light.energy = peak
    light.color = (e[0] / peak, e[1] / peak, e[2] / peak)
    light.angle = math.radians(s["angular_diameter"])
    light.cycles.cast_shadow = True
    light.cycles.use_multiple_importance_sampling = True
    # Cycles 3.4 lights have `max_bounces` (1024 by default) — leave it.
    obj = bpy.data.objects.new("veduta_sun", light)
    scene.collection.objects.link(obj)
    d = Vector(s["direction"]).normalized()
    obj.rotation_mode = "QUATERNION"
    obj.rotation_quaternion = d.to_track_quat("Z", "Y")  # local +Z towards the sun: shines along -Z


def set_world(scene, env, sky):
    world = bpy.data.worlds.new("veduta_world")
    scene.world = world
    world.use_nodes = True
    t = world.node_tree
    t.nodes.clear()
    bg = t.nodes.new("ShaderNodeBackground")
    bg.inputs["Strength"].default_value = 1.0
    out = t.nodes.new("ShaderNodeOutputWorld")
    t.links.new(bg.outputs[0], out.inputs["Surface"])
    if env["kind"] == "radiance":
        r = env["radiance"]
        k = env.get("intensity", 1.0)
        bg.inputs["Color"].default_value = (r[0] * k, r[1] * k, r[2] * k, 1.0)
    else:
        if not sky:
            raise SystemExit("cycles_build.py: the scene's environment is a map; pass --sky LATLONG.exr")
        img = bpy.data.images.load(sky)
        img.colorspace_settings.name = "Linear"
        tex = t.nodes.new("ShaderNodeTexEnvironment")
        tex.image = img
        tex.projection = "EQUIRECTANGULAR"
        tex.interpolation = "Linear"
        t.links.new(tex.outputs["Color"], bg.inputs["Color"])
    # Importance-sample the world (veduta samples its cubemap by luminance x solid angle).
    world.cycles.sampling_method = "MANUAL" if env["kind"] != "radiance" else "AUTOMATIC"
    if env["kind"] != "radiance":
        world.cycles.sample_map_resolution = 1024
    world.cycles.max_bounces = 1024


def main():
    a = args()
    with open(a["json"]) as f:
        data = json.load(f)
    clear_scene()
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    lo, hi = import_obj(a["obj"])
    mtl = read_mtl(os.path.splitext(a["obj"])[0] + ".mtl")
    made, from_file = set_materials(data["materials"], mtl)
    set_camera(scene, data["camera"])
    set_sun(scene, data["sun"])
    set_world(scene, data["environment"], a.get("sky"))
    res = data["camera"]["resolution"]
    scene.render.resolution_x, scene.render.resolution_y = res[0], res[1]
    scene.render.resolution_percentage = 100
    scene.render.pixel_aspect_x = scene.render.pixel_aspect_y = 1.0
    bpy.ops.wm.save_as_mainfile(filepath=os.path.abspath(a["blend"]), compress=False)
    meshes = sum(1 for o in scene.objects if o.type == "MESH")
    tris = sum(sum(len(p.vertices) - 2 for p in o.data.polygons) for o in scene.objects if o.type == "MESH")
    print("CYCLES_BUILD objects %d triangles %d bbox %.3f %.3f %.3f .. %.3f %.3f %.3f materials %d" % (
        meshes, tris, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z, len(made)))
    if from_file:
        print("CYCLES_BUILD materials from the .mtl only: " + ", ".join(from_file))


main()
