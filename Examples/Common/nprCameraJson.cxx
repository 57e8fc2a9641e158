// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprCameraJson.h"

#include "nprFiles.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtk_jsoncpp.h"
#include <memory>

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace
{
[[noreturn]] void Fail(const std::string& fileName, const std::string& message)
{
  throw std::runtime_error(fileName + ": " + message);
}

double Number(const Json::Value& value, const std::string& key, const std::string& fileName)
{
  if (!value.isNumeric())
  {
    Fail(fileName, "\"" + key + "\" must be a number");
  }
  const double number = value.asDouble();
  if (!std::isfinite(number))
  {
    Fail(fileName, "\"" + key + "\" must be finite");
  }
  return number;
}

template <size_t N>
std::array<double, N> Vector(
  const Json::Value& root, const std::string& key, const std::string& fileName)
{
  const Json::Value& value = root[key];
  if (!value.isArray() || value.size() != N)
  {
    Fail(fileName, "\"" + key + "\" must be an array of " + std::to_string(N) + " numbers");
  }
  std::array<double, N> result{};
  for (Json::ArrayIndex i = 0; i < N; ++i)
  {
    result[i] = Number(value[i], key, fileName);
  }
  return result;
}

std::string Array(const double* values, size_t count)
{
  std::string text = "[";
  for (size_t i = 0; i < count; ++i)
  {
    text += (i ? "," : "") + nprFormatNumber(values[i]);
  }
  return text + "]";
}
}

std::string nprFormatNumber(double value)
{
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  std::string text(buffer, result.ptr);
  if (text.find_first_of(".eEn") == std::string::npos)
  {
    text += ".0";
  }
  return text;
}

nprCameraState nprCameraState::FromCamera(vtkCamera* camera, int width, int height)
{
  nprCameraState state;
  camera->GetPosition(state.Position.data());
  camera->GetFocalPoint(state.FocalPoint.data());
  camera->GetViewUp(state.ViewUp.data());
  state.ViewAngle = camera->GetViewAngle();
  state.ParallelProjection = camera->GetParallelProjection() != 0;
  state.ParallelScale = camera->GetParallelScale();
  camera->GetClippingRange(state.ClippingRange.data());
  state.Size = { { width, height } };
  return state;
}

void nprCameraState::ApplyTo(vtkCamera* camera) const
{
  camera->SetPosition(this->Position.data());
  camera->SetFocalPoint(this->FocalPoint.data());
  camera->SetViewUp(this->ViewUp.data());
  camera->SetViewAngle(this->ViewAngle);
  camera->SetParallelProjection(this->ParallelProjection);
  camera->SetParallelScale(this->ParallelScale);
  camera->SetClippingRange(this->ClippingRange.data());
}

std::string nprCameraToJson(const nprCameraState& c)
{
  const double size[2] = { static_cast<double>(c.Size[0]), static_cast<double>(c.Size[1]) };
  std::string text = "{\"position\":" + Array(c.Position.data(), 3) +
    ",\"focal_point\":" + Array(c.FocalPoint.data(), 3) +
    ",\"view_up\":" + Array(c.ViewUp.data(), 3) +
    ",\"view_angle\":" + nprFormatNumber(c.ViewAngle) +
    ",\"parallel_projection\":" + (c.ParallelProjection ? "true" : "false") +
    ",\"parallel_scale\":" + nprFormatNumber(c.ParallelScale) +
    ",\"clipping_range\":" + Array(c.ClippingRange.data(), 2) + ",\"size\":[";
  text += std::to_string(static_cast<int>(size[0])) + "," +
    std::to_string(static_cast<int>(size[1])) + "]}";
  return text;
}

void nprWriteCameraFile(const std::string& fileName, const nprCameraState& camera)
{
  nprMakeOutputFolders(fileName);
  std::ofstream stream(fileName);
  stream << nprCameraToJson(camera) << "\n";
  stream.close();
  if (!stream)
  {
    throw nprCannotWrite(fileName, "camera file");
  }
}

