# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""npr-view's behaviour under an X server of its own (run this script under xvfb-run): the window
opens, xdotool's keys switch the styles, change the line width and crease angle, toggle the line
types, save screenshots and the camera, and show the help; the screenshots differ as each key
says, the saved camera reproduces the view in npr-render, VTK's own keys (w, f, ...) change
nothing, and without a display npr-view prints one error line and exits 1.

Images are compared by their pixels: "line" pixels are dark (every channel below 64) where the
shaded screenshot is not (the shading's own dark pixels lie on the bunny's rim)."""
import argparse
import json
import os
import queue
import shutil
import struct
import subprocess
import sys
import threading
import time
import zlib

parser = argparse.ArgumentParser()
parser.add_argument("--npr-view", required=True)
parser.add_argument("--npr-render", required=True)
parser.add_argument("--xdotool", default="xdotool")
parser.add_argument("--data", required=True)
parser.add_argument("--out", required=True)
parser.add_argument("--expect-version", required=True)
args = parser.parse_args()
shutil.rmtree(args.out, ignore_errors=True)
os.makedirs(args.out)
bunny = os.path.join(args.data, "bunny.ply")
failures = []
WIDTH, HEIGHT = 480, 360


def check(condition, message):
    print(("ok: " if condition else "FAILED: ") + message, flush=True)
    if not condition:
        failures.append(message)


def out(name):
    return os.path.join(args.out, name)


def read_png(path):
    """8-bit RGB or grey PNG (as vtkPNGWriter writes it) -> (width, height, rows of RGB tuples)."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, color, _, _, interlace = struct.unpack(">IIBBBBB", chunk)
            assert depth == 8 and color in (0, 2, 6) and interlace == 0, (path, depth, color)
        elif kind == b"IDAT":
            idat += chunk
        pos += 12 + length
    channels = {0: 1, 2: 3, 6: 4}[color]
    raw = zlib.decompress(idat)
    stride = width * channels
    previous = bytearray(stride)
    rows = []
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        previous = line
        if channels == 1:
            rows.append([(v, v, v) for v in line])
        else:
            rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
    return width, height, rows


def pixels(path, top=None):
    """The image's pixels, row by row (the first `top` rows only when given)."""
    _, _, rows = read_png(path)
    return [p for row in rows[:top] for p in row]


def line_pixels(path, shaded):
    """Pixels dark in path (every channel below 64) but not in the shaded image."""
    return sum(1 for p, q in zip(pixels(path), pixels(shaded)) if max(p) < 64 and max(q) >= 64)


def colours(path):
    return len(set(pixels(path)))


def differing(a, b, tolerance=32, top=None):
    """Fraction of pixels where some channel differs by more than tolerance."""
    pa, pb = pixels(a, top), pixels(b, top)
    if len(pa) != len(pb):
        return 1.0
    return sum(1 for p, q in zip(pa, pb) if max(abs(x - y) for x, y in zip(p, q)) > tolerance) / len(pa)


def run(*argv, env=None):
    result = subprocess.run([args.npr_view, *argv], capture_output=True, text=True, timeout=300, env=env)
    return result.returncode, result.stdout, result.stderr


# ---- Without a display: one error line, exit 1, before any window (VTK would abort) ----------
no_display = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
rc, stdout, err = run(bunny, env=no_display)
check(rc == 1 and err == "npr-view: error: no X display (DISPLAY is not set); use npr-render for "
      "headless rendering\n", "DISPLAY unset: exit 1 and one error line (got %d, %r)" % (rc, err))
rc, _, err = run(bunny, env=dict(no_display, DISPLAY=":4093"))
check(rc == 1 and err.startswith("npr-view: error: no X display: cannot open DISPLAY ':4093'")
      and err.count("\n") == 1, "unreachable display: exit 1 and one error line (got %d, %r)" % (rc, err))

# ---- Command line: the same errors and statuses as npr-render --------------------------------
rc, stdout, _ = run("--version")
check(rc == 0 and stdout == "npr-view %s\n" % args.expect_version, "--version (got %r)" % stdout)
rc, stdout, _ = run("--help")
check(rc == 0 and "--orbit-benchmark" in stdout and "--crease-angle" in stdout and "  k " in stdout,
      "--help lists the options, the styles' flags and the keys")
for argv, status, text in [((), 2, "no model file given"),
                           ((bunny, "--style", "pastel"), 2, "unknown style 'pastel'"),
                           ((bunny, "--line-width", "99"), 2, "--line-width expects a number in"),
                           ((bunny, "--size", "big"), 2, "--size expects WxH"),
                           ((bunny, "--wobble"), 2, "unknown option '--wobble'"),
                           ((out("missing.ply"),), 1, "missing.ply: no such file"),
                           ((bunny, "--camera-in", out("missing.json")), 1, "missing.json"),
                           ((bunny, "--camera-in", out("missing.json"), "--zoom", "2"), 2,
                            "cannot be combined with --camera-in"),
                           ((bunny, "--azimuth", "north"), 2, "--azimuth expects a number"),
                           ((bunny, "--face-creases", "--encoding", "half"), 2,
                            "--face-creases needs --encoding float"),
                           ((bunny, "--line-color", "reddish"), 2, "--line-color expects a colour name")]:
    rc, _, err = run(*argv)
    check(rc == status and err.startswith("npr-view: error: ") and text in err and err.count("\n") == 1,
          "%s: exit %d, one line with %r (got %d, %r)" % (" ".join(argv[1:]) or "no model", status, text, rc, err))

