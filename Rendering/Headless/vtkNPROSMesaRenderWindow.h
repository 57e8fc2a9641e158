// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPROSMesaRenderWindow
 * @brief   Headless render window on an OSMesa (Mesa off-screen) context.
 *
 * Debian's VTK 9.1 calls OpenGL through GLEW, whose entry points come from glXGetProcAddress,
 * and through direct gl* symbols of libOpenGL (glvnd). Neither sees an OSMesa context on its
 * own. A program that renders with this window therefore links the CMake target `NPR::OSMesa`,
 * which
 * - puts libOSMesa first among the program's libraries, so that direct gl* calls reach it, and
 * - compiles a small shim into the program that answers glXGetProcAddress(ARB) with
 *   OSMesaGetProcAddress, so that GLEW's entry points reach it.
 *
 * This class finds the OSMesa functions at run time in the program's own symbols. Without
 * `NPR::OSMesa` (for example from Python), or when the link order is wrong, the first render
 * fails with an error that says which of the two is missing, and draws nothing.
 *
 * Mesa removed OSMesa upstream in release 25.1; prefer vtkNPREGLRenderWindow where possible.
 */
#ifndef vtkNPROSMesaRenderWindow_h
#define vtkNPROSMesaRenderWindow_h

#include "vtkNPRHeadlessModule.h" // for export macro
#include "vtkNPRHeadlessRenderWindow.h"

#include <vector> // for std::vector

class VTKNPRHEADLESS_EXPORT vtkNPROSMesaRenderWindow : public vtkNPRHeadlessRenderWindow
{
public:
  static vtkNPROSMesaRenderWindow* New();
  vtkTypeMacro(vtkNPROSMesaRenderWindow, vtkNPRHeadlessRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * True when this program was linked with the NPR::OSMesa target (its shim is present and
   * libOSMesa is loaded). Does not create a context.
   */
  static bool IsLinkedWithOSMesa();

  const char* GetBackendName() override { return "osmesa"; }
  bool IsCurrent() override;
  void ReleaseCurrent() override;

protected:
  vtkNPROSMesaRenderWindow();
  ~vtkNPROSMesaRenderWindow() override;

  bool CreateContext() override;
  bool MakeContextCurrent() override;
  void DestroyContext() override;
  bool ContextExists() override { return this->Context != nullptr; }

private:
  vtkNPROSMesaRenderWindow(const vtkNPROSMesaRenderWindow&) = delete;
  void operator=(const vtkNPROSMesaRenderWindow&) = delete;

  void* Context = nullptr; // OSMesaContext
  // OSMesa needs a colour buffer for its default framebuffer; VTK draws into its own
  // framebuffer objects, so this one is never read and stays small.
  std::vector<unsigned char> DefaultBuffer;
};

#endif
