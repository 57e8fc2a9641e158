#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# Sets up a Debian 12 machine for vtkNPR, builds it, then renders the examples or runs the tests.
#
#   bash Utilities/bootstrap.sh examples   # install what is missing, build, render the example
#                                          # scenes into build/examples/, the gallery into
#                                          # build/gallery/
#   bash Utilities/bootstrap.sh test       # install what is missing, build, run every test stage
#   bash Utilities/bootstrap.sh packages   # install what is missing, build, make this machine's
#                                          # Debian packages (Debian 12: VTK 9.1, ParaView 5.11)
#
# Installs only the Debian packages that are missing (apt-get; through sudo when not root), so a
# second run goes straight to the (incremental) build. NPR_BUILD_DIR overrides the build folder.
#
# `test` runs these stages, in this order (NPR_STAGES, a comma-separated list, picks some; the
# default is all of them, which CI runs; NPR_STAGES=host is the quick local run):
#   format         every tracked C++ file follows .clang-format (Utilities/check-format.sh)
#   host           Debian 12, VTK 9.1: build and all tests, in $NPR_BUILD_DIR
#   fuzz           Debian 12: npr-fuzz-readers (AddressSanitizer, UBSan) on NPR_FUZZ_MUTANTS
#                  (default 1000) mutants of every model format from NPR_FUZZ_SEED (default 1),
#                  or for NPR_FUZZ_SECONDS; then a fresh-seed campaign of
#                  NPR_FUZZ_FRESH_SECONDS (default 24) that reports without failing;
#                  mutants that fail land in $NPR_BUILD_DIR/fuzz/crashes (fresh-crashes)
#   sanitize       Debian 12, VTK 9.1, built with AddressSanitizer and UndefinedBehaviorSanitizer
#                  (NPR_SANITIZE=ON): all tests but the long-running ones, in
#                  $NPR_BUILD_DIR/sanitize; NPR_SKIP_SANITIZE=1 leaves it out (quick local runs)
#   vtk-9.3        Debian 13, VTK 9.3: the same build and tests in a chroot, in $NPR_BUILD_DIR/vtk-9.3
#   vtk-9.6        Debian unstable, VTK 9.6 (no OSMesa): the same, in $NPR_BUILD_DIR/vtk-9.6
#   paraview-5.11  Debian 12, ParaView 5.11: the plugin and its tests, in $NPR_BUILD_DIR/paraview-5.11
#   paraview-5.13  Debian 13, ParaView 5.13: the same, in $NPR_BUILD_DIR/paraview-5.13
#   paraview-6.1   Debian unstable, ParaView 6.1: the same, in $NPR_BUILD_DIR/paraview-6.1
#   packages-bookworm  Debian 12: the Debian packages (cpack) of the host build, in
#                  $NPR_BUILD_DIR/packages, and of the ParaView 5.11 plugin, in
#                  $NPR_BUILD_DIR/paraview-5.11/packages; installed into clean Debian 12 chroots
#                  and checked there (Utilities/check-packages.sh)
#   packages-trixie    Debian 13: the same for the vtk-9.3 and paraview-5.13 builds
#   packages-sid       Debian unstable: the same for the vtk-9.6 and paraview-6.1 builds
#                  NPR_SKIP_PACKAGES=1 leaves the three package stages out (quick local runs)
# The chroots (Utilities/debian-chroot.sh) are made once in /var/cache/vtknpr and kept; their
# set-up starts in the background while the host builds. Every build of `test` compiles through
# ccache, whose cache is kept beside them (NPR_COMPILER_CACHE, default /var/cache/vtknpr/ccache;
# NPR_COMPILER_CACHE=off compiles without it), so that a fresh clone rebuilds in a fraction of the
# time. Every stage runs even when an earlier one
# failed; a table of tests passed and seconds per stage closes the run, and the exit status is
# non-zero when any stage failed.
set -euo pipefail

task=${1:-}
if [[ $task != examples && $task != test && $task != packages ]]; then
  echo "usage: bash Utilities/bootstrap.sh examples|test|packages" >&2
  exit 2
