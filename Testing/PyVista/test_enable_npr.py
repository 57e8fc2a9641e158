# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""Tests of vtknpr.pyvista: enable_npr and disable_npr on PyVista plotters, off screen.

    test_enable_npr.py CASE   (CASE: subplots, settings, compose, toggle, screenshot, snippet, all)

Each case fails (exit 1) on a failed check and on any VTK error or warning printed. Exits 77 (a
skipped test) when PyVista is not installed.
"""
import os
import re
import sys
import tempfile
import warnings

try:
    import pyvista as pv
except ImportError:
    print("test_enable_npr: PyVista is not installed for %s: skipped" % sys.executable)
    sys.exit(77)

import numpy as np
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow

import vtknpr  # noqa: F401
from vtknpr.pyvista import SETTINGS, disable_npr, enable_npr, export_drawing, npr_pass

FAILURES = []


def check(condition, message):
    print(("ok:     " if condition else "FAILED: ") + message)
    if not condition:
        FAILURES.append(message)


def plotter(shape=(1, 1), size=(240, 180)):
    p = pv.Plotter(off_screen=True, shape=shape, window_size=list(size))
    p.set_background("white")
    return p


def shot(p, scale=None):
    """Renders and returns the image (rows top down, RGB ints)."""
    p.render()
    return np.array(p.screenshot(return_img=True, scale=scale)).astype(int)


def differing(a, b):
    return float((np.abs(a - b).sum(axis=2) > 30).mean())


def reddish(image):
    """Pixels whose hue is red (eye-dome lighting darkens them, keeping the hue)."""
    r, g, b = image[:, :, 0], image[:, :, 1], image[:, :, 2]
    return int(((r > g + 60) & (r > b + 60)).sum())


def dark(image):
    return int((image.max(axis=2) < 80).sum())


def sphere_plotter(**kwargs):
    p = plotter(**kwargs)
    p.add_mesh(pv.Sphere(theta_resolution=32, phi_resolution=16), color="lightyellow")
    return p


def case_subplots():
    """A style per renderer: the left subplot styled, the right one as PyVista draws it."""
    def build():
        p = plotter(shape=(1, 2), size=(320, 160))
        for column in (0, 1):
            p.subplot(0, column)
            p.add_mesh(pv.Sphere(), color="lightyellow")
        return p
    plain = shot(build())
    p = build()
    p.subplot(0, 0)
    npr = enable_npr(p, "edges")
    styled = shot(p)
    check(npr is npr_pass(p.renderers[0]), "enable_npr returns the pass of the active renderer")
    check(npr_pass(p.renderers[1]) is None, "the other subplot has no style")
    left = differing(plain[:, :160], styled[:, :160])
    right = differing(plain[:, 160:], styled[:, 160:])
    check(left > 0.01, "the styled subplot differs from PyVista's in %.1f %% of its pixels"
          % (100 * left))
    check(right == 0.0, "the other subplot is PyVista's own image (%.2f %% differ)" % (100 * right))
    check(disable_npr(p.renderers[0]) and not disable_npr(p.renderers[0]),
          "disable_npr says whether a style was on")
    check(differing(plain, shot(p)) == 0.0, "after disable_npr the image is PyVista's own")
    p.close()


def case_settings():
    """Settings in PyVista's names and colours; bad ones refused with a clear error."""
    p = sphere_plotter()
    npr = enable_npr(p, "edges", line_color="red", line_width=3)
    red = reddish(shot(p))
    check(red > 150, "line_color='red': %d red pixels" % red)
    enable_npr(p, "toon", bands=3, specular=False)
    check(npr.GetToonPass().GetNumberOfBands() == 3 and npr.GetStyleName(npr.GetStyle()) ==
          "toon", "a second call changes the style and settings of the same pass")
    enable_npr(p, "sketch", paper_color="#ff8000", uncertainty=2.5)
    paper = npr.GetSketchPass().GetPaperColor()
    check(np.allclose(paper, (1.0, 128 / 255, 0.0), atol=0.01),
          "paper_color='#ff8000' gives %s" % (paper,))
    edges = enable_npr(p, "edges", suggestive_contours=True, suggestive_threshold=0.05,
                       suggestive_color="navy", smooth_silhouettes=True, face_creases=True).GetEdgePass()
    check(edges.GetSuggestiveContours() and abs(edges.GetSuggestiveContourThreshold() - 0.05) < 1e-12
          and np.allclose(edges.GetSuggestiveContourColor(), (0, 0, 128 / 255), atol=0.01)
          and edges.GetSmoothSilhouettes() and edges.GetFaceCreases(),
          "the suggestive, smooth-silhouette and face-crease settings reach the edge pass")
    check(len(SETTINGS) >= 20, "%d settings documented" % len(SETTINGS))
    for args, kwargs, error in (((p, "cartoon"), {}, ValueError),
                                ((p, "edges"), {"line_widht": 2}, TypeError),
                                (("not a plotter",), {}, TypeError)):
        try:
            enable_npr(*args, **kwargs)
            check(False, "enable_npr%r %r raised nothing" % (args, kwargs))
        except error as raised:
            check(True, "refused with %s: %s" % (error.__name__, raised))
    p.close()


