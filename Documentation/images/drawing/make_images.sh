#!/bin/sh
# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# Regenerates the pictures of Documentation/drawing.md with the commands shown there.
#
#   Documentation/images/drawing/make_images.sh build/bin/npr-render
#
# The commands run from the repository root (the model paths are relative to it) and write into
# this folder: each drawing as the SVG that vtkNPRDrawingExporter writes, then rasterised for the
# page by rsvg-convert (librsvg2-bin) at its own size, 1 point = 1 pixel. The isosurface comes
# from isosurface_drawing.py in this folder, run with /usr/bin/python3 and the vtknpr package
# beside NPR_RENDER (../lib/python3/dist-packages: the build tree's or the installed one).
set -eu
. "$(dirname "$0")/../render_common.sh"

size=640x480
python_path=$(dirname "$npr_render")/../lib/python3/dist-packages

# rasterise NAME: NAME.svg -> NAME.png at the drawing's size.
rasterise() {
  echo "rsvg-convert -w ${size%x*} -h ${size#*x} $1.svg -o $1.png"
  rsvg-convert -w "${size%x*}" -h "${size#*x}" "$out/$1.svg" -o "$out/$1.png"
}

cad="Testing/Data/cad_part.vtp --size $size --azimuth 35 --elevation 25"
rotor="Testing/Data/rotor.ply --size $size --azimuth 35 --elevation 25"

# The CAD part and the rotor, without and with hidden lines.
render cad_part.svg $cad --style drawing
rasterise cad_part
render cad_part_hidden.svg $cad --style drawing --hidden-lines
rasterise cad_part_hidden
render rotor.svg $rotor --style drawing
rasterise rotor
render rotor_hidden.svg $rotor --style drawing --hidden-lines
rasterise rotor_hidden

# Filled faces: the CAD part's faces as filled regions under its lines.
render cad_part_filled.svg $cad --style drawing --hidden-lines --fill-faces --background 0.82,0.86,0.9
rasterise cad_part_filled
render cad_part_toon_filled.svg $cad --style toon --fill-faces --fill-colors toon
rasterise cad_part_toon_filled

# A drawing sheet of the CAD part: four views on A4, rasterised at the page's size in points.
render cad_part_sheet.svg Testing/Data/cad_part.vtp --sheet iso,front,top,right --hidden-lines
echo "rsvg-convert -w 842 -h 595 cad_part_sheet.svg -o cad_part_sheet.png"
rsvg-convert -b white -w 842 -h 595 "$out/cad_part_sheet.svg" -o "$out/cad_part_sheet.png"

# A scientific scene: an isosurface of VTK's wavelet, through vtkNPRPass and vtkNPRDrawingExporter.
for flags in "" --hidden-lines --smooth-silhouettes "--smooth-silhouettes --hidden-lines"; do
  case $flags in
    "") name=isosurface ;;
    --hidden-lines) name=isosurface_hidden ;;
    --smooth-silhouettes) name=isosurface_smooth ;;
    *) name=isosurface_smooth_hidden ;;
  esac
  echo "python3 Documentation/images/drawing/isosurface_drawing.py --size $size $flags -o $name.svg"
  PYTHONPATH="$python_path${PYTHONPATH:+:$PYTHONPATH}" /usr/bin/python3 \
    "$out/isosurface_drawing.py" --size "$size" $flags -o "$out/$name.svg"
  rasterise "$name"
done

# The same scene annotated: the outer surface coloured by height with its scalar bar, points above
# the sources and a title, faces filled in their colours under the outline box.
echo "python3 Documentation/images/drawing/isosurface_drawing.py --size $size --fill-faces surface --outline --annotate -o isosurface_annotated.svg"
PYTHONPATH="$python_path${PYTHONPATH:+:$PYTHONPATH}" /usr/bin/python3 \
  "$out/isosurface_drawing.py" --size "$size" --fill-faces surface --outline --annotate \
  -o "$out/isosurface_annotated.svg"
rasterise isosurface_annotated
rm "$out/isosurface_annotated.svg" # 27 MB: only the picture is kept