fi
source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${NPR_BUILD_DIR:-$source_dir/build}

# VTK 9.1 with its Python bindings, EGL with Mesa's software renderer, OSMesa, Cairo, GLM (the
# lines' vector algebra, header only), the toolchain, and Xvfb for the tests of VTK's own X window.
packages=(libvtk9-dev python3-vtk9 libegl-dev libegl-mesa0 libgl1-mesa-dri libopengl-dev
  libosmesa6-dev libcairo2-dev libglm-dev cmake ninja-build g++ xvfb xauth)
# debootstrap for the chroots of the other releases (installed here, before their set-ups start
# side by side).
# dpkg-dev and file for CPack's Debian packages (dpkg-shlibdeps); xdotool to drive npr-view;
# ffmpeg for npr-render's MP4 videos; rsvg-convert and pdftoppm rasterise the exported SVG and PDF
# drawings in their tests.
if [[ $task == test ]]; then
  packages+=(debootstrap clang-format dpkg-dev file xdotool ffmpeg librsvg2-bin poppler-utils
    ccache)
elif [[ $task == packages ]]; then
  packages+=(debootstrap dpkg-dev file ccache)
fi
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

all_stages=(format host fuzz sanitize vtk-9.3 vtk-9.6 paraview-5.11 paraview-5.13 paraview-6.1
  packages-bookworm packages-trixie packages-sid)
IFS=, read -r -a stages <<<"${NPR_STAGES:-$(IFS=,; echo "${all_stages[*]}")}"
# `packages` makes the host release's packages alone, without the tests.
if [[ $task == packages ]]; then stages=(packages-bookworm); fi
for i in "${!stages[@]}"; do
  if [[ ${NPR_SKIP_SANITIZE:-0} != 0 && ${stages[i]} == sanitize ]] ||
    [[ ${NPR_SKIP_PACKAGES:-0} != 0 && ${stages[i]} == packages-* ]]; then
    unset 'stages[i]'
  fi
done
stages=("${stages[@]}")
for stage in "${stages[@]}"; do
  if [[ " ${all_stages[*]} " != *" $stage "* ]]; then
    echo "bootstrap: unknown stage '$stage' in NPR_STAGES (${all_stages[*]})" >&2
    exit 2
  fi
done
chroot_of() {
  case $1 in
    vtk-9.3) echo trixie-vtk ;;
    vtk-9.6 | paraview-6.1) echo sid ;;
    paraview-5.11) echo bookworm-paraview ;;
    paraview-5.13) echo trixie-paraview ;;
  esac
}
# The build stages whose packages a package stage installs.
builds_of() {
  case $1 in
    packages-bookworm) echo host paraview-5.11 ;;
    packages-trixie) echo vtk-9.3 paraview-5.13 ;;
    packages-sid) echo vtk-9.6 paraview-6.1 ;;
  esac
}

# Starts the set-up of every chroot the chosen stages need, in the background (downloads overlap
# the host's build); each logs to $build_dir/logs/chroot-NAME.log.
declare -A chroot_setup_pid=() chroot_setup_status=()
start_chroot_setups() {
  [[ $task != examples ]] || return 0
  local stage name build
  for stage in "${stages[@]}"; do
    for build in $stage $(builds_of "$stage"); do
      name=$(chroot_of "$build")
      if [[ -n $name && -z ${chroot_setup_pid[$name]:-} ]]; then
        bash "$source_dir/Utilities/debian-chroot.sh" "$name" setup \
          >"$build_dir/logs/chroot-$name.log" 2>&1 &
        chroot_setup_pid[$name]=$!
      fi
    done
  done
}

