// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-view's window: one renderer with the models, a vtkNPRPass whose settings the keys change,
// the corner overlay (style, settings, last frame time) and the help overlay, and the files
// the keys save. nprViewInteractorStyle passes its keys here.
#ifndef nprViewer_h
#define nprViewer_h

#include "nprPassSettings.h"

#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <string>

class vtkNPRPass;
class vtkObject;
class vtkRenderWindow;
class vtkRenderer;
class vtkTextActor;

// The keys and mouse buttons, one per line (for --help and the help overlay).
extern const char* const nprViewKeys;

class nprViewer
{
public:
  // Adds the overlays to renderer and its frame-time observers to window.
  nprViewer(vtkRenderWindow* window, vtkRenderer* renderer, const nprPassSettings& settings,
    const std::string& outputPrefix);
  ~nprViewer();

  // A key of the viewer's own (see the help text); false for any other key.
  bool HandleKey(char key);

  // Installs the current settings (style, lines) and updates the overlay text.
  void Apply();

  // Write the next free PREFIXNNNN.png (withOverlay: PREFIXNNNN-overlay.png, as shown; the two
  // share the numbers) and PREFIXcamera-NNNN.json; each prints its path on stdout. A file that
  // cannot be written is an error line on stderr; the viewer goes on.
  void SaveScreenshot(bool withOverlay);
  void SaveCamera();

  double GetLastFrameMilliseconds() const { return this->LastFrameMs; }

private:
  void OnRenderStart(vtkObject*, unsigned long, void*);
  void OnRenderEnd(vtkObject*, unsigned long, void*);
  std::string StatusText() const;
  std::string NextFreeName(
    const std::string& middle, const std::string& suffix, const std::string& otherSuffix);

  vtkRenderWindow* Window;
  vtkRenderer* Renderer;
  nprPassSettings Settings;
  std::string OutputPrefix;
  vtkSmartPointer<vtkNPRPass> Pass;
  vtkNew<vtkTextActor> Status;
  vtkNew<vtkTextActor> Help;
  double LastFrameMs = 0.0;
  double FrameStart = 0.0;
  unsigned long StartObserver = 0;
  unsigned long EndObserver = 0;
};

// VTK's trackball camera with npr-view's keys: they go to the viewer first; q and e quit and r
// resets the camera as in VTK; VTK's other keys (w, s, p, f, 3, ...) are not passed on, as their
// meanings (wireframe, surface, pick, fly to, stereo) clash with the viewer's or break the styles.
class nprViewInteractorStyle : public vtkInteractorStyleTrackballCamera
{
public:
  static nprViewInteractorStyle* New();
  vtkTypeMacro(nprViewInteractorStyle, vtkInteractorStyleTrackballCamera);
  void OnChar() override;

  nprViewer* Viewer = nullptr; // not owned
};

#endif
