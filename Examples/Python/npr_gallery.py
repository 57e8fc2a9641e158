# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""Every vtkNPRPass style side by side, labelled, on three subjects: Documentation/gallery.md.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/npr_gallery.py \\
        --out Documentation/images/gallery        # or: cmake --build build -t gallery

Subjects: a CAD part (Testing/Data/cad_part.vtp), a scan (the Stanford bunny, bunny.ply) and a
scientific scene (npr_scientific_scene.isosurface_scene: an isosurface in its outline box, the
data colour-mapped on the box's back face, a scalar bar and a title). Each is one headless window
with one viewport per style, all on one camera, each labelled with its style's name by a
vtkTextActor that VTK draws over the style. The models look as npr-render draws them (its colour,
highlight and normals).

Writes gallery_cad.png, gallery_scan.png, gallery_science.png (a grid of --columns panels of
--size, the last cell naming the subject) and styles.png (the CAD part in one row of --strip-size
panels, for the README).
"""
import argparse
import os
import sys

import vtknpr  # noqa: F401  (first: it imports the VTK modules it needs by itself)
from vtknpr import vtkNPRModelReader, vtkNPRPass, vtkNPRRenderWindowFactory, vtkNPRShadingNormals
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkTextActor
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
import vtkmodules.vtkRenderingFreeType  # noqa: F401  (the labels' text)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL object factory overrides)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from npr_scientific_scene import isosurface_scene  # noqa: E402  (the scene is built once, there)

STYLES = ["shaded", "edges", "toon", "toon+edges", "sketch", "inked", "drawing"]
# npr-render's look of a model (Examples/Common/nprModel.cxx, nprApplyModelLook): the first colour.
MODEL_COLOR = (0.85, 0.82, 0.75)


def size(text):
    """'WxH' -> (W, H)"""
    width, height = (int(part) for part in text.split("x"))
    if width < 16 or height < 16:
        raise ValueError(text)
    return width, height


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", required=True, help="folder to write the PNGs into")
    parser.add_argument("--data", default=os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                       "..", "..", "Testing", "Data"),
                        help="folder of cad_part.vtp and bunny.ply (default Testing/Data)")
    parser.add_argument("--size", type=size, default=(400, 300), metavar="WxH",
                        help="one panel of the subjects' grids (default 400x300)")
    parser.add_argument("--strip-size", type=size, default=(200, 170), metavar="WxH",
                        help="one panel of styles.png (default 200x170: 1400 px wide)")
    parser.add_argument("--columns", type=int, default=4, help="panels a row (default 4)")
    return parser.parse_args()


def model_scene(file_name, azimuth, elevation):
    """A renderer factory for a model as npr-render shows it, turned as render-examples does."""
    reader = vtkNPRModelReader()
    reader.SetFileName(file_name)
    normals = vtkNPRShadingNormals()  # npr-render's normals: creases kept sharp
    normals.SetInputConnection(reader.GetOutputPort())
    normals.Update()
    if reader.GetErrorMessage():
        sys.exit("npr_gallery: error: " + reader.GetErrorMessage())

    def scene():
        actor = vtkActor()
        actor.SetMapper(vtkPolyDataMapper())
        actor.GetMapper().SetInputData(normals.GetOutput())
        actor.GetMapper().ScalarVisibilityOff()
        actor.GetProperty().SetColor(*MODEL_COLOR)
        actor.GetProperty().SetSpecular(0.2)
        actor.GetProperty().SetSpecularPower(30.0)
        renderer = vtkRenderer()
        renderer.SetBackground(1.0, 1.0, 1.0)
        renderer.AddActor(actor)
        renderer.ResetCamera()
        renderer.GetActiveCamera().Azimuth(azimuth)
        renderer.GetActiveCamera().Elevation(elevation)
        renderer.GetActiveCamera().OrthogonalizeViewUp()
        renderer.ResetCamera()
        renderer.GetActiveCamera().Zoom(1.1)  # ResetCamera frames the bounding sphere: loose
        return renderer
    return scene


def add_text(renderer, text, font_size, x, y, centred):
    """Black text on an opaque white box at (x, y) of the viewport: readable over any style,
    since VTK draws it after the style's effect."""
    actor = vtkTextActor()
    actor.SetInput(text)
    actor.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
    actor.SetPosition(x, y)
    prop = actor.GetTextProperty()
    prop.SetFontSize(font_size)
    prop.SetColor(0.0, 0.0, 0.0)
    prop.SetBackgroundColor(1.0, 1.0, 1.0)
    prop.SetBackgroundOpacity(1.0)
    if centred:
        prop.SetJustificationToCentered()
        prop.SetVerticalJustificationToCentered()
    else:
        prop.SetBold(True)
        prop.SetVerticalJustificationToTop()
    renderer.AddViewProp(actor)


def viewport(index, columns, rows):
    """The index-th cell of the grid, row by row from the top left."""
    column, row = index % columns, index // columns
    return (column / columns, 1.0 - (row + 1) / rows, (column + 1) / columns, 1.0 - row / rows)


def render_styles(scene, caption, panel, columns, file_name):
    """One window, one viewport a style (the scene built anew for each, on the first one's
    camera), the caption in the cell after the last if the grid has one; written to file_name."""
    rows = -(-len(STYLES) // columns)
    window = vtkNPRRenderWindowFactory.CreateRenderWindow()
    if window is None:
        sys.exit("npr_gallery: error: no headless render window")
    window.SetMultiSamples(0)
    window.SetSize(panel[0] * columns, panel[1] * rows)
    font_size = max(10, panel[1] // 13)
    renderers = []
    for index, style in enumerate(STYLES):
        renderer = scene()
        if renderers:
            renderer.SetActiveCamera(renderers[0].GetActiveCamera())
        npr = vtkNPRPass()
        npr.SetStyle(vtkNPRPass.GetStyleFromName(style))
        renderer.SetPass(npr)
        renderer.SetViewport(*viewport(index, columns, rows))
        add_text(renderer, style, font_size, 0.02, 0.98, centred=False)  # the top left corner
        window.AddRenderer(renderer)
        renderers.append(renderer)
    if rows * columns > len(STYLES):
        blank = vtkRenderer()
        blank.SetBackground(1.0, 1.0, 1.0)
        blank.SetViewport(*viewport(len(STYLES), columns, rows))
        add_text(blank, caption, font_size, 0.5, 0.5, centred=True)
        window.AddRenderer(blank)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.ShouldRerenderOff()  # the frame just rendered: the drawing's lines are not cheap
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetCompressionLevel(9)
    writer.SetFileName(file_name)
    writer.SetInputData(grab.GetOutput())
    writer.Write()
    for renderer in renderers:
        renderer.GetPass().ReleaseGraphicsResources(window)
        renderer.SetPass(None)
    window.Finalize()
    print("npr_gallery: wrote %s (%d styles, %dx%d)"
          % (file_name, len(STYLES), window.GetSize()[0], window.GetSize()[1]))


def main():
    args = parse_arguments()
    os.makedirs(args.out, exist_ok=True)
    cad = model_scene(os.path.join(args.data, "cad_part.vtp"), 30, 30)
    scan = model_scene(os.path.join(args.data, "bunny.ply"), 20, 10)
    for name, scene, caption in (("cad", cad, "CAD part\n(cad_part.vtp)"),
                                 ("scan", scan, "scan\n(bunny.ply)"),
                                 ("science", lambda: isosurface_scene(with_data=True),
                                  "scientific scene\n(VTK's wavelet source)")):
        render_styles(scene, caption, args.size, args.columns,
                      os.path.join(args.out, "gallery_%s.png" % name))
    render_styles(cad, "", args.strip_size, len(STYLES), os.path.join(args.out, "styles.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