# Results per stage, for the closing table.
declare -A stage_passed=() stage_total=() stage_seconds=() stage_status=()
# Reads "N% tests passed, F tests failed out of T" from a ctest log.
record_ctest() {
  local stage=$1 log=$2 line
  line=$(grep -E "tests passed, [0-9]+ tests? failed out of [0-9]+" "$log" 2>/dev/null |
    tail -n 1 || true)
  if [[ $line =~ ([0-9]+)\ tests?\ failed\ out\ of\ ([0-9]+) ]]; then
    stage_total[$stage]=${BASH_REMATCH[2]}
    stage_passed[$stage]=$((BASH_REMATCH[2] - BASH_REMATCH[1]))
  fi
  # The format stage: "check-format: 117 of 117 files follow .clang-format".
  line=$(grep -E "[0-9]+ of [0-9]+ files follow" "$log" 2>/dev/null | tail -n 1 || true)
  if [[ $line =~ ([0-9]+)\ of\ ([0-9]+)\ files\ follow ]]; then
    stage_total[$stage]=${BASH_REMATCH[2]}
    stage_passed[$stage]=${BASH_REMATCH[1]}
  fi
  # The package stages: "check-packages: bookworm: 9 of 9 checks passed".
  line=$(grep -E "[0-9]+ of [0-9]+ checks passed" "$log" 2>/dev/null | tail -n 1 || true)
  if [[ $line =~ ([0-9]+)\ of\ ([0-9]+)\ checks\ passed ]]; then
    stage_total[$stage]=${BASH_REMATCH[2]}
    stage_passed[$stage]=${BASH_REMATCH[1]}
  fi
  # The fuzz stage: "...; 8 of 8 formats passed".
  line=$(grep -E "[0-9]+ of [0-9]+ formats passed" "$log" 2>/dev/null | tail -n 1 || true)
  if [[ $line =~ ([0-9]+)\ of\ ([0-9]+)\ formats\ passed ]]; then
    stage_total[$stage]=${BASH_REMATCH[2]}
    stage_passed[$stage]=${BASH_REMATCH[1]}
  fi
}

# ccache for the builds of `test`: a cache for the host and one per chroot (each release has its
# own ccache version), paths made relative to the source folder so that another clone hits it, and
# the working folder left out of the key (it is in the debug information of the sanitizer build
# only).
launcher=()
compiler_cache=${NPR_COMPILER_CACHE:-${NPR_CHROOT_BASE:-/var/cache/vtknpr}/ccache}
if [[ $task == examples || $compiler_cache == off ]] || ! command -v ccache >/dev/null ||
  ! { mkdir -p "$compiler_cache/host" 2>/dev/null && [[ -w $compiler_cache/host ]]; }; then
  compiler_cache= # (a user who cannot write there builds without it)
else
  export CCACHE_DIR=$compiler_cache/host CCACHE_BASEDIR=$source_dir CCACHE_NOHASHDIR=1
  export CCACHE_MAXSIZE=${CCACHE_MAXSIZE:-4G}
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi

build_host() {
  # Debian's interpreter: a python3 earlier on PATH (pyenv, venv) has no vtkmodules.
  if [[ ! -f $build_dir/CMakeCache.txt ]]; then
    cmake -S "$source_dir" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
      -DPython3_EXECUTABLE=/usr/bin/python3 "${launcher[@]}"
  fi
  cmake --build "$build_dir" -j "$(nproc)"
}

run_host_stage() {
  build_host 2>&1 | tee "$build_dir/logs/host.log"
  if ((PIPESTATUS[0] != 0)); then
    return 1
  fi
  ctest --test-dir "$build_dir" --output-on-failure -j 2 2>&1 | tee -a "$build_dir/logs/host.log"
  return "${PIPESTATUS[0]}"
}

# The reader fuzzer (Documentation/input.md), on the host build; its summary line gives the
# table's "formats passed/total". By default the same NPR_FUZZ_MUTANTS (1000) mutants of each
# format in every run, so that CI's verdict does not depend on the machine's speed;
# NPR_FUZZ_SECONDS explores for that long instead (new mutants, new findings).
run_fuzz_stage() {
  build_host >"$build_dir/logs/fuzz.log" 2>&1 || { cat "$build_dir/logs/fuzz.log"; return 1; }
  rm -rf "$build_dir/fuzz"
  local budget=(--mutants "${NPR_FUZZ_MUTANTS:-1000}")
  if [[ -n ${NPR_FUZZ_SECONDS:-} ]]; then budget=(--seconds "$NPR_FUZZ_SECONDS"); fi
  ASAN_OPTIONS=detect_leaks=0:exitcode=86 "$build_dir/bin/npr-fuzz-readers" \
    --seeds "$source_dir/Testing/Data/Fuzz/seeds" --work "$build_dir/fuzz/work" \
    --crashes "$build_dir/fuzz/crashes" "${budget[@]}" \
    --seed "${NPR_FUZZ_SEED:-1}" 2>&1 | tee -a "$build_dir/logs/fuzz.log"
  local verdict=${PIPESTATUS[0]}
  run_fresh_fuzz
  return "$verdict"
}

