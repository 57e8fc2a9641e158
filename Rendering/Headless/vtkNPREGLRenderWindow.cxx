// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPREGLRenderWindow.h"

#include "vtkObjectFactory.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>
#include <cstring>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkNPREGLRenderWindow);

namespace
{
bool EnvironmentFlag(const char* name)
{
  const char* value = std::getenv(name);
  return value && *value && std::strcmp(value, "0") != 0;
}

std::string EGLErrorString(EGLint code)
{
  switch (code)
  {
    case EGL_SUCCESS:
      return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    default:
      break;
  }
  std::ostringstream text;
  text << "EGL error 0x" << std::hex << code;
  return text.str();
}

struct EGLDeviceFunctions
{
  PFNEGLQUERYDEVICESEXTPROC QueryDevices = nullptr;
  PFNEGLQUERYDEVICESTRINGEXTPROC QueryDeviceString = nullptr;
  PFNEGLGETPLATFORMDISPLAYEXTPROC GetPlatformDisplay = nullptr;

  EGLDeviceFunctions()
  {
    this->QueryDevices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    this->QueryDeviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
      eglGetProcAddress("eglQueryDeviceStringEXT"));
    this->GetPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  }
};

struct DeviceInfo
{
  EGLDeviceEXT Device;
  bool Software;
  std::string Description;
};

std::vector<DeviceInfo> ListDevices(const EGLDeviceFunctions& egl)
{
  std::vector<DeviceInfo> devices;
  if (!egl.QueryDevices || !egl.QueryDeviceString)
  {
    return devices;
  }
  EGLint count = 0;
  if (!egl.QueryDevices(0, nullptr, &count) || count <= 0)
  {
    return devices;
  }
  std::vector<EGLDeviceEXT> handles(static_cast<size_t>(count));
  egl.QueryDevices(count, handles.data(), &count);
  for (EGLint i = 0; i < count; ++i)
  {
    const char* extensions = egl.QueryDeviceString(handles[i], EGL_EXTENSIONS);
    const bool software = extensions && std::strstr(extensions, "EGL_MESA_device_software");
    std::ostringstream text;
    text << "EGL device " << i;
    if (software)
    {
      text << " (software: EGL_MESA_device_software)";
    }
    else if (extensions && std::strstr(extensions, "EGL_EXT_device_drm"))
    {
      const char* file = egl.QueryDeviceString(handles[i], EGL_DRM_DEVICE_FILE_EXT);
      text << " (hardware: " << (file ? file : "DRM device") << ")";
    }
    else
    {
      text << " (hardware)";
    }
    devices.push_back({ handles[i], software, text.str() });
  }
  return devices;
}
}

vtkNPREGLRenderWindow::vtkNPREGLRenderWindow()
  : PreferHardware(!EnvironmentFlag("NPR_EGL_SOFTWARE"))
{
}

vtkNPREGLRenderWindow::~vtkNPREGLRenderWindow()
{
  this->ShutDown();
}

void vtkNPREGLRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PreferHardware: " << this->PreferHardware << "\n";
  os << indent << "UsesHardwareDevice: " << this->UsesHardwareDevice << "\n";
  os << indent << "DeviceDescription: " << this->DeviceDescription << "\n";
}

