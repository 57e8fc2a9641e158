// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-image-compare IMAGE BASELINE NAME: compares two PNGs with the harness's metric
// (nprTesting.h); exits 0 when they match. Used by the tests of npr-render's output.
#include "nprTesting.h"

#include "vtkImageData.h"

int main(int argc, char* argv[])
{
  if (argc != 4)
  {
    std::cerr << "usage: npr-image-compare IMAGE.png BASELINE.png NAME\n";
    return 2;
  }
  vtkSmartPointer<vtkImageData> image = nprReadPNG(argv[1]);
  if (!image)
  {
    std::cerr << "cannot read " << argv[1] << "\n";
    return 1;
  }
  return nprCompareWithBaselineFile(image, argv[2], argv[3]) ? 0 : 1;
}