# A short campaign from a fresh seed (NPR_FUZZ_FRESH_SEED, default the date and $RANDOM; printed
# so that it can be replayed with --seed) for NPR_FUZZ_FRESH_SECONDS (default 24): new mutants
# every run. Its findings are printed and kept in $NPR_BUILD_DIR/fuzz/fresh-crashes, but do not
# fail the stage (--explore): only the fixed corpus above does.
run_fresh_fuzz() {
  local seed=${NPR_FUZZ_FRESH_SEED:-$(date +%Y%m%d)$RANDOM}
  echo "fuzz: a fresh campaign, seed $seed (findings reported, not failing the stage)" |
    tee -a "$build_dir/logs/fuzz.log"
  ASAN_OPTIONS=detect_leaks=0:exitcode=86 "$build_dir/bin/npr-fuzz-readers" \
    --seeds "$source_dir/Testing/Data/Fuzz/seeds" --work "$build_dir/fuzz/fresh-work" \
    --crashes "$build_dir/fuzz/fresh-crashes" --seconds "${NPR_FUZZ_FRESH_SECONDS:-24}" \
    --seed "$seed" --explore 2>&1 | sed 's/^/fresh: /' | tee -a "$build_dir/logs/fuzz.log"
}

# The host build with ASan and UBSan (cmake/vtkNPRSanitize.cmake), in a build folder of its own:
# every test but the long-running ones (label LongRunning: a thousand windows take minutes under
# ASan, and ASan's quarantine and shadow memory make their resident-memory bound meaningless;
# LeakSanitizer checks every other test's process for leaks). The sanitizers' options and the
# suppressions file come with each test's environment (Documentation/testing.md).
run_sanitize_stage() {
  local sanitize_dir=$build_dir/sanitize
  {
    if [[ ! -f $sanitize_dir/CMakeCache.txt ]]; then
      cmake -S "$source_dir" -B "$sanitize_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DNPR_SANITIZE=ON -DPython3_EXECUTABLE=/usr/bin/python3 "${launcher[@]}"
    fi
    cmake --build "$sanitize_dir" -j "$(nproc)"
  } 2>&1 | tee "$build_dir/logs/sanitize.log"
  if ((PIPESTATUS[0] != 0)); then
    return 1
  fi
  # A failed test runs once more; a real leak or error fails both runs. (LeakSanitizer's tracer
  # dying of signal 11 is avoided by the tests' LSAN_OPTIONS: Documentation/testing.md.)
  ctest --test-dir "$sanitize_dir" --output-on-failure -j 2 -LE LongRunning --repeat until-pass:2 2>&1 |
    tee -a "$build_dir/logs/sanitize.log"
  return "${PIPESTATUS[0]}"
}

# Waits (once) for the set-ups of the chroots a stage uses, started by start_chroot_setups; their
# exit statuses land in chroot_setup_status.
wait_stage_chroots() {
  local build name
  for build in $1 $(builds_of "$1"); do
    name=$(chroot_of "$build")
    if [[ -n $name && -n ${chroot_setup_pid[$name]:-} && -z ${chroot_setup_status[$name]:-} ]]; then
      chroot_setup_status[$name]=0
      wait "${chroot_setup_pid[$name]}" || chroot_setup_status[$name]=$?
    fi
  done
}

