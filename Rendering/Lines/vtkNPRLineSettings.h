// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPRLineSettings
 * @brief   Which feature lines to find: the line types and the crease angle, in one place.
 *
 * vtkNPRFeatureLines, vtkNPRReferenceMask and vtkNPRDrawingLines each hold one
 * (GetLineSettings()) and declare their Silhouettes, Creases, Boundaries, NonManifoldEdges and
 * crease angle (vtkNPRFeatureLines's FeatureAngle) with vtkNPRLineSettingsMacro, which forwards
 * to it: the values, their defaults and the angle's clamp are this class's alone. A holder's
 * GetMTime() includes the settings' modification time, so a changed setting changes the
 * holder's MTime as a setter of its own would.
 *
 * @sa vtkNPRFeatureLines vtkNPRReferenceMask vtkNPRDrawingLines
 */
#ifndef vtkNPRLineSettings_h
#define vtkNPRLineSettings_h

#include "vtkNPRLinesModule.h" // for export macro
#include "vtkObject.h"

class VTKNPRLINES_EXPORT vtkNPRLineSettings : public vtkObject
{
public:
  static vtkNPRLineSettings* New();
  vtkTypeMacro(vtkNPRLineSettings, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The line types (all on by default): silhouettes, creases, boundaries (edges of one face)
   * and non-manifold edges (edges of more than two faces); see vtkNPRFeatureLines.
   */
  vtkSetMacro(Silhouettes, bool);
  vtkGetMacro(Silhouettes, bool);
  vtkBooleanMacro(Silhouettes, bool);
  vtkSetMacro(Creases, bool);
  vtkGetMacro(Creases, bool);
  vtkBooleanMacro(Creases, bool);
  vtkSetMacro(Boundaries, bool);
  vtkGetMacro(Boundaries, bool);
  vtkBooleanMacro(Boundaries, bool);
  vtkSetMacro(NonManifoldEdges, bool);
  vtkGetMacro(NonManifoldEdges, bool);
  vtkBooleanMacro(NonManifoldEdges, bool);
  ///@}

  ///@{
  /**
   * The angle between face normals, in degrees, above which an edge is a crease (default 30,
   * vtkNPREdgePass's default; clamped to [0, 180]).
   */
  vtkSetClampMacro(CreaseAngle, double, 0.0, 180.0);
  vtkGetMacro(CreaseAngle, double);
  ///@}

  /**
   * Prints the settings one a line, as a holder's PrintSelf() shows them: the crease angle
   * under `angleName` (the holder's name for it).
   */
  void PrintSettings(ostream& os, vtkIndent indent, const char* angleName) const;

protected:
  vtkNPRLineSettings() = default;
  ~vtkNPRLineSettings() override = default;

  bool Silhouettes = true;
  bool Creases = true;
  bool Boundaries = true;
  bool NonManifoldEdges = true;
  double CreaseAngle = 30.0;

private:
  vtkNPRLineSettings(const vtkNPRLineSettings&) = delete;
  void operator=(const vtkNPRLineSettings&) = delete;
};

// The macros are laid out by hand: clang-format reads a row of macro calls as one expression.
// clang-format off

// One setting of a holder's LineSettings (vtkNew<vtkNPRLineSettings>) under the holder's name.
#define vtkNPRLineSettingForwardMacro(name, setting, type)                                         \
  virtual void Set##name(type value) { this->LineSettings->Set##setting(value); }                  \
  virtual type Get##name() { return this->LineSettings->Get##setting(); }

// A boolean setting: also its On() and Off().
#define vtkNPRLineSettingBooleanMacro(name)                                                        \
  vtkNPRLineSettingForwardMacro(name, name, bool)                                                  \
  vtkBooleanMacro(name, bool)

// The crease angle under the holder's name, with its clamp's ends.
#define vtkNPRLineSettingAngleMacro(name)                                                          \
  vtkNPRLineSettingForwardMacro(name, CreaseAngle, double)                                         \
  virtual double Get##name##MinValue() { return this->LineSettings->GetCreaseAngleMinValue(); }    \
  virtual double Get##name##MaxValue() { return this->LineSettings->GetCreaseAngleMaxValue(); }

/**
 * In the public section of a class that holds a `vtkNew<vtkNPRLineSettings> LineSettings`:
 * GetLineSettings(), the GetMTime() that includes it, and the Set/Get (On/Off) of every setting,
 * the crease angle as `angleName` (with its Get...MinValue() and Get...MaxValue()), all
 * forwarded to it.
 */
#define vtkNPRLineSettingsMacro(angleName)                                                         \
  vtkNPRLineSettings* GetLineSettings() { return this->LineSettings; }                             \
  vtkMTimeType GetMTime() override                                                                 \
  {                                                                                                \
    const vtkMTimeType own = this->Superclass::GetMTime();                                         \
    const vtkMTimeType settings = this->LineSettings->GetMTime();                                  \
    return own > settings ? own : settings;                                                        \
  }                                                                                                \
  vtkNPRLineSettingBooleanMacro(Silhouettes)                                                       \
  vtkNPRLineSettingBooleanMacro(Creases)                                                           \
  vtkNPRLineSettingBooleanMacro(Boundaries)                                                        \
  vtkNPRLineSettingBooleanMacro(NonManifoldEdges)                                                  \
  vtkNPRLineSettingAngleMacro(angleName)

// clang-format on

#endif
