// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprFiles.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <unistd.h>

namespace fs = std::filesystem;

namespace
{
// The folder a file goes into; empty for a bare name (the current folder).
fs::path FolderOf(const std::string& path)
{
  return fs::path(path).parent_path();
}
}

void nprMakeOutputFolders(const std::string& path)
{
  const fs::path folder = FolderOf(path);
  std::error_code error;
  if (folder.empty() || fs::is_directory(folder, error))
  {
    return;
  }
  fs::create_directories(folder, error);
  if (error)
  {
    throw std::runtime_error(
      path + ": cannot create the folder " + folder.string() + ": " + error.message());
  }
}

std::string nprWhyNotWritable(const std::string& path)
{
  std::error_code error;
  if (fs::is_directory(path, error))
  {
    return "is a directory";
  }
  const fs::path folder = FolderOf(path);
  if (!folder.empty() && !fs::is_directory(folder, error))
  {
    return "no such directory: " + folder.string();
  }
  // Asked without opening, so that the question leaves no file behind.
  const std::string asked =
    fs::exists(path, error) ? path : (folder.empty() ? "." : folder.string());
  if (access(asked.c_str(), W_OK) != 0)
  {
    return std::strerror(errno);
  }
  return "the writer failed (the disk may be full)";
}

std::runtime_error nprCannotWrite(const std::string& path, const std::string& what)
{
  return std::runtime_error(path + ": cannot write the " + what + ": " + nprWhyNotWritable(path));
}
