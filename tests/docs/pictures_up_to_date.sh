#!/usr/bin/env bash
# The committed pictures (docs/*.png) are what docs/make_pictures.sh makes
# today, byte for byte, and it makes no picture that is not committed.
#   pictures_up_to_date.sh PROMYK SCRATCH_FOLDER
set -euo pipefail
promyk="$1"
scratch="$2"
docs="$(cd "$(dirname "$0")/../../docs" && pwd)"
rm -rf "$scratch"
mkdir -p "$scratch"
bash "$docs/make_pictures.sh" "$promyk" "$scratch"
status=0
for made in "$scratch"/*.png; do
  name="$(basename "$made")"
  if [ ! -f "$docs/$name" ]; then
    echo "docs/$name is made by make_pictures.sh but not committed"; status=1
  elif ! cmp -s "$made" "$docs/$name"; then
    echo "docs/$name differs from what make_pictures.sh makes today: run docs/make_pictures.sh and commit"; status=1
  fi
done
for committed in "$docs"/*.png; do
  [ -e "$committed" ] || continue
  name="$(basename "$committed")"
  [ -f "$scratch/$name" ] || { echo "docs/$name is committed but make_pictures.sh no longer makes it"; status=1; }
done
[ $status -eq 0 ] && echo "$(ls "$scratch"/*.png | wc -l) pictures up to date"
exit $status