# Runs "$2" in the chroot of build stage $1, after configuring (once) and building there; the
# output goes to stdout.
run_in_chroot_build() {
  local stage=$1 command=$2 name configure
  name=$(chroot_of "$stage")
  # wait_stage_chroots waited for it, in the main shell (this runs in a pipeline's subshell).
  if ((${chroot_setup_status[$name]:-0} != 0)); then
    echo "bootstrap: the $name chroot could not be set up:" >&2
    tail -n 20 "$build_dir/logs/chroot-$name.log" >&2
    return 1
  fi
  if [[ $stage == paraview-* ]]; then
    configure="-DNPR_BUILD_PARAVIEW_PLUGIN=ON"
  else
    configure="-DPython3_EXECUTABLE=/usr/bin/python3"
  fi
  if [[ -n $compiler_cache ]]; then
    configure+=" -DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache"
  fi
  mkdir -p "$build_dir/$stage"
  NPR_CHROOT_BUILD=$build_dir/$stage NPR_CHROOT_CCACHE=${compiler_cache:+$compiler_cache/$name} \
    bash "$source_dir/Utilities/debian-chroot.sh" "$name" run "
    set -e
    if [ ! -f /build/CMakeCache.txt ]; then
      cmake -S /src -B /build -G Ninja -DCMAKE_BUILD_TYPE=Release $configure
    fi
    cmake --build /build -j $(nproc)
    $command" 2>&1
}

# Builds and tests in a chroot: the module and its tests, or the ParaView plugin.
run_chroot_stage() {
  local stage=$1 ctest_options
  if [[ $stage == paraview-* ]]; then
    # Each plugin test runs in an X server of its own; a rare failure to open the display is
    # retried once (Documentation/paraview.md).
    ctest_options="--repeat until-pass:2"
  else
    # VTK 9.6's own EGL window sometimes draws garbage in the frame after ReleaseGraphicsResources
    # while a second window is alive (npr.egl.windows, 7 of 40 runs): a failed test is run again,
    # up to twice; one that fails three times still fails the stage (Documentation/releases.md).
    ctest_options="-j 2 --repeat until-pass:3"
  fi
  run_in_chroot_build "$stage" "ctest --test-dir /build --output-on-failure $ctest_options" |
    tee "$build_dir/logs/$stage.log"
  return "${PIPESTATUS[0]}"
}

# The Debian packages of a package stage's release: cpack in its two build folders (built first
# where needed); prints the folders that hold them, one a line.
make_packages() {
  local build
  for build in $(builds_of "$1"); do
    if [[ $build == host ]]; then
      build_host >&2 && rm -rf "$build_dir/packages" &&
        (cd "$build_dir" && cpack -G DEB) >&2 || return 1
      echo "$build_dir/packages"
    else
      run_in_chroot_build "$build" "rm -rf /build/packages && cd /build && cpack -G DEB" >&2 ||
        return 1
      echo "$build_dir/$build/packages"
    fi
  done
}

