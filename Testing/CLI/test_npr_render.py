# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""npr-render's behaviour: camera files round-trip exactly, --frames prints its JSON line, NaN
points give a warning, and every bad input gives one clear error line and a non-zero exit."""
import argparse
import json
import os
import subprocess
import sys

parser = argparse.ArgumentParser()
parser.add_argument("--npr-render", required=True)
# How this build reaches OSMesa: a separate program linked with NPR::OSMesa (VTK 9.1-9.3),
# npr-render's own --backend osmesa (VTK 9.4+ with libOSMesa), or not at all (no libOSMesa).
osmesa = parser.add_mutually_exclusive_group(required=True)
osmesa.add_argument("--npr-render-osmesa")
osmesa.add_argument("--osmesa-in-npr-render", action="store_true")
osmesa.add_argument("--no-osmesa", action="store_true")
parser.add_argument("--data", required=True)
parser.add_argument("--out", required=True)
parser.add_argument("--expect-version", required=True, help="the project's version")
args = parser.parse_args()
os.makedirs(args.out, exist_ok=True)
models = os.path.join(args.data, "Models")
bunny = os.path.join(args.data, "bunny.ply")
rotor = os.path.join(args.data, "rotor.ply")
failures = []
passes = []


# npr-render prints a progress line for each step over NPR_PROGRESS_SECONDS (1 s): the checks of
# stderr must not depend on the machine's speed (a sanitizer build without Mesa's shader cache
# took over 1 s for a sketch's first frame), so the threshold is out of reach unless a check sets
# it (env).
NO_PROGRESS = {"NPR_PROGRESS_SECONDS": "100000"}


def run(*argv, program=None, env=None):
    result = subprocess.run([program or args.npr_render, *argv], capture_output=True, text=True, timeout=300,
                            env=dict(os.environ, **(NO_PROGRESS if env is None else env)))
    return result.returncode, result.stdout, result.stderr


def check(condition, message):
    print(("ok: " if condition else "FAILED: ") + message)
    (passes if condition else failures).append(message)


def out(name):
    return os.path.join(args.out, name)


# --version: the program's name and the project's version, exit status 0.
rc, stdout, err = run("--version")
check(rc == 0 and stdout == "npr-render %s\n" % args.expect_version,
      "--version prints 'npr-render %s' (got %r, %r)" % (args.expect_version, stdout, err))


# Progress lines: with the threshold at 0 every step prints one on stderr (read with the triangle
# count, normals, first frame, output); --quiet prints none, and a bad threshold is ignored.
every_step = {"NPR_PROGRESS_SECONDS": "0"}
rc, _, err = run(bunny, "--style", "edges", "--size", "160x120", "-o", out("progress.png"), env=every_step)
lines = err.splitlines()
expected = ["npr-render: read %s (75408 triangles): " % bunny, "npr-render: normals of %s: " % bunny,
            "npr-render: first frame (edges): ", "npr-render: wrote %s: " % out("progress.png")]
check(rc == 0 and len(lines) == 4 and all(line.startswith(start) and line.endswith(" s")
                                          for line, start in zip(lines, expected)),
      "progress: one line per step in order (got %r)" % lines)
rc, _, err = run(bunny, "--style", "edges", "--size", "160x120", "-o", out("progress.png"), "--quiet",
                 env=every_step)
check(rc == 0 and err == "", "--quiet: no progress line (got %r)" % err)
rc, _, err = run(bunny, "--size", "160x120", "-o", out("progress.png"), env={"NPR_PROGRESS_SECONDS": "x"})
check(rc == 0 and "first frame" not in err, "a bad NPR_PROGRESS_SECONDS keeps the 1 s threshold (%r)" % err)


# Camera round trip: the camera written is the camera used; rendering with it reproduces the
# image bit for bit, and the clipping range is taken as given.
rc, _, err = run(rotor, "--azimuth", "40", "--elevation", "25", "--zoom", "1.3", "--size", "320x240",
                 "-o", out("rt_a.png"), "--camera-out", out("cam.json"))
check(rc == 0, "render with --camera-out (%s)" % err.strip())
text = open(out("cam.json")).read()
camera = json.loads(text)
keys = ["position", "focal_point", "view_up", "view_angle", "parallel_projection", "parallel_scale",
        "clipping_range", "size"]
check(list(camera) == keys, "camera keys in the documented order: %s" % list(camera))
check(text.startswith('{"position":[') and "\n" not in text.strip(), "camera file on one line, no spaces")
check(camera["size"] == [320, 240], "camera size is the render size")
check(abs(camera["view_angle"] - 30.0 / 1.3) < 1e-9 and camera["parallel_projection"] is False,
      "perspective, view angle narrowed by --zoom: %s" % camera["view_angle"])
rc, _, err = run(rotor, "--camera-in", out("cam.json"), "-o", out("rt_b.png"), "--camera-out", out("cam2.json"))
check(rc == 0, "render with --camera-in (%s)" % err.strip())
check(open(out("rt_a.png"), "rb").read() == open(out("rt_b.png"), "rb").read(),
      "--camera-in reproduces the --camera-out render exactly")
check(json.load(open(out("cam2.json"))) == camera, "the camera read is the camera written back")
with open(out("cam_comma.json"), "w") as f:
    f.write(text.strip()[:-1] + ",}")
rc, _, err = run(rotor, "--camera-in", out("cam_comma.json"), "-o", out("x.png"))
check(rc == 1 and "not valid JSON" in err, "a trailing comma is not JSON (%s)" % err.strip())
narrow = dict(camera, clipping_range=[camera["clipping_range"][0], camera["clipping_range"][0] * 1.0001])
json.dump(narrow, open(out("cam_narrow.json"), "w"))
rc, _, _ = run(rotor, "--camera-in", out("cam_narrow.json"), "-o", out("rt_c.png"), "--camera-out", out("cam3.json"))
check(rc == 0 and json.load(open(out("cam3.json")))["clipping_range"] == narrow["clipping_range"],
      "--camera-in keeps the given clipping range (not reset)")
check(open(out("rt_c.png"), "rb").read() != open(out("rt_a.png"), "rb").read(),
      "a near-zero depth range clips the model away")

# --frames: one JSON line with the timing figures.
rc, stdout, err = run(bunny, "--frames", "3", "--size", "200x150")
lines = [line for line in stdout.splitlines() if line.strip()]
check(rc == 0 and len(lines) == 1, "--frames prints one line (%s)" % err.strip())
timing = json.loads(lines[0]) if lines else {}
for key in ["median_ms", "min_ms", "max_ms", "triangles", "pixels", "renderer"]:
    check(key in timing, "--frames reports %s" % key)
check(timing.get("triangles") == 75408 and timing.get("pixels") == 30000 and timing.get("frames") == 3,
      "--frames counts: %s" % timing)
check(0 < timing.get("min_ms", 0) <= timing.get("median_ms", 0) <= timing.get("max_ms", 0),
      "min <= median <= max")

# OSMesa renders the same scene, where this build has it.
if not args.no_osmesa:
    osmesa_args = [] if args.npr_render_osmesa else ["--backend", "osmesa"]
    rc, stdout, err = run(rotor, "--size", "160x120", "--frames", "1", "-o", out("osmesa.png"), *osmesa_args,
                          program=args.npr_render_osmesa)
    check(rc == 0 and json.loads(stdout)["backend"] == "osmesa", "OSMesa renders (%s)" % err.strip())

# NaN coordinates: a warning, and the image is still made.
rc, _, err = run(os.path.join(models, "cube_nan.ply"), "--size", "64x64", "-o", out("nan.png"))
check(rc == 0 and "warning" in err and "NaN/Inf" in err and os.path.exists(out("nan.png")),
      "NaN points are dropped with a warning (%s)" % err.strip())

# A picture of the background alone is never silent: the model zoomed far below a pixel gives one
# warning (exit 0, the image made); the same model in view none.
for style in ("shaded", "edges"):
    rc, _, err = run(rotor, "--size", "64x64", "--style", style, "--zoom", "0.00001", "-o", out("tiny.png"))
    check(rc == 0 and err.strip().startswith("npr-render: warning: the 64x64 picture shows only the "
                                             "background: none of the ") and os.path.exists(out("tiny.png")),
          "%s: a model far below a pixel gives a warning (%r)" % (style, err.strip()))
rc, _, err = run(rotor, "--size", "64x64", "--style", "edges", "-o", out("in_view.png"))
check(rc == 0 and err == "", "a model in view: no warning (%r)" % err)

# A partly bad OBJ (NaN/Inf vertices, one face on finite points): one warning, the face drawn.
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    scalars = image.GetPointData().GetScalars()
    values = [scalars.GetValue(i) for i in range(scalars.GetNumberOfValues())]
    return image.GetDimensions(), scalars.GetNumberOfComponents(), scalars.GetDataTypeAsString(), values


rc, _, err = run(os.path.join(models, "part_nan.obj"), "--size", "64x64", "-o", out("part_nan.png"))
lines = err.strip().splitlines()
check(rc == 0 and len(lines) == 1 and lines[0].startswith("npr-render: warning: ") and
      "dropped 2 points with NaN/Inf coordinates and the 2 cells" in lines[0],
      "a partly NaN OBJ gives one warning (%s)" % err.strip())
_, components, _, values = read_png(out("part_nan.png"))
drawn = sum(1 for i in range(0, len(values), components) if values[i:i + 3] != [255, 255, 255])
check(drawn > 200, "the finite face of the partly NaN OBJ is drawn (%d non-background pixels)" % drawn)

# Nothing drawable (no finite cell, every point on one line, too small for float rendering to
# frame): an error for every style, and for --frames, never a blank image with exit status 0.
for model in ("all_nan.obj", "flat.obj", "tiny.vtk"):
    for style in ("shaded", "edges", "toon", "toon+edges", "sketch", "inked"):
        for extra in (["-o", out("blank.png")], ["--frames", "2"]):
            if os.path.exists(out("blank.png")):
                os.remove(out("blank.png"))
            rc, stdout, err = run(os.path.join(models, model), "--style", style, "--size", "64x64", *extra)
            lines = err.strip().splitlines()
            check(rc == 1 and len(lines) == 1 and "nothing to draw" in lines[0] and not stdout.strip()
                  and not os.path.exists(out("blank.png")),
                  "%s --style %s %s: exit 1, 'nothing to draw' (%s)" % (model, style, extra[0], err.strip()))

# Several models and formats in one scene.
rc, _, err = run(os.path.join(models, "cube.glb"), os.path.join(models, "cube.off"), "--size", "64x64",
                 "-o", out("two.png"))
check(rc == 0, "two models in one scene (%s)" % err.strip())

# --style edges and --edge-mask: an 8-bit grey mask of the render's size, white lines on black.
rc, _, err = run(rotor, "--style", "edges", "--size", "160x120", "--azimuth", "30", "-o", out("edges.png"),
                 "--edge-mask", out("mask.png"))
check(rc == 0, "--style edges with --edge-mask (%s)" % err.strip())
dims, components, kind, values = read_png(out("mask.png"))
lit = sum(1 for v in values if v > 127)
check(dims[:2] == (160, 120) and components == 1 and kind == "unsigned char",
      "the edge mask is 8-bit grey at the render's size: %s %d %s" % (dims, components, kind))
check(300 < lit < 0.3 * 160 * 120 and values.count(0) > 0.5 * 160 * 120,
      "the edge mask has white lines on black (%d line pixels)" % lit)
rc, _, err = run(rotor, "--style", "edges", "--lines", "none", "--size", "160x120", "--edge-mask", out("none.png"))
check(rc == 0 and max(read_png(out("none.png"))[3]) == 0, "--lines none gives an empty mask (%s)" % err.strip())
# Suggestive contours alone: lines inside the bunny's outline (its folds), none with no line type.
rc, _, err = run(bunny, "--style", "edges", "--lines", "suggestive", "--size", "320x240", "--edge-mask",
                 out("suggestive.png"))
check(rc == 0 and max(read_png(out("suggestive.png"))[3]) > 0,
      "--lines suggestive draws suggestive contours (%s)" % err.strip())
rc, _, err = run(bunny, "--style", "edges", "--smooth-silhouettes", "--face-creases", "--size", "160x120",
                 "--edge-mask", out("smooth.png"))
check(rc == 0 and max(read_png(out("smooth.png"))[3]) > 0, "--smooth-silhouettes --face-creases (%s)" % err.strip())
rc, _, _ = run(rotor, "--style", "edges", "--lines", "silhouettes", "--line-width", "4", "--size", "160x120",
               "--azimuth", "30", "--edge-mask", out("wide.png"))
wide = sum(v for v in read_png(out("wide.png"))[3]) / 255.0
rc2, _, _ = run(rotor, "--style", "edges", "--lines", "silhouettes", "--line-width", "1", "--size", "160x120",
                "--azimuth", "30", "--edge-mask", out("thin.png"))
thin = sum(v for v in read_png(out("thin.png"))[3]) / 255.0
check(rc == 0 and rc2 == 0 and 2.5 * thin < wide < 5.5 * thin,
      "--line-width 4 draws about 4 times the coverage of --line-width 1 (%.0f vs %.0f)" % (wide, thin))

# --reference-mask: the visible object-space lines of --lines, white on black, for any style; the
# same camera as the render, so it lines up with --edge-mask.
def lit_pixels(values):
    return sum(1 for v in values if v)


rc, _, err = run(rotor, "--size", "160x120", "--azimuth", "30", "--reference-mask", out("ref.png"))
check(rc == 0 and os.path.exists(out("ref.png")), "--reference-mask with the shaded style (%s)" % err.strip())
dims, components, kind, reference = read_png(out("ref.png"))
check(dims[:2] == (160, 120) and components == 1 and kind == "unsigned char",
      "the reference mask is 8-bit grey at the render's size: %s %d %s" % (dims, components, kind))
check(set(reference) <= {0, 255} and 300 < lit_pixels(reference) < 0.3 * 160 * 120,
      "the reference mask has white lines on black (%d line pixels)" % lit_pixels(reference))
rc, _, err = run(rotor, "--style", "edges", "--size", "160x120", "--azimuth", "30", "--line-width", "1",
                 "--no-antialias", "--edge-mask", out("ref_edges.png"), "--reference-mask", out("ref_b.png"))
check(rc == 0 and read_png(out("ref_b.png"))[3] == reference,
      "the reference mask does not depend on the style (%s)" % err.strip())
edge = read_png(out("ref_edges.png"))[3]
near = sum(1 for i, v in enumerate(reference) if v and any(
    edge[(i // 160 + dy) * 160 + i % 160 + dx] > 127
    for dy in (-1, 0, 1) for dx in (-1, 0, 1) if 0 <= i // 160 + dy < 120 and 0 <= i % 160 + dx < 160))
check(near >= 0.9 * lit_pixels(reference),
      "the edge mask lines up with the reference: %d of %d reference pixels within 1 px" % (near, lit_pixels(reference)))
counts = {}
for name, model, extra in (("creases", rotor, ["--lines", "creases"]), ("none", rotor, ["--lines", "none"]),
                           ("angle10", bunny, ["--lines", "creases", "--crease-angle", "10"]),
                           ("angle60", bunny, ["--lines", "creases", "--crease-angle", "60"])):
    rc, _, err = run(model, "--size", "160x120", "--azimuth", "30", "--reference-mask", out("ref_%s.png" % name), *extra)
    check(rc == 0, "--reference-mask %s (%s)" % (" ".join(extra), err.strip()))
    counts[name] = lit_pixels(read_png(out("ref_%s.png" % name))[3])
check(counts["none"] == 0 and 0 < counts["creases"] < lit_pixels(reference),
      "--lines selects the reference's lines: %s" % counts)
check(counts["angle60"] < counts["angle10"], "--crease-angle: fewer bunny creases at 60 than at 10 degrees: %s" % counts)

# --style toon, toon+edges and sketch: each renders and differs from the others; the sketch is the
# same for the same seed and differs for another seed.
styles = {}
for style, extra in (("shaded", []), ("toon", ["--toon-bands", "2"]), ("toon+edges", []),
                     ("sketch", ["--noise-seed", "7"]), ("sketch", ["--noise-seed", "7", "--paper-color", "#fff8e0"]),
                     ("sketch", ["--noise-seed", "8"]), ("sketch", ["--noise-seed", "7", "--uncertainty", "0"])):
    name = "%s%s.png" % (style, "".join(extra).replace("#", "").replace("-", "_"))
    rc, _, err = run(rotor, "--style", style, "--size", "160x120", "--azimuth", "30", "-o", out(name), *extra)
    check(rc == 0, "--style %s %s renders (%s)" % (style, " ".join(extra), err.strip()))
    styles[name] = read_png(out(name))[3]
rc, _, err = run(rotor, "--style", "sketch", "--noise-seed", "7", "--size", "160x120", "--azimuth", "30",
                 "-o", out("sketch_again.png"))
check(read_png(out("sketch_again.png"))[3] == styles["sketch__noise_seed7.png"], "the same seed gives the same sketch")
names = sorted(styles)
for i, a in enumerate(names):
    for b in names[i + 1:]:
        check(styles[a] != styles[b], "%s and %s differ" % (a, b))

# --style inked and --encoding: each renders a mask with lines; packed masks differ from float's;
# the inked mask outlines the rotor.
masks = {}
for name, extra in (("inked", ["--style", "inked"]),
                    ("float", ["--style", "edges", "--encoding", "float"]),
                    ("half", ["--style", "edges", "--encoding", "half"]),
                    ("packed8", ["--style", "edges", "--encoding", "packed8"]),
                    ("packed16", ["--style", "edges", "--encoding", "packed16", "--packed-blur"])):
    rc, _, err = run(rotor, "--size", "160x120", "--azimuth", "30", "--edge-mask", out("mask_%s.png" % name),
                     "-o", out("image_%s.png" % name), *extra)
    check(rc == 0, "%s renders with a mask (%s)" % (" ".join(extra), err.strip()))
    masks[name] = read_png(out("mask_%s.png" % name))[3]
    lit = sum(1 for v in masks[name] if v > 127)
    check(100 < lit < 0.3 * 160 * 120, "the %s mask has lines (%d line pixels)" % (name, lit))
check(masks["packed8"] != masks["float"] and masks["packed16"] != masks["packed8"],
      "the packed encodings give their own lines")

# Errors: one line on stderr that names the problem, non-zero exit, no crash.
open(out("a_file"), "w").close()
os.makedirs(out("a_folder.png"), exist_ok=True)
errors = [
    ([os.path.join(models, "missing.ply"), "-o", out("x.png")], "no such file"),
    ([os.path.join(models, "empty.stl"), "-o", out("x.png")], "is empty"),
    ([os.path.join(models, "truncated.ply"), "-o", out("x.png")], "truncated"),
    ([os.path.join(models, "bad_keyword.off"), "-o", out("x.png")], "is no OFF keyword"),
    ([os.path.join(models, "bad.gltf"), "-o", out("x.png")], "malformed glTF file: invalid JSON"),
    ([os.path.join(models, "cube.xyz"), "-o", out("x.png")], "unknown model format"),
    # Each of these crashed npr-render (missing glTF buffer) or drew a blank image with exit 0.
    ([os.path.join(models, "missing_buffer.gltf"), "-o", out("x.png")], "missing_buffer.gltf: malformed glTF file: buffer 0 file 'missing_buffer.bin' is missing"),
    ([os.path.join(models, "short_buffer.gltf"), "-o", out("x.png")], "fewer than its byteLength"),
    ([os.path.join(models, "bad_accessor.gltf"), "-o", out("x.png")], "does not fit in bufferView 0"),
    ([os.path.join(models, "bad_indices.gltf"), "-o", out("x.png")], "is vertex 7 of 7"),
    ([os.path.join(models, "bad_length.glb"), "-o", out("x.png")], "malformed GLB file"),
    ([os.path.join(models, "short_points.vtk"), "-o", out("x.png")], "short_points.vtk: malformed legacy VTK file: POINTS declares 8 points but holds 3"),
    ([os.path.join(models, "all_nan.obj"), "-o", out("x.png")], "all_nan.obj: nothing to draw"),
    ([os.path.join(models, "bad_index.obj"), "-o", out("x.png")], "bad_index.obj: malformed OBJ file: line 4: uses vertex 9 of 3"),
    ([os.path.join(models, "bad_negative_index.obj"), "-o", out("x.png")], "uses vertex -9, before the first"),
    ([os.path.join(models, "bad_index.vtp"), "-o", out("x.png")], "bad_index.vtp: nothing to draw"),
    ([rotor, "--style", "watercolour", "-o", out("x.png")], "unknown style 'watercolour' (valid styles: shaded, edges, toon, toon+edges, sketch, inked, drawing)"),
    ([rotor, "--style", "toon", "--toon-bands", "0", "-o", out("x.png")], "--toon-bands expects an integer in 1..64"),
    ([rotor, "--style", "sketch", "--uncertainty", "40", "-o", out("x.png")], "--uncertainty expects a number in 0..32"),
    ([rotor, "--style", "sketch", "--noise-frequency", "0", "-o", out("x.png")], "--noise-frequency expects a number in 0.05..25"),
    ([rotor, "--style", "sketch", "--noise-seed", "-1", "-o", out("x.png")], "--noise-seed expects an integer in 0..2147483647"),
    ([rotor, "--style", "sketch", "--paper-color", "2,0,0", "-o", out("x.png")], "--paper-color"),
    ([rotor, "--style", "sketch", "--edge-mask", out("m.png")], "--edge-mask needs --style edges, toon+edges or inked"),
    ([rotor, "--style", "edges", "--crease-angle", "500", "-o", out("x.png")], "--crease-angle expects a number in 1..179"),
    ([rotor, "--style", "edges", "--silhouette-threshold", "2", "-o", out("x.png")], "--silhouette-threshold expects a number in"),
    ([rotor, "--style", "edges", "--line-width", "0", "-o", out("x.png")], "--line-width expects a number in 0.5..16"),
    ([rotor, "--style", "edges", "--contour-side", "sideways", "-o", out("x.png")], "--contour-side expects inside, outside or both"),
    ([rotor, "--style", "edges", "--suggestive-threshold", "0", "-o", out("x.png")], "--suggestive-threshold expects a number in"),
    ([rotor, "--style", "edges", "--lines", "silhouettes,hatching", "-o", out("x.png")], "--lines expects silhouettes, creases, contours, suggestive or none, got 'hatching'"),
    ([rotor, "--style", "edges", "--line-color", "2,0,0", "-o", out("x.png")], "--line-color expects a colour name (such as red, navy, wheat), r,g,b in 0..1 or #rrggbb, got '2,0,0'"),
    ([rotor, "--edge-mask", out("m.png")], "--edge-mask needs --style edges, toon+edges or inked"),
    ([rotor, "--style", "edges", "--encoding", "packed4", "-o", out("x.png")], "--encoding expects float, half, packed8 or packed16, got 'packed4'"),
    ([rotor, "--style", "edges", "--packed-threshold", "0", "-o", out("x.png")], "--packed-threshold expects a number in 0.001..4"),
    ([rotor, "--size", "100", "-o", out("x.png")], "--size expects WxH"),
    ([rotor, "--size", "0x100", "-o", out("x.png")], "--size width expects an integer in 1..16384"),
    ([rotor, "--zoom", "-2", "-o", out("x.png")], "--zoom expects a positive factor"),
    ([rotor, "--azimuth", "north", "-o", out("x.png")], "--azimuth expects a number"),
    ([rotor, "--background", "1,2,3", "-o", out("x.png")], "--background expects a colour name"),
    ([rotor, "--frames", "0"], "--frames expects an integer"),
    ([rotor, "--backend", "vulkan", "-o", out("x.png")], "unknown backend 'vulkan'"),
    ([rotor, "--bogus", "-o", out("x.png")], "unknown option '--bogus'"),
    ([rotor], "nothing to do"),
    ([rotor, "-o"], "-o needs a value"),
    (["-o", out("x.png")], "no model file given"),
    ([rotor, "--camera-in", os.path.join(models, "missing.json"), "-o", out("x.png")], "cannot open the camera file"),
    ([rotor, "--camera-in", os.path.join(models, "bad.gltf"), "-o", out("x.png")], "not valid JSON"),
    # A folder that cannot be made (its parent is a file) and a PNG that is a folder: the reason.
    ([rotor, "-o", os.path.join(out("a_file"), "dir", "x.png")],
     "a_file/dir/x.png: cannot create the folder %s: Not a directory" % os.path.join(out("a_file"), "dir")),
    ([rotor, "--reference-mask", os.path.join(out("a_file"), "m.png")], "cannot create the folder"),
    ([rotor, "--size", "32x32", "-o", out("a_folder.png")], "a_folder.png: cannot write the PNG: is a directory"),
    ([rotor, "--size", "32x32", "--camera-out", out("a_folder.png")],
     "a_folder.png: cannot write the camera file: is a directory"),
    ([rotor, "--line-color", "reddish", "-o", out("x.png")], "--line-color expects a colour name"),
    # Combinations that cannot draw what they ask for.
    ([rotor, "--style", "drawing", "--lines", "contours", "-o", out("x.png")],
     "--style drawing draws silhouettes (with boundaries) and creases; the --lines given leave it nothing to draw"),
    ([rotor, "--style", "drawing", "--lines", "none", "-o", out("x.svg")], "leave it nothing to draw"),
    ([rotor, "--style", "edges", "--face-creases", "--encoding", "half", "-o", out("x.png")],
     "--face-creases needs --encoding float (only it keeps the faces' normals), not half"),
    ([rotor, "--style", "toon+edges", "--face-creases", "--encoding", "packed8", "-o", out("x.png")],
     "--face-creases needs --encoding float"),
    ([rotor, "--style", "sketch", "--smooth-silhouettes", "--encoding", "packed16", "-o", out("x.png")],
     "--smooth-silhouettes needs --encoding float or half"),
    ([rotor, "--style", "edges", "--lines", "suggestive", "--encoding", "packed8", "-o", out("x.png")],
     "--lines suggestive needs --encoding float or half"),
    ([rotor, "--style", "Pastel", "-o", out("x.png")], "unknown style 'Pastel'"),
    ([rotor, "--backend", "x", "-o", out("x.png")], "DISPLAY is not set"),
    ([rotor, "--camera-in", out("cam.json"), "--zoom", "2", "-o", out("x.png")], "cannot be combined with --camera-in"),
] + ([] if args.osmesa_in_npr_render else [
    ([rotor, "--backend", "osmesa", "-o", out("x.png")],
     "not available in this build" if args.no_osmesa else
     "no osmesa render window: this npr-render renders with EGL or X; for OSMesa run npr-render-osmesa "
     "with the same options"),
])
along_view = [f - p for f, p in zip(camera["focal_point"], camera["position"])]
json.dump(dict(camera, view_up=along_view), open(out("cam_bad_up.json"), "w"))
errors.append(([rotor, "--camera-in", out("cam_bad_up.json"), "-o", out("x.png")], "view_up"))
json.dump({k: v for k, v in camera.items() if k != "focal_point"}, open(out("cam_missing.json"), "w"))
errors.append(([rotor, "--camera-in", out("cam_missing.json"), "-o", out("x.png")], 'missing "focal_point"'))
for argv, expected in errors:
    rc, stdout, err = run(*argv)
    lines = err.strip().splitlines()
    ok = rc not in (0,) and rc > 0 and len(lines) == 1 and lines[0].startswith("npr-render: error: ") \
        and expected in lines[0]
    check(ok, "%s -> rc %d, %r" % (" ".join(os.path.basename(a) for a in argv), rc, err.strip()))


# ---- What a newcomer types: style names as ParaView writes them, colour names, folders made,
# and a warning for each flag that the style does not use (the image is then as without it).
def image(path):
    dimensions, components, _, values = read_png(path)
    return dimensions, components, values


small = ["--size", "120x90", "--azimuth", "30"]
rc, _, err = run(rotor, *small, "--style", "toon+edges", "-o", out("style_canonical.png"))
check(rc == 0 and err == "", "--style toon+edges renders (%r)" % err)
for spelling in ("Toon+Edges", "TOON+EDGES", "Toon + Edges"):
    rc, _, err = run(rotor, *small, "--style", spelling, "-o", out("style_spelled.png"))
    check(rc == 0 and err == "" and image(out("style_spelled.png")) == image(out("style_canonical.png")),
          "--style '%s' is toon+edges (%r)" % (spelling, err))
rc, stdout, err = run(rotor, "--size", "64x48", "--frames", "1", "--compare-style", "Sketch,Drawing")
check(rc == 0 and [c["style"] for c in json.loads(stdout).get("compare", [])] == ["sketch", "drawing"],
      "--compare-style takes ParaView's spellings (%r)" % err)

rc, _, err = run(rotor, *small, "--style", "edges", "--line-width", "3", "--line-color", "Red",
                 "-o", out("red_lines.png"))
_, components, values = image(out("red_lines.png")) if rc == 0 else (None, 3, [])
pixels = [values[i:i + components] for i in range(0, len(values), components)]
red = sum(1 for p in pixels if p[0] > 200 and p[1] < 60 and p[2] < 60)
dark = sum(1 for p in pixels if max(p[:3]) < 60)
check(rc == 0 and red > 100 and dark < red / 20, "--line-color Red draws red lines (%d red, %d dark pixels)" % (red, dark))
# Names read as PyVista reads them (CSS values): grey is 128 (VTK's own grey is 192), Indian_Red
# is CSS's indianred (VTK's indian_red differs).
for name, expected in (("navy", [0, 0, 128]), ("Grey", [128, 128, 128]), ("Indian_Red", [205, 92, 92]),
                       ("light grey", [211, 211, 211])):
    rc, _, err = run(rotor, "--size", "32x24", "--background", name, "-o", out("named.png"))
    corner = image(out("named.png"))[2][:3] if rc == 0 else None
    check(rc == 0 and err == "" and corner == expected, "--background %s is %s (%s, %r)" % (name, expected, corner, err))
rc, _, err = run(rotor, *small, "--style", "sketch", "--paper-color", "wheat", "-o", out("named.png"))
check(rc == 0 and err == "", "a colour name for --paper-color (%r)" % err)

made = {"-o": out(os.path.join("made", "a", "x.png")), "--camera-out": out(os.path.join("made", "b", "c.json")),
        "--edge-mask": out(os.path.join("made", "c", "m.png")),
        "--reference-mask": out(os.path.join("made", "d", "r.png"))}
rc, _, err = run(rotor, *small, "--style", "edges", *[x for pair in made.items() for x in pair])
check(rc == 0 and all(os.path.isfile(path) for path in made.values()),
      "missing output folders are made for every file written (%r)" % err)

warnings = [
    (["--style", "edges", "--toon-bands", "4"],
     "--toon-bands applies to --style toon, toon+edges or sketch; ignored with --style edges"),
    (["--style", "toon", "--line-width", "3"],
     "--line-width applies to --style edges, toon+edges, sketch, inked or drawing; ignored with --style toon"),
    (["--style", "shaded", "--uncertainty", "5"], "--uncertainty applies to --style sketch; ignored with --style shaded"),
    (["--style", "edges", "--hidden-lines"], "--hidden-lines applies to --style drawing; ignored with --style edges"),
    (["--style", "inked", "--crease-angle", "20"], "--crease-angle applies to --style edges, toon+edges, sketch or drawing; ignored with --style inked"),
    (["--style", "edges", "--packed-blur"], "--packed-blur applies only with --encoding packed8 or packed16"),
    (["--style", "edges", "--suggestive-threshold", "0.1"], "--suggestive-threshold has no effect: --lines has no suggestive"),
    (["--style", "sketch", "--toon-bands", "5"], "the toon flags apply to the sketch only with --sketch-toon"),
    (["--style", "drawing", "--lines", "silhouettes,contours"],
     "--style drawing draws no contours or suggestive contours (only silhouettes, boundaries and creases)"),
]
for extra, expected in warnings:
    style = extra[1]
    rc, _, plain_err = run(rotor, *small, "--style", style, "-o", out("warn_plain.png"))
    rc2, _, err = run(rotor, *small, *extra, "-o", out("warn_flag.png"))
    lines = err.strip().splitlines()
    same = rc2 == 0 and image(out("warn_flag.png")) == image(out("warn_plain.png")) or "--lines" in extra
    check(rc == 0 and rc2 == 0 and lines == ["npr-render: warning: " + expected] and same,
          "%s: one warning, exit 0, the image as without it (%r)" % (" ".join(extra), err.strip()))
rc, _, err = run(rotor, *small, "--style", "shaded", "--lines", "creases", "--crease-angle", "20",
                 "--reference-mask", out("ref_only.png"))
check(rc == 0 and err == "", "--lines and --crease-angle with --reference-mask: no warning (%r)" % err)
rc, _, err = run(rotor, "--size", "64x48", "--frames", "1", "--style", "edges", "--compare-style", "toon",
                 "--toon-bands", "4")
check(rc == 0 and err == "", "a flag of a --compare-style style: no warning (%r)" % err)

print("%d passed, %d failed" % (len(passes), len(failures)))
sys.exit(1 if failures else 0)
