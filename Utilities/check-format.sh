#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# Checks that every tracked C++ file follows .clang-format (VTK's settings); with --fix, formats
# them. Templates configured by CMake (*.in) are left alone: clang-format breaks their @VAR@.
# Uses Debian's clang-format (14 on Debian 12): another release may format some lines otherwise.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
mapfile -t files < <(git ls-files '*.h' '*.cxx' | grep -v '^Testing/Data/')
if [[ ${1:-} == --fix ]]; then
  clang-format -i --style=file "${files[@]}"
  echo "check-format: formatted ${#files[@]} files"
  exit 0
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
