// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPROSMesaRenderWindow.h"

#include "vtkObjectFactory.h"

#include <dlfcn.h>

#include <string>

vtkStandardNewMacro(vtkNPROSMesaRenderWindow);

namespace
{
// From GL/osmesa.h, declared here so that the module neither includes nor links OSMesa: the
// program provides it (target NPR::OSMesa) and the functions are looked up in its symbols.
constexpr int OSMESA_RGBA = 0x1908;
constexpr int OSMESA_FORMAT = 0x22;
constexpr int OSMESA_DEPTH_BITS = 0x30;
constexpr int OSMESA_STENCIL_BITS = 0x31;
constexpr int OSMESA_PROFILE = 0x33;
constexpr int OSMESA_CORE_PROFILE = 0x34;
constexpr int OSMESA_CONTEXT_MAJOR_VERSION = 0x36;
constexpr int OSMESA_CONTEXT_MINOR_VERSION = 0x37;
constexpr unsigned int GL_UNSIGNED_BYTE_TYPE = 0x1401;
constexpr int DefaultBufferSize = 16;

using GenericFunction = void (*)();
using CreateContextAttribsFunction = void* (*)(const int*, void*);
using MakeCurrentFunction = unsigned char (*)(void*, void*, unsigned int, int, int);
using GetCurrentContextFunction = void* (*)();
using DestroyContextFunction = void (*)(void*);
using GetProcAddressFunction = GenericFunction (*)(const char*);
using GLXGetProcAddressFunction = GenericFunction (*)(const unsigned char*);

struct OSMesaFunctions
{
  CreateContextAttribsFunction CreateContextAttribs = nullptr;
  MakeCurrentFunction MakeCurrent = nullptr;
  GetCurrentContextFunction GetCurrentContext = nullptr;
  DestroyContextFunction DestroyContext = nullptr;
  GetProcAddressFunction GetProcAddress = nullptr;

  OSMesaFunctions()
  {
    this->CreateContextAttribs = reinterpret_cast<CreateContextAttribsFunction>(
      dlsym(RTLD_DEFAULT, "OSMesaCreateContextAttribs"));
    this->MakeCurrent =
      reinterpret_cast<MakeCurrentFunction>(dlsym(RTLD_DEFAULT, "OSMesaMakeCurrent"));
    this->GetCurrentContext =
      reinterpret_cast<GetCurrentContextFunction>(dlsym(RTLD_DEFAULT, "OSMesaGetCurrentContext"));
    this->DestroyContext =
      reinterpret_cast<DestroyContextFunction>(dlsym(RTLD_DEFAULT, "OSMesaDestroyContext"));
    this->GetProcAddress =
      reinterpret_cast<GetProcAddressFunction>(dlsym(RTLD_DEFAULT, "OSMesaGetProcAddress"));
  }
  bool Complete() const
  {
    return this->CreateContextAttribs && this->MakeCurrent && this->GetCurrentContext &&
      this->DestroyContext && this->GetProcAddress;
  }
};

const OSMesaFunctions& OSMesa()
{
  static const OSMesaFunctions functions;
  return functions;
}

// True when glXGetProcAddressARB, as GLEW will find it, hands out OSMesa's entry points.
bool ShimAnswersForOSMesa()
{
  auto glxGetProcAddress =
    reinterpret_cast<GLXGetProcAddressFunction>(dlsym(RTLD_DEFAULT, "glXGetProcAddressARB"));
  if (!glxGetProcAddress)
  {
    return false;
  }
  const char* probe = "glGenFramebuffers";
  return glxGetProcAddress(reinterpret_cast<const unsigned char*>(probe)) ==
    OSMesa().GetProcAddress(probe);
}
}

vtkNPROSMesaRenderWindow::vtkNPROSMesaRenderWindow()
  : DefaultBuffer(DefaultBufferSize * DefaultBufferSize * 4)
{
}

vtkNPROSMesaRenderWindow::~vtkNPROSMesaRenderWindow()
{
  this->ShutDown();
}

void vtkNPROSMesaRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LinkedWithOSMesa: " << vtkNPROSMesaRenderWindow::IsLinkedWithOSMesa() << "\n";
}

bool vtkNPROSMesaRenderWindow::IsLinkedWithOSMesa()
{
  return OSMesa().Complete() && dlsym(RTLD_DEFAULT, "vtkNPROSMesaShimLinked") != nullptr;
}

bool vtkNPROSMesaRenderWindow::CreateContext()
{
  const OSMesaFunctions& osmesa = OSMesa();
  if (!osmesa.Complete())
  {
    this->SetContextError("libOSMesa is not loaded in this program: link it with the CMake "
                          "target NPR::OSMesa (Python programs cannot use OSMesa; use EGL)");
    return false;
  }
  if (!ShimAnswersForOSMesa())
  {
    this->SetContextError("glXGetProcAddressARB does not hand out OSMesa's entry points, so GLEW "
                          "would bypass the OSMesa context: link the program with NPR::OSMesa");
    return false;
  }
  const int attributes[] = { OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS,
    8, OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
    OSMESA_CONTEXT_MINOR_VERSION, 2, 0 };
  this->Context = osmesa.CreateContextAttribs(attributes, nullptr);
  if (!this->Context)
  {
    this->SetContextError("OSMesaCreateContextAttribs (OpenGL 3.2 core) failed");
    return false;
  }
  return true;
}

bool vtkNPROSMesaRenderWindow::MakeContextCurrent()
{
  if (!this->Context)
  {
    return false;
  }
  const OSMesaFunctions& osmesa = OSMesa();
  if (osmesa.GetCurrentContext() == this->Context)
  {
    return true;
  }
  if (!osmesa.MakeCurrent(this->Context, this->DefaultBuffer.data(), GL_UNSIGNED_BYTE_TYPE,
        DefaultBufferSize, DefaultBufferSize))
  {
    this->SetContextError("OSMesaMakeCurrent failed");
    return false;
  }
  return true;
}

bool vtkNPROSMesaRenderWindow::IsCurrent()
{
  return this->Context && OSMesa().GetCurrentContext() == this->Context;
}

void vtkNPROSMesaRenderWindow::ReleaseCurrent()
{
  if (this->IsCurrent())
  {
    OSMesa().MakeCurrent(nullptr, nullptr, 0, 0, 0);
  }
}

void vtkNPROSMesaRenderWindow::DestroyContext()
{
  if (!this->Context)
  {
    return;
  }
  this->ReleaseCurrent();
  OSMesa().DestroyContext(this->Context);
  this->Context = nullptr;
}