def case_compose():
    """PyVista's own passes over a style: EDL and SSAA compose; SSAO and shadows are refused."""
    p = sphere_plotter()
    enable_npr(p, "edges", line_color="red", line_width=2)
    lines = reddish(shot(p))
    p.enable_eye_dome_lighting()
    styled_edl = shot(p)
    p.close()
    p = sphere_plotter()
    p.enable_eye_dome_lighting()
    plain_edl = shot(p)
    p.close()
    # EDL darkens the pixels beside a depth step, so most of the silhouette's red goes dark.
    check(differing(plain_edl, styled_edl) > 0.01 and reddish(styled_edl) > 0.1 * lines,
          "eye-dome lighting over the style: %d of %d red line pixels, %.1f %% of the pixels "
          "differ from EDL alone" % (reddish(styled_edl), lines,
                                     100 * differing(plain_edl, styled_edl)))
    p = sphere_plotter()
    enable_npr(p, "edges", line_color="red", line_width=2)
    p.enable_anti_aliasing("ssaa")
    with_ssaa = reddish(shot(p))
    check(with_ssaa > 0.3 * lines, "SSAA over the style: %d of %d red line pixels"
          % (with_ssaa, lines))
    p.disable_anti_aliasing()
    p.enable_anti_aliasing("fxaa")
    with_fxaa = reddish(shot(p))
    check(with_fxaa > 0.3 * lines, "FXAA with the style: %d of %d red line pixels"
          % (with_fxaa, lines))
    p.close()

    # Blur processes the styled image: it differs from the blur alone. (Depth of field is not
    # tested: off screen on llvmpipe PyVista's depth-of-field image is black, with or without a
    # style.)
    for name, turn_on in (("blur", lambda p: p.add_blurring()),):
        images = []
        for style in (None, "edges"):
            p = sphere_plotter()
            if style:
                enable_npr(p, style, line_color="red", line_width=2)
            turn_on(p)
            images.append(shot(p))
            p.close()
        check(differing(images[0], images[1]) > 0.01,
              "%s over the style: %.1f %% of the pixels differ from %s alone"
              % (name, 100 * differing(images[0], images[1]), name))

    p = sphere_plotter()
    enable_npr(p, "edges")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        p.enable_ssao()
        image = shot(p)
    said = [str(w.message) for w in caught if "cannot be combined" in str(w.message)]
    check(len(said) == 1, "SSAO enabled after the style: one warning (%s)" % said)
    check(npr_pass(p) is None and image.shape[0] == 180,
          "the style is off and the frame completes")
    p.close()
    p = sphere_plotter()
    p.enable_shadows()
    try:
        enable_npr(p, "edges")
        check(False, "enable_npr with shadows on raised nothing")
    except RuntimeError as raised:
        check("shadows" in str(raised), "enable_npr with shadows on refused: %s" % raised)
    p.close()


def resident_kb():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0


def case_toggle():
    """The style on and off 100 times in one plotter: memory stays flat, nothing reported."""
    p = sphere_plotter()
    plain = shot(p)
    after = {}
    for cycle in range(1, 101):
        enable_npr(p, ("edges", "toon+edges", "sketch", "inked")[cycle % 4])
        shot(p)
        disable_npr(p)
        image = shot(p)
        if cycle in (10, 100):
            after[cycle] = resident_kb()
    growth = after[100] - after[10]
    check(differing(plain, image) == 0.0, "after 100 cycles the image is PyVista's own")
    check(growth < 16 * 1024, "resident memory grew %d KiB from cycle 10 to 100 (%.1f KiB per "
          "cycle; bound 16 MiB)" % (growth, growth / 90.0))
    p.close()


def case_screenshot():
    """screenshot(scale=2) draws the lines twice as wide: about 4 times the dark pixels."""
    p = sphere_plotter()
    enable_npr(p, "edges", line_width=2)
    one = dark(shot(p))
    two = dark(shot(p, scale=2))
    check(one > 100 and 3.0 < two / one < 5.0,
          "scale=2: %d dark pixels, %d at scale 1 (ratio %.2f, expected near 4)"
          % (two, one, two / max(one, 1)))
    p.close()
    # save_graphic (GL2PS) rasterises the 3D props into the file: the style is in that image. (With
    # Debian's GL2PS, built without PNG, an SVG gets no raster at all, styled or not.)
    written = {}
    for style in (None, "toon"):
        p = sphere_plotter()
        if style:
            enable_npr(p, style, bands=2)
        p.render()
        path = os.path.join(tempfile.mkdtemp(), "graphic.pdf")
        p.save_graphic(path)
        with open(path, "rb") as graphic:
            written[style] = graphic.read()
        p.close()
    check(len(written["toon"]) > 10000 and written["toon"] != written[None],
          "save_graphic to PDF: %d bytes, its raster differs from the unstyled one"
          % len(written["toon"]))
    p.close()


