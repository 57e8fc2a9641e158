// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// --azimuth, --elevation and --zoom, shared by npr-render and npr-view: the camera moves after the
// reset that fits the models in view.
#ifndef nprCameraOptions_h
#define nprCameraOptions_h

class nprArgumentReader;
class vtkRenderer;

// Their help text (ends with a newline).
extern const char* const nprCameraOptionsHelp;

struct nprCameraMove
{
  double Azimuth = 0.0;
  double Elevation = 0.0;
  double Zoom = 1.0;
  bool Given = false; // any of the three on the command line
};

// When the reader's current argument is one of the three, parses its value into move and returns
// true; false for any other argument. Throws nprUsageError for a bad value.
bool nprParseCameraOption(nprArgumentReader& arguments, nprCameraMove& move);

// Resets the renderer's camera to its props, then turns and zooms it by move.
void nprApplyCameraMove(vtkRenderer* renderer, const nprCameraMove& move);

#endif
