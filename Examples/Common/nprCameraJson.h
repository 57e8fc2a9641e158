// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Reads and writes the camera file of npr-render --camera-in / --camera-out:
// {"position":[x,y,z],"focal_point":[x,y,z],"view_up":[x,y,z],"view_angle":30.0,
//  "parallel_projection":false,"parallel_scale":1.0,"clipping_range":[near,far],"size":[w,h]}
#ifndef nprCameraJson_h
#define nprCameraJson_h

#include <array>
#include <stdexcept>
#include <string>

class vtkCamera;

struct nprCameraState
{
  std::array<double, 3> Position{ { 0, 0, 1 } };
  std::array<double, 3> FocalPoint{ { 0, 0, 0 } };
  std::array<double, 3> ViewUp{ { 0, 1, 0 } };
  double ViewAngle = 30.0;
  bool ParallelProjection = false;
  double ParallelScale = 1.0;
  std::array<double, 2> ClippingRange{ { 0.01, 1000.0 } };
  std::array<int, 2> Size{ { 0, 0 } }; // {0, 0}: the file gave none

  static nprCameraState FromCamera(vtkCamera* camera, int width, int height);
  void ApplyTo(vtkCamera* camera) const; // the clipping range is applied as given
};

// Throws std::runtime_error with one line naming the file and the problem.
nprCameraState nprReadCameraFile(const std::string& fileName);
void nprWriteCameraFile(const std::string& fileName, const nprCameraState& camera);
std::string nprCameraToJson(const nprCameraState& camera);

// Shortest text that reads back as the same double; integral values keep a ".0".
std::string nprFormatNumber(double value);

// text as a JSON string, quotes included (control characters become spaces).
std::string nprJsonString(const std::string& text);

#endif
