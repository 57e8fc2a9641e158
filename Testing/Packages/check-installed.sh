#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# Checks vtkNPR's installed Debian packages, inside the clean chroot they were installed in
# (Utilities/check-packages.sh runs it; /src is the source tree, read for its models and tests).
#
#   bash Testing/Packages/check-installed.sh SET VERSION
#
# SET: vtk (libvtknpr0.1, libvtknpr-dev, python3-vtknpr, vtknpr-tools), paraview (paraview-vtknpr)
# or all (both, on a release whose ParaView uses its VTK). VERSION: the packages' Debian version.
# Prints one line per check and "check-packages: N of M checks passed"; exits non-zero when one
# failed.
set -uo pipefail
set_name=${1:?SET} version=${2:?VERSION}
upstream=${version%%-*}
# The library package is named after the soname: major.minor.
library_package=libvtknpr$(echo "$upstream" | cut -d. -f1,2)
work=/tmp/vtknpr-checks
rm -rf "$work" && mkdir -p "$work"
passed=0 total=0

# check NAME COMMAND...: runs the command, its output in $work/NAME.log, shown on failure.
check() {
  local name=$1
  shift
  total=$((total + 1))
  if (cd "$work" && "$@") >"$work/$name.log" 2>&1; then
    passed=$((passed + 1))
    echo "check-packages: $name passed"
    # What it measured: pixel counts, the consumer's tests, versions.
    grep -E 'line pixels|tests passed|^npr-render [0-9]|NPRView:|version: [0-9]|[0-9] paths$' "$work/$name.log" |
      tail -n 4 | sed 's/^/    /'
  else
    echo "check-packages: $name FAILED:"
    tail -n 30 "$work/$name.log" | sed 's/^/    /'
  fi
}

installed_version() {
  local package
  for package in "$@"; do
    dpkg-query -W -f='${Package} ${Version} ${db:Status-Status}\n' "$package"
    [[ $(dpkg-query -W -f='${Version} ${db:Status-Status}' "$package") == "$version installed" ]] ||
      return 1
  done
}

check_vtk() {
  check packages-installed installed_version "$library_package" libvtknpr-dev python3-vtknpr vtknpr-tools
  check npr-render-version bash -c "npr-render --version | tee /dev/stderr | grep -qx 'npr-render $upstream'"
  # A model rendered headless (EGL, Mesa's llvmpipe) and its image checked.
  check npr-render-model bash -c "npr-render /src/Testing/Data/cad_part.vtp --style edges \
    --size 480x360 --azimuth 30 --elevation 30 -o $work/cad_part.png &&
    python3 /src/Testing/Packages/check_vtknpr.py image $work/cad_part.png"
  # An orbit as an Ogg Theora video (VTK's movie writer, a dependency of vtknpr-tools).
  check npr-render-orbit bash -c "npr-render /src/Testing/Data/cad_part.vtp --style sketch \
    --size 160x120 --orbit 4 -o $work/orbit.ogv && test \$(head -c 4 $work/orbit.ogv) = OggS"
  # A technical drawing as SVG (Cairo, through libvtknpr's dependencies): hidden lines dashed.
  check npr-render-drawing bash -c "npr-render /src/Testing/Data/cad_part.vtp --style drawing \
    --hidden-lines --size 480x360 --azimuth 30 --elevation 30 -o $work/part.svg &&
    grep -q 'class=\"npr-hidden\"' $work/part.svg && grep -q stroke-dasharray $work/part.svg &&
    echo \"\$(grep -c '<path' $work/part.svg) paths\""
  # The viewer, installed with the tools: without a display, one error line and exit status 1.
  check npr-view-no-display bash -c "env -u DISPLAY npr-view /src/Testing/Data/cad_part.vtp \
    2>$work/view.txt; status=\$?; cat $work/view.txt; test \$status -eq 1 &&
    grep -q 'no X display' $work/view.txt"
  # The system's Python, no PYTHONPATH: import vtknpr and render through vtkNPRPass.
  check python-vtknpr env -u PYTHONPATH python3 /src/Testing/Packages/check_vtknpr.py python "$upstream"
  # A separate project: find_package(vtkNPR) from /usr, built and its tests run (EGL rendering,
  # only NPR::Passes linked, OSMesa where the module has its own window).
  check find-package-consumer bash -c "cmake -S /src/Testing/Consumer -B $work/consumer -G Ninja \
    -DCMAKE_BUILD_TYPE=Release -DNPR_EXPECTED_DIR=/usr/lib/cmake/vtkNPR &&
    cmake --build $work/consumer && ctest --test-dir $work/consumer --output-on-failure"
  check find-package-version-refused bash -c "! cmake -S /src/Testing/Consumer/Version \
    -B $work/version-99 -G Ninja -DNPR_REQUESTED_VERSION=99 >$work/version-99.txt 2>&1 &&
    cat $work/version-99.txt && grep -q 'version: $upstream' $work/version-99.txt"
}

check_paraview() {
  # -noreset: pvbatch connects as pvpython, its parent, leaves; a resetting Xvfb would drop it.
  local xvfb_args="-screen 0 1280x1024x24 -noreset"
  check packages-installed-paraview installed_version paraview-vtknpr
  local plugin
  plugin=$(dpkg -L paraview-vtknpr | grep '/NPRView\.so$' | head -n 1)
  echo "check-packages: the plugin is $plugin"
  # pvpython loads the installed plugin by its path, reports its version, renders the NPR view.
  check pvpython-plugin xvfb-run -a -s "$xvfb_args" pvpython \
    /src/Testing/Packages/check_plugin.py "$plugin" "$upstream" "$work/plugin.png"
  # The documented way to load it at start-up: PV_PLUGIN_PATH, with the pvbatch snippet of
  # Documentation/paraview.md.
  check pvbatch-plugin-path xvfb-run -a -s "$xvfb_args" pvpython \
    /src/Plugin/Testing/Python/TestDocSnippet.py --pvbatch "$(command -v pvbatch)" \
    --plugin-dir "$(dirname "$plugin")" --page /src/Documentation/paraview.md \
    --output-dir "$work/doc-snippet"
}

case $set_name in
  vtk) check_vtk ;;
  paraview) check_paraview ;;
  all)
    check_vtk
    check_paraview
    ;;
  *) echo "check-installed: unknown set '$set_name' (vtk, paraview, all)" >&2; exit 2 ;;
esac
echo "check-packages: $passed of $total checks passed"
((passed == total))
