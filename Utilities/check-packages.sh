#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
# Installs vtkNPR's Debian packages of one release into a clean chroot of that release and checks
# them there (Testing/Packages/check-installed.sh): the release's minimal system, the packages'
# own dependencies as apt resolves them, and the tools the checks use (CMake, g++ and Ninja to
# build a consumer; Xvfb and pvpython for ParaView, which draws through X).
#
#   bash Utilities/check-packages.sh RELEASE DIR...
#
# RELEASE: bookworm, trixie or sid. DIR: folders holding the release's .deb files (cpack's
# output). On Debian 12 and 13 the library packages and the ParaView plugin are installed into
# separate clean chroots, as a user installs them: those releases' ParaView packages conflict
# with their VTK's Python package. On unstable, whose ParaView uses the system's VTK, all five go
# into one. apt reads the package lists of the release's build chroots (Utilities/debian-chroot.sh),
# so it installs the VTK and ParaView the packages were built against, and takes the packages the
# build chroots downloaded from their caches.
#
# Each clean chroot is an overlay (overlayfs) on the release's kept minimal system
# ($NPR_CHROOT_BASE/base-SUITE) with an empty upper layer, mounted at $NPR_CHROOT_BASE/RELEASE-clean
# and removed afterwards. Unpacking the 400-550 dependencies takes minutes, so they are installed
# once and kept as a layer of their own: apt first resolves, in a clean overlay, what installing
# the packages would pull in (`apt-get install -s`); a layer that holds exactly that list (its
# name is the list's hash) goes under the check's overlay, and apt then installs vtkNPR's packages
# alone, which the script verifies. When the resolution changes (new packages, new dependencies,
# a moved archive) a new layer is made from the minimal system. NPR_PACKAGE_LAYERS=0 installs
# everything from the minimal system every time; without overlayfs (or NPR_PACKAGE_OVERLAY=0)
# the clean chroot is a copy of the minimal system, without layers.
set -Eeuo pipefail
trap 'echo "check-packages: failed at line $LINENO" >&2' ERR

release=${1:-}
shift || true
case $release in
  bookworm) build_chroots=(bookworm-paraview) sets=(vtk paraview) ;;
  trixie) build_chroots=(trixie-vtk trixie-paraview) sets=(vtk paraview) ;;
  sid) build_chroots=(sid) sets=(all) ;;
  *) echo "usage: bash Utilities/check-packages.sh bookworm|trixie|sid DIR..." >&2; exit 2 ;;
esac
if (($# == 0)); then
  echo "check-packages: no folder of packages given" >&2
  exit 2
fi
if ((EUID != 0)); then
  exec sudo --preserve-env=NPR_CHROOT_BASE,NPR_DEBIAN_MIRROR,NPR_PACKAGE_LAYERS,NPR_PACKAGE_OVERLAY bash "${BASH_SOURCE[0]}" "$release" "$@"
fi
source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
base=${NPR_CHROOT_BASE:-/var/cache/vtknpr}
clean=$release-clean
root=$base/$clean
apt_cache=$base/apt-cache-$release

debs=()
for dir in "$@"; do
  for deb in "$dir"/*.deb; do
    [[ -f $deb ]] && debs+=("$deb")
  done
done
if ((${#debs[@]} == 0)); then
  echo "check-packages: no .deb in $*" >&2
  exit 1
fi

# The packages of one set: vtk (everything but the plugin), paraview (the plugin), all.
debs_of_set() {
  local deb package
  for deb in "${debs[@]}"; do
    package=$(dpkg-deb -f "$deb" Package)
    case $1 in
      vtk) [[ $package != paraview-vtknpr ]] && echo "$deb" ;;
      paraview) [[ $package == paraview-vtknpr ]] && echo "$deb" ;;
      all) echo "$deb" ;;
    esac
  done
  return 0
}

# Hard links (copies across file systems) of the .deb files of $1 into $2, those not there yet.
link_debs() {
  local from=$1 to=$2 deb
  [[ -d $from ]] || return 0
  mkdir -p "$to"
  for deb in "$from"/*.deb; do
    [[ -f $deb && ! -e $to/${deb##*/} ]] || continue
    ln "$deb" "$to/" 2>/dev/null || cp "$deb" "$to/"
  done
}

