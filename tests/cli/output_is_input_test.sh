#!/usr/bin/env bash
# An output may not be an input: `render --scene s.png --traces s.png`, an
# -o that is the scene by another path, a hard link or a symbolic link, or
# standard output appended to the scene: exit 2 before anything is written,
# the scene unchanged, no file created.
# usage: output_is_input_test.sh PROMYK WORKDIR
set -u
promyk=$1 dir=$2
. "$(dirname "$0")/lib.sh"
# messages are wrapped to 80 columns (continuation lines indented by 4): join them
j() { sed ':a;N;$!ba;s/\n    / /g' "$1"; }

scene='{"spheres": [{"S": [0, 0, 3], "r": 1}], "lights": [{"L": [1, 1, 0]}]}'
# refused NAME ARGS...: exit 2, "the output would replace the input", s.png
# as it was, and only the set-up's files in the folder.
refused() {
  local name=$1; shift
  local before; before=$(ls -A | sort | tr '\n' ' ')
  "$promyk" "$@" >>out.txt 2>err.txt
  local code=$?
  if [ "$code" = 2 ] && j err.txt | grep -q "would replace the input" && [ "$(cat s.png)" = "$scene" ] &&
     [ "$(ls -A | sort | tr '\n' ' ')" = "$before" ]; then ok
  else bad "$name: exit $code, s.png: $(head -c 80 s.png), files: $(ls -A | tr '\n' ' '), stderr: $(cat err.txt)"; fi
}

# The scene is named s.png, so that -o accepts the name (the loader reads it
# by its content) and the check, not the extension, is what refuses.
setup() { rm -rf ./* && echo "$scene" >s.png && : >out.txt && : >err.txt; }

setup; refused "--traces is the scene" render --w 8 --scene s.png -o x.png --traces s.png
setup; refused "-o is the scene" render --w 8 --scene s.png -o s.png
setup; refused "-o is the scene by ./" render --w 8 --scene s.png -o ./s.png
setup; mkdir d; refused "-o is the scene by d/../" render --w 8 --scene s.png -o d/../s.png
setup; ln s.png hard.png; refused "-o is a hard link to the scene" render --w 8 --scene s.png -o hard.png
setup; ln -s s.png link.png; refused "-o is a symbolic link to the scene" render --w 8 --scene s.png -o link.png
setup; ln -s s.png link.json; refused "the scene is a symbolic link to -o" render --w 8 --scene link.json -o s.png
setup; ln -s s.png link.jsonl; refused "--traces is a link to the scene" render --w 8 --scene s.png -o x.png --traces link.jsonl
# The issue's first example, with a scene named s.json.
rm -rf ./*; echo "$scene" >s.json
"$promyk" render --w 8 --scene s.json -o x.png --traces s.json >out.txt 2>err.txt
code=$?
if [ "$code" = 2 ] && j err.txt | grep -q "would replace the input" && [ "$(cat s.json)" = "$scene" ] && [ ! -e x.png ]; then ok
else bad "--scene s.json --traces s.json: exit $code: $(cat err.txt)"; fi
# Standard output appended to the scene.
setup
"$promyk" render --w 8 --scene s.png -o - >>s.png 2>err.txt
code=$?
if [ "$code" = 2 ] && j err.txt | grep -q "would replace the input" && [ "$(cat s.png)" = "$scene" ]; then ok
else bad "-o - appended to the scene: exit $code: $(cat err.txt)"; fi

# In Polish.
setup
"$promyk" --lang pl render --w 8 --scene s.png -o s.png >out.txt 2>err.txt
code=$?
if [ "$code" = 2 ] && j err.txt | grep -q "wynik zastąpiłby dane wejściowe"; then ok; else bad "Polish: exit $code: $(cat err.txt)"; fi

# Not refused: a copy of the scene, and the scene written beside itself.
setup; cp s.png copy.json
"$promyk" render --w 8 --scene copy.json -o s2.png --traces t.jsonl >out.txt 2>err.txt
code=$?
if [ "$code" = 0 ] && [ -s s2.png ] && [ -s t.jsonl ]; then ok; else bad "distinct files: exit $code: $(cat err.txt)"; fi

summary
