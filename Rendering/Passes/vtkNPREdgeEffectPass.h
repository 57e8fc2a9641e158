// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNPREdgeEffectPass
 * @brief   The base of the image effects drawn from an edge pass: vtkNPRSketchPass and
 *          vtkNPRDrawingPass.
 *
 * Holds the vtkNPREdgePass whose G-buffer the effect reads (its vtkNPRGBufferPass, drawn earlier
 * in the frame; the edge pass itself is not rendered) and whose line settings it uses, and
 * supplies that G-buffer to the frame of vtkNPRImageEffectPass: without an edge pass or its
 * G-buffer nothing is drawn, with a warning.
 *
 * @sa vtkNPRImageEffectPass vtkNPREdgePass vtkNPRSketchPass vtkNPRDrawingPass
 */
#ifndef vtkNPREdgeEffectPass_h
#define vtkNPREdgeEffectPass_h

#include "vtkNPRImageEffectPass.h"
#include "vtkNPRPassesModule.h" // for export macro

class vtkNPREdgePass;

class VTKNPRPASSES_EXPORT vtkNPREdgeEffectPass : public vtkNPRImageEffectPass
{
public:
  vtkTypeMacro(vtkNPREdgeEffectPass, vtkNPRImageEffectPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The edge pass whose G-buffer is read and whose line settings are used (required).
   */
  virtual void SetEdgePass(vtkNPREdgePass* pass);
  vtkGetObjectMacro(EdgePass, vtkNPREdgePass);
  ///@}

protected:
  vtkNPREdgeEffectPass() = default;
  ~vtkNPREdgeEffectPass() override;

  // The edge pass's G-buffer (a step of vtkNPRImageEffectPass's frame).
  vtkNPRGBufferPass* GetGBuffer() override;

  vtkNPREdgePass* EdgePass = nullptr;

private:
  vtkNPREdgeEffectPass(const vtkNPREdgeEffectPass&) = delete;
  void operator=(const vtkNPREdgeEffectPass&) = delete;
};

#endif
