// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The 2D props over a renderer's scene (text, scalar bars, legends, logos) as a vector drawing
// paints them over its lines (vtkNPRDrawingExporter):
// - each text (a vtkTextActor, or a vtkActor2D whose mapper is a vtkTextMapper) as its glyph
//   outlines from VTK's vtkTextRenderer (StringToPath: the font, size, justification and
//   rotation the render has), at its actor's position, in its text colour and opacity, over
//   its background box and under its frame where its text property has them;
// - every other visible 2D prop (vtkScalarBarActor, vtkCornerAnnotation, a logo), and a text
//   VTK gives no outlines for, as one image of its pixels alone: the window rendered with only
//   those props, over black and over white, which gives each pixel's colour and coverage, so
//   the scene's vector faces and lines stay vector around and under it.
// Private to NPR::Passes.
#ifndef vtkNPROverlays_h
#define vtkNPROverlays_h

#include "vtkSmartPointer.h" // for the grabbed image
#include "vtkType.h"         // for vtkIdType

#include <cstdint> // for the image's pixels
#include <string>  // for the error message
#include <vector>  // for the texts

typedef struct _cairo cairo_t;
class vtkImageData;
class vtkRenderer;

// The renderer's part of its window, rendered again (RGB, row 0 at the bottom).
vtkSmartPointer<vtkImageData> vtkNPRGrabViewport(vtkRenderer* renderer);

class vtkNPROverlays
{
public:
  // Collects the renderer's visible 2D props as texts and the image of the others. The image
  // needs the window rendered twice with only those props (the renderer's other props, its
  // background, gradient, texture and pass, and the window's other renderers, switched off for
  // it); all are restored and the window rendered once more, so that it shows its picture again.
  void Capture(vtkRenderer* renderer);

  // Paints the texts, then the image, onto `cr`, whose user space is the drawing's (one unit a
  // pixel, width x height pixels, row 0 at the top; the renderer's pixels are scaled to it).
  // `paths` is set to the Cairo paths painted for the texts (each text's glyphs one, its
  // background box and its frame one each). False, with `error` set, when Cairo fails.
  bool Paint(cairo_t* cr, int width, int height, vtkIdType& paths, std::string& error) const;

  vtkIdType GetNumberOfTexts() const { return static_cast<vtkIdType>(this->Texts.size()); }
  // The 2D props drawn in the image (0 when there is none).
  vtkIdType GetNumberOfImageProps() const { return this->ImageProps; }

private:
  struct Text
  {
    std::vector<double> Points; // x, y in the renderer's pixels, row 0 at the bottom
    std::vector<int> Codes;     // vtkPath's control point types
    double Color[4];            // RGBA
    double Box[8];              // the metrics' corners (background and frame), x, y each
    double BackgroundColor[4];  // RGBA; alpha 0: no background
    double FrameColor[3];
    int FrameWidth = 0; // 0: no frame
  };
  struct Image
  {
    int Left = 0, Top = 0, Width = 0, Height = 0; // in the image, row 0 at the top
    std::vector<std::uint32_t> Pixels;            // Cairo's premultiplied ARGB, top row first
  };

  // A text prop's outlines; false when it is not a text VTK gives outlines for.
  bool AddText(vtkRenderer* renderer, class vtkProp* prop);
  void CaptureImage(vtkRenderer* renderer, const std::vector<class vtkProp*>& props);
  static void PaintText(cairo_t* cr, const Text& text, double height, vtkIdType& paths);

  std::vector<Text> Texts;
  Image Picture;
  int RendererSize[2] = { 0, 0 };
  vtkIdType ImageProps = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkNPROverlays.h
