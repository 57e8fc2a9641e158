# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""The screenshots of Documentation/paraview.md, made by pvbatch with the plugin: the test scene
(Plugin/Testing/Python/nprviewscene.py) in every style of "Render View (NPR)", and the edges
style with ForceDepthOnly (what a parallel render draws). Run in the ParaView 5.11 chroot, after
the paraview-5.11 test stage built the plugin:

  NPR_CHROOT_BUILD=$PWD/build/paraview-5.11 bash Utilities/debian-chroot.sh bookworm-paraview run \
    'xvfb-run -a pvbatch --force-offscreen-rendering \
       Documentation/images/paraview/make_screenshots.py \
       --plugin /build/lib/paraview-5.11/plugins/NPRView/NPRView.so \
       --output-dir Documentation/images/paraview'
"""
import os
import sys

from paraview.simple import LoadPlugin, Render, SaveScreenshot

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "..", "Plugin", "Testing", "Python"))
from nprviewscene import STYLES, create_scene, plugin_arguments  # noqa: E402

args = plugin_arguments()

LoadPlugin(args.plugin, ns=globals())
size = [480, 360]
view, _ = create_scene(size)
shots = [(style, 0) for style in STYLES] + [("Edges", 1)]
for style, depth_only in shots:
    view.Style = style
    view.ForceDepthOnly = depth_only
    Render(view)
    name = style.lower().replace("+", "-") + ("-depth-only" if depth_only else "")
    SaveScreenshot(os.path.join(args.output_dir, name + ".png"), view, ImageResolution=size)
    print("wrote", name + ".png")
