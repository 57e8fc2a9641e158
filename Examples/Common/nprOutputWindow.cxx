// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "nprOutputWindow.h"

#include "vtkObjectFactory.h"

#include <cctype>
#include <iostream>

vtkStandardNewMacro(nprOutputWindow);

void nprOutputWindow::DisplayText(const char* text)
{
  if (!text || !*text)
  {
    return;
  }
  this->Last = Summarise(text);
  if (!this->EchoPrefix.empty())
  {
    std::cerr << this->EchoPrefix << (this->Verbose ? std::string(text) : LastLine(text) + "\n");
  }
  else if (this->Verbose)
  {
    std::cerr << text;
  }
}

std::string nprOutputWindow::LastLine(std::string text)
{
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
  {
    text.pop_back();
  }
  text.erase(0, text.find_last_of('\n') + 1);
  return text;
}

std::string nprOutputWindow::Summarise(std::string text)
{
  text = LastLine(text);
  const size_t colon = text.find("): ");
  if (text.compare(0, 3, "vtk") == 0 && colon != std::string::npos)
  {
    text.erase(0, colon + 3);
  }
  return text;
}
