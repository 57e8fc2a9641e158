#!/usr/bin/env bash
# Creates or updates a Debian 12 (bookworm) chroot with ParaView 5.11 and its development files, and
# runs a command inside it with the vtkNPR source tree bind-mounted at /src.
#
#   bash Utilities/paraview-chroot.sh setup            # create/update the chroot only
#   bash Utilities/paraview-chroot.sh run 'command'    # setup, then run 'command' in /src
#
# Debian's ParaView bundles VTK 9.2 and conflicts with the host's libvtk9-dev (VTK 9.1), so the
# plugin is built and tested here. The chroot lives outside the source tree and is kept between runs:
# a stamp file records the package list, so a second run installs nothing. Needs root (uses sudo
# otherwise). Mounts are made in a private mount namespace and vanish when the command exits.
#
# Environment:
#   NPR_PARAVIEW_CHROOT  chroot folder (default /var/cache/vtknpr/paraview-chroot)
#   NPR_DEBIAN_MIRROR    Debian mirror (default http://deb.debian.org/debian)
#   NPR_PLUGIN_BUILD_DIR a host folder mounted at /build in the chroot (optional)
set -euo pipefail

action=${1:-}
if [[ $action != setup && $action != run ]]; then
  echo "usage: bash Utilities/paraview-chroot.sh setup | run 'command'" >&2
  exit 2
fi
if ((EUID != 0)); then
  exec sudo --preserve-env=NPR_PARAVIEW_CHROOT,NPR_DEBIAN_MIRROR,NPR_PLUGIN_BUILD_DIR \
    bash "${BASH_SOURCE[0]}" "$@"
fi
source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
root=${NPR_PARAVIEW_CHROOT:-/var/cache/vtknpr/paraview-chroot}
mirror=${NPR_DEBIAN_MIRROR:-http://deb.debian.org/debian}

# ParaView, its development files and the -dev packages its CMake configuration needs without
# depending on them; MPI to run pvbatch in parallel; Xvfb because Debian's ParaView is GLX-only.
packages=(paraview paraview-dev python3-paraview
  cmake ninja-build g++ xvfb xauth
  libx11-dev libxcursor-dev libpng-dev libutfcpp-dev mpi-default-dev mpi-default-bin libglew-dev
  libgl-dev libfreetype-dev libjpeg-dev liblz4-dev liblzma-dev libtiff-dev libdouble-conversion-dev
  libpython3-dev python3-numpy libegl-dev)
# ^ libegl-dev: the NPR module's EGL render window is compiled into the plugin.
stamp=$root/.vtknpr-packages
wanted="bookworm ${packages[*]}"

# Runs "$@" (a shell command string) inside the chroot, /src being the source tree.
in_chroot() {
  unshare --mount --fork --propagation private /bin/bash -c '
    set -e
    root=$1 src=$2 command=$3 build=$4
    mount -t proc proc "$root/proc"
    mount --rbind /sys "$root/sys"
    mount --rbind /dev "$root/dev"
    mkdir -p "$root/src"
    mount --bind "$src" "$root/src"
    if [ -n "$build" ]; then
      mkdir -p "$root/build"
      mount --bind "$build" "$root/build"
    fi
    cp -L /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
    exec chroot "$root" /usr/bin/env -i HOME=/root LANG=C.UTF-8 TERM=dumb \
      PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
      DEBIAN_FRONTEND=noninteractive OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
      /bin/bash -c "cd /src && $command"
  ' in-chroot "$root" "$source_dir" "$1" "${NPR_PLUGIN_BUILD_DIR:-}"
}

if [[ ! -f $stamp || $(cat "$stamp") != "$wanted" ]]; then
  start=$SECONDS
  if [[ ! -x $root/usr/bin/apt-get ]]; then
    if ! command -v debootstrap >/dev/null; then
      echo "paraview-chroot: installing debootstrap"
      DEBIAN_FRONTEND=noninteractive apt-get update -q
      DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends debootstrap
    fi
    echo "paraview-chroot: debootstrap bookworm into $root"
    rm -rf "$root"
    mkdir -p "$(dirname "$root")"
    debootstrap --variant=minbase bookworm "$root.partial" "$mirror"
    mv "$root.partial" "$root"
  fi
  echo "paraview-chroot: installing ${packages[*]}"
  in_chroot "apt-get update -q && apt-get install -y -q --no-install-recommends ${packages[*]} \
    && apt-get clean"
  echo "$wanted" >"$stamp"
  echo "paraview-chroot: ready in $((SECONDS - start)) s"
fi

if [[ $action == run ]]; then
  in_chroot "$2"
fi
