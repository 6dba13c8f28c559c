"""Renders a scene built by bench/cycles/cycles_build.py with Cycles, with veduta's render
settings, to a linear float EXR, and prints its render time.

  blender -b OUT/scene.blend -t THREADS --python bench/cycles/cycles_render.py -- \
      --spp N --max-depth D --seed S --res WxH --filter blackman-harris --filter-width W \
      --out IMAGE.exr [--time-limit SECONDS]

Printed (for bench/cycles_compare.sh): `CYCLES_RENDER wall W` — the seconds of
bpy.ops.render.render, from Cycles' start to the written file. Cycles' own split (its
`cycles.<layer>.render_time`, the path tracing without scene synchronisation and BVH build, and
`total_time`) is in the EXR's header, which bench/cycles/compare_images.py reads.

Settings, veduta -> Cycles:
* spp -> samples; adaptive sampling OFF (veduta's --noise-threshold is 0 by default), denoising
  OFF, no clamping (sample_clamp_direct/indirect = 0; Cycles' default clamps indirect light at
  10), Filter Glossy (blur_glossy) 0 (Cycles' default 1 blurs glossy paths: biased), caustics on,
  light_sampling_threshold 0 (Cycles' default 0.01 drops shadow rays of lights whose
  contribution is small by chance: unbiased, but noise veduta has not), seed fixed and not
  animated. Sampling pattern: Cycles' default (progressive multi-jitter in 3.4); veduta has its
  own sequences, so the noise differs in structure, not in expectation.
* max_depth D -> max_bounces = diffuse = glossy = transmission = D - 1. veduta counts the surface
  hits of a path, at each of which the lights are sampled, D = 1 being direct light only;
  Cycles counts the bounces after the first hit, 0 being direct light only. Both trace the last
  hit's BSDF ray to collect the sun and sky it reaches directly (the other half of MIS), and
  both let it pass transparent surfaces (veduta's panes) on the way.
* Thin glass passes: no vertex in veduta, a transparent bounce in Cycles; transparent_max_bounces
  is set to 256 (Cycles: 8 by default, after which a pane turns opaque, for shadow rays too) and
  min_transparent_bounces to the same, so that Cycles plays no Russian roulette at panes, as
  veduta plays none.
* Russian roulette: veduta, from the third surface hit on, continues with probability
  min(1, max channel of the throughput / 0.1), decided when the second hit's bounce is drawn.
  Cycles, at each hit from the third on (min_light_bounces = 0: its kernel keeps min_bounce + 1
  bounces free of roulette), continues with min(1, sqrt(max channel)). Both are unbiased; the
  rules differ and cannot be made the same, so noise per sample differs a little.
* Pixel filter: veduta's `filter` / `filter_width` -> pixel_filter_type / filter_width. Cycles'
  Blackman-Harris of width w spans -w … +w pixels (its filter table doubles the width), a box
  of width w spans -w/2 … +w/2; veduta's filter_width is meant to be the same number
  (issue 19); older veduta builds spanned -w/2 … +w/2 with Blackman-Harris, i.e. half Cycles'.
* Colour: a float EXR is written linear, untouched by the view transform; Standard, no look,
  exposure 0, gamma 1 all the same, and the film is opaque (the sky is in the image, alpha 1,
  as veduta's).
* Threads: Blender's -t, and render.threads (FIXED).
"""

import sys
import time

import bpy


def args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    out = {}
    i = 0
    while i < len(argv):
        out[argv[i].lstrip("-").replace("-", "_")] = argv[i + 1]
        i += 2
    return out


def main():
    a = args()
    scene = bpy.context.scene
    c = scene.cycles
    scene.render.engine = "CYCLES"
    c.device = "CPU"
    c.samples = int(a["spp"])
    c.use_adaptive_sampling = False
    c.time_limit = float(a.get("time_limit", 0))
    c.use_denoising = False
    c.use_preview_denoising = False
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.blur_glossy = 0.0
    c.caustics_reflective = True
    c.caustics_refractive = True
    c.light_sampling_threshold = 0.0
    c.seed = int(a.get("seed", 0))
    c.use_animated_seed = False
    depth = int(a["max_depth"])
    bounces = max(depth - 1, 0)
    c.max_bounces = bounces
    c.diffuse_bounces = bounces
    c.glossy_bounces = bounces
    c.transmission_bounces = bounces
    c.volume_bounces = 0
    c.transparent_max_bounces = 256
    c.min_transparent_bounces = 256
    c.min_light_bounces = 0
    c.ao_bounces = 0
    c.ao_bounces_render = 0
    c.use_fast_gi = False
    filt = a.get("filter", "blackman-harris")
    c.pixel_filter_type = "BOX" if filt == "box" else "BLACKMAN_HARRIS"
    c.filter_width = float(a.get("filter_width", 1.0 if filt == "box" else 1.5))
    c.use_auto_tile = False
    if hasattr(c, "use_layer_samples"):
        c.use_layer_samples = "IGNORE"
    w, h = (int(v) for v in a["res"].lower().split("x"))
    r = scene.render
    r.resolution_x, r.resolution_y, r.resolution_percentage = w, h, 100
    r.film_transparent = False
    r.use_persistent_data = False
    r.threads_mode = "FIXED"
    r.threads = int(a.get("threads", 2))
    r.use_border = False
    r.use_compositing = False
    r.use_sequencer = False
    r.use_stamp = False  # no burnt-in text; the metadata is still written to the EXR header
    r.use_stamp_render_time = True
    vs = scene.view_settings
    vs.view_transform = "Standard"
    vs.look = "None"
    vs.exposure = 0.0
    vs.gamma = 1.0
    scene.display_settings.display_device = "sRGB"
    scene.sequencer_colorspace_settings.name = "Linear"
    im = r.image_settings
    im.file_format = "OPEN_EXR"
    im.color_mode = "RGB"
    im.color_depth = "32"
    im.exr_codec = "ZIP"
    r.filepath = a["out"]
    r.use_file_extension = False
    for layer in scene.view_layers:
        layer.use_pass_combined = True
    start = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    wall = time.perf_counter() - start
    print("CYCLES_RENDER wall %.4f spp %d max_bounces %d res %dx%d threads %d" % (
        wall, c.samples, c.max_bounces, w, h, r.threads))


main()
