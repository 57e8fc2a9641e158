// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The files the programs write: their folders made on demand, and the reason one cannot be
// written, for every error that names a file.
#ifndef nprFiles_h
#define nprFiles_h

#include <stdexcept>
#include <string>

// Makes the missing folders above path, as mkdir -p does. Throws std::runtime_error
// "PATH: cannot create the folder DIR: REASON".
void nprMakeOutputFolders(const std::string& path);

// Why path cannot be written, for a writer that failed without saying: "is a directory",
// "no such directory: DIR", or the system's reason ("Permission denied", ...).
std::string nprWhyNotWritable(const std::string& path);

// The error of a writer that failed: "PATH: cannot write the WHAT: REASON".
std::runtime_error nprCannotWrite(const std::string& path, const std::string& what);

#endif
