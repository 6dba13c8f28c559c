# What Blender makes of veduta's exports: imports each file given after "--" into an empty scene
# and prints its objects, meshes, materials, how many objects have a material, a few names,
# whether a camera and a sun arrived, and which materials arrived as glass (Principled BSDF
# transmission > 0) with their roughness. OBJ goes through Blender 3.4's C++ importer
# (bpy.ops.wm.obj_import, which reads `o` as objects) with Z up and Y forward, as veduta writes
# it; glTF and GLB through the bundled glTF importer.
# Usage: blender -b --factory-startup --python-exit-code 1 -P bench/blender_import.py -- FILE...
import os
import sys
import time

import bpy


def allow_numpy_bool():
    """Blender 3.4's glTF importer calls numpy.bool, which numpy 1.24 (Debian 12's) removed; the
    alias it stood for is put back, or glTF files do not import at all on Debian 12."""
    import warnings

    import numpy
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        present = hasattr(numpy, 'bool')
    if not present:
        numpy.bool = numpy.bool_


def import_file(path):
    extension = os.path.splitext(path)[1].lower()
    if extension == ".obj":
        bpy.ops.wm.obj_import(filepath=path, up_axis='Z', forward_axis='Y')
    elif extension in (".gltf", ".glb"):
        allow_numpy_bool()
        bpy.ops.import_scene.gltf(filepath=path)
    else:
        raise ValueError(f"{path}: not an OBJ, glTF or GLB file")


def principled(material):
    if not material.use_nodes:
        return None
    for node in material.node_tree.nodes:
        if node.type == 'BSDF_PRINCIPLED':
            return node
    return None


def report(path, seconds):
    objects = list(bpy.data.objects)
    meshes = [o for o in objects if o.type == 'MESH']
    with_material = [o for o in meshes if any(slot.material for slot in o.material_slots)]
    cameras = [o for o in objects if o.type == 'CAMERA']
    suns = [o for o in objects if o.type == 'LIGHT' and o.data.type == 'SUN']
    glass = []
    for material in bpy.data.materials:
        bsdf = principled(material)
        if bsdf and bsdf.inputs['Transmission'].default_value > 0:
            glass.append(f"{material.name} (transmission {bsdf.inputs['Transmission'].default_value:g}, "
                         f"roughness {bsdf.inputs['Roughness'].default_value:g}, "
                         f"alpha {bsdf.inputs['Alpha'].default_value:g})")
    print(f"{os.path.basename(path)}: imported in {seconds:.1f} s")
    print(f"  objects: {len(objects)}")
    print(f"  mesh objects: {len(meshes)}, meshes: {len(bpy.data.meshes)}")
    print(f"  materials: {len(bpy.data.materials)}")
    print(f"  mesh objects with a material: {len(with_material)}")
    print(f"  names: {', '.join(sorted(o.name for o in meshes)[:5])}")
    print(f"  camera: {'yes' if cameras else 'no'}"
          + (f" (lens {cameras[0].data.lens:.1f} mm)" if cameras else ""))
    print(f"  sun: {'yes' if suns else 'no'}" + (f" (strength {suns[0].data.energy:g})" if suns else ""))
    print(f"  glass with transmission > 0: {len(glass)}" + (f": {'; '.join(glass[:3])}" if glass else ""))
    images = [i for i in bpy.data.images if i.source == 'FILE']
    print(f"  images: {len(images)}")


def main():
    files = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if not files:
        raise SystemExit("usage: blender -b -P blender_import.py -- FILE...")
    for path in files:
        bpy.ops.wm.read_factory_settings(use_empty=True)
        start = time.monotonic()
        import_file(os.path.abspath(path))
        report(path, time.monotonic() - start)


main()