bool vtkNPREGLRenderWindow::OpenDisplay()
{
  const EGLDeviceFunctions egl;
  if (!egl.GetPlatformDisplay)
  {
    this->SetContextError("libEGL offers no eglGetPlatformDisplayEXT (EGL_EXT_platform_base)");
    return false;
  }
  const std::vector<DeviceInfo> devices = ListDevices(egl);
  std::vector<const DeviceInfo*> candidates;
  if (const char* forced = std::getenv("NPR_EGL_DEVICE"))
  {
    char* end = nullptr;
    const long index = std::strtol(forced, &end, 10);
    if (end == forced || *end || index < 0 || index >= static_cast<long>(devices.size()))
    {
      std::ostringstream text;
      text << "NPR_EGL_DEVICE=" << forced << " names no EGL device (" << devices.size()
           << " found)";
      this->SetContextError(text.str());
      return false;
    }
    candidates.push_back(&devices[static_cast<size_t>(index)]);
  }
  else
  {
    for (int pass = this->PreferHardware ? 0 : 1; pass < 2; ++pass)
    {
      for (const DeviceInfo& device : devices)
      {
        if (device.Software == (pass == 1))
        {
          candidates.push_back(&device);
        }
      }
    }
  }

  EGLint major = 0, minor = 0;
  for (const DeviceInfo* device : candidates)
  {
    EGLDisplay display = egl.GetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device->Device, nullptr);
    if (display != EGL_NO_DISPLAY && eglInitialize(display, &major, &minor))
    {
      this->Display = display;
      this->UsesHardwareDevice = !device->Software;
      this->DeviceDescription = device->Description;
      return true;
    }
  }
  if (candidates.empty() || !std::getenv("NPR_EGL_DEVICE"))
  {
    EGLDisplay display =
      egl.GetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display != EGL_NO_DISPLAY && eglInitialize(display, &major, &minor))
    {
      this->Display = display;
      this->UsesHardwareDevice = false;
      this->DeviceDescription = "Mesa surfaceless platform";
      return true;
    }
  }
  std::ostringstream text;
  text << "no EGL display could be opened (" << devices.size() << " EGL devices, "
       << EGLErrorString(eglGetError()) << "; is an EGL vendor library installed?)";
  this->SetContextError(text.str());
  return false;
}

bool vtkNPREGLRenderWindow::CreateContext()
{
  if (!this->Display && !this->OpenDisplay())
  {
    return false;
  }
  EGLDisplay display = static_cast<EGLDisplay>(this->Display);
  const EGLint configAttributes[] = { EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
    EGL_OPENGL_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_NONE };
  const EGLint anySurface[] = { EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE };
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!eglBindAPI(EGL_OPENGL_API))
  {
    this->SetContextError("eglBindAPI(EGL_OPENGL_API) failed: " + EGLErrorString(eglGetError()));
    return false;
  }
  // Surfaceless contexts need no surface type; a pbuffer-capable config is only preferred.
  if ((!eglChooseConfig(display, configAttributes, &config, 1, &count) || count < 1) &&
    (!eglChooseConfig(display, anySurface, &config, 1, &count) || count < 1))
  {
    this->SetContextError("no EGL config with desktop OpenGL on " + this->DeviceDescription);
    return false;
  }
  const EGLint contextAttributes[] = { EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 2,
    EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE };
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
  if (context == EGL_NO_CONTEXT)
  {
    this->SetContextError("eglCreateContext (OpenGL 3.2 core) failed on " +
      this->DeviceDescription + ": " + EGLErrorString(eglGetError()));
    return false;
  }
  this->Context = context;
  return true;
}

bool vtkNPREGLRenderWindow::MakeContextCurrent()
{
  if (!this->Context)
  {
    return false;
  }
  if (eglGetCurrentContext() == static_cast<EGLContext>(this->Context))
  {
    return true;
  }
  if (!eglMakeCurrent(static_cast<EGLDisplay>(this->Display), EGL_NO_SURFACE, EGL_NO_SURFACE,
        static_cast<EGLContext>(this->Context)))
  {
    this->SetContextError("eglMakeCurrent failed: " + EGLErrorString(eglGetError()));
    return false;
  }
  return true;
}

bool vtkNPREGLRenderWindow::IsCurrent()
{
  return this->Context && eglGetCurrentContext() == static_cast<EGLContext>(this->Context);
}

void vtkNPREGLRenderWindow::ReleaseCurrent()
{
  if (this->IsCurrent())
  {
    eglMakeCurrent(
      static_cast<EGLDisplay>(this->Display), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
}

void vtkNPREGLRenderWindow::DestroyContext()
{
  if (!this->Context)
  {
    return;
  }
  this->ReleaseCurrent();
  eglDestroyContext(static_cast<EGLDisplay>(this->Display), static_cast<EGLContext>(this->Context));
  this->Context = nullptr;
}
