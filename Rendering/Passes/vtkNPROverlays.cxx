// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPROverlays.h"

#include "vtkActor2D.h"
#include "vtkCoordinate.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNPRVectorFile.h"
#include "vtkNew.h"
#include "vtkPath.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkProp3D.h"
#include "vtkPropCollection.h"
#include "vtkRenderPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkSmartPointer.h"
#include "vtkTextActor.h"
#include "vtkTextMapper.h"
#include "vtkTextProperty.h"
#include "vtkTextRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <set>

vtkSmartPointer<vtkImageData> vtkNPRGrabViewport(vtkRenderer* renderer)
{
  // Rendered without a swap, so that the back buffer keeps the frame (and a window on screen
  // keeps showing its own picture), then read. Not through vtkWindowToImageFilter: it crashes on
  // PyVista's windows (VTK 9.3 and 9.6, even without rendering again).
  vtkRenderWindow* window = renderer->GetRenderWindow();
  const vtkTypeBool swap = window->GetSwapBuffers();
  window->SwapBuffersOff();
  window->Render();
  window->SetSwapBuffers(swap);
  const int* origin = renderer->GetOrigin();
  const int* size = renderer->GetSize();
  const int x0 = origin[0], y0 = origin[1], width = size[0], height = size[1];
  vtkNew<vtkUnsignedCharArray> pixels;
  auto image = vtkSmartPointer<vtkImageData>::New();
  if (width <= 0 || height <= 0 ||
    !window->GetPixelData(x0, y0, x0 + width - 1, y0 + height - 1, 0, pixels, 0) ||
    pixels->GetNumberOfTuples() != static_cast<vtkIdType>(width) * height)
  {
    return image; // empty: nothing to embed
  }
  image->SetDimensions(width, height, 1);
  image->GetPointData()->SetScalars(pixels);
  return image;
}

namespace
{
// What the image of the 2D props switches off, put back as it was when it goes out of scope.
class OverlaysOnly
{
public:
  OverlaysOnly(vtkRenderer* renderer, const std::set<vtkProp*>& shown)
    : Renderer(renderer)
    , Pass(renderer->GetPass())
    , Gradient(renderer->GetGradientBackground())
    , Textured(renderer->GetTexturedBackground())
    , Preserve(renderer->GetPreserveColorBuffer())
  {
    renderer->GetBackground(this->Background);
    vtkPropCollection* props = renderer->GetViewProps();
    vtkCollectionSimpleIterator it;
    props->InitTraversal(it);
    while (vtkProp* prop = props->GetNextProp(it))
    {
      this->Visibility.emplace_back(prop, prop->GetVisibility());
      prop->SetVisibility(shown.count(prop) ? prop->GetVisibility() : 0);
    }
    vtkRendererCollection* renderers = renderer->GetRenderWindow()->GetRenderers();
    renderers->InitTraversal(it);
    while (vtkRenderer* other = renderers->GetNextRenderer(it))
    {
      if (other != renderer)
      {
        this->Draw.emplace_back(other, other->GetDraw());
        other->DrawOff();
      }
    }
    renderer->SetPass(nullptr);
    renderer->GradientBackgroundOff();
    renderer->TexturedBackgroundOff();
    renderer->PreserveColorBufferOff();
  }

  ~OverlaysOnly()
  {
    for (const auto& entry : this->Visibility)
    {
      entry.first->SetVisibility(entry.second);
    }
    for (const auto& entry : this->Draw)
    {
      entry.first->SetDraw(entry.second);
    }
    this->Renderer->SetPass(this->Pass);
    this->Renderer->SetGradientBackground(this->Gradient);
    this->Renderer->SetTexturedBackground(this->Textured);
    this->Renderer->SetPreserveColorBuffer(this->Preserve);
    this->Renderer->SetBackground(this->Background);
  }

