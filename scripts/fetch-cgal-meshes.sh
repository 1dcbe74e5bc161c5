#!/usr/bin/env bash
# Fetches the real meshes that Debian ships in libcgal-demo (armadillo,
# bunny00, refined_elephant, ...) into DEST (default: data/meshes).
# Needs apt-get (run `apt-get update` first on a fresh machine); no network
# access beyond Debian's package archive.
set -euo pipefail
dest=${1:-data/meshes}
if [ -f "$dest/armadillo.off" ] && [ -f "$dest/refined_elephant.off" ]; then
  exit 0
fi
mkdir -p "$dest"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
chmod 777 "$work"  # apt-get download drops privileges to _apt when it can
(cd "$work" && apt-get download -q libcgal-demo >/dev/null 2>&1 || apt-get download libcgal-demo)
dpkg-deb -x "$work"/libcgal-demo_*.deb "$work/pkg"
tar -xzf "$work/pkg/usr/share/doc/libcgal-dev/data.tar.gz" -C "$work" data/meshes
cp "$work"/data/meshes/* "$dest"/
echo "meshes in $dest: $(ls "$dest" | wc -l) files"
