# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""Runs the pvpython snippet of Documentation/paraview.md as written: the first ```python block,
with pvbatch, in an empty folder, the plugin found through PV_PLUGIN_PATH as the page says. The
snippet must write npr-toon-edges.png with lines and bands in it. Fails by exception.

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
    f.write(blocks[0])
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
print("PASS")
