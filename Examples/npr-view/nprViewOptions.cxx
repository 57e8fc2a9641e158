// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprViewOptions.h"

#include "nprArguments.h"
#include "nprPassOptions.h"
#include "nprViewer.h"

#include "vtkNPRPass.h"

#include <iostream>

namespace
{
const char* const Usage = R"(usage: npr-view [options] MODEL [MODEL...]

Shows the given models in an X window with the vtkNPR styles; mouse and keys as in VTK's
trackball camera, and the keys below. Needs an X display (use npr-render without one).
Models: .stl .obj .ply .vtp .vtk .gltf .glb .off

  --size WxH               window size in pixels (default 1024x768, or the size in
                           --camera-in's file)
  --background COLOR       a colour name, r,g,b in 0..1 or #rrggbb (default white)
  --camera-in FILE         start with this camera (JSON, as npr-render --camera-in)
  --output-prefix PREFIX   screenshots PREFIXNNNN.png, cameras PREFIXcamera-NNNN.json
                           (default npr-view-, in the current directory)
  --orbit-benchmark N      turn the camera 1 degree per frame for N frames, print one
                           JSON line with the frame times and exit
  -h, --help               this text
  --version                the program and vtkNPR version

)";
}

nprViewOptions nprParseViewOptions(int argc, char* argv[])
{
  nprViewOptions options;
  static const std::string help = std::string(Usage) + "Camera (not with --camera-in):\n" +
    nprCameraOptionsHelp + "\nKeys:\n" + nprViewKeys + "\n" + nprPassOptionsHelp;
  nprArgumentReader arguments(argc, argv, help.c_str());
  while (arguments.Next())
  {
    const std::string& arg = arguments.Current();
    if (nprParsePassOption(arguments, options.Pass) || nprParseSceneOption(arguments, options))
    {
      continue; // --style and the flags of the styles; the models, the frame and the camera
    }
    if (arg == "--output-prefix")
    {
      options.OutputPrefix = arguments.Value();
    }
    else if (arg == "--orbit-benchmark")
    {
      options.OrbitFrames = nprParseInteger(arg, arguments.Value(), 1, 100000);
    }
    else
    {
      throw nprUsageError("unknown option '" + arg + "' (see --help)");
    }
  }
  nprCheckSceneOptions(options);
  // The keys switch between every style: only what no style uses, or cannot work, is told.
  std::vector<std::string> styles;
  for (int style = vtkNPRPass::SHADED; style <= vtkNPRPass::DRAWING; ++style)
  {
    styles.push_back(vtkNPRPass::GetStyleName(style));
  }
  for (const std::string& warning : nprCheckPassOptions(options.Pass, styles))
  {
    std::cerr << "npr-view: warning: " << warning << "\n";
  }
  return options;
}
