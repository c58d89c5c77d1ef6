#!/usr/bin/env bash
# Makes the pictures of README.md and docs/ with promyk render (never
# screenshots), so that each can be made again and checked: the test
# docs.pictures_up_to_date runs this script into a temporary folder and
# compares every picture with the committed one byte for byte.
#   docs/make_pictures.sh [PROMYK [FOLDER]]
# PROMYK defaults to build/release/promyk, FOLDER to docs/. Run it from
# anywhere; commit the pictures it writes when promyk's images change.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
promyk="$(realpath "${1:-$here/../build/release/promyk}")"
out="${2:-$here}"
case "$out" in -*) echo "make_pictures.sh: the folder must not begin with '-': $out" >&2; exit 2;; esac
mkdir -p "$out"
out="$(cd "$out" && pwd)"
export LANG=C.UTF-8
unset LC_ALL LC_MESSAGES LANGUAGE
cd "$here/.."

# README, 1. Render the article's scene (small: a picture for a page).
"$promyk" render --w 256 -o "$out/article.png" 2>/dev/null
# README: the 8 x 8 pane, each pixel a block, and its branch map.
"$promyk" render --w 8 --scale 32 --grid -o "$out/pane.png" 2>/dev/null
"$promyk" render --map branch --w 8 --scale 32 --grid -o "$out/branches.png" 2>/dev/null
# README, 3. Make your own scene: docs/my.json is the scene shown there.
"$promyk" render --scene docs/my.json --w 256 -o "$out/my.png" 2>/dev/null
# docs/maps.md: the error of float against quad.
"$promyk" render --map error --real float --w 128 -o "$out/error_float.png" 2>/dev/null
