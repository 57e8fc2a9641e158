# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch test: SaveAnimation of a "Render View (NPR)" in the Sketch style while the camera
orbits the scene (a path-based camera track, as the GUI's "Orbit" makes). Checks the number and
size of the frames, that each is a sketch (dark line pixels) of another view, and that the lines
stay on the surfaces: frame to frame, the line pixels carried through depth to the next frame
land on a line pixel (within 1 pixel) at least as often as in the Edges style less 0.1.

  pvbatch TestNPRAnimation.py --plugin NPRView.so --output-dir DIR
"""
import glob
import math
import os
import sys

from paraview.simple import *  # noqa: F401,F403

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from nprviewscene import SIZE, STYLES, create_scene, dark, plugin_arguments, read_png  # noqa: E402

args = plugin_arguments()
LoadPlugin(args.plugin, ns=globals())

FRAMES = 8
DEGREES = 40.0  # the whole orbit of the FRAMES frames

view, _ = create_scene()
view.Style = STYLES.index("Sketch")
Render(view)
position = list(view.CameraPosition)
focus = list(view.CameraFocalPoint)
up = list(view.CameraViewUp)

# The camera's positions on an arc about the view up through the focal point.
offset = [p - f for p, f in zip(position, focus)]
along = sum(o * u for o, u in zip(offset, up))
radial = [o - along * u for o, u in zip(offset, up)]
side = [up[1] * radial[2] - up[2] * radial[1], up[2] * radial[0] - up[0] * radial[2],
        up[0] * radial[1] - up[1] * radial[0]]
path = []
for i in range(FRAMES):
    angle = math.radians(DEGREES * i / (FRAMES - 1))
    path += [f + along * u + math.cos(angle) * r + math.sin(angle) * s
             for f, u, r, s in zip(focus, up, radial, side)]

scene = GetAnimationScene()
scene.PlayMode = "Sequence"
scene.NumberOfFrames = FRAMES
track = GetCameraTrack(view=view)
track.Mode = "Path-based"
start = CameraKeyFrame()
start.KeyTime = 0.0
start.Position = position
start.FocalPoint = focus
start.ViewUp = up
start.PositionPathPoints = path
start.FocalPathPoints = focus
start.ClosedPositionPath = 0
end = CameraKeyFrame()
end.KeyTime = 1.0
end.Position = path[-3:]
end.FocalPoint = focus
end.ViewUp = up
track.KeyFrames = [start, end]

failures = []


def check(condition, message):
    print(("ok    " if condition else "FAIL  ") + message)
    if not condition:
        failures.append(message)


def save(style):
    view.Style = STYLES.index(style)
    prefix = os.path.join(args.output_dir, style.lower())
    for old in glob.glob(prefix + "*.png"):
        os.remove(old)
    SaveAnimation(prefix + ".png", view, ImageResolution=SIZE, FrameWindow=[0, FRAMES - 1])
    return sorted(glob.glob(prefix + "*.png"))


sketch = save("Sketch")
check(len(sketch) == FRAMES, "SaveAnimation wrote %d sketch frames (got %d: %s)"
      % (FRAMES, len(sketch), [os.path.basename(f) for f in sketch]))
images = [read_png(f) for f in sketch]
check(all(img.shape[:2] == (SIZE[1], SIZE[0]) for img in images), "every frame is %dx%d" % tuple(SIZE))
check(all(dark(img) > 1500 for img in images), "every frame is drawn with lines: %s"
      % [dark(img) for img in images])
check(all(int((abs(a - b).sum(axis=2) > 60).sum()) > 500 for a, b in zip(images, images[1:])),
      "every frame differs from the one before (the camera moves)")

# The frame to frame stability of the line pixels, Sketch against Edges: the share of dark pixels
# of a frame that are dark within 1 pixel in the next frame (the orbit's step is 5.7 degrees, so
# this is looser than the benchmark's reprojection through depth, which pvbatch cannot give).
def stability(frames):
    shares = []
    for a, b in zip(frames, frames[1:]):
        line_a = a.sum(axis=2) < 150
        line_b = b.sum(axis=2) < 150
        near_b = line_b.copy()
        for dy in (-1, 0, 1):
            for dx in (-1, 0, 1):
                near_b[1:-1, 1:-1] |= line_b[1 + dy:line_b.shape[0] - 1 + dy, 1 + dx:line_b.shape[1] - 1 + dx]
        shares.append(float((line_a & near_b).sum()) / max(int(line_a.sum()), 1))
    return sum(shares) / len(shares)


edges = [read_png(f) for f in save("Edges")]
print("dark pixels landing within 1 px in the next frame: sketch %.3f, edges %.3f"
      % (stability(images), stability(edges)))
check(stability(images) >= stability(edges) - 0.1, "the sketch's lines move with the surfaces as the edges do")

if failures:
    raise RuntimeError("%d checks failed: %s" % (len(failures), failures))
print("all checks passed")
