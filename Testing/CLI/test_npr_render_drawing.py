# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""npr-render -o with vector drawings: .svg, .pdf, .ps and .eps write the lines (over the image,
in the edges style), .png stays an image, and an unknown extension, a missing folder or a folder
as the file each exit non-zero with one line `npr-render: error: ...` and leave no file; --sheet
writes a drawing sheet in each format and refuses what it cannot do; --fill-faces writes the faces
as filled paths under the strokes, in the face or the surface colours."""
import os
import re
import shutil
import subprocess

from npr_cli_checks import CLI

cli = CLI(timeout=300)
part = cli.model("cad_part.vtp")
run, check, out = cli.run, cli.check, cli.out


def pdf_page_size(path, data):
    """The first page's size in points: from the page dictionary where Cairo writes it as text
    (1.16), else from pdfinfo (Cairo 1.18 compresses it into an object stream)."""
    if b"/MediaBox [ 0 0 320 240 ]" in data:
        return (320, 240)
    pdfinfo = shutil.which("pdfinfo")
    if not pdfinfo:
        return None
    info = subprocess.run([pdfinfo, path], capture_output=True, text=True).stdout
    for line in info.splitlines():
        if line.startswith("Page size:"):
            parts = line.split()
            return (round(float(parts[2])), round(float(parts[4])))
    return None


common = ["--size", "320x240", "--azimuth", "30", "--elevation", "30"]
for name in ("edges.svg", "edges.pdf", "edges.ps", "edges.eps", "EDGES.SVG"):
    path = out(name)
    if os.path.exists(path):
        os.remove(path)
    rc, _, err = run(part, "--style", "edges", *common, "-o", path)
    check(rc == 0 and os.path.isfile(path), "-o %s writes it (%s)" % (name, err.strip()))
    if not os.path.isfile(path):
        continue
    data = open(path, "rb").read()
    if name.lower().endswith(".svg"):
        text = data.decode()
        check('width="320pt" height="240pt"' in text and "<image" in text and
              '<g class="npr-silhouette">' in text and text.count("<path") > 10,
              "%s: the page, the image under the lines, the groups, %d paths" % (name, text.count("<path")))
    elif name.endswith(".pdf"):
        check(data.startswith(b"%PDF-") and pdf_page_size(path, data) == (320, 240),
              "%s: a 320x240 pt PDF (%s)" % (name, pdf_page_size(path, data)))
    else:
        check(data.startswith(b"%!PS-Adobe-3.0") and (b"EPSF" in data) == name.endswith(".eps"),
              "%s: PostScript" % name)

# The drawing style with hidden lines (the target command), where this build has the style.
rc, _, err = run(part, "--style", "drawing", "--hidden-lines", *common, "-o", out("part.svg"))
if rc != 0 and "unknown style 'drawing'" in err:
    print("skipped: --style drawing is not in this build")
else:
    text = open(out("part.svg")).read() if os.path.isfile(out("part.svg")) else ""
    check(rc == 0 and '<g class="npr-hidden">' in text and "stroke-dasharray" in text and "<image" not in text,
          "--style drawing --hidden-lines -o part.svg: dashed hidden strokes, no image (%s)" % err.strip())

# .png stays an image.
rc, _, err = run(part, *common, "-o", out("image.png"))
check(rc == 0 and open(out("image.png"), "rb").read(8) == b"\x89PNG\r\n\x1a\n", "-o image.png writes a PNG")

# Errors: one line each, non-zero, no file.
os.makedirs(out("folder.svg"), exist_ok=True)
open(out("a_file"), "w").close()
rc, _, err = run(part, *common, "-o", out(os.path.join("new", "folder", "x.svg")))
check(rc == 0 and os.path.isfile(out(os.path.join("new", "folder", "x.svg"))),
      "-o new/folder/x.svg makes the folders (%r)" % err)
for target, expected in ((out("drawing.jpg"), "unknown extension (supported: .png, .svg, .pdf, .ps, .eps"),
                         (out("drawing"), "unknown extension"),
                         (os.path.join(out("a_file"), "x.svg"), "cannot create the folder"),
                         (out("folder.svg"), "is a directory")):
    rc, _, err = run(part, *common, "-o", target)
    lines = err.strip().splitlines()
    check(rc != 0 and len(lines) == 1 and lines[0].startswith("npr-render: error: ") and expected in lines[0],
          "-o %s: exit %d, one error line with '%s' (%r)" % (os.path.basename(target), rc, expected, err))
    check(not os.path.isfile(target), "-o %s: no file left" % os.path.basename(target))
rc, _, err = run(part, "--orbit", "3", "-o", out("orbit.svg"))
check(rc != 0 and "--orbit needs" in err, "--orbit with .svg is refused (%s)" % err.strip())

# Drawing sheets: the command, the page in each format, and the usage errors (exit 2).
for name, magic in (("sheet.pdf", b"%PDF"), ("sheet.svg", b"<?xml"), ("sheet.eps", b"%!PS")):
    rc, _, err = run(part, "--sheet", "iso,front,top,right", "-o", out(name))
    data = open(out(name), "rb").read() if os.path.isfile(out(name)) else b""
    check(rc == 0 and data.startswith(magic), "--sheet -o %s (%r)" % (name, err.strip()))
rc, _, err = run(part, "--sheet", "front,top", "--sheet-paper", "A3", "--sheet-angle", "third",
                 "--sheet-margin", "15", "--hidden-lines", "-o", out("sheet_a3.pdf"))
data = open(out("sheet_a3.pdf"), "rb").read() if os.path.isfile(out("sheet_a3.pdf")) else b""
size = pdf_page_size(out("sheet_a3.pdf"), data) if data else None
check(rc == 0 and err == "" and (size is None or size == (1191, 842)),
      "--sheet-paper A3: an A3 landscape page, no warning (%r, %r)" % (size, err.strip()))
for extra, expected in ((["--sheet", "front,side", "-o", out("x.svg")], "unknown view 'side'"),
                        (["--sheet", "front", "-o", out("x.png")], "--sheet needs -o FILE"),
                        (["--sheet-angle", "third", "-o", out("x.svg")], "needs --sheet VIEWS"),
                        (["--sheet", "front", "--sheet-paper", "B5", "-o", out("x.svg")], "not A4, A3 or letter"),
                        (["--sheet", "front", "--style", "edges", "-o", out("x.svg")], "--sheet draws the drawing style")):
    rc, _, err = run(part, *extra)
    check(rc == 2 and expected in err, "%s: exit 2 with '%s' (%r)" % (" ".join(extra[:2]), expected, err.strip()))

# Filled faces: paths with a fill under the strokes, in the drawing style's face colour (white) or
# the part's own colour (as a PDF), and the usage errors.
rc, _, err = run(part, "--style", "drawing", "--fill-faces", "-o", out("filled.svg"))
svg = open(out("filled.svg")).read() if os.path.isfile(out("filled.svg")) else ""
# Cairo 1.16 writes style="fill:rgb(100%,100%,100%)", 1.18 fill="rgb(100%, 100%, 100%)".
WHITE_FILL = re.compile(r'fill(?::|=")rgb\(100%, ?100%, ?100%\)')
check(rc == 0 and len(WHITE_FILL.findall(svg)) > 100 and "npr-silhouette" in svg,
      "--fill-faces: white filled paths under the strokes (%r)" % err.strip())
rc, _, err = run(part, "--style", "toon", "--fill-faces", "--fill-colors", "toon",
                 "-o", out("filled_toon.svg"))
svg = open(out("filled_toon.svg")).read() if os.path.isfile(out("filled_toon.svg")) else ""
fills = set(re.findall(r'fill(?::|=")(rgb\([^)]*\))', svg))
check(rc == 0 and len(fills) >= 3 and "<image" not in svg,
      "--fill-colors toon: the toon bands' colours, no raster (%d colours, %r)" % (len(fills), err.strip()))
rc, _, err = run(part, "--sheet", "iso,front", "--fill-faces", "-o", out("filled_sheet.svg"))
svg = open(out("filled_sheet.svg")).read() if os.path.isfile(out("filled_sheet.svg")) else ""
check(rc == 0 and len(WHITE_FILL.findall(svg)) > 50,
      "--sheet with --fill-faces: each view's faces filled (%r)" % err.strip())
rc, _, err = run(part, "--style", "drawing", "--fill-faces", "--fill-colors", "surface",
                 "-o", out("filled_surface.pdf"))
data = open(out("filled_surface.pdf"), "rb").read() if os.path.isfile(out("filled_surface.pdf")) else b""
check(rc == 0 and data.startswith(b"%PDF"), "--fill-colors surface -o .pdf (%r)" % err.strip())
for extra, expected in ((["--fill-faces", "-o", out("x.png")], "--fill-faces needs -o FILE"),
                        (["--fill-colors", "surface", "-o", out("x.svg")], "needs --fill-faces"),
                        (["--fill-faces", "--fill-colors", "shiny", "-o", out("x.svg")], "not face, surface or toon")):
    rc, _, err = run(part, *extra)
    check(rc == 2 and expected in err, "%s: exit 2 with '%s' (%r)" % (" ".join(extra[:2]), expected, err.strip()))

cli.exit()
