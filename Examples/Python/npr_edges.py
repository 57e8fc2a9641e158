"""Line drawing of one model with vtkNPRPass, rendered headless (EGL, no X server) to a PNG.

    PYTHONPATH=build/lib/python3/dist-packages python3 Examples/Python/npr_edges.py \
        Testing/Data/cad_part.vtp -o cad_part.png --line-width 2 --silhouette-color 0.8,0,0

Models: anything vtkNPRModelReader reads (.stl .obj .ply .vtp .vtk .gltf .glb .off).

With --check the script also verifies the result and exits 1 when a check fails (it runs as a
test): the image has line pixels on the object, a second render with nothing changed reuses the
G-buffer, and the shaded style (no lines) has far fewer dark pixels. The checks assume dark lines
(the default black, or a --silhouette-color with every channel below 60/255) on light surfaces.
"""
import argparse
import sys

import vtknpr  # first: it imports the VTK modules it needs by itself
from vtknpr import vtkNPRModelReader, vtkNPRPass, vtkNPRRenderWindowFactory
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL object factory overrides)

DARK = 60  # a pixel is "dark" when its brightest channel is below this (0..255)


def numbers(text, count, kind=float):
    """'a,b,c' (or 'WxH' with sep='x') -> a list of count numbers; argparse reports a ValueError."""
    sep = "x" if kind is int else ","
    values = [kind(part) for part in text.split(sep)]
    if len(values) != count:
        raise ValueError(text)
    return values


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("model", help="model file")
    parser.add_argument("-o", "--output", required=True, help="PNG to write")
    parser.add_argument("--size", type=lambda s: numbers(s, 2, int), default=[800, 600],
                        metavar="WxH", help="image size in pixels (default 800x600)")
    parser.add_argument("--line-width", type=float, default=1.5,
                        help="line width in pixels, 0.5..16 (default 1.5)")
    parser.add_argument("--crease-angle", type=float, default=30.0,
                        help="normal angle in degrees that makes a crease, 1..179 (default 30)")
    parser.add_argument("--silhouette-color", type=lambda s: numbers(s, 3), default=[0, 0, 0],
                        metavar="R,G,B", help="silhouette colour, each part in 0..1 (default 0,0,0)")
    parser.add_argument("--azimuth", type=float, default=30.0, help="camera azimuth (default 30)")
    parser.add_argument("--elevation", type=float, default=30.0, help="camera elevation (default 30)")
    parser.add_argument("--check", action="store_true", help="verify the result; exit 1 on failure")
    return parser.parse_args()


def read_model(file_name):
    """The model's surface, with normals like npr-render computes them when it has none."""
    reader = vtkNPRModelReader()
    reader.SetFileName(file_name)
    reader.Update()
    if reader.GetErrorMessage():
        sys.exit("npr_edges: error: " + reader.GetErrorMessage())
    model = reader.GetOutput()
    if model.GetPointData().GetNormals() or model.GetNumberOfPolys() + model.GetNumberOfStrips() == 0:
        return model
    normals = vtkPolyDataNormals()  # smooth shading that keeps edges sharper than 30 degrees
    normals.SetInputData(model)
    normals.SetFeatureAngle(30.0)
    normals.SplittingOn()
    normals.ConsistencyOff()
    normals.Update()
    return normals.GetOutput()


def grab(window):
    """The window's image (vtkImageData, RGB), from the back buffer as last rendered."""
    grabber = vtkWindowToImageFilter()
    grabber.SetInput(window)
    grabber.ReadFrontBufferOff()
    grabber.ShouldRerenderOff()
    grabber.Update()
    image = vtkImageData()
    image.DeepCopy(grabber.GetOutput())
    return image


def count_dark(image, box):
    """Number of pixels with every channel below DARK inside box = (x0, y0, x1, y1), inclusive."""
    width = image.GetDimensions()[0]
    scalars = image.GetPointData().GetScalars()
    components = scalars.GetNumberOfComponents()
    data = memoryview(scalars).cast("B")
    dark = 0
    for y in range(box[1], box[3] + 1):
        row = y * width
        for x in range(box[0], box[2] + 1):
            i = (row + x) * components
            if data[i] < DARK and data[i + 1] < DARK and data[i + 2] < DARK:
                dark += 1
    return dark


