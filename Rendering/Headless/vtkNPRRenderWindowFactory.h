// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRRenderWindowFactory
 * @brief   The one way programs and tests get a render window: EGL, OSMesa or X.
 *
 * CreateRenderWindow() returns a new render window of the requested backend, ready for
 * off-screen rendering, or nullptr and a warning that says why (vtkGenericWarningMacro) when that
 * backend cannot render in this process. Backends:
 *
 * - "egl": no X server needed. The default. vtkNPREGLRenderWindow with VTK 9.1 to 9.3 (built
 *   for X only), VTK's own vtkEGLRenderWindow from VTK 9.4 on.
 * - "osmesa": with VTK 9.1 to 9.3 vtkNPROSMesaRenderWindow, and the program must link the CMake
 *   target NPR::OSMesa (in such a program OpenGL calls go to libOSMesa, so it is also the default
 *   there); from VTK 9.4 on VTK's vtkOSOpenGLRenderWindow, which loads libOSMesa itself. A build
 *   configured without libOSMesa (Mesa 25.1 and later ship none) reports that the backend is not
 *   available in this build.
 * - "x": VTK's own X window (vtkXOpenGLRenderWindow), off-screen; needs an X display that opens
 *   (DISPLAY, e.g. under Xvfb).
 *
 * With no backend named, the environment variable NPR_BACKEND (egl|osmesa|x) decides, then the
 * defaults above. The headless windows create their context here, so a failure is reported
 * before the first render rather than as a black image.
 *
 * @code
 * vtkSmartPointer<vtkRenderWindow> window =
 *   vtkSmartPointer<vtkRenderWindow>::Take(vtkNPRRenderWindowFactory::CreateRenderWindow());
 * @endcode
 */
#ifndef vtkNPRRenderWindowFactory_h
#define vtkNPRRenderWindowFactory_h

#include "vtkNPRHeadlessModule.h" // for export macro
#include "vtkObject.h"
#include "vtkWrappingHints.h" // for VTK_NEWINSTANCE

class vtkRenderWindow;

class VTKNPRHEADLESS_EXPORT vtkNPRRenderWindowFactory : public vtkObject
{
public:
  static vtkNPRRenderWindowFactory* New();
  vtkTypeMacro(vtkNPRRenderWindowFactory, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * A new render window of the given backend ("egl", "osmesa", "x"; nullptr or "" for the
   * default), multisampling off, or nullptr with an error when it cannot render here.
   * The caller owns the returned reference.
   */
  VTK_NEWINSTANCE
  static vtkRenderWindow* CreateRenderWindow(const char* backend = nullptr);

  /**
   * The backend CreateRenderWindow(nullptr) picks: NPR_BACKEND if set, else "osmesa" in a program
   * linked with NPR::OSMesa (VTK 9.1 to 9.3), else "egl".
   */
  static const char* GetDefaultBackend();

  /**
   * True for "egl", "osmesa" and "x".
   */
  static bool IsKnownBackend(const char* backend);

  /**
   * The backends, separated by '|' ("egl|osmesa|x"), for messages.
   */
  static const char* GetKnownBackends() { return "egl|osmesa|x"; }

  /**
   * The name of the backend a window belongs to ("egl", "osmesa", "x"), or "unknown".
   */
  static const char* GetBackendName(vtkRenderWindow* window);

  /**
   * The GL_RENDERER string of a window's context, creating the context first if needed
   * ("" when there is none).
   */
  static const char* GetGLRenderer(vtkRenderWindow* window);

protected:
  vtkNPRRenderWindowFactory() = default;
  ~vtkNPRRenderWindowFactory() override = default;

private:
  vtkNPRRenderWindowFactory(const vtkNPRRenderWindowFactory&) = delete;
  void operator=(const vtkNPRRenderWindowFactory&) = delete;
};

#endif
