#!/usr/bin/env bash
# Sets up a Debian 12 machine for vtkNPR, builds it, then renders the examples or runs the tests.
#
#   bash Utilities/bootstrap.sh examples   # install what is missing, build, render the example
#                                          # scenes into build/examples/
#   bash Utilities/bootstrap.sh test       # install what is missing, build, run all tests
#
# Installs only the Debian packages that are missing (apt-get; through sudo when not root), so a
# second run goes straight to the (incremental) build. NPR_BUILD_DIR overrides the build folder.
#
# `test` then builds and tests the ParaView plugin in a Debian 12 chroot with ParaView 5.11
# (Utilities/paraview-chroot.sh: created once in /var/cache/vtknpr/paraview-chroot and kept, so a
# second run installs nothing), in $NPR_BUILD_DIR/paraview-plugin. NPR_PARAVIEW_PLUGIN=OFF skips
# that stage (default ON).
set -euo pipefail

task=${1:-}
if [[ $task != examples && $task != test ]]; then
  echo "usage: bash Utilities/bootstrap.sh examples|test" >&2
  exit 2
fi
source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${NPR_BUILD_DIR:-$source_dir/build}

# VTK 9.1 with its Python bindings, EGL with Mesa's software renderer, OSMesa, the toolchain, and
# Xvfb for the tests of VTK's own X window.
packages=(libvtk9-dev python3-vtk9 libegl-dev libegl-mesa0 libgl1-mesa-dri libopengl-dev
  libosmesa6-dev cmake ninja-build g++ xvfb xauth)
missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if ((${#missing[@]})); then
  echo "bootstrap: installing ${missing[*]}"
  sudo=()
  if ((EUID != 0)); then sudo=(sudo); fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo[@]}" apt-get update -q
  "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# Debian's interpreter: a python3 earlier on PATH (pyenv, venv) has no vtkmodules.
if [[ ! -f $build_dir/CMakeCache.txt ]]; then
  cmake -S "$source_dir" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DPython3_EXECUTABLE=/usr/bin/python3
fi
cmake --build "$build_dir" -j "$(nproc)"

# Headless: no X server is needed or used.
unset DISPLAY
if [[ $task == examples ]]; then
  cmake --build "$build_dir" --target render-examples
  echo "bootstrap: example images in $build_dir/examples:"
  ls -1 "$build_dir"/examples/*.png
else
  ctest --test-dir "$build_dir" --output-on-failure -j 2
  if [[ ${NPR_PARAVIEW_PLUGIN:-ON} != OFF ]]; then
    start=$SECONDS
    mkdir -p "$build_dir/paraview-plugin"
    NPR_PLUGIN_BUILD_DIR=$build_dir/paraview-plugin \
      bash "$source_dir/Utilities/paraview-chroot.sh" run '
        set -e
        if [ ! -f /build/CMakeCache.txt ]; then
          cmake -S /src -B /build -G Ninja -DCMAKE_BUILD_TYPE=Release -DNPR_BUILD_PARAVIEW_PLUGIN=ON
        fi
        cmake --build /build -j 2
        ctest --test-dir /build --output-on-failure --repeat until-pass:2'
    echo "bootstrap: ParaView plugin stage took $((SECONDS - start)) s"
  fi
fi