  OverlaysOnly(const OverlaysOnly&) = delete;
  void operator=(const OverlaysOnly&) = delete;

private:
  vtkRenderer* Renderer;
  vtkSmartPointer<vtkRenderPass> Pass;
  bool Gradient, Textured;
  vtkTypeBool Preserve;
  double Background[3];
  std::vector<std::pair<vtkSmartPointer<vtkProp>, vtkTypeBool>> Visibility;
  std::vector<std::pair<vtkSmartPointer<vtkRenderer>, vtkTypeBool>> Draw;
};

// The text, text property and anchor of a text prop; false for any other prop.
bool TextOf(vtkRenderer* renderer, vtkProp* prop, std::string& input, vtkTextProperty*& property,
  const double*& anchor)
{
  if (auto* textActor = vtkTextActor::SafeDownCast(prop))
  {
    textActor->ComputeScaledFont(renderer); // as its render does: the size it is drawn at
    input = textActor->GetInput() ? textActor->GetInput() : "";
    property = textActor->GetScaledTextProperty();
    anchor = textActor->GetActualPositionCoordinate()->GetComputedDoubleViewportValue(renderer);
    return property != nullptr;
  }
  auto* actor = vtkActor2D::SafeDownCast(prop);
  auto* mapper = actor ? vtkTextMapper::SafeDownCast(actor->GetMapper()) : nullptr;
  if (!mapper)
  {
    return false;
  }
  input = mapper->GetInput() ? mapper->GetInput() : "";
  property = mapper->GetTextProperty();
  anchor = actor->GetActualPositionCoordinate()->GetComputedDoubleViewportValue(renderer);
  return property != nullptr;
}

// The coverage and colour of each pixel from the props drawn over black and over white:
// white - black = 1 - coverage, and over black the colour is already multiplied by it.
std::uint32_t Premultiplied(const unsigned char* black, const unsigned char* white)
{
  int difference = 0;
  for (int c = 0; c < 3; ++c)
  {
    difference += static_cast<int>(white[c]) - static_cast<int>(black[c]);
  }
  const int alpha = std::clamp(255 - (difference + 1) / 3, 0, 255);
  std::uint32_t pixel = static_cast<std::uint32_t>(alpha) << 24;
  for (int c = 0; c < 3; ++c)
  {
    pixel |= static_cast<std::uint32_t>(std::min<int>(black[c], alpha)) << (16 - 8 * c);
  }
  return pixel;
}

// The glyph outlines of a text as a Cairo path: `points` x, y pairs in the renderer's pixels (row 0
// at the bottom), `codes` vtkPath's control point types.
void TraceGlyphs(
  cairo_t* cr, const std::vector<double>& points, const std::vector<int>& codes, double height)
{
  // vtkPath's codes: a conic curve's points come in pairs (control, end), a cubic's in threes.
  const size_t count = codes.size();
  auto x = [&](size_t i) { return points[2 * i]; };
  auto y = [&](size_t i) { return height - points[2 * i + 1]; };
  for (size_t i = 0; i < count; ++i)
  {
    switch (codes[i])
    {
      case vtkPath::MOVE_TO:
        cairo_close_path(cr);
        cairo_move_to(cr, x(i), y(i));
        break;
      case vtkPath::CONIC_CURVE:
        if (i + 1 < count && cairo_has_current_point(cr))
        {
          double x0, y0;
          cairo_get_current_point(cr, &x0, &y0);
          const double cx = x(i), cy = y(i), ex = x(i + 1), ey = y(i + 1);
          cairo_curve_to(cr, x0 + 2.0 / 3.0 * (cx - x0), y0 + 2.0 / 3.0 * (cy - y0),
            ex + 2.0 / 3.0 * (cx - ex), ey + 2.0 / 3.0 * (cy - ey), ex, ey);
          ++i;
        }
        break;
      case vtkPath::CUBIC_CURVE:
        if (i + 2 < count)
        {
          cairo_curve_to(cr, x(i), y(i), x(i + 1), y(i + 1), x(i + 2), y(i + 2));
          i += 2;
        }
        break;
      default: // LINE_TO
        cairo_line_to(cr, x(i), y(i));
        break;
    }
  }
}
}

void vtkNPROverlays::Capture(vtkRenderer* renderer)
{
  this->Texts.clear();
  this->Picture = Image();
  this->ImageProps = 0;
  vtkRenderWindow* window = renderer ? renderer->GetRenderWindow() : nullptr;
  if (!window)
  {
    return;
  }
  const int* size = renderer->GetSize();
  this->RendererSize[0] = size[0];
  this->RendererSize[1] = size[1];
  std::vector<vtkProp*> imaged;
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (prop->GetVisibility() && !vtkProp3D::SafeDownCast(prop) && !this->AddText(renderer, prop))
    {
      imaged.push_back(prop);
    }
  }
  if (!imaged.empty())
  {
    this->CaptureImage(renderer, imaged);
  }
}

