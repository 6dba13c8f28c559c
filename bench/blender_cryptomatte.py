# Blender's own Cryptomatte node (compositor, source "Image") picks a name in a veduta EXR and
# writes its matte as a one-layer EXR (bench/blender_cryptomatte.sh).
# Usage: blender -b --factory-startup -P bench/blender_cryptomatte.py -- EXR LAYER NAME WIDTH HEIGHT MATTE.exr
import sys

import bpy

exr, layer, name, width, height, matte = sys.argv[sys.argv.index("--") + 1:]
image = bpy.data.images.load(exr)
scene = bpy.context.scene
scene.render.engine = 'BLENDER_WORKBENCH'  # the compositor runs after a render; keep that cheap
# The render's size, given: a multilayer image reports none until its pixels are read.
scene.render.resolution_x, scene.render.resolution_y = int(width), int(height)
scene.render.resolution_percentage = 100
scene.use_nodes = True
tree = scene.node_tree
for node in list(tree.nodes):
    tree.nodes.remove(node)
crypto = tree.nodes.new("CompositorNodeCryptomatteV2")
crypto.source = 'IMAGE'
crypto.image = image
crypto.layer_name = layer
crypto.matte_id = name
composite = tree.nodes.new("CompositorNodeComposite")
tree.links.new(crypto.outputs['Matte'], composite.inputs['Image'])
bpy.ops.render.render()
scene.render.image_settings.file_format = 'OPEN_EXR'
scene.render.image_settings.color_depth = '32'
bpy.data.images['Render Result'].save_render(matte)
