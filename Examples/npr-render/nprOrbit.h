// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-render --orbit: the camera turned about the view up through the focal point, one frame per
// step, written as numbered PNGs, an Ogg Theora video (VTK's vtkOggTheoraWriter), an MP4
// (Debian's ffmpeg program) or an AVI (VTK's vtkFFMPEGWriter, where the installed VTK has it:
// it writes AVI whatever the name).
#ifndef nprOrbit_h
#define nprOrbit_h

#include <string>

class vtkRenderWindow;
class vtkRenderer;

struct nprOrbitSettings
{
  std::string Output; // NAME.png (NAME_0001.png, ...), NAME.ogv or .ogg, NAME.mp4, NAME.avi
  int Frames = 0;
  double Degrees = 360.0; // the whole turn; frame k is at k x Degrees / Frames
  double Rate = 25.0;     // frames per second of a video
};

// What an output name asks for: "png", "ogv", "mp4", "avi", or "" for any other extension.
std::string nprOrbitOutputKind(const std::string& output);

// The name of the index-th frame (from 1) of a PNG sequence of count frames: out.png gives
// out_0001.png (at least 4 digits).
std::string nprOrbitFramePath(const std::string& output, int index, int count);

// Throws std::runtime_error when the output cannot be written here (an MP4 without the ffmpeg
// program, an AVI without vtkFFMPEGWriter, a video file that cannot be created).
void nprCheckOrbitOutput(const nprOrbitSettings& settings);

// Renders and writes the frames, from the renderer's current camera, with a progress line on a
// terminal. Throws std::runtime_error when a file cannot be written.
void nprWriteOrbit(
  vtkRenderWindow* window, vtkRenderer* renderer, const nprOrbitSettings& settings);

#endif