layers=$base/layers
mkdir -p "$layers"
upper=$base/$clean.upper
# The minimal system of the release, made with its build chroots (a machine whose chroots
# predate it makes one now).
bash "$source_dir/Utilities/debian-chroot.sh" "$clean" base

# The clean chroot: an overlay of the layers $@ (uppermost first) and the release's minimal
# system, with the empty upper layer $upper, at $root.
unmount_clean() {
  if mountpoint -q "$root"; then umount "$root"; fi
  rm -rf "$upper" "$upper.work"
  if [[ $use_overlay == 0 ]]; then rm -rf "$root"; fi
}
mount_clean() {
  local lower="" layer
  unmount_clean
  if [[ $use_overlay == 0 ]]; then # a copy of the minimal system instead
    rm -rf "$root"
    cp -a "$base/base-$release" "$root"
    return
  fi
  for layer in "$@"; do lower+="$layer:"; done
  lower+=$base/base-$release
  mkdir -p "$root" "$upper" "$upper.work"
  mount -t overlay overlay -o "lowerdir=$lower,upperdir=$upper,workdir=$upper.work" "$root"
}
# Without overlayfs (a kernel without it, NPR_PACKAGE_OVERLAY=0) each clean chroot is a copy of
# the minimal system and everything is installed every time.
use_overlay=${NPR_PACKAGE_OVERLAY:-1}
if ! grep -qw overlay /proc/filesystems; then
  echo "check-packages: no overlayfs here: each clean chroot is a copy, without layers"
  use_overlay=0
fi
if [[ $use_overlay == 0 ]]; then NPR_PACKAGE_LAYERS=0; fi
trap 'unmount_clean' EXIT

# apt's package lists ($lists: the first build chroot's, or those a set had to update), and the
# packages downloaded so far, in the chroot.
prepare_apt() {
  local chroot_name
  for chroot_name in "${build_chroots[@]}"; do
    if [[ ! -d $base/$chroot_name/var/lib/apt/lists ]]; then
      echo "check-packages: $release: the build chroot $chroot_name is missing" >&2
      exit 1
    fi
  done
  find "$lists" -maxdepth 1 -type f ! -name lock -exec cp -t "$root/var/lib/apt/lists/" {} +
  for chroot_name in "${build_chroots[@]}"; do
    link_debs "$base/$chroot_name/var/cache/apt/archives" "$root/var/cache/apt/archives"
  done
  link_debs "$apt_cache" "$root/var/cache/apt/archives"
}

# Runs $1 in the clean chroot, /build being $incoming; output to stdout.
in_clean() {
  NPR_CHROOT_BUILD=$incoming bash "$source_dir/Utilities/debian-chroot.sh" "$clean" run "$1"
}

