// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// What a frame of the G-buffer is drawn from, and where its props land on screen. Private to the
// passes module (vtkNPRGBufferPass): a frame with the same signature draws the same image, and
// only the rectangle the props cover needs the full-screen passes.
#ifndef vtkNPRFrameSignature_h
#define vtkNPRFrameSignature_h

#include "vtkType.h" // for vtkMTimeType

#include <algorithm> // for std::equal
#include <vector>    // for std::vector

class vtkCamera;
class vtkProp;
class vtkRenderState;

// What a G-buffer is drawn from: a frame with the same signature draws the same image.
struct vtkNPRFrameSignature
{
  struct PropStamp
  {
    vtkProp* Prop;
    vtkMTimeType Time;
    bool operator==(const PropStamp& other) const
    {
      return this->Prop == other.Prop && this->Time == other.Time;
    }
  };
  std::vector<PropStamp> Props;
  std::vector<vtkMTimeType> Lights;
  vtkCamera* Camera = nullptr;
  vtkMTimeType CameraTime = 0;
  // The renderer's own settings that change the shaded colour (its MTime also changes when
  // images are read back, so it cannot be used).
  double RendererSettings[5] = { 0, 0, 0, 0, 0 };
  vtkMTimeType PassTime = 0;
  int Size[2] = { 0, 0 };
  bool Normals = false;
  bool Ids = false;

  bool operator==(const vtkNPRFrameSignature& o) const
  {
    return this->Props == o.Props && this->Lights == o.Lights && this->Camera == o.Camera &&
      this->CameraTime == o.CameraTime &&
      std::equal(this->RendererSettings, this->RendererSettings + 5, o.RendererSettings) &&
      this->PassTime == o.PassTime && this->Size[0] == o.Size[0] && this->Size[1] == o.Size[1] &&
      this->Normals == o.Normals && this->Ids == o.Ids;
  }
};

// The signature of this frame: props and their redraw times, lights, camera, the renderer's
// shading settings, the pass's settings time, the size and the channels written.
vtkNPRFrameSignature vtkNPRTakeFrameSignature(const vtkRenderState* state, int width, int height,
  bool normals, bool ids, vtkMTimeType passTime);

// The screen rectangle (xmin, ymin, xmax, ymax, inclusive) that the bounds of the frame's opaque
// props project to, with a margin for wide lines; the whole buffer when unknown (a prop without
// bounds, a corner behind the eye), and xmax < xmin when nothing is on screen.
void vtkNPRScreenRectangleOfProps(const vtkRenderState* state, int width, int height, int rect[4]);

#endif
// VTK-HeaderTest-Exclude: vtkNPRFrameSignature.h
