// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprViewer.h"

#include "nprCameraJson.h"
#include "nprTiming.h"
#include "nprWindowImage.h"

#include "vtkCommand.h"
#include "vtkNPRPass.h"
#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

namespace
{
// A process-wide clock in milliseconds, for the frame time between two events.
double NowMilliseconds()
{
  static const nprClock::time_point origin = nprClock::now();
  return nprSecondsSince(origin) * 1e3;
}

bool Exists(const std::string& path)
{
  return std::ifstream(path).good();
}

// The setting that a key (either case) switches on and off: a kind of line, or the hidden lines;
// nullptr for any other key.
bool* ToggledBy(char key, nprPassSettings& s)
{
  switch (std::tolower(static_cast<unsigned char>(key)))
  {
    case 's':
      return &s.Silhouettes;
    case 'c':
      return &s.Creases;
    case 'o':
      return &s.Contours;
    case 'd':
      return &s.HiddenLines;
    default:
      return nullptr;
  }
}
}

const char* const nprViewKeys =
  R"(  1..7   style: shaded, edges, toon, toon+edges, sketch, inked, drawing
  d      hidden lines of the drawing on / off
  + -    line width up / down by 0.5 px
  ] [    crease angle up / down by 5 degrees
  s c o  silhouettes, creases, contours on / off
  p      save a screenshot of the render (no overlay)
  P      save a screenshot as shown (with the overlay)
  k      save the camera (JSON for npr-render --camera-in)
  r      reset the camera
  h      help overlay on / off
  q e    quit
mouse: left rotate, middle or shift+left pan, right or wheel zoom, ctrl+left spin
)";

vtkStandardNewMacro(nprViewInteractorStyle);

void nprViewInteractorStyle::OnChar()
{
  vtkRenderWindowInteractor* interactor = this->Interactor;
  char key = interactor->GetKeyCode();
  // VTK 9.3's X interactor gives a shifted letter in lower case, with the shift key down.
  if (interactor->GetShiftKey() && std::islower(static_cast<unsigned char>(key)))
  {
    key = static_cast<char>(std::toupper(static_cast<unsigned char>(key)));
  }
  if (this->Viewer && this->Viewer->HandleKey(key))
  {
    interactor->Render();
    return;
  }
  switch (std::tolower(static_cast<unsigned char>(key)))
  {
    case 'q': // quit, as in VTK
    case 'e':
    case 'r': // reset the camera, as in VTK
      this->Superclass::OnChar();
      break;
    default: // VTK's other keys would change the actors or the window under the styles
      break;
  }
}

nprViewer::nprViewer(vtkRenderWindow* window, vtkRenderer* renderer,
  const nprPassSettings& settings, const std::string& outputPrefix)
  : Window(window)
  , Renderer(renderer)
  , Settings(settings)
  , OutputPrefix(outputPrefix)
  , Pass(nprMakePass(settings))
{
  // The status in the lower left corner, readable on any background and model.
  vtkTextProperty* status = this->Status->GetTextProperty();
  status->SetFontFamilyToCourier();
  status->SetFontSize(14);
  status->SetColor(0.1, 0.1, 0.1);
  status->SetBackgroundColor(1.0, 1.0, 1.0);
  status->SetBackgroundOpacity(0.75);
  this->Status->SetDisplayPosition(6, 6);
  renderer->AddActor2D(this->Status);

  vtkTextProperty* help = this->Help->GetTextProperty();
  help->SetFontFamilyToCourier();
  help->SetFontSize(14);
  help->SetColor(0.0, 0.0, 0.0);
  help->SetBackgroundColor(1.0, 1.0, 0.85);
  help->SetBackgroundOpacity(0.9);
  help->SetVerticalJustificationToTop();
  const std::string keys = std::string("npr-view keys\n") + nprViewKeys;
  this->Help->SetInput(keys.substr(0, keys.size() - 1).c_str()); // without the last newline
  this->Help->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  this->Help->GetPositionCoordinate()->SetValue(0.02, 0.98);
  this->Help->VisibilityOff();
  renderer->AddActor2D(this->Help);

  // The overlay shows the time of the frame before: the text is set as a frame starts.
  this->StartObserver =
    window->AddObserver(vtkCommand::StartEvent, this, &nprViewer::OnRenderStart);
  this->EndObserver = window->AddObserver(vtkCommand::EndEvent, this, &nprViewer::OnRenderEnd);
  this->Apply();
}

nprViewer::~nprViewer()
{
  this->Window->RemoveObserver(this->StartObserver);
  this->Window->RemoveObserver(this->EndObserver);
}

