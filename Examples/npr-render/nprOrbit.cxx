// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprOrbit.h"

#include "nprFiles.h"
#include "nprWindowImage.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOggTheoraWriter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkWindowToImageFilter.h"
#ifdef NPR_HAS_VTK_FFMPEG
#include "vtkFFMPEGWriter.h"
#endif

#include <algorithm>
#include <cctype>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace
{
std::string Lower(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool EndsWith(const std::string& text, const std::string& end)
{
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// ffmpeg on PATH, or "".
std::string FindFFmpeg()
{
  const char* path = std::getenv("PATH");
  std::istringstream folders(path ? path : "/usr/bin:/bin");
  std::string folder;
  while (std::getline(folders, folder, ':'))
  {
    const std::string candidate = (folder.empty() ? "." : folder) + "/ffmpeg";
    if (access(candidate.c_str(), X_OK) == 0)
    {
      return candidate;
    }
  }
  return "";
}

std::string ShellQuoted(const std::string& text)
{
  std::string quoted = "'";
  for (char c : text)
  {
    quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  }
  return quoted + "'";
}

// A video file must be creatable before minutes of rendering are spent.
void CheckWritable(const std::string& path)
{
  std::ofstream probe(path, std::ios::binary | std::ios::trunc);
  if (!probe)
  {
    throw nprCannotWrite(path, "video");
  }
}

// Where the frames go.
class FrameSink
{
public:
  virtual ~FrameSink() = default;
  virtual void Add(vtkRenderWindow* window, int index) = 0;
  virtual void Finish() {}
};

class PNGSink : public FrameSink
{
public:
  PNGSink(const nprOrbitSettings& settings)
    : Settings(settings)
  {
  }
  void Add(vtkRenderWindow* window, int index) override
  {
    nprWritePNG(nprReadWindowImage(window, false),
      nprOrbitFramePath(this->Settings.Output, index, this->Settings.Frames));
  }

private:
  const nprOrbitSettings& Settings;
};

// A VTK movie writer fed from the window.
class MovieSink : public FrameSink
{
public:
  MovieSink(vtkRenderWindow* window, vtkGenericMovieWriter* writer, const std::string& path)
    : Writer(writer)
    , Path(path)
  {
    this->Grab->SetInput(window);
    this->Grab->SetInputBufferTypeToRGB();
    this->Grab->ReadFrontBufferOff();
    this->Grab->ShouldRerenderOff();
    writer->SetInputConnection(this->Grab->GetOutputPort());
    writer->SetFileName(path.c_str());
    writer->Start();
    this->Check();
  }
  void Add(vtkRenderWindow*, int) override
  {
    this->Grab->Modified();
    this->Writer->Write();
    this->Check();
  }
  void Finish() override
  {
    this->Writer->End();
    this->Check();
  }

private:
  void Check()
  {
    if (this->Writer->GetError())
    {
      throw std::runtime_error(this->Path + ": cannot write the video (" +
        vtkGenericMovieWriter::GetStringFromErrorCode(this->Writer->GetErrorCode()) + ")");
    }
  }
  vtkNew<vtkWindowToImageFilter> Grab;
  vtkSmartPointer<vtkGenericMovieWriter> Writer;
  std::string Path;
};

// Raw RGB frames piped into Debian's ffmpeg program (H.264 in MP4).
class FFmpegSink : public FrameSink
{
public:
  FFmpegSink(const std::string& ffmpeg, const nprOrbitSettings& settings, int width, int height)
    : Path(settings.Output)
  {
    std::ostringstream command;
    // Rows come bottom first (vflip); H.264 in 4:2:0 wants even sizes (pad).
    command << ShellQuoted(ffmpeg) << " -y -loglevel error -f rawvideo -pix_fmt rgb24 -s " << width
            << "x" << height << " -framerate " << settings.Rate << " -i - -vf "
            << ShellQuoted("vflip,pad=ceil(iw/2)*2:ceil(ih/2)*2")
            << " -c:v libx264 -pix_fmt yuv420p "
            << "-movflags +faststart " << ShellQuoted(settings.Output);
    this->PreviousSigpipe = std::signal(SIGPIPE, SIG_IGN); // a failed ffmpeg is an error here
    this->Pipe = popen(command.str().c_str(), "w");
    if (!this->Pipe)
    {
      throw std::runtime_error("cannot start " + ffmpeg);
    }
  }
  ~FFmpegSink() override
  {
    if (this->Pipe)
    {
      pclose(this->Pipe);
    }
    std::signal(SIGPIPE, this->PreviousSigpipe);
  }
  void Add(vtkRenderWindow* window, int) override
  {
    vtkSmartPointer<vtkImageData> image = nprReadWindowImage(window, false);
    const int* dims = image->GetDimensions();
    const size_t bytes = static_cast<size_t>(dims[0]) * dims[1] * 3;
    if (std::fwrite(image->GetScalarPointer(), 1, bytes, this->Pipe) != bytes)
    {
      this->Finish();
      throw std::runtime_error(this->Path + ": ffmpeg stopped taking frames");
    }
  }
  void Finish() override
  {
    const int status = this->Pipe ? pclose(this->Pipe) : 0;
    this->Pipe = nullptr;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    {
      throw std::runtime_error(this->Path + ": ffmpeg could not write the video");
    }
  }

private:
  std::string Path;
  FILE* Pipe = nullptr;
  void (*PreviousSigpipe)(int) = SIG_DFL;
};
}

std::string nprOrbitOutputKind(const std::string& output)
{
  const std::string name = Lower(output);
  if (EndsWith(name, ".png"))
  {
    return "png";
  }
  if (EndsWith(name, ".ogv") || EndsWith(name, ".ogg"))
  {
    return "ogv";
  }
  if (EndsWith(name, ".mp4"))
  {
    return "mp4";
  }
  if (EndsWith(name, ".avi"))
  {
    return "avi";
  }
  return "";
}

std::string nprOrbitFramePath(const std::string& output, int index, int count)
{
  const size_t width = std::max<size_t>(4, std::to_string(std::max(count, 1)).size());
  std::string number = std::to_string(index);
  if (number.size() < width)
  {
    number.insert(0, width - number.size(), '0');
  }
  const size_t dot = output.size() - 4; // ".png", checked by nprOrbitOutputKind
  return output.substr(0, dot) + "_" + number + output.substr(dot);
}

void nprCheckOrbitOutput(const nprOrbitSettings& settings)
{
  const std::string kind = nprOrbitOutputKind(settings.Output);
  if (kind == "mp4" && FindFFmpeg().empty())
  {
    throw std::runtime_error(settings.Output +
      ": writing MP4 needs the ffmpeg program (Debian package ffmpeg), which is not on PATH; "
      "write .ogv or PNG frames instead");
  }
#ifndef NPR_HAS_VTK_FFMPEG
  if (kind == "avi")
  {
    throw std::runtime_error(settings.Output +
      ": writing AVI needs VTK's vtkFFMPEGWriter, which this VTK does not have; write .ogv, "
      ".mp4 (with the ffmpeg program) or PNG frames instead");
  }
#endif
  if (kind != "png")
  {
    CheckWritable(settings.Output);
  }
}

void nprWriteOrbit(vtkRenderWindow* window, vtkRenderer* renderer, const nprOrbitSettings& settings)
{
  nprCheckOrbitOutput(settings);
  const int* size = window->GetSize();
  std::unique_ptr<FrameSink> sink;
  const std::string kind = nprOrbitOutputKind(settings.Output);
  if (kind == "ogv")
  {
    vtkNew<vtkOggTheoraWriter> writer;
    writer->SetRate(static_cast<int>(settings.Rate + 0.5));
    writer->SetQuality(2);
    sink.reset(new MovieSink(window, writer, settings.Output));
  }
  else if (kind == "mp4")
  {
    sink.reset(new FFmpegSink(FindFFmpeg(), settings, size[0], size[1]));
  }
#ifdef NPR_HAS_VTK_FFMPEG
  else if (kind == "avi")
  {
    vtkNew<vtkFFMPEGWriter> writer;
    writer->SetRate(static_cast<int>(settings.Rate + 0.5));
    writer->SetQuality(2);
    sink.reset(new MovieSink(window, writer, settings.Output));
  }
#endif
  else
  {
    sink.reset(new PNGSink(settings));
  }

  const bool terminal = isatty(fileno(stderr)) != 0;
  vtkCamera* camera = renderer->GetActiveCamera();
  const double step = settings.Degrees / settings.Frames;
  for (int index = 1; index <= settings.Frames; ++index)
  {
    if (index > 1)
    {
      camera->Azimuth(step);
      camera->OrthogonalizeViewUp();
      renderer->ResetCameraClippingRange();
    }
    window->Render();
    sink->Add(window, index);
    if (terminal)
    {
      std::cerr << "\rnpr-render: frame " << index << "/" << settings.Frames << std::flush;
    }
  }
  sink->Finish();
  if (terminal)
  {
    std::cerr << "\n";
  }
}