namespace
{
// The file's JSON, strictly (no comments, no trailing commas); fails with the parser's message.
Json::Value ParseJsonFile(const std::string& fileName)
{
  std::ifstream stream(fileName);
  if (!stream)
  {
    Fail(fileName, "cannot open the camera file");
  }
  std::stringstream text;
  text << stream.rdbuf();
  Json::Value root;
  Json::CharReaderBuilder builder;
  Json::CharReaderBuilder::strictMode(&builder.settings_);
  std::string errors;
  const std::string content = text.str();
  std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
  if (!reader->parse(content.data(), content.data() + content.size(), &root, &errors))
  {
    const size_t newline = errors.find('\n');
    const size_t detail = errors.find_first_not_of(' ', newline + 1);
    Fail(fileName,
      "not valid JSON: " + errors.substr(0, newline) + " " +
        (detail == std::string::npos ? ""
                                     : errors.substr(detail, errors.find('\n', detail) - detail)));
  }
  return root;
}

// An object with the camera's keys, each once, "size" optional, nothing else.
void CheckKeys(const Json::Value& root, const std::string& fileName)
{
  if (!root.isObject())
  {
    Fail(fileName, "the camera must be a JSON object");
  }
  static const char* const keys[] = { "position", "focal_point", "view_up", "view_angle",
    "parallel_projection", "parallel_scale", "clipping_range", "size" };
  for (const std::string& member : root.getMemberNames())
  {
    bool known = false;
    for (const char* key : keys)
    {
      known = known || member == key;
    }
    if (!known)
    {
      Fail(fileName, "unknown key \"" + member + "\"");
    }
  }
  for (const char* key : keys)
  {
    if (!root.isMember(key) && std::string(key) != "size")
    {
      Fail(fileName, std::string("missing \"") + key + "\"");
    }
  }
}

// The values, each of its type; the size, where given, two integers in 1..16384.
nprCameraState CameraFromJson(Json::Value& root, const std::string& fileName)
{
  nprCameraState camera;
  camera.Position = Vector<3>(root, "position", fileName);
  camera.FocalPoint = Vector<3>(root, "focal_point", fileName);
  camera.ViewUp = Vector<3>(root, "view_up", fileName);
  camera.ViewAngle = Number(root["view_angle"], "view_angle", fileName);
  if (!root["parallel_projection"].isBool())
  {
    Fail(fileName, "\"parallel_projection\" must be true or false");
  }
  camera.ParallelProjection = root["parallel_projection"].asBool();
  camera.ParallelScale = Number(root["parallel_scale"], "parallel_scale", fileName);
  camera.ClippingRange = Vector<2>(root, "clipping_range", fileName);
  if (root.isMember("size"))
  {
    const std::array<double, 2> size = Vector<2>(root, "size", fileName);
    if (size[0] < 1 || size[1] < 1 || size[0] > 16384 || size[1] > 16384 ||
      size[0] != std::floor(size[0]) || size[1] != std::floor(size[1]))
    {
      Fail(fileName, "\"size\" must be two integers in 1..16384");
    }
    camera.Size = { { static_cast<int>(size[0]), static_cast<int>(size[1]) } };
  }
  return camera;
}

// A camera VTK can use: a view direction, an up vector off it, an angle, a scale and a range.
void CheckCamera(const nprCameraState& camera, const std::string& fileName)
{
  double direction[3];
  vtkMath::Subtract(camera.FocalPoint.data(), camera.Position.data(), direction);
  double side[3];
  vtkMath::Cross(direction, camera.ViewUp.data(), side);
  if (vtkMath::Norm(direction) == 0.0)
  {
    Fail(fileName, "\"position\" and \"focal_point\" are the same point");
  }
  if (vtkMath::Norm(side) <= 1e-12 * vtkMath::Norm(direction) * vtkMath::Norm(camera.ViewUp.data()))
  {
    Fail(fileName, "\"view_up\" is zero or parallel to the view direction");
  }
  if (camera.ViewAngle <= 0.0 || camera.ViewAngle >= 180.0)
  {
    Fail(fileName, "\"view_angle\" must be in (0, 180) degrees");
  }
  if (camera.ParallelScale <= 0.0)
  {
    Fail(fileName, "\"parallel_scale\" must be positive");
  }
  if (camera.ClippingRange[1] <= camera.ClippingRange[0] ||
    (!camera.ParallelProjection && camera.ClippingRange[0] <= 0.0))
  {
    Fail(fileName,
      "\"clipping_range\" must be [near, far] with far > near (and near > 0 in "
      "perspective)");
  }
}
}

nprCameraState nprReadCameraFile(const std::string& fileName)
{
  Json::Value root = ParseJsonFile(fileName);
  CheckKeys(root, fileName);
  const nprCameraState camera = CameraFromJson(root, fileName);
  CheckCamera(camera, fileName);
  return camera;
}

std::string nprJsonString(const std::string& text)
{
  std::string quoted = "\"";
  for (char c : text)
  {
    if (c == '"' || c == '\\')
    {
      quoted += '\\';
    }
    quoted += (static_cast<unsigned char>(c) < 0x20) ? ' ' : c;
  }
  return quoted + "\"";
}
