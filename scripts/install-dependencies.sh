#!/usr/bin/env bash
# Installs what building and testing expmap needs, from Debian 12's archive.
# Run as root (or through sudo). Arguments name optional extra packages
# (scripts/build-docs.sh passes doxygen).
set -euo pipefail
if [ "$(id -u)" -ne 0 ]; then exec sudo "$0" "$@"; fi
export DEBIAN_FRONTEND=noninteractive
packages=(g++ cmake make ccache
          libcgal-dev libeigen3-dev libsuitesparse-dev libmetis-dev
          libboost-graph-dev libboost-test-dev
          libopenmesh-dev
          python3-numpy  # the test that loads `expmap batch` .npz output with NumPy
          "$@")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  apt-get update -q
  apt-get install -y -q --no-install-recommends "${missing[@]}"
else
  # apt-get download (for the meshes) needs package lists too.
  [ -n "$(ls -A /var/lib/apt/lists 2>/dev/null | grep -v lock)" ] || apt-get update -q
fi