def case_export():
    """export_drawing writes the drawing style's lines as SVG, with fill_faces the faces too, in
    the sphere's own colour with fill_colors="surface"; bad fill_colors is a ValueError; the
    plotter's points, text and scalar bar go into the file too."""
    p = plotter()
    p.add_mesh(pv.Sphere(theta_resolution=32, phi_resolution=16), color="red")
    enable_npr(p, "drawing")
    p.render()
    folder = tempfile.mkdtemp()
    lines = os.path.join(folder, "lines.svg")
    filled = os.path.join(folder, "filled.svg")
    export_drawing(p, lines)
    exporter = export_drawing(p, filled, fill_faces=True, fill_colors="surface")
    text = open(filled).read()
    red = re.compile(r'fill(?::|=")rgb\(100%, ?0%, ?0%\)')  # Cairo 1.16 and 1.18
    check(exporter.GetNumberOfFilledFaces() > 100 and red.search(text)
          and not red.search(open(lines).read()),
          "fill_faces: %d red faces in the SVG" % exporter.GetNumberOfFilledFaces())
    try:
        export_drawing(p, filled, fill_faces=True, fill_colors="shiny")
        check(False, "fill_colors='shiny' was accepted")
    except ValueError:
        pass
    # A mesh coloured by scalars (its scalar bar), a text and three points beside the sphere: the
    # points as vector discs, the text as outlines, the scalar bar as the file's one image.
    p.add_mesh(pv.Sphere(center=(0.0, 1.2, 0.0)).elevation(), scalars="Elevation")
    p.add_text("vtkNPR", position=(10, 10), font_size=12)
    p.add_mesh(pv.PolyData([[1.2, 0.0, 0.0], [1.2, 0.4, 0.0], [1.2, -0.4, 0.0]]), color="blue",
               point_size=8, render_points_as_spheres=True)
    p.reset_camera()
    p.render()
    annotated = os.path.join(folder, "annotated.svg")
    exporter = export_drawing(p, annotated, fill_faces=True, fill_colors="surface")
    text = open(annotated).read()
    check(exporter.GetNumberOfStrokes(7) == 3 and exporter.GetNumberOfTexts() == 1
          and exporter.GetNumberOfImagedOverlays() >= 1 and text.count("<image") == 1,
          "annotated: %d points, %d texts, %d 2D props in the image, %d images"
          % (exporter.GetNumberOfStrokes(7), exporter.GetNumberOfTexts(),
             exporter.GetNumberOfImagedOverlays(), text.count("<image")))
    p.close()


def python_blocks(page, only_pyvista):
    """The page's python blocks in order (later ones continue earlier ones); with only_pyvista,
    those that import PyVista."""
    text = open(page).read()
    code = [block.split("```", 1)[0] for block in text.split("```python\n")[1:]]
    uses = re.compile(r"^\s*(import pyvista|from pyvista)\b", re.M)
    return [block for block in code if not only_pyvista or uses.search(block)]


def case_snippet():
    """Every python block of Documentation/pyvista.md and the PyVista block of README.md run,
    each page's in one namespace from a folder whose Testing/ is the repository's, and write the
    pictures they name."""
    repository = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
    for page, only_pyvista in (("Documentation/pyvista.md", False), ("README.md", True)):
        blocks = python_blocks(os.path.join(repository, page), only_pyvista)
        folder = tempfile.mkdtemp()
        os.symlink(os.path.join(repository, "Testing"), os.path.join(folder, "Testing"))
        cwd = os.getcwd()
        os.chdir(folder)
        try:
            namespace = {}
            for block in blocks:
                exec(compile(block, page, "exec"), namespace)
        finally:
            os.chdir(cwd)
        named = set(re.findall(r"[\"']([\w.-]+\.(?:png|svg))[\"']", "".join(blocks)))
        written = {name for name in named if os.path.isfile(os.path.join(folder, name))
                   and os.path.getsize(os.path.join(folder, name)) > 1000}
        check(blocks and named and written == named,
              "%s: %d blocks wrote %s of %s" % (page, len(blocks), sorted(written), sorted(named)))


CASES = {"subplots": case_subplots, "settings": case_settings, "compose": case_compose,
         "toggle": case_toggle, "screenshot": case_screenshot, "snippet": case_snippet,
         "export": case_export}


def main():
    names = sys.argv[1:] or ["all"]
    if names == ["all"]:
        names = list(CASES)
    pv.OFF_SCREEN = True
    for name in names:
        messages = vtkStringOutputWindow()
        vtkOutputWindow.SetInstance(messages)
        print("---- %s" % name)
        CASES[name]()
        printed = messages.GetOutput().strip()
        check(not printed, "VTK printed nothing%s" % ((": " + printed[:400]) if printed else ""))
    vtkOutputWindow.SetInstance(None)
    print("%s (%d failed checks)" % ("FAILED" if FAILURES else "PASSED", len(FAILURES)))
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