def projected_box(renderer, bounds, width, height):
    """The screen rectangle (x0, y0, x1, y1) covered by the 8 corners of bounds, in the image."""
    xs, ys = [], []
    for x in bounds[0:2]:
        for y in bounds[2:4]:
            for z in bounds[4:6]:
                renderer.SetWorldPoint(x, y, z, 1.0)
                renderer.WorldToDisplay()
                px, py, _ = renderer.GetDisplayPoint()
                xs.append(px)
                ys.append(py)
    clamp = lambda v, top: max(0, min(top, int(v)))  # noqa: E731
    return (clamp(min(xs), width - 1), clamp(min(ys), height - 1),
            clamp(max(xs), width - 1), clamp(max(ys), height - 1))


def main():
    args = parse_arguments()
    model = read_model(args.model)

    mapper = vtkPolyDataMapper()
    mapper.SetInputData(model)
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.85, 0.82, 0.75)
    renderer = vtkRenderer()
    renderer.SetBackground(1.0, 1.0, 1.0)
    renderer.AddActor(actor)

    # The whole line-drawing chain in one pass; its edge pass takes the tuning.
    npr = vtkNPRPass()
    edges = npr.GetEdgePass()
    edges.SetLineWidth(args.line_width)
    edges.SetCreaseAngle(args.crease_angle)
    edges.SetSilhouetteColor(*args.silhouette_color)
    renderer.SetPass(npr)

    window = vtkNPRRenderWindowFactory.CreateRenderWindow()  # NPR_BACKEND, else EGL: headless
    if window is None:
        sys.exit("npr_edges: error: no headless render window (see Documentation/backends.md)")
    window.SetMultiSamples(0)  # the G-buffer is single-sampled; the edge pass anti-aliases lines
    window.SetSize(*args.size)
    window.AddRenderer(renderer)
    renderer.ResetCamera()  # after the window exists: fits the model to its aspect ratio
    camera = renderer.GetActiveCamera()
    camera.Azimuth(args.azimuth)
    camera.Elevation(args.elevation)
    camera.OrthogonalizeViewUp()
    renderer.ResetCameraClippingRange()
    window.Render()

    edge_image = grab(window)
    writer = vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputData(edge_image)
    writer.Write()
    print("wrote %s (%dx%d, %s)" % (args.output, args.size[0], args.size[1],
                                    vtkNPRRenderWindowFactory.GetGLRenderer(window)))
    if not args.check:
        return 0

    failures = []

    def check(ok, text):
        print(("ok      " if ok else "FAILED  ") + text)
        if not ok:
            failures.append(text)

    # 1. Lines on the object. Its outline alone, a closed curve touching all four sides of its
    # screen box (w x h), is at least 2 x sqrt(w^2 + h^2) pixels long; a 1.5 px line has at least
    # one dark pixel per pixel of length along it. Half of that bound allows for anti-aliased
    # diagonal steps and thin lines, and is still far above what a shaded image without lines has
    # on light surfaces.
    box = projected_box(renderer, model.GetBounds(), *args.size)
    diagonal = ((box[2] - box[0]) ** 2 + (box[3] - box[1]) ** 2) ** 0.5
    needed = int(diagonal)  # 0.5 x 2 x diagonal
    edge_dark = count_dark(edge_image, box)
    check(edge_dark > needed, "edges: %d dark pixels in the object's box %s, more than %d"
          % (edge_dark, box, needed))

    # 2. An unchanged scene reuses the G-buffer and the line image.
    gbuffer = npr.GetGBufferPass()
    window.Render()
    check(gbuffer.GetNumberOfGeometryDraws() == 1, "two renders, nothing changed: %d G-buffer "
          "draw(s), expected 1" % gbuffer.GetNumberOfGeometryDraws())
    check(edges.GetNumberOfLineImageUpdates() == 1, "two renders, nothing changed: %d line image "
          "update(s), expected 1" % edges.GetNumberOfLineImageUpdates())
    check(gbuffer.GetWritesNormals(), "the G-buffer holds normals (creases are on)")

    # 3. The shaded style draws no lines: far fewer dark pixels, and no G-buffer.
    draws = gbuffer.GetNumberOfGeometryDraws()
    npr.SetStyleToShaded()
    window.Render()
    shaded_dark = count_dark(grab(window), box)
    check(shaded_dark < 0.5 * edge_dark, "shaded: %d dark pixels, less than half of the %d with "
          "edges" % (shaded_dark, edge_dark))
    check(gbuffer.GetNumberOfGeometryDraws() == draws, "shaded: no G-buffer draw")

    print("%d passed, %d failed" % (6 - len(failures), len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
