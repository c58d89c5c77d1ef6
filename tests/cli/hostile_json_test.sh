#!/usr/bin/env bash
# Deep and huge JSON (issue 19, hostile runs): scenes nested 100 000 deep,
# a scene over 1 MiB, a number literal of 100 000 digits, arrays of a million
# elements, and the same shapes as diff's trace files and as --answers. Each
# is refused with exit 3 and a message naming the file, within 3 s of
# processor time, under a memory and time cap (prlimit: 2 GB of address
# space, 20 s of processor time; 30 s of wall-clock time):
# never a crash, a stack overflow (a signal) or exit 70.
# usage: hostile_json_test.sh PROMYK WORKDIR
set -u
promyk=$1 dir=$2
. "$(dirname "$0")/lib.sh"
# messages are wrapped to 80 columns (continuation lines indented by 4): join them
j() { sed ':a;N;$!ba;s/\n    / /g' "$1"; }

# nested N OPEN CLOSE: OPEN N times, then CLOSE N times.
nested() { awk -v n="$1" -v o="$2" -v c="$3" 'BEGIN { for (k = 0; k < n; k++) printf "%s", o; for (k = 0; k < n; k++) printf "%s", c; print "" }'; }
# many N ITEM: a JSON array of N copies of ITEM.
many() { awk -v n="$1" -v x="$2" 'BEGIN { printf "["; for (k = 0; k < n; k++) printf "%s%s", (k ? "," : ""), x; print "]" }'; }
digits() { awk -v n="$1" 'BEGIN { for (k = 0; k < n; k++) printf "%d", (k % 9) + 1 }'; }

# refused NAME FILE-IN-MESSAGE COMMAND...: exit 3 within 3 s of processor
# time (user + system: the wall-clock time of a machine shared by several
# builds says little; 30 s of it end the run), a message on stderr that
# names the file, nothing on stdout, no image left.
refused() {
  local name=$1 file=$2
  shift 2
  local TIMEFORMAT='%3U %3S' code
  { time prlimit --as=2000000000 --cpu=20 -- timeout -s KILL 30 "$promyk" "$@" >out.txt 2>err.txt; } 2>time.txt
  code=$?
  local ms
  ms=$(awk '{ printf "%d", ($1 + $2) * 1000 }' time.txt)
  if [ "$code" != 3 ]; then
    bad "$name: exit $code, expected 3: $(head -c 300 err.txt)"
    return
  fi
  [ "$ms" -le 3000 ] || { bad "$name: took $ms ms of processor time"; return; }
  j err.txt | grep -qF "$file" || { bad "$name: the message does not name $file: $(head -c 300 err.txt)"; return; }
  [ ! -s out.txt ] || { bad "$name: wrote standard output"; return; }
  [ ! -e x.png ] || { bad "$name: left x.png"; rm -f x.png; return; }
  ok
}

# --- scenes ---------------------------------------------------------------
nested 100000 '[' ']' >deep_array.json
nested 100000 '{"a":' '}' >deep_object.json
{ printf '{"spheres": '; nested 100000 '[' ']'; printf '}'; } >deep_inside.json
{ printf '{"spheres": [{"S": [0, 0, 3], "r": '; nested 100000 '{"r":' '}'; printf '}], "lights": [{"L": [1, 1, 1]}]}'; } \
  >deep_value.json
nested 100000 '[' '' >deep_unclosed.json
for scene in deep_array deep_object deep_inside deep_value deep_unclosed; do
  refused "scene $scene" "$scene.json" render --scene "$scene.json" -o x.png --w 8
  refused "scene check $scene" "$scene.json" scene check "$scene.json"
done
grep -q "nest" err.txt || bad "the nesting is not named: $(cat err.txt)"
# Over 1 MiB: valid JSON, the spheres padded with spaces.
awk 'BEGIN { printf "{\"spheres\": ["; for (k = 0; k < 40000; k++) printf "%s{\"S\": [0, 0, %d], \"r\": 1}", (k ? ", " : ""), k + 3; print "], \"lights\": [{\"L\": [1, 1, 1]}]}" }' \
  >big.json
