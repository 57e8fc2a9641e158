# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkNPR for PyVista: one call turns a style on for a plotter's renderer.

    import pyvista as pv
    from vtknpr.pyvista import enable_npr

    plotter = pv.Plotter(off_screen=True)
    plotter.add_mesh(pv.Sphere())
    enable_npr(plotter, "toon+edges", line_width=2, line_color="navy")
    plotter.screenshot("sphere.png")

The style belongs to one renderer (the plotter's active one, or the renderer given), so each
subplot has its own. It takes the place of the vtkRenderStepsPass in PyVista's own chain of
passes, so PyVista's eye-dome lighting, anti-aliasing (SSAA, FXAA), blur and depth of field are
applied over the styled image. SSAO and shadows draw the scene themselves with their own shaders:
they cannot be combined with a style, and enabling one refuses (RuntimeError) or, when enabled
afterwards, turns the style off with a warning.
"""
import warnings
import weakref

import pyvista
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass

from .vtkNPRPasses import vtkNPRDrawingExporter, vtkNPRPass, vtkNPRSketchPass

__all__ = ["enable_npr", "disable_npr", "npr_pass", "export_drawing", "SETTINGS"]

STYLES = ("shaded", "edges", "toon", "toon+edges", "sketch", "inked", "drawing")

# PyVista-style names of the passes' settings, and what each sets.
SETTINGS = {
    "line_width": "width of every line in pixels at 72 DPI (edges and ink)",
    "line_color": "colour of every line (silhouettes, creases, contours, ink)",
    "max_line_fraction": "largest share of an object's width one of its lines may take, 0..1"
                         " (0: no limit)",
    "surface_line_shade": "lines over a surface in its own colour times this, 0..1 (0: the lines'"
                          " own colours)",
    "silhouette_color": "colour of the silhouette lines",
    "silhouette_width": "width of the silhouettes in pixels at 72 DPI (0: line_width)",
    "crease_width": "width of the creases in pixels at 72 DPI (0: line_width)",
    "depth_falloff": "whether line widths fall off with depth, near_line_scale to far_line_scale"
                     " (bool)",
    "near_line_scale": "width scale of the nearest lines with depth_falloff, 0.1..4",
    "far_line_scale": "width scale of the farthest lines with depth_falloff, 0.1..4",
    "contour_width": "width of the object contours in pixels at 72 DPI (0: line_width)",
    "suggestive_width": "width of the suggestive contours in pixels at 72 DPI (0: line_width)",
    "crease_color": "colour of the crease lines",
    "contour_color": "colour of the object contour lines",
    "silhouettes": "whether depth discontinuities are drawn (bool)",
    "creases": "whether normal discontinuities are drawn (bool)",
    "contours": "whether object outlines are drawn (bool)",
    "suggestive_contours": "whether suggestive contours are drawn (bool)",
    "suggestive_threshold": "strength a suggestive contour needs, 0.0001..1",
    "suggestive_color": "colour of the suggestive contours",
    "smooth_silhouettes": "silhouettes also where the shading normal turns away (bool)",
    "face_creases": "creases between the faces' own normals, for CAD meshes (bool)",
    "crease_angle": "angle in degrees between normals above which a crease is drawn",
    "line_anti_aliasing": "whether lines are anti-aliased (bool)",
    "bands": "number of toon bands",
    "specular": "whether toon shading keeps a specular band (bool)",
    "sketch_toon_shading": "whether sketches are filled with toon bands instead of flat colours",
    "uncertainty": "how far sketch strokes wander, in pixels",
    "noise_frequency": "how quickly sketch strokes wander",
    "noise_seed": "seed of the sketch noise (int)",
    "noise_space": "'surface' (the wobble stays on the surfaces when the camera moves) or 'screen'",
    "paper": "whether sketches are drawn on paper (bool)",
    "paper_color": "colour of the sketch's paper",
    "hidden_lines": "whether the drawing shows its hidden lines, dashed (bool)",
    "face_color": "colour of the drawing's faces",
    "taper": "length in pixels at 72 DPI over which the drawing's strokes grow from their ends"
             " (0: none)",
    "curvature_width": "the drawing's strokes up to 1 + this times as wide where they bend, 0..4",
}

# The PyVista passes that draw the scene with their own shaders.
_INCOMPATIBLE = {"vtkSSAOPass": "SSAO (enable_ssao)"}

_BINDINGS = weakref.WeakKeyDictionary()  # renderer -> _Binding


def _color(value):
    return pyvista.Color(value).float_rgb


def _noise_space(value):
    spaces = {"screen": vtkNPRSketchPass.SCREEN, "surface": vtkNPRSketchPass.SURFACE}
    if value not in spaces:
        raise ValueError("noise_space must be 'surface' or 'screen', got %r" % (value,))
    return spaces[value]


# Each setting: how its value is read, and the (pass, setter) pairs it goes to.
_SETTERS = {
    "line_width": (float, [("edges", "SetLineWidth"), ("ink", "SetLineWidth")]),
    "max_line_fraction": (float, [("edges", "SetMaximumLineFraction")]),
    "surface_line_shade": (float, [("edges", "SetSurfaceLineShade")]),
    "line_color": (_color, [("edges", "SetSilhouetteColor"), ("edges", "SetCreaseColor"),
                            ("edges", "SetContourColor"), ("edges", "SetSuggestiveContourColor"),
                            ("ink", "SetInkColor")]),
    "silhouette_color": (_color, [("edges", "SetSilhouetteColor")]),
    "silhouette_width": (float, [("edges", "SetSilhouetteLineWidth")]),
    "crease_width": (float, [("edges", "SetCreaseLineWidth")]),
    "depth_falloff": (bool, [("edges", "SetDepthFalloff")]),
    "near_line_scale": (float, [("edges", "SetNearLineScale")]),
    "far_line_scale": (float, [("edges", "SetFarLineScale")]),
    "contour_width": (float, [("edges", "SetContourLineWidth")]),
    "suggestive_width": (float, [("edges", "SetSuggestiveContourLineWidth")]),
    "crease_color": (_color, [("edges", "SetCreaseColor")]),
    "contour_color": (_color, [("edges", "SetContourColor")]),
    "suggestive_color": (_color, [("edges", "SetSuggestiveContourColor")]),
    "silhouettes": (bool, [("edges", "SetSilhouettes")]),
    "creases": (bool, [("edges", "SetCreases")]),
    "contours": (bool, [("edges", "SetContours")]),
    "suggestive_contours": (bool, [("edges", "SetSuggestiveContours")]),
    "suggestive_threshold": (float, [("edges", "SetSuggestiveContourThreshold")]),
    "smooth_silhouettes": (bool, [("edges", "SetSmoothSilhouettes")]),
    "face_creases": (bool, [("edges", "SetFaceCreases")]),
    "crease_angle": (float, [("edges", "SetCreaseAngle")]),
    "line_anti_aliasing": (bool, [("edges", "SetAntiAliasing")]),
    "bands": (int, [("toon", "SetNumberOfBands")]),
    "specular": (bool, [("toon", "SetSpecular")]),
    "sketch_toon_shading": (bool, [("npr", "SetSketchToonShading")]),
    "uncertainty": (float, [("sketch", "SetUncertainty")]),
    "noise_frequency": (float, [("sketch", "SetNoiseFrequency")]),
    "noise_seed": (int, [("sketch", "SetNoiseSeed")]),
    "noise_space": (_noise_space, [("sketch", "SetNoiseSpace")]),
    "paper": (bool, [("sketch", "SetPaper")]),
    "paper_color": (_color, [("sketch", "SetPaperColor")]),
    "hidden_lines": (bool, [("npr", "SetHiddenLines")]),
    "face_color": (_color, [("drawing", "SetFaceColor")]),
    "taper": (float, [("drawing", "SetTaperLength")]),
    "curvature_width": (float, [("drawing", "SetCurvatureWidth")]),
}


def _apply(npr, settings):
    unknown = sorted(set(settings) - set(SETTINGS))
    if unknown:
        raise TypeError("enable_npr: unknown setting(s) %s; known: %s"
                        % (", ".join(unknown), ", ".join(sorted(SETTINGS))))
    passes = {"npr": npr, "edges": npr.GetEdgePass(), "toon": npr.GetToonPass(),
              "sketch": npr.GetSketchPass(), "ink": npr.GetInkPass(),
              "drawing": npr.GetDrawingPass()}
    for name, value in settings.items():
        read, targets = _SETTERS[name]
        value = read(value)
        for which, setter in targets:
            getattr(passes[which], setter)(*(value if isinstance(value, tuple) else (value,)))


def _renderer_of(target):
    """The vtkRenderer of a plotter (its active renderer) or the renderer itself."""
    renderer = getattr(target, "renderer", target)
    if not hasattr(renderer, "SetPass"):
        raise TypeError("enable_npr: expected a pyvista.Plotter or a renderer, got %r"
                        % type(target).__name__)
    return renderer


def _pyvista_passes(renderer):
    """PyVista's pass manager of the renderer (pyvista.Renderer), or None for a plain one."""
    return getattr(renderer, "_render_passes", None)


def _incompatible_passes(passes):
    """The PyVista passes turned on in `passes` that cannot be combined with a style."""
    clash = [label for name, label in _INCOMPATIBLE.items() if name in passes._passes]
    if passes._shadow_map_pass is not None:
        clash.append("shadows (enable_shadows)")
    return clash


class _Binding:
    """Keeps a vtkNPRPass in a renderer's chain of passes whatever PyVista does to it."""

    def __init__(self, renderer, npr):
        # Weak: the renderer owns the observer that owns this binding.
        self._renderer = weakref.ref(renderer)
        self.npr = npr
        self.observer = renderer.AddObserver("StartEvent", self._keep_in_chain)
        self._keep_in_chain()

    @property
    def renderer(self):
        return self._renderer()

    def _collection(self):
        passes = _pyvista_passes(self.renderer)
        return None if passes is None else passes._pass_collection

    def _keep_in_chain(self, *unused):
        passes = _pyvista_passes(self.renderer)
        if passes is None:  # a plain vtkRenderer
            if self.renderer.GetPass() is not self.npr:
                self.renderer.SetPass(self.npr)
            return
        clash = _incompatible_passes(passes)
        if clash:
            warnings.warn("vtknpr: %s cannot be combined with the style %r: the style is off "
                          "for this renderer" % (", ".join(clash), self.npr.GetStyleName(
                              self.npr.GetStyle())), RuntimeWarning, stacklevel=2)
            self.release()
            return
        collection = self._collection()
        items = [collection.GetItemAsObject(i) for i in range(collection.GetNumberOfItems())]
        if self.npr not in items:
            for item in items:
                if item.IsA("vtkRenderStepsPass"):
                    collection.ReplaceItem(items.index(item), self.npr)
                    break
            else:
                collection.AddItem(self.npr)
        # With no pass of its own PyVista gives the renderer none, which would drop the style.
        if self.renderer.GetPass() is None:
            self.renderer.SetPass(passes._camera_pass)

    def release(self):
        """Takes the style out of the renderer and frees its graphics resources."""
        self.renderer.RemoveObserver(self.observer)
        _BINDINGS.pop(self.renderer, None)
        passes = _pyvista_passes(self.renderer)
        if passes is None:
            if self.renderer.GetPass() is self.npr:
                self.renderer.SetPass(None)
        else:
            collection = self._collection()
            for i in range(collection.GetNumberOfItems()):
                if collection.GetItemAsObject(i) is self.npr:
                    # Put back what PyVista started from.
                    collection.ReplaceItem(i, vtkRenderStepsPass())
            passes._update_passes()
        window = self.renderer.GetRenderWindow()
        if window is not None:
            self.npr.ReleaseGraphicsResources(window)


def enable_npr(target, style="edges", **settings):
    """Draws a plotter's active renderer (or the renderer given) in an NPR style.

    Parameters
    ----------
    target : pyvista.Plotter or pyvista.Renderer or vtkRenderer
        With a plotter, its active renderer (select a subplot with ``plotter.subplot``).
    style : str
        One of "shaded", "edges", "toon", "toon+edges", "sketch", "inked".
    **settings
        The names in ``vtknpr.pyvista.SETTINGS``; colours as anything ``pyvista.Color`` takes.

    Returns
    -------
    vtkNPRPass
        The pass, for further tuning. Calling again on the same renderer changes its style and
        settings.
    """
    if style not in STYLES:
        raise ValueError("enable_npr: unknown style %r; one of %s" % (style, ", ".join(STYLES)))
    renderer = _renderer_of(target)
    passes = _pyvista_passes(renderer)
    if passes is not None:
        clash = _incompatible_passes(passes)
        if clash:
            raise RuntimeError("enable_npr: %s cannot be combined with an NPR style; disable it "
                               "first" % ", ".join(clash))
    binding = _BINDINGS.get(renderer)
    npr = binding.npr if binding is not None else vtkNPRPass()
    _apply(npr, settings)
    npr.SetStyle(vtkNPRPass.GetStyleFromName(style))
    if binding is None:
        _BINDINGS[renderer] = _Binding(renderer, npr)
    return npr


def disable_npr(target):
    """Draws the renderer as PyVista does again, and frees the style's graphics resources.

    Returns whether a style was on.
    """
    binding = _BINDINGS.get(_renderer_of(target))
    if binding is None:
        return False
    binding.release()
    return True


def npr_pass(target):
    """The vtkNPRPass of the renderer, or None when no style is on."""
    binding = _BINDINGS.get(_renderer_of(target))
    return None if binding is None else binding.npr


_FILL_COLORS = {"face": vtkNPRDrawingExporter.FACE_COLOR,
                "surface": vtkNPRDrawingExporter.SURFACE_COLORS,
                "toon": vtkNPRDrawingExporter.TOON_BANDS}


def export_drawing(target, filename, fill_faces=False, fill_colors="face"):
    """Writes the renderer's lines as a vector drawing (vtkNPRDrawingExporter): .svg, .pdf, .ps
    or .eps, in the renderer's style (over its image unless the style is "drawing").

    Parameters
    ----------
    target : pyvista.Plotter or pyvista.Renderer or vtkRenderer
        With a plotter, its active renderer; render it first.
    filename : str
        The file; its extension gives the format.
    fill_faces : bool
        Also write the visible faces as filled regions under the lines, back to front (in place
        of the image), so the file shows the faces as the render does.
    fill_colors : str
        "face" (the drawing style's face colour), "surface" (each mesh's own colour or scalar
        colours, flat and unlit) or "toon" (those colours in the toon bands of the lights).

    Raises ValueError for an unknown fill_colors and RuntimeError when the file cannot be written.
    """
    if fill_colors not in _FILL_COLORS:
        raise ValueError("export_drawing: fill_colors %r is not 'face', 'surface' or 'toon'"
                         % (fill_colors,))
    exporter = vtkNPRDrawingExporter()
    exporter.SetRenderer(_renderer_of(target))
    # PyVista's chain of passes holds the style's pass: the exporter is given its parts, and in
    # the drawing style, or with the faces filled, no image is embedded under the lines.
    npr = npr_pass(target)
    drawing = npr is not None and npr.GetStyle() == vtkNPRPass.DRAWING
    if npr is not None:
        exporter.SetDrawingPass(npr.GetDrawingPass())
        exporter.SetEdgePass(npr.GetEdgePass())
    exporter.SetEmbedImage(0 if drawing or fill_faces else -1)
    exporter.SetFileName(str(filename))
    exporter.SetFillFaces(bool(fill_faces))
    exporter.SetFillColors(_FILL_COLORS[fill_colors])
    if not exporter.Write():
        raise RuntimeError("export_drawing: " + exporter.GetErrorMessage())
    return exporter