# The keys reach every style, so a style's flag gives no warning; one another flag turns off does.
rc, stdout, err = run(bunny, "--size", "%dx%d" % (WIDTH, HEIGHT), "--style", "Toon+Edges", "--toon-bands", "4",
                      "--uncertainty", "5", "--line-color", "navy", "--packed-blur", "--orbit-benchmark", "1")
check(rc == 0 and json.loads(stdout or "{}").get("style") == "toon+edges" and
      err == "npr-view: warning: --packed-blur applies only with --encoding packed8 or packed16\n",
      "--style Toon+Edges, colour names, one warning for a flag that does nothing (%r)" % err)

# ---- --orbit-benchmark: frames timed in the window, one JSON line ------------------------------
rc, stdout, err = run(bunny, "--size", "%dx%d" % (WIDTH, HEIGHT), "--style", "edges", "--orbit-benchmark", "5")
try:
    line = json.loads(stdout)
except ValueError:
    line = {}
check(rc == 0 and line.get("frames") == 5 and line.get("style") == "edges" and
      0 < line.get("median_ms", 0) <= line.get("max_ms", 0) and line.get("width") == WIDTH,
      "--orbit-benchmark 5 prints its JSON line (%r, %r)" % (stdout, err))

# ---- The interactive session ---------------------------------------------------------------------
prefix = out("view-")
viewer = subprocess.Popen([args.npr_view, bunny, "--size", "%dx%d" % (WIDTH, HEIGHT), "--output-prefix", prefix],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
lines = queue.Queue()
threading.Thread(target=lambda: [lines.put(l.rstrip("\n")) for l in viewer.stdout], daemon=True).start()


def xdotool(*argv):
    return subprocess.run([args.xdotool, *argv], capture_output=True, text=True, timeout=60)


def saved(*keys):
    """Sends the keys; the last saves a file: waits for its path on stdout and returns it."""
    xdotool("key", "--delay", "30", *keys)
    try:
        path = lines.get(timeout=120)
    except queue.Empty:
        viewer.kill()  # its stderr ends only when it does
        sys.exit("FAILED: no file saved after keys %s (stderr: %s)" % (keys, viewer.stderr.read()))
    check(os.path.isfile(path), "keys %s: saved %s" % (" ".join(keys), path))
    return path


# --onlyvisible: a window found before it is mapped cannot take the focus, and the keys sent
# to it would be lost (seen under ASan on a loaded machine).
found = xdotool("search", "--sync", "--onlyvisible", "--name", "^npr-view: bunny.ply$")
window = found.stdout.split()[0] if found.returncode == 0 and found.stdout.split() else None
check(window is not None, "the window 'npr-view: bunny.ply' appears (%s)" % found.stderr.strip())
if window is None:
    viewer.kill()
    sys.exit(1)
xdotool("windowfocus", "--sync", window)
xdotool("mousemove", "--window", window, str(WIDTH // 2), str(HEIGHT // 2))

shaded = saved("p")
check(shaded == prefix + "0001.png", "first screenshot is PREFIX0001.png (%s)" % shaded)
edges = saved("2", "p")
wide = saved("plus", "plus", "plus", "p")  # line width 1.5 -> 3
sharp = saved("minus", "minus", "minus", "bracketleft", "bracketleft", "bracketleft", "bracketleft", "p")  # 30 -> 10 deg
none = saved("bracketright", "bracketright", "bracketright", "bracketright", "s", "c", "o", "p")
back = saved("s", "c", "o", "p")
toon = saved("3", "p")
sketch = saved("5", "p")
inked = saved("6", "p")
drawing = saved("7", "p")
hidden = saved("d", "p")
visible = saved("d", "p")
counts = {name: line_pixels(path, shaded) for name, path in
          [("edges", edges), ("wide", wide), ("sharp", sharp), ("none", none), ("back", back),
           ("toon", toon), ("sketch", sketch), ("inked", inked), ("drawing", drawing)]}
# Measured (480x360, llvmpipe): edges 1091, wide 2616, sharp 2886, none 0, toon 0, sketch 1151,
# inked 1380.
print("line pixels:", counts, flush=True)
check(counts["edges"] > 500, "edges: line pixels where shaded has none")
check(counts["wide"] > 1.5 * counts["edges"], "+ + +: line width 3 gives more line pixels than 1.5")
check(counts["sharp"] > 1.3 * counts["edges"], "[ x4: crease angle 10 gives more line pixels than 30")
check(counts["none"] < 50, "s c o: no line types, no line pixels")
check(differing(back, edges, 0) == 0, "s c o again and ] x4, - x3: the edges image as before")
check(counts["toon"] < 50 and colours(toon) < colours(shaded) / 4,
      "toon: no lines, a few bands (%d colours against shaded's %d)" % (colours(toon), colours(shaded)))
check(counts["sketch"] > 500 and differing(sketch, edges) > 0.01, "sketch: lines, and not the edges image")
check(counts["inked"] > 500 and differing(inked, edges) > 0.005, "inked: ink lines, not the edges image")
check(counts["drawing"] > 500 and differing(drawing, edges) > 0.005,
      "drawing: lines, and not the edges image")
check(differing(hidden, drawing) > 0.001, "d: the hidden lines appear")
check(differing(visible, drawing, 0) == 0, "d again: the drawing as before")

# VTK's keys that clash: w (wireframe), s/S (surface), f (fly to), p (pick), 3 (stereo), j, t, a,
# u: none may change the view.
same = saved("2", "w", "W", "f", "F", "j", "t", "a", "u", "p")
check(differing(same, edges, 0) == 0, "VTK's w, f, j, t, a, u keys change nothing")

# Rotate with the mouse, save the camera and the screenshot; npr-render reproduces the view.
xdotool("mousemove", "--window", window, str(WIDTH // 2), str(HEIGHT // 2), "mousedown", "1")
for step in range(1, 11):
    xdotool("mousemove", "--window", window, str(WIDTH // 2 + 8 * step), str(HEIGHT // 2 + 3 * step))
xdotool("mouseup", "1")
camera_path = saved("k")
check(camera_path == prefix + "camera-0001.json", "camera file is PREFIXcamera-0001.json (%s)" % camera_path)
turned = saved("p")
check(differing(turned, edges) > 0.02, "the mouse drag turned the view")
camera = json.load(open(camera_path))
check(list(camera) == ["position", "focal_point", "view_up", "view_angle", "parallel_projection",
                       "parallel_scale", "clipping_range", "size"] and camera["size"] == [WIDTH, HEIGHT],
      "the camera file has npr-render's keys and the window's size")
result = subprocess.run([args.npr_render, bunny, "--style", "edges", "--camera-in", camera_path,
                         "-o", out("npr_render_camera.png")], capture_output=True, text=True, timeout=300)
check(result.returncode == 0, "npr-render --camera-in the saved camera (%s)" % result.stderr.strip())
# The same view in npr-render (EGL) as in npr-view's X window: at most 0.5 % of the pixels differ
# by more than 32 levels in a channel (measured: none).
fraction = differing(turned, out("npr_render_camera.png"))
check(fraction <= 0.005, "npr-render with the saved camera reproduces the view (%.4f %% of pixels differ)"
      % (100 * fraction))

# Help: P saves what is on screen (overlays included), p the render alone.
plain = saved("P")
helped = saved("h", "P")
render_with_help = saved("p")
hidden = saved("h", "P")
check(differing(plain, turned) > 0.01, "P includes the status overlay, p does not")
check(differing(helped, plain) > 0.05, "h shows the help overlay (%.1f %% of pixels change)"
      % (100 * differing(helped, plain)))
# The top half holds the help; the status (bottom left) shows the last frame time, which varies.
check(differing(hidden, plain, 0, top=HEIGHT // 2) == 0, "h again hides the help")
check(differing(render_with_help, turned, 0) == 0, "p leaves the overlays out, help shown or not")

xdotool("key", "q")
try:
    status = viewer.wait(timeout=60)
except subprocess.TimeoutExpired:
    viewer.kill()
    status = None
err = viewer.stderr.read()
check(status == 0 and err == "", "q quits with status 0 and nothing on stderr (%s, %r)" % (status, err))

# ---- --azimuth, --elevation, --zoom: the camera npr-render makes of the same flags -------------
moves = ["--azimuth", "40", "--elevation", "25", "--zoom", "1.3"]
moved = subprocess.Popen([args.npr_view, bunny, "--size", "%dx%d" % (WIDTH, HEIGHT), *moves,
                          "--output-prefix", out("moved-")], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True)
found = xdotool("search", "--sync", "--onlyvisible", "--name", "^npr-view: bunny.ply$")
window = found.stdout.split()[0] if found.returncode == 0 and found.stdout.split() else None
if window:
    xdotool("windowfocus", "--sync", window)
    xdotool("key", "k")
path = moved.stdout.readline().strip() if window else ""
xdotool("key", "q")
try:
    moved.wait(timeout=60)
except subprocess.TimeoutExpired:
    moved.kill()
result = subprocess.run([args.npr_render, bunny, "--size", "%dx%d" % (WIDTH, HEIGHT), *moves,
                         "--camera-out", out("moved_render.json")], capture_output=True, text=True, timeout=300)
view_camera = json.load(open(path)) if os.path.isfile(path) else {}
render_camera = json.load(open(out("moved_render.json"))) if result.returncode == 0 else {}
close = all(abs(a - b) <= 1e-6 * max(1.0, abs(b)) for key in ("position", "focal_point", "view_up")
            for a, b in zip(view_camera.get(key, [1e9]), render_camera.get(key, [0])))
check(close and view_camera.get("position") != None,
      "npr-view %s starts from npr-render's camera for the same flags (%s, %s)"
      % (" ".join(moves), view_camera.get("position"), render_camera.get("position")))

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
