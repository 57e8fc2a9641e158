// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Compiled into every program that links NPR::OSMesa (see vtkNPROSMesaRenderWindow.h).
//
// Debian's VTK 9.1 gets its OpenGL entry points from GLEW, and GLEW asks glXGetProcAddressARB.
// Defined in the executable and exported, these definitions come before libGLX's in symbol
// lookup, so GLEW receives OSMesa's functions, which work on the current OSMesa context.

extern "C"
{
  using npr_gl_function = void (*)();
  npr_gl_function OSMesaGetProcAddress(const char* name);

  // Looked up by vtkNPROSMesaRenderWindow::IsLinkedWithOSMesa().
  __attribute__((visibility("default"))) int vtkNPROSMesaShimLinked = 1;

  __attribute__((visibility("default"))) npr_gl_function glXGetProcAddressARB(
    const unsigned char* name)
  {
    // OSMesa hands out do-nothing stubs even for glX* names; GLX is not there.
    if (name[0] == 'g' && name[1] == 'l' && name[2] == 'X')
    {
      return nullptr;
    }
    return OSMesaGetProcAddress(reinterpret_cast<const char*>(name));
  }

  __attribute__((visibility("default"))) npr_gl_function glXGetProcAddress(
    const unsigned char* name)
  {
    return glXGetProcAddressARB(name);
  }
}
