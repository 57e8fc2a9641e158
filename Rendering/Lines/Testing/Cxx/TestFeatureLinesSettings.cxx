// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// TestFeatureLines' case of the line settings the filter, the reference mask and the drawing
// lines share (vtkNPRLineSettings): one settings object behind the setters of every class.
#include "nprFeatureLineTesting.h"

#include "vtkNPRDrawingLines.h"
#include "vtkNPRLineSettings.h"
#include "vtkNPRReferenceMask.h"
#include "vtkNew.h"

#include <iostream>
#include <sstream>
#include <string>

namespace
{
using namespace nprFeatureLineTesting;

// A holder (vtkNPRFeatureLines, vtkNPRReferenceMask, vtkNPRDrawingLines) starts with a fresh
// vtkNPRLineSettings's defaults, its setters and getters are GetLineSettings()'s, the angle is
// clamped as vtkNPRLineSettings clamps it, and a changed setting (through either) changes the
// holder's MTime while an unchanged one does not.
template <class Holder>
void CheckLineSettings(const std::string& name, const std::string& angleName,
  void (Holder::*setAngle)(double), double (Holder::*getAngle)())
{
  vtkNew<vtkNPRLineSettings> fresh;
  vtkNew<Holder> holder;
  vtkNPRLineSettings* settings = holder->GetLineSettings();
  NPR_CHECK(settings && settings->GetClassName() == std::string("vtkNPRLineSettings"),
    name << ": no line settings");
  if (!settings)
  {
    return;
  }
  NPR_CHECK(holder->GetSilhouettes() == fresh->GetSilhouettes() &&
      holder->GetCreases() == fresh->GetCreases() &&
      holder->GetBoundaries() == fresh->GetBoundaries() &&
      holder->GetNonManifoldEdges() == fresh->GetNonManifoldEdges() &&
      (holder.Get()->*getAngle)() == fresh->GetCreaseAngle() && fresh->GetCreaseAngle() == 30.0,
    name << ": defaults differ from vtkNPRLineSettings's");
  for (const double angle : { -5.0, 500.0, 45.0 })
  {
    (holder.Get()->*setAngle)(angle);
    fresh->SetCreaseAngle(angle);
    NPR_CHECK((holder.Get()->*getAngle)() == fresh->GetCreaseAngle() &&
        settings->GetCreaseAngle() == fresh->GetCreaseAngle(),
      name << ": " << angleName << " " << angle << " kept as " << (holder.Get()->*getAngle)()
           << ", vtkNPRLineSettings keeps " << fresh->GetCreaseAngle());
  }
  holder->SilhouettesOff();
  holder->SetNonManifoldEdges(false);
  settings->SetBoundaries(false);
  NPR_CHECK(!settings->GetSilhouettes() && !settings->GetNonManifoldEdges() &&
      !holder->GetBoundaries() && holder->GetCreases(),
    name << ": the setters and GetLineSettings() disagree");
  const vtkMTimeType before = holder->GetMTime();
  holder->SetCreases(true);
  NPR_CHECK(holder->GetMTime() == before, name << ": an unchanged setting changed the MTime");
  holder->CreasesOff();
  const vtkMTimeType changed = holder->GetMTime();
  settings->SetSilhouettes(true);
  NPR_CHECK(before < changed && changed < holder->GetMTime(),
    name << ": a changed setting left the MTime as it was");
  std::ostringstream printed;
  holder->Print(printed);
  NPR_CHECK(printed.str().find(angleName + ": 45\n") != std::string::npos &&
      printed.str().find("Silhouettes: 1\n") != std::string::npos,
    name << ": PrintSelf lacks the settings:\n"
         << printed.str());
}

int LineSettings()
{
  CheckLineSettings<vtkNPRFeatureLines>("vtkNPRFeatureLines", "FeatureAngle",
    &vtkNPRFeatureLines::SetFeatureAngle, &vtkNPRFeatureLines::GetFeatureAngle);
  CheckLineSettings<vtkNPRReferenceMask>("vtkNPRReferenceMask", "CreaseAngle",
    &vtkNPRReferenceMask::SetCreaseAngle, &vtkNPRReferenceMask::GetCreaseAngle);
  CheckLineSettings<vtkNPRDrawingLines>("vtkNPRDrawingLines", "CreaseAngle",
    &vtkNPRDrawingLines::SetCreaseAngle, &vtkNPRDrawingLines::GetCreaseAngle);
  // The pipeline sees a change made through GetLineSettings(): the creases go.
  auto filter = MakeFilter(AllTypes);
  filter->SetInputData(CubeSource());
  filter->Update();
  const size_t creases = EdgesOf(Lines(filter), vtkNPRFeatureLines::CREASE).size();
  filter->GetLineSettings()->CreasesOff();
  filter->Update();
  const size_t after = EdgesOf(Lines(filter), vtkNPRFeatureLines::CREASE).size();
  std::cout << creases << " crease edges of the cube, " << after
            << " after GetLineSettings()->CreasesOff()\n";
  NPR_CHECK(creases == 12 && after == 0, "the settings' change did not reach the output");
  return nprTestResult();
}
}
NPR_TEST_CASE("line-settings", LineSettings);
