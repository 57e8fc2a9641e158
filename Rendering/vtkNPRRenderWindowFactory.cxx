#include "vtkNPRRenderWindowFactory.h"

#include "vtkNPREGLRenderWindow.h"
#include "vtkNPROSMesaRenderWindow.h"
#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"

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
  return vtkNPROSMesaRenderWindow::IsLinkedWithOSMesa() ? "osmesa" : "egl";
}

vtkRenderWindow* vtkNPRRenderWindowFactory::CreateRenderWindow(const char* backend)
{
  const std::string name = (backend && *backend) ? backend : GetDefaultBackend();
  vtkSmartPointer<vtkRenderWindow> window;
  if (name == "egl" || name == "osmesa")
  {
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
      vtkGenericWarningMacro(<< "no " << name << " render window: " << headless->GetContextError());
      return nullptr;
    }
    window = headless;
  }
  else if (name == "x")
  {
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display)
    {
      vtkGenericWarningMacro(<< "no x render window: DISPLAY is not set (run under xvfb-run, or "
                                "use NPR_BACKEND=egl)");
      return nullptr;
    }
    // VTK's X window aborts the process when the display cannot be opened: try it first.
    if (!OpenXDisplay(display))
    {
      vtkGenericWarningMacro(<< "no x render window: cannot open the X display '" << display
                             << "'");
      return nullptr;
    }
    window = vtkSmartPointer<vtkRenderWindow>::New(); // VTK's own X window
    window->SetOffScreenRendering(1);
  }
  else
  {
    vtkGenericWarningMacro(<< "unknown render window backend '" << name << "'; valid backends: "
                           << GetKnownBackends());
    return nullptr;
  }
  window->SetMultiSamples(0);
  window->Register(nullptr); // the caller owns this reference
  return window;
}

const char* vtkNPRRenderWindowFactory::GetBackendName(vtkRenderWindow* window)
{
  if (auto* headless = vtkNPRHeadlessRenderWindow::SafeDownCast(window))
  {
    return headless->GetBackendName();
  }
  if (window && std::strcmp(window->GetClassName(), "vtkXOpenGLRenderWindow") == 0)
  {
    return "x";
  }
  return "unknown";
}

const char* vtkNPRRenderWindowFactory::GetGLRenderer(vtkRenderWindow* window)
{
  if (auto* headless = vtkNPRHeadlessRenderWindow::SafeDownCast(window))
  {
    headless->InitializeContext();
    return headless->GetGLRenderer();
  }
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