bool vtkNPROverlays::AddText(vtkRenderer* renderer, vtkProp* prop)
{
  std::string input;
  vtkTextProperty* property = nullptr;
  const double* anchor = nullptr;
  if (!TextOf(renderer, prop, input, property, anchor))
  {
    return false;
  }
  if (input.empty())
  {
    return true; // nothing drawn
  }
  vtkTextRenderer* fonts = vtkTextRenderer::GetInstance();
  const int dpi = renderer->GetRenderWindow()->GetDPI();
  vtkNew<vtkPath> path;
  vtkTextRenderer::Metrics metrics;
  if (!fonts || !fonts->StringToPath(property, input, path, dpi) ||
    !fonts->GetMetrics(property, input, metrics, dpi))
  {
    return false; // no outlines (no font renderer): an image
  }
  Text text;
  const vtkIdType count = path->GetNumberOfPoints();
  vtkIntArray* codes = vtkIntArray::SafeDownCast(path->GetCodes());
  for (vtkIdType i = 0; codes && i < count && i < codes->GetNumberOfTuples(); ++i)
  {
    double x[3];
    path->GetPoint(i, x);
    text.Points.push_back(anchor[0] + x[0]);
    text.Points.push_back(anchor[1] + x[1]);
    text.Codes.push_back(codes->GetValue(i));
  }
  property->GetColor(text.Color);
  text.Color[3] = property->GetOpacity();
  const vtkVector2i corners[4] = { metrics.TopLeft, metrics.TopRight, metrics.BottomRight,
    metrics.BottomLeft };
  for (int k = 0; k < 4; ++k)
  {
    text.Box[2 * k] = anchor[0] + corners[k][0];
    text.Box[2 * k + 1] = anchor[1] + corners[k][1];
  }
  property->GetBackgroundColor(text.BackgroundColor);
  text.BackgroundColor[3] = property->GetBackgroundOpacity();
  property->GetFrameColor(text.FrameColor);
  text.FrameWidth = property->GetFrame() ? property->GetFrameWidth() : 0;
  this->Texts.push_back(std::move(text));
  return true;
}

void vtkNPROverlays::CaptureImage(vtkRenderer* renderer, const std::vector<vtkProp*>& props)
{
  vtkSmartPointer<vtkImageData> black, white;
  {
    OverlaysOnly only(renderer, std::set<vtkProp*>(props.begin(), props.end()));
    renderer->SetBackground(0.0, 0.0, 0.0);
    black = vtkNPRGrabViewport(renderer);
    renderer->SetBackground(1.0, 1.0, 1.0);
    white = vtkNPRGrabViewport(renderer);
  }
  renderer->GetRenderWindow()->Render(); // the picture again
  const int* dimensions = black->GetDimensions();
  const int width = dimensions[0], height = dimensions[1];
  const int* other = white->GetDimensions();
  if (other[0] != width || other[1] != height || black->GetNumberOfScalarComponents() < 3 ||
    white->GetNumberOfScalarComponents() < 3)
  {
    return;
  }
  const auto* b = static_cast<const unsigned char*>(black->GetScalarPointer());
  const auto* w = static_cast<const unsigned char*>(white->GetScalarPointer());
  const int components = black->GetNumberOfScalarComponents();
  std::vector<std::uint32_t> pixels(static_cast<size_t>(width) * height);
  int left = width, right = -1, top = height, bottom = -1; // of the covered pixels
  for (int j = 0; j < height; ++j) // VTK's row 0 is the bottom, Cairo's the top
  {
    const size_t row = static_cast<size_t>(height - 1 - j) * width;
    for (int i = 0; i < width; ++i)
    {
      const size_t at = (row + i) * components;
      const std::uint32_t pixel = Premultiplied(b + at, w + at);
      pixels[static_cast<size_t>(j) * width + i] = pixel;
      if (pixel >> 24)
      {
        left = std::min(left, i);
        right = std::max(right, i);
        top = std::min(top, j);
        bottom = std::max(bottom, j);
      }
    }
  }
  this->ImageProps = static_cast<vtkIdType>(props.size());
  if (right < 0)
  {
    return; // the props drew nothing
  }
  Image& picture = this->Picture;
  picture.Left = left;
  picture.Top = top;
  picture.Width = right - left + 1;
  picture.Height = bottom - top + 1;
  picture.Pixels.reserve(static_cast<size_t>(picture.Width) * picture.Height);
  for (int j = top; j <= bottom; ++j)
  {
    const auto first = pixels.begin() + static_cast<std::ptrdiff_t>(j) * width + left;
    picture.Pixels.insert(picture.Pixels.end(), first, first + picture.Width);
  }
}

