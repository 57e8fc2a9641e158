#!/bin/sh
# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# Regenerates the images of Documentation/edges.md with the commands shown there.
#
#   Documentation/images/edges/make_images.sh build/bin/npr-render
#
# The commands run from the repository root (the model paths are relative to it) and write into
# this folder; each is printed as edges.md shows it, "npr-render ... -o NAME.png".
set -eu
. "$(dirname "$0")/../render_common.sh"

# The edge style with every line type, and VTK's plain shading for comparison.
render edges.png Testing/Data/cad_part.vtp --style edges --size 480x360 --azimuth 30 --elevation 30
render shaded.png Testing/Data/cad_part.vtp --style shaded --size 480x360 --azimuth 30 --elevation 30

# Each line type alone.
render silhouettes.png Testing/Data/cad_part.vtp --style edges --size 480x360 --azimuth 30 --elevation 30 --lines silhouettes
render creases.png Testing/Data/cad_part.vtp --style edges --size 480x360 --azimuth 30 --elevation 30 --lines creases
render contours.png Testing/Data/bunny.ply Testing/Data/rotor.ply --style edges --size 480x360 --azimuth -20 --zoom 1.3 --lines contours

# Crease angle.
render crease_angle_20.png Testing/Data/cad_part.vtp --style edges --size 480x360 --azimuth 30 --elevation 30 --lines creases --crease-angle 20
render crease_angle_60.png Testing/Data/cad_part.vtp --style edges --size 480x360 --azimuth 30 --elevation 30 --lines creases --crease-angle 60

# Line width.
render line_width_1.png Testing/Data/cad_part.vtp --style edges --size 480x360 --azimuth 30 --elevation 30 --line-width 1
render line_width_3.png Testing/Data/cad_part.vtp --style edges --size 480x360 --azimuth 30 --elevation 30 --line-width 3
render line_width_6.png Testing/Data/cad_part.vtp --style edges --size 480x360 --azimuth 30 --elevation 30 --line-width 6

# Line weights: heavy silhouettes over light creases, in the edges and the drawing style.
render line_weights.png Testing/Data/cad_part.vtp --style edges --size 480x360 --azimuth 30 --elevation 30 --silhouette-width 3 --crease-width 0.75
render line_weights_drawing.png Testing/Data/cad_part.vtp --style drawing --hidden-lines --size 480x360 --azimuth 30 --elevation 30 --silhouette-width 2 --crease-width 0.75
render line_weights_depth.png Testing/Data/cad_part.vtp --style edges --size 480x360 --azimuth 30 --elevation 12 --zoom 1.3 --line-width 2 --depth-falloff --near-line-scale 2 --far-line-scale 0.4
render line_weights_taper.png Testing/Data/cad_part.vtp --style drawing --size 480x360 --azimuth 30 --elevation 30 --line-width 2.5 --taper 30 --curvature-width 0.5 --depth-falloff

# Contour side, on two models: the rotor stands in front of the bunny and cuts into it.
render contour_side_inside.png Testing/Data/bunny.ply Testing/Data/rotor.ply --style edges --size 480x360 --azimuth -20 --zoom 1.3 --lines contours --contour-side inside --contour-color 0.85,0,0 --line-width 4
render contour_side_outside.png Testing/Data/bunny.ply Testing/Data/rotor.ply --style edges --size 480x360 --azimuth -20 --zoom 1.3 --lines contours --contour-side outside --contour-color 0.85,0,0 --line-width 4
render contour_side_both.png Testing/Data/bunny.ply Testing/Data/rotor.ply --style edges --size 480x360 --azimuth -20 --zoom 1.3 --lines contours --contour-side both --contour-color 0.85,0,0 --line-width 4

# A colour per line type.
render colors.png Testing/Data/bunny.ply Testing/Data/rotor.ply --style edges --size 480x360 --azimuth -20 --zoom 1.3 --line-width 2 --silhouette-color 0.9,0,0 --crease-color 0,0.35,1 --contour-color 0,0.65,0

# Suggestive contours, red, with silhouettes and creases.
render suggestive.png Testing/Data/bunny.ply --style edges --size 480x360 --lines silhouettes,creases,suggestive --suggestive-color 0.85,0,0

# Stream tubes coloured by a scalar (Lines on thin objects): a Python example, with the wrapped
# modules of the same build.
PYTHONPATH="$(dirname "$npr_render")/../lib/python3/dist-packages" /usr/bin/python3 \
  Examples/Python/npr_stream_tubes.py --size 320x240 -o "$out/stream_tubes.png"
