# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# Sourced by the make_images.sh scripts (". ../render_common.sh" with the script's own
# arguments): checks them, moves to the repository root (the model paths are relative to it) and
# defines render NAME.png ARGS...: npr-render ARGS -o NAME.png, written into the calling script's
# folder and printed as the documentation shows it.
if [ $# -ne 1 ]; then
  echo "usage: $0 NPR_RENDER" >&2
  exit 2
fi
npr_render=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
out=$(cd "$(dirname "$0")" && pwd)
cd "$out/../../.."

render() {
  name=$1
  shift
  echo "npr-render $* -o $name"
  "$npr_render" "$@" -o "$out/$name"
}