void vtkNPROverlays::PaintText(cairo_t* cr, const Text& text, double height, vtkIdType& paths)
{
  // The metrics' box (turned with the text), each side moved in by `inset` pixels.
  auto boxPath = [&](double inset)
  {
    for (int k = 0; k < 4; ++k)
    {
      const double* corner = text.Box + 2 * k;
      double x = corner[0], y = corner[1];
      for (int neighbour : { (k + 1) % 4, (k + 3) % 4 })
      {
        const double dx = text.Box[2 * neighbour] - corner[0];
        const double dy = text.Box[2 * neighbour + 1] - corner[1];
        const double length = std::hypot(dx, dy);
        x += length > 0.0 ? inset * dx / length : 0.0;
        y += length > 0.0 ? inset * dy / length : 0.0;
      }
      (k == 0 ? cairo_move_to : cairo_line_to)(cr, x, height - y);
    }
    cairo_close_path(cr);
  };
  if (text.BackgroundColor[3] > 0.0)
  {
    boxPath(0.0);
    cairo_set_source_rgba(cr, text.BackgroundColor[0], text.BackgroundColor[1],
      text.BackgroundColor[2], text.BackgroundColor[3]);
    cairo_fill(cr);
    ++paths;
  }
  const size_t count = text.Codes.size();
  TraceGlyphs(cr, text.Points, text.Codes, height);
  if (count > 0)
  {
    cairo_close_path(cr);
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
    cairo_set_source_rgba(cr, text.Color[0], text.Color[1], text.Color[2], text.Color[3]);
    cairo_fill(cr);
    ++paths;
  }
  if (text.FrameWidth > 0) // inside the box, as VTK's text renderer draws it
  {
    boxPath(0.5 * text.FrameWidth);
    cairo_set_source_rgb(cr, text.FrameColor[0], text.FrameColor[1], text.FrameColor[2]);
    cairo_set_line_width(cr, text.FrameWidth);
    cairo_set_dash(cr, nullptr, 0, 0.0);
    cairo_stroke(cr);
    ++paths;
  }
}

bool vtkNPROverlays::Paint(
  cairo_t* cr, int width, int height, vtkIdType& paths, std::string& error) const
{
  paths = 0;
  if (this->Texts.empty() && this->Picture.Pixels.empty())
  {
    return true;
  }
  const int rw = this->RendererSize[0], rh = this->RendererSize[1];
  if (rw <= 0 || rh <= 0)
  {
    return true;
  }
  cairo_save(cr);
  // The props were placed in the renderer's pixels; the drawing may have another size.
  cairo_scale(cr, static_cast<double>(width) / rw, static_cast<double>(height) / rh);
  for (const Text& text : this->Texts)
  {
    PaintText(cr, text, rh, paths);
  }
  const Image& picture = this->Picture;
  if (!picture.Pixels.empty())
  {
    cairo_surface_t* image =
      cairo_image_surface_create(CAIRO_FORMAT_ARGB32, picture.Width, picture.Height);
    unsigned char* data = cairo_image_surface_get_data(image);
    const int stride = cairo_image_surface_get_stride(image);
    for (int j = 0; data && j < picture.Height; ++j)
    {
      std::copy_n(picture.Pixels.begin() + static_cast<std::ptrdiff_t>(j) * picture.Width,
        picture.Width, reinterpret_cast<std::uint32_t*>(data + static_cast<size_t>(j) * stride));
    }
    cairo_surface_mark_dirty(image);
    cairo_set_source_surface(cr, image, picture.Left, picture.Top);
    cairo_paint(cr);
    cairo_surface_destroy(image);
  }
  cairo_restore(cr);
  return vtkNPRCairoSucceeded(cr, error);
}
