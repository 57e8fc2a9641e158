#!/bin/sh
# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# Regenerates the images of Documentation/classic-techniques.md with the commands shown there.
#
#   Documentation/images/classic/make_images.sh build/bin/npr-render
#
# The commands run from the repository root (the model paths are relative to it) and write into
# this folder; each is printed as classic-techniques.md shows it, "npr-render ... -o NAME.png".
set -eu
. "$(dirname "$0")/../render_common.sh"

cad="Testing/Data/cad_part.vtp --size 480x360 --azimuth 30 --elevation 30"
bunny="Testing/Data/bunny.ply --size 480x360 --azimuth 20 --elevation 10"

# Inking: fat back-face wireframe, then the faces with polygon offset.
render inked_cad.png $cad --style inked --line-width 2
render inked_bunny.png $bunny --style inked --line-width 2
render inked_width_4.png $bunny --style inked --line-width 4

# The G-buffer encodings of the edge pass.
for encoding in float half packed8 packed16; do
  render edges_${encoding}_cad.png $cad --style edges --encoding $encoding
  render edges_${encoding}_bunny.png $bunny --style edges --encoding $encoding
done
render edges_packed8_bunny_low.png $bunny --style edges --encoding packed8 --packed-threshold 0.03
render edges_packed8_bunny_blur.png $bunny --style edges --encoding packed8 --packed-blur --packed-threshold 0.05
