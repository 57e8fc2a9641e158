#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# Checks that every tracked C++ file follows .clang-format (VTK's settings); with --fix, formats
# them. Templates configured by CMake (*.in) are left alone: clang-format breaks their @VAR@.
# Also checks that every source, shader, script, CMake and module file names its licence (an
# SPDX-License-Identifier line among its first five: Documentation/contributing.md).
# Uses Debian's clang-format (14 on Debian 12): another release may format some lines otherwise.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
mapfile -t files < <(git ls-files '*.h' '*.cxx' | grep -v '^Testing/Data/')
if [[ ${1:-} == --fix ]]; then
  clang-format -i --style=file "${files[@]}"
  echo "check-format: formatted ${#files[@]} files"
  exit 0
fi
mapfile -t licensed < <(git ls-files '*.h' '*.cxx' '*.in' '*.glsl' '*.py' '*.sh' '*.cmake' \
  'CMakeLists.txt' '*vtk.module' '*paraview.plugin' '.ci/run' | grep -v '^Testing/Data/')
unlicensed=()
for file in "${licensed[@]}"; do
  if ! head -n 5 "$file" | grep -q 'SPDX-License-Identifier: '; then
    unlicensed+=("$file")
  fi
done
echo "check-format: $((${#licensed[@]} - ${#unlicensed[@]})) of ${#licensed[@]} files carry an SPDX licence header"
if ((${#unlicensed[@]})); then
  echo "check-format: these have none in their first five lines:" >&2
  printf '  %s\n' "${unlicensed[@]}" >&2
fi
unformatted=()
for file in "${files[@]}"; do
  if ! clang-format --dry-run -Werror --style=file "$file" >/dev/null 2>&1; then
    unformatted+=("$file")
  fi
done
echo "check-format: $((${#files[@]} - ${#unformatted[@]})) of ${#files[@]} files follow .clang-format" \
  "($(clang-format --version))"
if ((${#unformatted[@]})); then
  echo "check-format: these differ from it:" >&2
  printf '  %s\n' "${unformatted[@]}" >&2
  echo "check-format: run 'bash Utilities/check-format.sh --fix' and commit the result" >&2
  exit 1
fi
((${#unlicensed[@]} == 0))
