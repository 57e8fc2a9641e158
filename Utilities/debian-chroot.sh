#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# Debian chroots in which vtkNPR is built and tested against other VTK and ParaView releases.
#
#   bash Utilities/debian-chroot.sh NAME setup            # create it, install what is missing
#   bash Utilities/debian-chroot.sh NAME run 'command'    # setup, then run 'command' in /src
#   bash Utilities/debian-chroot.sh NAME refresh          # apt-get update + upgrade (on request)
#   bash Utilities/debian-chroot.sh NAME base             # only the release's minimal system
#   bash Utilities/debian-chroot.sh list                  # the chroots and what they hold
#
# NAME               Debian    what it holds
# trixie-vtk         13        VTK 9.3 (libvtk9-dev, python3-vtk9), OSMesa
# trixie-paraview    13        ParaView 5.13 (bundles VTK 9.3.1; conflicts with python3-vtk9)
# bookworm-paraview  12        ParaView 5.11 (bundles VTK 9.2; conflicts with the host's VTK 9.1)
# sid                unstable  VTK 9.6 and ParaView 6.1 (which uses the system VTK); no OSMesa
# bookworm-clean     12        nothing but Debian's minimal system: where vtkNPR's own packages
# trixie-clean       13        are installed and checked (Utilities/check-packages.sh mounts
# sid-clean          unstable  them as overlays on the release's base for each check)
#
# A chroot is made once with debootstrap in $NPR_CHROOT_BASE/NAME (default /var/cache/vtknpr)
# and kept. Packages are installed only when missing, and the package lists are updated only
# then, so a release whose archive moves on (Debian unstable) changes only on `refresh`.
# debootstrap makes each release's minimal system once, in $NPR_CHROOT_BASE/base-SUITE, and a
# chroot starts as a copy of it; the base is kept as it is, before any package is added, for the
# clean chroots. Downloaded packages stay in each chroot's apt cache, so that a clean chroot
# installs them without fetching them again.
# The archive is the one the host's own apt sources use for its release (NPR_DEBIAN_MIRROR
# overrides it). Needs root (uses sudo otherwise). Mounts are made in a private mount namespace
# and vanish when the command exits.
#
# Environment:
#   NPR_CHROOT_BASE    folder of the chroots (default /var/cache/vtknpr)
#   NPR_DEBIAN_MIRROR  Debian archive URI (default: from /etc/apt/sources.list{,.d})
#   NPR_CHROOT_BUILD   a host folder mounted at /build in the chroot (optional)
#   NPR_CHROOT_CCACHE  a host folder mounted at /ccache in the chroot, ccache's cache there
#                      (optional; CCACHE_DIR points to it)
set -Eeuo pipefail
trap 'echo "debian-chroot: ${name:-}: failed at line $LINENO" >&2' ERR

usage() {
  echo "usage: bash Utilities/debian-chroot.sh NAME setup|refresh|base | NAME run 'command' | list" >&2
  exit 2
}
name=${1:-}
action=${2:-}
if [[ $name == list ]]; then
  action=list
elif [[ $action != setup && $action != run && $action != refresh && $action != base ]]; then
  usage
fi
if ((EUID != 0)); then
  exec sudo --preserve-env=NPR_CHROOT_BASE,NPR_DEBIAN_MIRROR,NPR_CHROOT_BUILD,NPR_CHROOT_CCACHE \
    bash "${BASH_SOURCE[0]}" "$@"
fi
source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
base=${NPR_CHROOT_BASE:-/var/cache/vtknpr}

# What every chroot needs to build and test: the toolchain, Mesa's EGL (software), Xvfb, Cairo
# (the passes paint the drawing style's strokes with it), GLM (the lines' vector algebra, header
# only; the ParaView plugin compiles the lines too); and to make Debian packages with CPack
# (dpkg-shlibdeps, file).
common=(cmake ninja-build g++ ccache xvfb xauth libegl-mesa0 libgl1-mesa-dri libopengl-dev
  libcairo2-dev libglm-dev dpkg-dev file)
