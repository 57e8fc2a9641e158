# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""npr-render --orbit: numbered PNG frames (the first is the still of the same camera, the others
differ), an Ogg Theora video read back (its frame size, rate and number of frames), an MP4 where
the ffmpeg program is installed (read back with ffprobe) and an AVI where VTK has its FFMPEG
writer, or their clear errors, and the usage errors."""
import json
import os
import shutil
import struct
import subprocess

from npr_cli_checks import CLI
from vtkmodules.vtkIOImage import vtkPNGReader

cli = CLI(timeout=600)
cad = cli.model("cad_part.vtp")
run, check, out = cli.run, cli.check, cli.out


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    return struct.unpack(">II", head[16:24]) if head[:8] == b"\x89PNG\r\n\x1a\n" else None


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    scalars = reader.GetOutput().GetPointData().GetScalars()
    return [scalars.GetValue(i) for i in range(scalars.GetNumberOfValues())] if scalars else []


def theora_stream(path):
    """(picture width, height, frame rate, number of frames) of the first Theora stream of an Ogg
    file, from its pages: the identification header and one packet per frame after the three
    header packets (a zero-length packet repeats the previous frame and counts as one)."""
    data = open(path, "rb").read()
    packets, partial, position = [], b"", 0
    while position < len(data):
        if data[position:position + 4] != b"OggS":
            raise ValueError("no Ogg page at byte %d" % position)
        segments = data[position + 26]
        table = data[position + 27:position + 27 + segments]
        body = position + 27 + segments
        for size in table:
            partial += data[body:body + size]
            body += size
            if size < 255:
                packets.append(partial)
                partial = b""
        position = body
    if not packets or packets[0][:7] != b"\x80theora":
        raise ValueError("not a Theora stream")
    ident = packets[0]
    width = int.from_bytes(ident[14:17], "big")
    height = int.from_bytes(ident[17:20], "big")
    numerator, denominator = struct.unpack(">II", ident[22:30])
    headers = sum(1 for p in packets[:3] if p[:1] in (b"\x80", b"\x81", b"\x82"))
    return width, height, numerator / denominator, len(packets) - headers


# ---- PNG frames ----
frames = 6
size = (200, 150)
rc, _, err = run(cad, "--style", "sketch", "--orbit", str(frames), "--size", "%dx%d" % size,
                 "--azimuth", "30", "--elevation", "20", "-o", out("orbit.png"),
                 "--camera-out", out("orbit_camera.json"))
check(rc == 0, "--orbit %d -o orbit.png (%s)" % (frames, err.strip()))
names = ["orbit_%04d.png" % i for i in range(1, frames + 1)]
check(all(os.path.exists(out(n)) for n in names) and not os.path.exists(out("orbit_%04d.png" % (frames + 1))),
      "exactly %d numbered frames: %s" % (frames, sorted(n for n in os.listdir(cli.args.out) if n.startswith("orbit_"))))
check(all(png_size(out(n)) == size for n in names if os.path.exists(out(n))), "every frame is %dx%d" % size)
contents = [open(out(n), "rb").read() for n in names if os.path.exists(out(n))]
check(len(set(contents)) == len(contents), "every frame differs from the others")
rc, _, err = run(cad, "--style", "sketch", "--size", "%dx%d" % size, "--camera-in", out("orbit_camera.json"),
                 "-o", out("still.png"))
# Tolerance: a channel may differ by 2 of 255 (a sketch drawn again differs by 1 in a few values).
first, still = read_png(out("orbit_0001.png")), read_png(out("still.png"))
largest = max(abs(a - b) for a, b in zip(first, still)) if len(first) == len(still) else 999
check(rc == 0 and largest <= 2,
      "the first frame is the still of the camera the orbit starts from, --camera-out (largest "
      "difference %d)" % largest)
rc, _, err = run(cad, "--orbit", "2", "--orbit-degrees", "180", "--size", "%dx%d" % size, "-o", out("half.png"))
check(rc == 0 and open(out("half_0002.png"), "rb").read() != open(out("half_0001.png"), "rb").read(),
      "--orbit 2 --orbit-degrees 180: two different frames (%s)" % err.strip())

# ---- Ogg Theora video ----
video_size = (321, 241)  # odd on purpose: the writer pads, the picture keeps its size
rc, _, err = run(cad, "--style", "sketch", "--orbit", "10", "--fps", "12", "--size", "%dx%d" % video_size,
                 "-o", out("orbit.ogv"))
check(rc == 0, "--orbit 10 -o orbit.ogv (%s)" % err.strip())
try:
    width, height, rate, count = theora_stream(out("orbit.ogv"))
    check((width, height) == video_size, "the video's picture is %dx%d (got %dx%d)" % (video_size + (width, height)))
    check(count == 10, "the video has 10 frames (got %d)" % count)
    check(abs(rate - 12) < 1e-6, "the video runs at 12 frames per second (got %g)" % rate)
except (OSError, ValueError) as error:
    check(False, "orbit.ogv reads back as Ogg Theora: %s" % error)

# ---- MP4 through the ffmpeg program, AVI through VTK's vtkFFMPEGWriter (VTK 9.4 and later in
# Debian); a clear error where the program or the writer is missing ----
rc, _, err = run(cad, "--orbit", "8", "--size", "%dx%d" % video_size, "-o", out("orbit.mp4"))
if shutil.which("ffmpeg"):
    check(rc == 0, "--orbit 8 -o orbit.mp4 (%s)" % err.strip())
    if shutil.which("ffprobe"):
        probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
                                "-show_entries", "stream=nb_read_frames,width,height", "-of", "json",
                                out("orbit.mp4")], capture_output=True, text=True)
        stream = json.loads(probe.stdout or "{}").get("streams", [{}])[0]
        check(int(stream.get("nb_read_frames", 0)) == 8, "the MP4 has 8 frames (%s)" % stream)
        check((stream.get("width"), stream.get("height")) == (322, 242),
              "the MP4 is padded to even sizes (%s)" % stream)
else:
    check(rc == 1 and "needs the ffmpeg program" in err, "without ffmpeg, MP4 is a clear error (%s)" % err.strip())
    print("note: ffmpeg not installed: the MP4 itself is not checked here")
rc, _, err = run(cad, "--orbit", "8", "--size", "%dx%d" % video_size, "-o", out("orbit.avi"))
if rc == 0:
    with open(out("orbit.avi"), "rb") as f:
        head = f.read(12)
    check(head[:4] == b"RIFF" and head[8:12] == b"AVI " and os.path.getsize(out("orbit.avi")) > 2000,
          "orbit.avi is an AVI file (%r, %d bytes)" % (head, os.path.getsize(out("orbit.avi"))))
else:
    check(rc == 1 and "needs VTK's vtkFFMPEGWriter" in err, "without vtkFFMPEGWriter, AVI is a clear error (%s)"
          % err.strip())

# ---- Frames into a folder that does not exist yet: it is made ----
rc, _, err = run(cad, "--orbit", "2", "--size", "64x48", "-o", out(os.path.join("frames", "new", "cad.png")))
check(rc == 0 and sorted(os.listdir(out(os.path.join("frames", "new")))) == ["cad_0001.png", "cad_0002.png"],
      "--orbit -o frames/new/cad.png makes the folders (%s)" % err.strip())

# ---- Usage errors ----
open(out("a_file"), "w").close()
os.makedirs(out("a_folder.ogv"), exist_ok=True)
for argv, expected in [
    ([cad, "--orbit", "4"], "--orbit needs -o"),
    ([cad, "--orbit", "4", "-o", out("x.gif")], "--orbit needs -o"),
    ([cad, "-o", out("x.avi")], "a video needs --orbit N"),
    ([cad, "-o", out("x.ogv")], "a video needs --orbit N"),
    ([cad, "--orbit", "0", "-o", out("x.png")], "--orbit"),
    ([cad, "--orbit", "3", "--frames", "2", "-o", out("x.png")], "cannot be combined"),
    ([cad, "--orbit", "3", "--fps", "0", "-o", out("x.ogv")], "--fps"),
    ([cad, "--orbit", "3", "-o", os.path.join(out("a_file"), "x.ogv")], "cannot create the folder"),
    ([cad, "--orbit", "3", "-o", os.path.join(out("a_file"), "x.png")], "cannot create the folder"),
    ([cad, "--orbit", "3", "-o", out("a_folder.ogv")], "a_folder.ogv: cannot write the video: is a directory"),
]:
    rc, _, err = run(*argv)
    lines = err.strip().splitlines()
    check(rc in (1, 2) and len(lines) == 1 and lines[0].startswith("npr-render: error: ") and expected in lines[0],
          "%s -> rc %d, %r" % (" ".join(os.path.basename(a) for a in argv), rc, err.strip()))

cli.exit()
