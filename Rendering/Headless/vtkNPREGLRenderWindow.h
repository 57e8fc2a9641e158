// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPREGLRenderWindow
 * @brief   Headless render window on an EGL context: no X server, no window.
 *
 * Creates a desktop OpenGL 3.2 core context through EGL with no surface (surfaceless) and lets VTK
 * render into its own framebuffer objects. The EGL device is chosen as follows:
 *
 * 1. `NPR_EGL_DEVICE=<index>` picks that device of eglQueryDevicesEXT's list.
 * 2. Otherwise, when PreferHardware is on (the default unless `NPR_EGL_SOFTWARE` is set to a
 *    value other than 0), the first hardware device (one without EGL_MESA_device_software, e.g.
 *    an NVIDIA GPU or a DRM render node) whose display initialises.
 * 3. Otherwise Mesa's software device (llvmpipe), then Mesa's surfaceless platform.
 *
 * When none of these gives a display and a context, the window reports the EGL error once through
 * vtkErrorMacro and renders nothing (see vtkNPRHeadlessRenderWindow).
 *
 * Every window makes its own context; several windows may live in one process, and one display
 * per device is shared between them (EGL displays are never terminated, as other code in the
 * process may use them).
 */
#ifndef vtkNPREGLRenderWindow_h
#define vtkNPREGLRenderWindow_h

#include "vtkNPRHeadlessModule.h" // for export macro
#include "vtkNPRHeadlessRenderWindow.h"

#include <string> // for std::string

class VTKNPRHEADLESS_EXPORT vtkNPREGLRenderWindow : public vtkNPRHeadlessRenderWindow
{
public:
  static vtkNPREGLRenderWindow* New();
  vtkTypeMacro(vtkNPREGLRenderWindow, vtkNPRHeadlessRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Prefer a hardware EGL device to Mesa's software renderer. Set before the first render.
   * Default: on, unless the environment variable NPR_EGL_SOFTWARE is set and not "0".
   */
  vtkSetMacro(PreferHardware, bool);
  vtkGetMacro(PreferHardware, bool);
  vtkBooleanMacro(PreferHardware, bool);
  ///@}

  /**
   * The EGL device in use, e.g. "EGL device 1 (software: EGL_MESA_device_software)" ("" before a
   * context exists).
   */
  const char* GetDeviceDescription() const { return this->DeviceDescription.c_str(); }

  /**
   * True when the context runs on a hardware device.
   */
  bool GetUsesHardwareDevice() const { return this->UsesHardwareDevice; }

  const char* GetBackendName() override { return "egl"; }
  bool IsCurrent() override;
  void ReleaseCurrent() override;

protected:
  vtkNPREGLRenderWindow();
  ~vtkNPREGLRenderWindow() override;

  bool CreateContext() override;
  bool MakeContextCurrent() override;
  void DestroyContext() override;
  bool ContextExists() override { return this->Context != nullptr; }

private:
  vtkNPREGLRenderWindow(const vtkNPREGLRenderWindow&) = delete;
  void operator=(const vtkNPREGLRenderWindow&) = delete;

  bool OpenDisplay();

  bool PreferHardware = true;
  bool UsesHardwareDevice = false;
  std::string DeviceDescription;
  void* Display = nullptr; // EGLDisplay
  void* Context = nullptr; // EGLContext
};

#endif