void nprViewer::Apply()
{
  nprApplyPassSettings(this->Pass, this->Settings);
  // "shaded" is VTK's own chain, as in npr-render: no pass.
  this->Renderer->SetPass(this->Settings.Style == "shaded" ? nullptr : this->Pass.Get());
  this->Status->SetInput(this->StatusText().c_str());
}

bool nprViewer::HandleKey(char key)
{
  nprPassSettings& s = this->Settings;
  if (bool* setting = ToggledBy(key, s))
  {
    *setting = !*setting;
    this->Apply();
    return true;
  }
  switch (key)
  {
    case '1':
    case '2':
    case '3':
    case '4':
    case '5':
    case '6':
    case '7':
      // Keys 1..7 in the order of vtkNPRPass's styles.
      s.Style = vtkNPRPass::GetStyleName(vtkNPRPass::SHADED + (key - '1'));
      break;
    case '+':
    case '=': // + without shift on most keyboards
      s.LineWidth = std::min(16.0, s.LineWidth + 0.5);
      break;
    case '-':
    case '_':
      s.LineWidth = std::max(0.5, s.LineWidth - 0.5);
      break;
    case ']':
      s.CreaseAngle = std::min(179.0, s.CreaseAngle + 5.0);
      break;
    case '[':
      s.CreaseAngle = std::max(1.0, s.CreaseAngle - 5.0);
      break;
    case 'p':
      this->SaveScreenshot(false);
      return true;
    case 'P':
      this->SaveScreenshot(true);
      return true;
    case 'k':
    case 'K':
      this->SaveCamera();
      return true;
    case 'h':
    case 'H':
      this->Help->SetVisibility(!this->Help->GetVisibility());
      return true;
    default:
      return false;
  }
  this->Apply();
  return true;
}

std::string nprViewer::StatusText() const
{
  const nprPassSettings& s = this->Settings;
  std::string lines;
  lines += s.Silhouettes ? " silhouettes" : "";
  lines += s.Creases ? " creases" : "";
  lines += s.Contours ? " contours" : "";
  lines += s.Style == "drawing" && s.HiddenLines ? " hidden" : "";
  char text[512];
  std::snprintf(text, sizeof(text),
    "style %s\nlines:%s\nline width %.1f px, crease angle %.0f deg\nframe %.1f ms   (h: keys)",
    s.Style.c_str(), lines.empty() ? " none" : lines.c_str(), s.LineWidth, s.CreaseAngle,
    this->LastFrameMs);
  return text;
}

void nprViewer::OnRenderStart(vtkObject*, unsigned long, void*)
{
  this->Status->SetInput(this->StatusText().c_str());
  this->FrameStart = NowMilliseconds();
}

void nprViewer::OnRenderEnd(vtkObject*, unsigned long, void*)
{
  // Until the GPU has finished the frame, as npr-render --frames counts it.
  this->Window->WaitForCompletion();
  this->LastFrameMs = NowMilliseconds() - this->FrameStart;
}

std::string nprViewer::NextFreeName(
  const std::string& middle, const std::string& suffix, const std::string& otherSuffix)
{
  // Never overwrites: the first number whose files (either kind of screenshot) do not exist.
  for (int number = 1;; ++number)
  {
    std::ostringstream name;
    name << this->OutputPrefix << middle;
    name.width(4);
    name.fill('0');
    name << number;
    if (!Exists(name.str() + suffix) && (otherSuffix.empty() || !Exists(name.str() + otherSuffix)))
    {
      return name.str() + suffix;
    }
  }
}

void nprViewer::SaveScreenshot(bool withOverlay)
{
  const std::string path = withOverlay ? this->NextFreeName("", "-overlay.png", ".png")
                                       : this->NextFreeName("", ".png", "-overlay.png");
  const bool status = this->Status->GetVisibility() != 0;
  const bool help = this->Help->GetVisibility() != 0;
  if (!withOverlay)
  {
    this->Status->VisibilityOff();
    this->Help->VisibilityOff();
  }
  try
  {
    nprWriteWindowPNG(this->Window, path, false); // renders the frame it writes
    std::cout << path << std::endl;
  }
  catch (const std::exception& error)
  {
    // A file that cannot be written is no reason to close the window.
    std::cerr << "npr-view: error: " << error.what() << std::endl;
  }
  this->Status->SetVisibility(status);
  this->Help->SetVisibility(help);
}

void nprViewer::SaveCamera()
{
  const std::string path = this->NextFreeName("camera-", ".json", "");
  const int* size = this->Window->GetSize();
  try
  {
    nprWriteCameraFile(
      path, nprCameraState::FromCamera(this->Renderer->GetActiveCamera(), size[0], size[1]));
    std::cout << path << std::endl;
  }
  catch (const std::exception& error)
  {
    std::cerr << "npr-view: error: " << error.what() << std::endl;
  }
}