apt_options="-y -q --no-install-recommends -o Acquire::Check-Valid-Until=false"
passed_all=0 total_all=0 failed=0
for set in "${sets[@]}"; do
  start=$SECONDS
  mapfile -t set_debs < <(debs_of_set "$set")
  if ((${#set_debs[@]} == 0)); then
    echo "check-packages: $release: no package of the set '$set' in $*" >&2
    failed=1 total_all=$((total_all + 1))
    continue
  fi
  version=$(dpkg-deb -f "${set_debs[0]}" Version)
  own=()
  for deb in "${set_debs[@]}"; do own+=("$(dpkg-deb -f "$deb" Package)"); done
  tools=()
  [[ $set != paraview ]] && tools+=(cmake g++ ninja-build)
  [[ $set != vtk ]] && tools+=(xvfb xauth python3-paraview)
  incoming=$(mktemp -d "$base/incoming.XXXXXX")
  cp "${set_debs[@]}" "$incoming/"
  log=$incoming/log
  status=0

  lists=$base/${build_chroots[0]}/var/lib/apt/lists
  layer_options=()
  if [[ ${NPR_PACKAGE_LAYERS:-1} != 0 ]]; then
    # What apt would install besides vtkNPR's packages, with versions (dependencies.txt), and
    # the layer that holds exactly that. A new layer's packages are downloaded first: when the
    # kept lists name versions the archive no longer has, the lists are updated and the
    # dependencies resolved again.
    mount_clean
    prepare_apt
    for attempt in kept updated; do
      if [[ $attempt == updated ]]; then
        echo "check-packages: $release: the kept package lists fail; updating them"
        in_clean "apt-get -o Acquire::Check-Valid-Until=false update -q" >"$log" 2>&1 ||
          { tail -n 20 "$log"; exit 1; }
        mkdir -p "$incoming/lists"
        find "$root/var/lib/apt/lists" -maxdepth 1 -type f ! -name lock \
          -exec cp -t "$incoming/lists/" {} +
        lists=$incoming/lists
      fi
      if ! in_clean "apt-get install -s $apt_options /build/*.deb ${tools[*]}" \
        >"$incoming/resolution.txt" 2>&1; then
        [[ $attempt == kept ]] && continue
        cat "$incoming/resolution.txt"
        exit 1
      fi
      awk -v own=" ${own[*]} " '/^Inst / && index(own, " " $2 " ") == 0 {
          version = $3; sub(/^\(/, "", version); print $2 "=" version }' \
        "$incoming/resolution.txt" | sort >"$incoming/dependencies.txt"
      key=$(sha256sum "$incoming/dependencies.txt" | cut -c1-16)
      layer=$layers/$release-$key
      [[ -d $layer ]] && break
      if in_clean "apt-get install --download-only $apt_options \$(cat /build/dependencies.txt)" \
        >"$log" 2>&1; then
        link_debs "$root/var/cache/apt/archives" "$apt_cache"
        break
      fi
      if [[ $attempt == updated ]]; then
        tail -n 20 "$log"
        exit 1
      fi
    done
    if [[ ! -d $layer ]]; then
      echo "check-packages: $release: a new layer of $(wc -l <"$incoming/dependencies.txt") dependencies ($layer)"
      printf '%s\n' "${tools[@]}" >"$incoming/tools.txt"
      # Those apt would pull in are marked automatically installed, as it would mark them.
      mount_clean
      prepare_apt
      in_clean "apt-get install $apt_options \$(cat /build/dependencies.txt) &&
        sed 's/=.*//' /build/dependencies.txt | grep -v -x -F -f /build/tools.txt |
        xargs -r apt-mark auto >/dev/null" >"$log" 2>&1 || { tail -n 30 "$log"; exit 1; }
      link_debs "$root/var/cache/apt/archives" "$apt_cache"
      rm -f "$upper"/var/cache/apt/archives/*.deb
      umount "$root"
      rm -rf "$layer.partial" && mv "$upper" "$layer.partial" && mv "$layer.partial" "$layer"
      rm -rf "$upper.work"
    fi
    touch "$layer"
    layer_options=("$layer")
    # Keep this release's two newest layers.
    ls -1dt "$layers/$release"-* 2>/dev/null | grep -v '\.partial$' | tail -n +3 | xargs -r rm -rf
  fi

  mount_clean "${layer_options[@]}"
  prepare_apt
  echo "check-packages: $release: installing $(cd "$incoming" && echo *.deb) into a clean chroot"
  in_clean "
    set -e
    apt-get install $apt_options /build/*.deb ${tools[*]} >/build/install.log 2>&1 ||
      { tail -n 40 /build/install.log; exit 1; }
    grep -E '^[0-9]+ upgraded, [0-9]+ newly installed' /build/install.log
    newly=\$(sed -n 's/^[0-9]* upgraded, \([0-9]*\) newly installed.*/\1/p' /build/install.log)
    if [ ${#layer_options[@]} -ne 0 ] && [ \"\$newly\" != ${#set_debs[@]} ]; then
      echo \"check-packages: apt installed \$newly packages over the layer, expected the ${#set_debs[@]} of vtkNPR alone\"
      exit 1
    fi
    bash /src/Testing/Packages/check-installed.sh $set $version" 2>&1 | tee "$log" || status=$?
  link_debs "$root/var/cache/apt/archives" "$apt_cache"
  unmount_clean
  line=$(grep -E "check-packages: [0-9]+ of [0-9]+ checks passed" "$log" | tail -n 1 || true)
  if [[ $line =~ ([0-9]+)\ of\ ([0-9]+)\ checks ]]; then
    passed_all=$((passed_all + BASH_REMATCH[1])) total_all=$((total_all + BASH_REMATCH[2]))
  else
    total_all=$((total_all + 1)) # the installation itself failed
  fi
  ((status == 0)) || failed=1
  rm -rf "$incoming"
  echo "check-packages: $release: set '$set' ($version) in $((SECONDS - start)) s"
done
echo "check-packages: $release: $passed_all of $total_all checks passed"
exit "$failed"