# Lists the packages in the given folders with their sizes.
list_packages() {
  local folder
  for folder in "$@"; do
    ls -l "$folder"/*.deb | awk '{ print "  " $5 " bytes  " $NF }'
  done
}

# A package stage: the release's packages made, then installed into clean chroots of the release
# and checked (Utilities/check-packages.sh).
run_package_stage() {
  local stage=$1 folders=()
  mapfile -t folders < <(make_packages "$stage") && ((${#folders[@]} == 2)) || return 1
  echo "bootstrap: ${stage#packages-} packages:"
  list_packages "${folders[@]}"
  bash "$source_dir/Utilities/check-packages.sh" "${stage#packages-}" "${folders[@]}"
}

# After the table (CI keeps only the end of the output): the names of a failed stage's tests and
# the sanitizer's or ctest's first words on each.
report_failed_tests() {
  local stage=$1 log=$2
  [[ -f $log ]] || return 0
  echo "bootstrap: $stage: what failed ($log):"
  sed -n '/The following tests FAILED:/,$p' "$log" | grep -E '^[[:space:]]+[0-9]+ - ' | sed 's/^/  /'
  grep -E '(ERROR|SUMMARY): (Address|Leak|UndefinedBehavior)Sanitizer|Sanitizer has encountered|Tracer caught|runtime error:|\*\*\*(Timeout|Exception)|Subprocess aborted|Child aborted|: check failed: |Traceback|Error:|No space left|Killed|Segmentation fault|out of memory' \
    "$log" | sort | uniq -c | sort -rn | head -n 20 | sed 's/^/  /'
}

run_test_stages() {
  local stage start failed=0 passed_all=0 failed_all=0
  for stage in "${stages[@]}"; do
    echo "bootstrap: ---- stage $stage ----"
    start=$SECONDS
    wait_stage_chroots "$stage"
    if [[ $stage == format ]]; then
      if bash "$source_dir/Utilities/check-format.sh" 2>&1 | tee "$build_dir/logs/format.log"; then
        stage_status[$stage]=passed
      else
        stage_status[$stage]=FAILED
      fi
    elif [[ $stage == host ]]; then
      run_host_stage && stage_status[$stage]=passed || stage_status[$stage]=FAILED
    elif [[ $stage == fuzz ]]; then
      run_fuzz_stage && stage_status[$stage]=passed || stage_status[$stage]=FAILED
    elif [[ $stage == sanitize ]]; then
      run_sanitize_stage && stage_status[$stage]=passed || stage_status[$stage]=FAILED
    elif [[ $stage == packages-* ]]; then
      run_package_stage "$stage" 2>&1 | tee "$build_dir/logs/$stage.log"
      ((PIPESTATUS[0] == 0)) && stage_status[$stage]=passed || stage_status[$stage]=FAILED
    else
      run_chroot_stage "$stage" && stage_status[$stage]=passed || stage_status[$stage]=FAILED
    fi
    stage_seconds[$stage]=$((SECONDS - start))
    record_ctest "$stage" "$build_dir/logs/$stage.log"
    [[ ${stage_status[$stage]} == passed ]] || failed=1
  done
  echo "bootstrap: stage          result   tests passed/total   seconds"
  for stage in "${stages[@]}"; do
    printf 'bootstrap: %-14s %-8s %8s/%-12s %7s\n' "$stage" "${stage_status[$stage]}" \
      "${stage_passed[$stage]:-?}" "${stage_total[$stage]:-?}" "${stage_seconds[$stage]}"
    passed_all=$((passed_all + ${stage_passed[$stage]:-0}))
    failed_all=$((failed_all + ${stage_total[$stage]:-0} - ${stage_passed[$stage]:-0}))
  done
  echo "bootstrap: all stages took $((SECONDS - run_start)) s"
  # A stage that stopped before its tests counts as one failure.
  for stage in "${stages[@]}"; do
    if [[ ${stage_status[$stage]} != passed && -z ${stage_passed[$stage]:-} ]]; then
      failed_all=$((failed_all + 1))
    fi
  done
  echo "$passed_all passed, $failed_all failed"
  for stage in "${stages[@]}"; do
    [[ ${stage_status[$stage]} == passed ]] || report_failed_tests "$stage" "$build_dir/logs/$stage.log"
  done
  return "$failed"
}

run_start=$SECONDS
mkdir -p "$build_dir/logs"
start_chroot_setups

# Headless: no X server is needed or used.
unset DISPLAY
if [[ $task == examples ]]; then
  build_host
  cmake --build "$build_dir" --target render-examples gallery
  echo "bootstrap: example images in $build_dir/examples, every style in $build_dir/gallery:"
  ls -1 "$build_dir"/examples/*.png "$build_dir"/examples/*.svg "$build_dir"/gallery/*.png
elif [[ $task == packages ]]; then
  wait_stage_chroots packages-bookworm
  mapfile -t folders < <(make_packages packages-bookworm)
  ((${#folders[@]} == 2)) || { echo "bootstrap: the packages could not be made" >&2; exit 1; }
  echo "bootstrap: Debian 12 packages, made in $((SECONDS - run_start)) s" \
    "(install: Documentation/packages.md):"
  list_packages "${folders[@]}"
else
  run_test_stages
fi