# VTK and its Python bindings; EGL's development files for the module's own EGL window (VTK < 9.4);
# xdotool to drive npr-view in its test; rsvg-convert and pdftoppm to rasterise the exported SVG and
# PDF drawings in theirs. The ParaView plugin compiles the passes and lines only and needs none of
# them.
vtk=(libvtk9-dev python3-vtk9 libegl-dev xdotool librsvg2-bin poppler-utils)
# PyVista on that VTK, for the vtknpr.pyvista entry point and PyVista's examples as clients.
pyvista=(python3-pyvista)
# ParaView's development files and the -dev packages its CMake configuration needs without
# depending on them (HDF5 and NetCDF: ParaView 5.13 reaches them through IOSS); MPI to run
# pvbatch in parallel.
paraview=(paraview paraview-dev python3-paraview libx11-dev libxcursor-dev libpng-dev
  libutfcpp-dev mpi-default-dev mpi-default-bin libglew-dev libgl-dev libfreetype-dev libjpeg-dev
  liblz4-dev liblzma-dev libtiff-dev libdouble-conversion-dev libpython3-dev python3-numpy
  libhdf5-dev libnetcdf-dev)
case $name in
  trixie-vtk) suite=trixie packages=("${common[@]}" "${vtk[@]}" "${pyvista[@]}" libosmesa6-dev) ;;
  trixie-paraview) suite=trixie packages=("${common[@]}" "${paraview[@]}") ;;
  bookworm-paraview) suite=bookworm packages=("${common[@]}" "${paraview[@]}") ;;
  sid) suite=sid packages=("${common[@]}" "${vtk[@]}" "${paraview[@]}" "${pyvista[@]}") ;;
  bookworm-clean | trixie-clean | sid-clean) suite=${name%-clean} packages=() ;;
  list)
    for known in trixie-vtk trixie-paraview bookworm-paraview sid bookworm-clean trixie-clean \
      sid-clean; do
      state="not created"
      [[ -x $base/$known/usr/bin/apt-get ]] && state="$base/$known"
      echo "$known: $state"
    done
    exit 0
    ;;
  *) echo "debian-chroot: unknown chroot '$name' (trixie-vtk, trixie-paraview, bookworm-paraview, sid, bookworm-clean, trixie-clean, sid-clean)" >&2
    exit 2 ;;
esac
root=$base/$name
# The host's archive may be a dated snapshot, whose Release files are past their Valid-Until
# (Debian unstable's expire a week after they are made): the signature is still checked.
apt_update_options="-o Acquire::Check-Valid-Until=false"

