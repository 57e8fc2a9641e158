// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRRenderWindowFactory.h"

#include "vtkNPRConfigure.h"
#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"

#if NPR_HAS_OWN_HEADLESS_WINDOWS // VTK 9.1 to 9.3: X-only builds, the module's own windows
#include "vtkNPREGLRenderWindow.h"
#include "vtkNPROSMesaRenderWindow.h"
#else // VTK 9.4 and later: VTK's own headless windows
#include "vtkCommand.h"
#include "vtkEGLRenderWindow.h"
#include "vtkNew.h"
#if NPR_HAS_OSMESA
#include "vtkOSOpenGLRenderWindow.h"
#endif
#include "vtkRenderingOpenGLConfigure.h" // VTK_USE_X
#ifdef VTK_USE_X
#include "vtkXOpenGLRenderWindow.h"
#endif
#endif

#include <X11/Xlib.h>

#include <cstdlib>
#include <cstring>
#include <map>
#include <string>

vtkStandardNewMacro(vtkNPRRenderWindowFactory);

namespace
{
// Opens a connection to the X display and keeps it for the life of the process: an X server such
// as Xvfb resets when its last client disconnects, and a window opened during that reset fails.
bool OpenXDisplay(const std::string& name)
{
  struct Connections
  {
    std::map<std::string, Display*> Open;
    ~Connections()
    {
      for (auto& connection : this->Open)
      {
        XCloseDisplay(connection.second);
      }
    }
  };
  static Connections connections;
  auto found = connections.Open.find(name);
  if (found != connections.Open.end())
  {
    return true;
  }
  Display* connection = XOpenDisplay(name.c_str());
  if (connection)
  {
    connections.Open[name] = connection;
  }
  return connection != nullptr;
}

#if !NPR_HAS_OWN_HEADLESS_WINDOWS
// Collects what a VTK window reports while it creates its context, for the factory's message.
class MessageCollector : public vtkCommand
{
public:
  static MessageCollector* New() { return new MessageCollector; }
  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    const char* text = static_cast<const char*>(callData);
    if (text && *text)
    {
      // VTK's text is "Warning: In FILE, line N\nCLASS (ADDRESS): message": keep the message.
      std::string line(text);
      line.erase(line.find_last_not_of(" \n") + 1);
      const size_t object =
        line.find("): ", line.rfind('\n') == std::string::npos ? 0 : line.rfind('\n'));
      if (object != std::string::npos)
      {
        line.erase(0, object + 3);
      }
      this->Messages += (this->Messages.empty() ? "" : "; ") + line;
    }
  }
  std::string Messages;
};

// VTK's EGL or OSMesa window with its context created now; nullptr and the reason when that fails.
vtkSmartPointer<vtkRenderWindow> CreateVTKHeadlessWindow(const std::string& name, std::string& why)
{
  vtkSmartPointer<vtkOpenGLRenderWindow> window;
  if (name == "egl")
  {
    window = vtkSmartPointer<vtkEGLRenderWindow>::New();
  }
#if NPR_HAS_OSMESA
  else
  {
    window = vtkSmartPointer<vtkOSOpenGLRenderWindow>::New();
  }
#endif
  vtkNew<MessageCollector> messages;
  window->AddObserver(vtkCommand::ErrorEvent, messages);
  window->AddObserver(vtkCommand::WarningEvent, messages);
  window->SetShowWindow(false);
  window->SetSize(64, 64); // a small first surface; callers set the real size
  window->Initialize();
  int major = 0, minor = 0;
  if (window->GetGenericContext())
  {
    window->GetOpenGLVersion(major, minor); // 0.0 when VTK could not load OpenGL
  }
  window->RemoveObservers(vtkCommand::ErrorEvent);
  window->RemoveObservers(vtkCommand::WarningEvent);
  if (major * 10 + minor < 32)
  {
    why = std::string(window->GetClassName()) + " could not create an OpenGL 3.2 context" +
      (messages->Messages.empty() ? std::string() : " (" + messages->Messages + ")");
    return nullptr;
  }
  return window;
}
#endif

// The EGL or OSMesa window with its context made now; nullptr and the reason when that fails.
vtkSmartPointer<vtkRenderWindow> CreateHeadlessWindow(const std::string& name, std::string& why)
{
#if NPR_HAS_OWN_HEADLESS_WINDOWS
  vtkSmartPointer<vtkNPRHeadlessRenderWindow> headless;
  if (name == "egl")
  {
    headless = vtkSmartPointer<vtkNPREGLRenderWindow>::New();
  }
  else
  {
    headless = vtkSmartPointer<vtkNPROSMesaRenderWindow>::New();
  }
  if (!headless->InitializeContext())
  {
    why = headless->GetContextError();
    return nullptr;
  }
  return headless;
#else
  return CreateVTKHeadlessWindow(name, why);
#endif
}

