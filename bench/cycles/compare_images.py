#!/usr/bin/env python3
"""Image figures for bench/cycles_compare.sh (OpenImageIO + numpy, Debian's python3-openimageio
and python3-numpy).

  compare_images.py relmse IMAGE REF            relMSE of IMAGE against REF
  compare_images.py regions IMAGE REF [N]       mean ratio and the worst relative difference of
                                                the means of N x N regions (default 4)
  compare_images.py mean IMAGE                  mean of R, G, B
  compare_images.py cycles-time IMAGE.exr       Cycles' render and total time from the header

relMSE = mean over pixels and channels of (x - ref)^2 / (ref^2 + 0.01), the measure of issue 19
and of `veduta diff --metric relmse`. Only R, G and B count: veduta's multilayer EXR
(ViewLayer.Combined.R/G/B) and Cycles' single-layer one (R, G, B) are both read.
"""

import sys

import numpy as np
import OpenImageIO as oiio


def rgb(path):
    buf = oiio.ImageBuf(path)
    if buf.has_error:
        sys.exit("compare_images.py: %s: %s" % (path, buf.geterror()))
    names = list(buf.spec().channelnames)
    pixels = buf.get_pixels(oiio.FLOAT)
    idx = []
    for c in "RGB":
        for cand in ("ViewLayer.Combined." + c, "Combined." + c, c):
            if cand in names:
                idx.append(names.index(cand))
                break
        else:
            sys.exit("compare_images.py: %s has no %s channel (%s)" % (path, c, ", ".join(names)))
    return pixels[:, :, idx].astype(np.float64)


def relmse(x, ref):
    return float(np.mean((x - ref) ** 2 / (ref ** 2 + 0.01)))


def regions(x, ref, n):
    h, w = ref.shape[:2]
    worst, where = 0.0, (0, 0)
    for j in range(n):
        for i in range(n):
            sl = (slice(j * h // n, (j + 1) * h // n), slice(i * w // n, (i + 1) * w // n))
            a, b = x[sl].mean(), ref[sl].mean()
            d = abs(a - b) / max(b, 1e-9)
            if d > worst:
                worst, where = d, (i, j)
    return worst, where


def seconds(text):
    v = 0.0
    for part in text.strip().split(":"):
        v = v * 60 + float(part)
    return v


def main():
    cmd = sys.argv[1] if len(sys.argv) > 1 else ""
    if cmd == "relmse":
        print("%.6g" % relmse(rgb(sys.argv[2]), rgb(sys.argv[3])))
    elif cmd == "regions":
        x, ref = rgb(sys.argv[2]), rgb(sys.argv[3])
        n = int(sys.argv[4]) if len(sys.argv) > 4 else 4
        worst, where = regions(x, ref, n)
        print("mean_ratio %.5f worst_region %.5f at %d,%d" % (x.mean() / max(ref.mean(), 1e-12), worst,
                                                              where[0], where[1]))
    elif cmd == "mean":
        m = rgb(sys.argv[2]).reshape(-1, 3).mean(axis=0)
        print("%.6g %.6g %.6g" % tuple(m))
    elif cmd == "cycles-time":
        spec = oiio.ImageInput.open(sys.argv[2]).spec()
        found = {}
        for a in spec.extra_attribs:
            if a.name.startswith("cycles.") and a.name.endswith(("render_time", "total_time",
                                                                  "synchronization_time")):
                found[a.name.rsplit(".", 1)[1]] = seconds(str(a.value))
        if "render_time" not in found:
            sys.exit("compare_images.py: %s has no cycles.*.render_time in its header" % sys.argv[2])
        print("render %.4f total %.4f sync %.4f" % (found["render_time"], found.get("total_time", 0),
                                                    found.get("synchronization_time", 0)))
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