[ "$(wc -c <big.json)" -gt 1048576 ] || bad "set-up: big.json is not over 1 MiB"
refused "scene over 1 MiB" "big.json" render --scene big.json -o x.png --w 8
j err.txt | grep -q "1048576\|1 MiB" || bad "scene over 1 MiB: the limit is not named: $(cat err.txt)"
# A million-element array (2 MB): over the limit too; half a million within it.
{ printf '{"spheres": '; many 1000000 0; printf ', "lights": [{"L": [1, 1, 1]}]}'; } >million.json
refused "scene of a million-element array" "million.json" render --scene million.json -o x.png --w 8
{ printf '{"spheres": '; many 500000 0; printf ', "lights": [{"L": [1, 1, 1]}]}'; } >half_million.json
refused "scene of half a million numbers" "half_million.json" render --scene half_million.json -o x.png --w 8
# Number literals: 100 000 digits (infinite in double), its inverse, and a huge exponent.
printf '{"z_E": %s, "spheres": [{"S": [0, 0, 3], "r": 1}], "lights": [{"L": [1, 1, 1]}]}\n' "$(digits 100000)" >long_number.json
refused "a number of 100 000 digits" "long_number.json" render --scene long_number.json -o x.png --w 8
j err.txt | grep -q "z_E" || bad "long number: the field is not named: $(cat err.txt)"
printf '{"z_E": 0.%s, "spheres": [{"S": [0, 0, 3], "r": 1}], "lights": [{"L": [1, 1, 1]}]}\n' "$(digits 100000)" \
  >long_fraction.json
"$promyk" render --scene long_fraction.json -o x.png --w 8 >out.txt 2>err.txt && ok || bad "a fraction of 100 000 digits: exit $?"
rm -f x.png
printf '{"z_E": 1e999999999999, "spheres": [{"S": [0, 0, 3], "r": 1}], "lights": [{"L": [1, 1, 1]}]}\n' >huge_exponent.json
refused "a huge exponent" "huge_exponent.json" render --scene huge_exponent.json -o x.png --w 8
printf '{"z_E": 2, "spheres": [{"S": [0, 0, 3], "r": 1e-999999999999}], "lights": [{"L": [1, 1, 1]}]}\n' >tiny_exponent.json
refused "a tiny exponent" "tiny_exponent.json" render --scene tiny_exponent.json -o x.png --w 8

# --- diff's trace files -----------------------------------------------------
"$promyk" trace --format json >a.json 2>/dev/null || bad "set-up: a trace"
nested 100000 '[' ']' >deep_trace.json
refused "diff: a trace nested 100 000 deep" "deep_trace.json" diff a.json deep_trace.json
nested 100000 '{"steps":' '}' >deep_steps.json
refused "diff: steps nested 100 000 deep" "deep_steps.json" diff deep_steps.json a.json
{ printf '{"pixel": {"i": 0, "j": 0}, "steps": '; many 1000000 '{}'; printf '}'; } >million_steps.json
refused "diff: a million steps" "million_steps.json" diff a.json million_steps.json
printf '{"pixel": {"i": %s, "j": 0}}\n' "$(digits 100000)" >long_pixel.json
refused "diff: a pixel of 100 000 digits" "long_pixel.json" diff a.json long_pixel.json

# --- --answers ------------------------------------------------------------------
nested 100000 '{"a":' '}' >deep_answers.json
refused "--answers nested 100 000 deep" "deep_answers.json" lesson sphere --answers deep_answers.json
nested 100000 '[' ']' >deep_answers_array.json
refused "--answers of nested arrays" "deep_answers_array.json" lesson sphere --answers deep_answers_array.json
{ printf '{"C": '; many 1000000 6.4; printf '}'; } >million_answers.json
refused "--answers with a million-element array" "million_answers.json" lesson sphere --answers million_answers.json

summary
