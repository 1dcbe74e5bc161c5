#!/usr/bin/env bash
# The quality evaluation (Herholz & Alexa 2019, section 7.2: Table 1 and
# Figs. 9, 13, 14) on this machine, from a fresh Debian 12 machine: installs
# the dependencies (plus librsvg2-bin and imagemagick for the pictures),
# fetches the libcgal-demo meshes, builds expmap-evaluate only and runs
#
#   --mesh-quality  regular / edge-flipped / anisotropic planar grids (Fig. 13)
#   --folds         fold-overs, distortion and the time factor on armadillo,
#                   bunny00, refined_elephant, camel, bull, dino (Figs. 9, 14)
#   --accuracy      sphere, Gaussian bump and saddle at three resolutions,
#                   against analytic and ODE references (Table 1)
#
# Writes
#   doc/accuracy_table.md, doc/mesh_quality.md, doc/folds.md   the tables
#   doc/evaluation/*.csv                                       the raw numbers
#   doc/evaluation/output.txt                                  what the program printed
#   doc/figures/*.png                                          the pictures
# (doc/results.md discusses them; benchmark/expmap_evaluate.cpp and the
# study files in benchmark/evaluation/ document every measure.)
#
# Arguments are passed to expmap-evaluate, e.g. `scripts/evaluate.sh --folds`
# or `--sources 20`. Time on 2 cores: about 6 minutes of evaluation (the exact
# polyhedral reference on the finest saddle takes one of them) plus the build
# (~1.5 minutes) and, on a fresh machine, the installs.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS

scripts/install-dependencies.sh
if [ "$(id -u)" -eq 0 ]; then sudo=(); else sudo=(sudo); fi
missing=()
for p in librsvg2-bin imagemagick; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
scripts/fetch-cgal-meshes.sh data/meshes

# Only this target: scripts/build.sh would also build every test suite.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DEXPMAP_BUILD_BENCHMARKS=ON >/dev/null
cmake --build build --target expmap_evaluate -j2
evaluate=build/benchmark/expmap-evaluate

svg=build/evaluation-svg
rm -rf "$svg"
mkdir -p doc/evaluation doc/figures
"$evaluate" --out doc --meshes data/meshes --svg-dir "$svg" "$@" | tee doc/evaluation/output.txt

# Pictures: one combined SVG per figure -> PNG, quantized to 64 colours so
# each stays well under 300 KB. ImageMagick's convert is called by its
# versioned name, so a different `convert` earlier in PATH cannot interfere.
magick=$(command -v convert-im6.q16 || command -v magick || echo /usr/bin/convert)
if [ -f "$svg/figures.txt" ]; then
  while read -r name; do
    [ -n "$name" ] || continue
    rsvg-convert "$svg/$name.svg" -o "$svg/$name.png"
    "$magick" "$svg/$name.png" -background '#fcfcfa' -alpha remove -alpha off +dither -colors 64 \
      "PNG8:doc/figures/$name.png"
    echo "doc/figures/$name.png: $(( $(stat -c %s "doc/figures/$name.png") / 1024 )) KB"
  done < "$svg/figures.txt"
fi
echo "evaluation done in $((SECONDS - start)) s: doc/*.md, doc/evaluation/, doc/figures/"
