# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""Runs the pvpython code of Documentation/paraview.md as written: its ```python blocks one after
the other as one script (each continues the last), with pvbatch, in an empty folder, the plugin
found through PV_PLUGIN_PATH as the page says. The first must write npr-toon-edges.png with lines
and bands in it; every other picture a block names (the drawing as PNG and SVG, the orbit's
frames) must be written and not be empty. Fails by exception.

  pvpython TestDocSnippet.py --pvbatch PATH --plugin-dir DIR --page paraview.md --output-dir DIR
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from nprviewscene import dark, read_png  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("--pvbatch", required=True)
ap.add_argument("--plugin-dir", required=True)
ap.add_argument("--page", required=True)
ap.add_argument("--output-dir", required=True)
args = ap.parse_args()

blocks = re.findall(r"```python\n(.*?)```", open(args.page).read(), re.S)
if not blocks:
    raise RuntimeError("no ```python block in " + args.page)
shutil.rmtree(args.output_dir, ignore_errors=True)
os.makedirs(args.output_dir)
with open(os.path.join(args.output_dir, "snippet.py"), "w") as f:
    f.write("\n".join(blocks))
env = dict(os.environ, PV_PLUGIN_PATH=args.plugin_dir)
subprocess.run([args.pvbatch, "--force-offscreen-rendering", "snippet.py"], cwd=args.output_dir,
               env=env, check=True, timeout=240)
image = read_png(os.path.join(args.output_dir, "npr-toon-edges.png"))
lines = dark(image)
covered = image[(abs(image - image[0, 0]).sum(axis=2) > 30)]
shades = len(set(map(tuple, covered.reshape(-1, 3) // 8)))
print("the snippet's image: %dx%d, %d line pixels, %d shades on the surface"
      % (image.shape[1], image.shape[0], lines, shades))
if image.shape[:2] != (600, 800) or lines < 2000:
    raise RuntimeError("FAIL: the snippet's image is not an 800x600 view with lines")
named = re.findall(r"[\"']([\w.-]+\.(?:png|svg))[\"']", "".join(blocks[1:]))
for name in named:
    # SaveAnimation numbers its frames: orbit.png -> orbit.0000.png, ...
    stem, extension = os.path.splitext(name)
    frames = [f for f in os.listdir(args.output_dir) if re.match(re.escape(stem) + r"(\.\d+)?"
                                                                  + re.escape(extension) + "$", f)]
    sizes = [os.path.getsize(os.path.join(args.output_dir, f)) for f in frames]
    print("%s: %d files, %s bytes" % (name, len(frames), sizes[:3]))
    if not frames or min(sizes) < 1000:
        raise RuntimeError("FAIL: the page's code did not write %s" % name)
print("PASS")