# The URI of the host's apt source for its own Debian release (deb822 or one-line format).
host_mirror() {
  local codename uri
  codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
  uri=$(awk -v suite="$codename" '
    /^URIs:/ { uri = $2 }
    /^Suites:/ { for (i = 2; i <= NF; i++) if ($i == suite && uri != "") { print uri; exit } }
    /^$/ { uri = "" }' /etc/apt/sources.list.d/*.sources 2>/dev/null | head -n 1)
  if [[ -z $uri ]]; then
    uri=$(awk -v suite="$codename" '$1 == "deb" {
        for (i = 2; i <= NF; i++) if ($i !~ /^\[/ && $i ~ /:\/\//) { if ($(i + 1) == suite)
          { print $i; exit } break } }' /etc/apt/sources.list /etc/apt/sources.list.d/*.list \
      2>/dev/null | head -n 1)
  fi
  echo "$uri"
}

# Runs "$1" (a shell command string) inside the chroot, /src being the source tree.
in_chroot() {
  unshare --mount --fork --propagation private /bin/bash -c '
    set -e
    root=$1 src=$2 command=$3 build=$4 ccache=$5
    cache_environment=()
    mount -t proc proc "$root/proc"
    mount --rbind /sys "$root/sys"
    mount --rbind /dev "$root/dev"
    mkdir -p "$root/src"
    mount --bind "$src" "$root/src"
    if [ -n "$build" ]; then
      mkdir -p "$root/build"
      mount --bind "$build" "$root/build"
    fi
    if [ -n "$ccache" ]; then
      mkdir -p "$root/ccache" "$ccache"
      mount --bind "$ccache" "$root/ccache"
      cache_environment=(CCACHE_DIR=/ccache CCACHE_NOHASHDIR=1)
    fi
    cp -L /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
    exec chroot "$root" /usr/bin/env -i HOME=/root LANG=C.UTF-8 TERM=dumb \
      PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
      DEBIAN_FRONTEND=noninteractive OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
      "${cache_environment[@]}" /bin/bash -c "cd /src && $command"
  ' in-chroot "$root" "$source_dir" "$1" "${NPR_CHROOT_BUILD:-}" "${NPR_CHROOT_CCACHE:-}"
}

# The release's minimal system, $NPR_CHROOT_BASE/base-SUITE, made once with debootstrap (chroots
# of one release may be set up side by side: the first to finish is kept).
make_base() {
  local kept=$base/base-$suite mirror partial
  [[ -x $kept/usr/bin/apt-get ]] && return 0
  mirror=${NPR_DEBIAN_MIRROR:-$(host_mirror)}
  if [[ -z $mirror ]]; then
    echo "debian-chroot: no Debian archive in the host's apt sources; set NPR_DEBIAN_MIRROR" >&2
    exit 1
  fi
  if ! command -v debootstrap >/dev/null; then
    echo "debian-chroot: installing debootstrap"
    DEBIAN_FRONTEND=noninteractive apt-get update -q
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends debootstrap
  fi
  partial=$kept.partial.$$
  echo "debian-chroot: debootstrap $suite into $kept"
  rm -rf "$partial"
  mkdir -p "$base"
  debootstrap --variant=minbase "$suite" "$partial" "$mirror"
  # Keep what apt downloads (a clean chroot reuses it), and no documentation.
  rm -f "$partial/etc/apt/apt.conf.d/docker-clean"
  printf '%s\n' 'path-exclude=/usr/share/doc/*' 'path-include=/usr/share/doc/*/copyright' \
    'path-exclude=/usr/share/man/*' 'path-exclude=/usr/share/locale/*' \
    >"$partial/etc/dpkg/dpkg.cfg.d/01-vtknpr-nodoc"
  echo 'force-unsafe-io' >"$partial/etc/dpkg/dpkg.cfg.d/02-vtknpr-unsafe-io"
  mv -T "$partial" "$kept" 2>/dev/null || rm -rf "$partial"
}

setup() {
  local start=$SECONDS
  if [[ ! -x $root/usr/bin/apt-get ]]; then
    make_base
    rm -rf "$root"
    cp -a "$base/base-$suite" "$root"
  fi
  local installed missing
  # dpkg-query fails for a package it has never seen: that one is missing too.
  installed=$(chroot "$root" dpkg-query -W -f='${Package} ${db:Status-Status}\n' \
    "${packages[@]}" 2>/dev/null | awk '$2 == "installed" { print $1 }' | sort || true)
  missing=$(comm -13 <(echo "$installed") <(printf '%s\n' "${packages[@]}" | sort) | tr '\n' ' ')
  if [[ -n ${missing// /} ]]; then
    echo "debian-chroot: $name: installing $missing"
    in_chroot "apt-get $apt_update_options update -q && apt-get install -y -q \
      --no-install-recommends $missing"
    echo "debian-chroot: $name ready in $((SECONDS - start)) s"
  fi
}

case $action in
  setup) setup ;;
  refresh)
    setup
    in_chroot "apt-get $apt_update_options update -q && apt-get upgrade -y -q"
    ;;
  base) make_base ;;
  run)
    setup
    if [[ -n ${NPR_CHROOT_BUILD:-} ]]; then mkdir -p "$NPR_CHROOT_BUILD"; fi
    in_chroot "$3"
    ;;
esac