// VTK's X window, drawing off screen; nullptr and the reason when no X display can be used.
vtkSmartPointer<vtkRenderWindow> CreateXWindow(std::string& why)
{
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    why = "DISPLAY is not set (run under xvfb-run, or use NPR_BACKEND=egl)";
    return nullptr;
  }
  // VTK's X window aborts the process when the display cannot be opened: try it first.
  if (!OpenXDisplay(display))
  {
    why = std::string("cannot open the X display '") + display + "'";
    return nullptr;
  }
#if NPR_HAS_OWN_HEADLESS_WINDOWS
  auto window = vtkSmartPointer<vtkRenderWindow>::New(); // VTK's own X window
#elif defined(VTK_USE_X)
  // vtkRenderWindow::New() picks a window at run time since VTK 9.4: ask for X itself.
  vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkXOpenGLRenderWindow>::New();
#else
  why = "this VTK was built without X";
  vtkSmartPointer<vtkRenderWindow> window;
  return window;
#endif
  window->SetOffScreenRendering(1);
  return window;
}
}

void vtkNPRRenderWindowFactory::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DefaultBackend: " << vtkNPRRenderWindowFactory::GetDefaultBackend() << "\n";
}

bool vtkNPRRenderWindowFactory::IsKnownBackend(const char* backend)
{
  return backend &&
    (!std::strcmp(backend, "egl") || !std::strcmp(backend, "osmesa") || !std::strcmp(backend, "x"));
}

const char* vtkNPRRenderWindowFactory::GetDefaultBackend()
{
  const char* requested = std::getenv("NPR_BACKEND");
  if (requested && *requested)
  {
    return requested;
  }
#if NPR_HAS_OWN_HEADLESS_WINDOWS && NPR_HAS_OSMESA
  return vtkNPROSMesaRenderWindow::IsLinkedWithOSMesa() ? "osmesa" : "egl";
#else
  return "egl";
#endif
}

vtkRenderWindow* vtkNPRRenderWindowFactory::CreateRenderWindow(const char* backend)
{
  const std::string name = (backend && *backend) ? backend : GetDefaultBackend();
#if !NPR_HAS_OSMESA
  if (name == "osmesa")
  {
    vtkGenericWarningMacro(<< "no osmesa render window: the osmesa backend is not available in "
                              "this build (libOSMesa was not found when vtkNPR was configured; "
                              "Mesa 25.1 and later ship none): use egl");
    return nullptr;
  }
#endif
  vtkSmartPointer<vtkRenderWindow> window;
  std::string why;
  if (name == "egl" || name == "osmesa")
  {
    window = CreateHeadlessWindow(name, why);
  }
  else if (name == "x")
  {
    window = CreateXWindow(why);
  }
  else
  {
    vtkGenericWarningMacro(<< "unknown render window backend '" << name
                           << "'; valid backends: " << GetKnownBackends());
    return nullptr;
  }
  if (!window)
  {
    vtkGenericWarningMacro(<< "no " << name << " render window: " << why);
    return nullptr;
  }
  window->SetMultiSamples(0);
  window->Register(nullptr); // the caller owns this reference
  return window;
}

const char* vtkNPRRenderWindowFactory::GetBackendName(vtkRenderWindow* window)
{
#if NPR_HAS_OWN_HEADLESS_WINDOWS
  if (auto* headless = vtkNPRHeadlessRenderWindow::SafeDownCast(window))
  {
    return headless->GetBackendName();
  }
#endif
  if (window)
  {
    const std::string name = window->GetClassName();
    if (name == "vtkXOpenGLRenderWindow")
    {
      return "x";
    }
    if (name == "vtkEGLRenderWindow")
    {
      return "egl";
    }
    if (name == "vtkOSOpenGLRenderWindow")
    {
      return "osmesa";
    }
  }
  return "unknown";
}

const char* vtkNPRRenderWindowFactory::GetGLRenderer(vtkRenderWindow* window)
{
#if NPR_HAS_OWN_HEADLESS_WINDOWS
  if (auto* headless = vtkNPRHeadlessRenderWindow::SafeDownCast(window))
  {
    headless->InitializeContext();
    return headless->GetGLRenderer();
  }
#endif
  if (!window)
  {
    return "";
  }
  // Other windows: VTK's report holds the string (it makes the window's context current).
  static thread_local std::string renderer;
  const std::string report = window->ReportCapabilities();
  const std::string key = "OpenGL renderer string:";
  const size_t start = report.find(key);
  if (start == std::string::npos)
  {
    return "";
  }
  const size_t begin = report.find_first_not_of(' ', start + key.size());
  renderer = report.substr(begin, report.find('\n', begin) - begin);
  return renderer.c_str();
}
