#!/bin/sh
# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# Regenerates the images of Documentation/toon-sketch.md with the commands shown there.
#
#   Documentation/images/toon-sketch/make_images.sh build/bin/npr-render
#
# The commands run from the repository root (the model paths are relative to it) and write into
# this folder; each is printed as toon-sketch.md shows it, "npr-render ... -o NAME.png".
set -eu
. "$(dirname "$0")/../render_common.sh"

cad="Testing/Data/cad_part.vtp --size 480x360 --azimuth 30 --elevation 30"
bunny="Testing/Data/bunny.ply --size 480x360 --azimuth 20 --elevation 10"

# Toon shading, alone and with lines.
render toon.png $cad --style toon
render toon_edges.png $cad --style toon+edges

# Number of bands.
render toon_bands_2.png $bunny --style toon --toon-bands 2
render toon_bands_3.png $bunny --style toon --toon-bands 3
render toon_bands_6.png $bunny --style toon --toon-bands 6

# Per pixel and per vertex.
render toon_per_pixel.png $cad --zoom 1.8 --style toon --toon-bands 5
render toon_per_vertex.png $cad --zoom 1.8 --style toon --toon-bands 5 --toon-per-vertex

# The sketch: default, on paper, and filled with toon bands.
render sketch.png $cad --style sketch
render sketch_paper.png $cad --style sketch --paper-color 1,0.97,0.9
render sketch_toon.png $cad --style sketch --paper-color 1,0.97,0.9 --sketch-toon

# Uncertainty.
render sketch_uncertainty_0.png $bunny --style sketch --uncertainty 0
render sketch_uncertainty_3.png $bunny --style sketch --uncertainty 3
render sketch_uncertainty_8.png $bunny --style sketch --uncertainty 8

# Noise frequency and seed.
render sketch_frequency_0.5.png $bunny --style sketch --uncertainty 5 --noise-frequency 0.5
render sketch_frequency_6.png $bunny --style sketch --uncertainty 5 --noise-frequency 6
render sketch_seed_2.png $bunny --style sketch --uncertainty 5 --noise-seed 2

# A short orbit (6 degrees a frame) in both noise spaces: NAME_0001.png to NAME_0004.png.
orbit="Testing/Data/cad_part.vtp --size 240x180 --azimuth 30 --elevation 30 --zoom 1.6 --style sketch --uncertainty 4 --orbit 4 --orbit-degrees 24"
render orbit_surface.png $orbit
render orbit_screen.png $orbit --noise-space screen
