#!/usr/bin/env bash
# promyk export (issue 16): the page holds the scene's data where the
# template marks it; a trace file of another scene or w, or one too large, is
# refused with the way out; the output rules are render's (atomic, -o -,
# outputs that are inputs, a missing folder).
# usage: export_test.sh PROMYK WORKDIR
set -u
promyk=$1 dir=$2
. "$(dirname "$0")/lib.sh"
j() { sed ':a;N;$!ba;s/\n    / /g' "$1"; }
scene='{"name": "two", "spheres": [{"S": [0, 0, 3], "r": 1}], "lights": [{"L": [1, 1, 0]}]}'
echo "$scene" >s.json

# The default: promyk.html, the article's scene at w = 128, one data block.
if "$promyk" export 2>err.txt && [ -s promyk.html ] && j err.txt | grep -q "wrote promyk.html (the page of scene article at w = 128" &&
   [ "$(grep -c '<script id="promyk-data" type="application/json">{' promyk.html)" = 1 ] &&
   ! grep -q '@PROMYK_EXPORT_DATA@' promyk.html; then ok
else bad "export: $(cat err.txt)"; fi
# The data: the image (w·w grey levels) and the branch map (w·w bytes), base64.
data() { sed -n 's/.*<script id="promyk-data" type="application\/json">\({.*}\)<\/script>.*/\1/p' "$1"; }
if data promyk.html | python3 -c '
import base64, json, sys
d = json.load(sys.stdin)
image, atlas = base64.b64decode(d["image"]), base64.b64decode(d["branch_map"])
assert d["w"] == 128 and d["channels"] == 1 and len(image) == 128 * 128 and len(atlas) == 128 * 128, d["w"]
assert set(atlas) <= {0, 1, 2}, set(atlas)     # miss, dark, lit: the article has no other kind
assert image[0] == 128 and atlas[0] == 0         # the corner misses: background 1/2
assert d["scene_text"] == "" and d["scene_file"] == ""'; then ok
else bad "the embedded data"; fi
# A scene file's own text goes in, and its name.
if "$promyk" export --scene s.json --w 8 -o p.html 2>err.txt && data p.html | python3 -c '
import base64, json, sys
d = json.load(sys.stdin)
assert base64.b64decode(d["scene_text"]).decode() == open("s.json").read() and d["scene_file"] == "s.json"'; then ok
else bad "--scene s.json: $(cat err.txt)"; fi

# -o -: to a pipe, the same page; a terminal is refused (script gives one).
if "$promyk" export --w 8 -o - 2>/dev/null | cmp -s - <("$promyk" export --w 8 -o p8.html 2>/dev/null; cat p8.html); then ok
else bad "-o - differs from the file"; fi
if command -v script >/dev/null; then
  script -qec "$promyk export --w 8 -o -" /dev/null >tty.txt 2>&1
  if grep -q "would write the HTML page to the terminal" tty.txt; then ok; else bad "-o - on a terminal: $(cat tty.txt)"; fi
fi

# Trace files: the same scene and w are taken; another w, another scene, a
# line that is no trace and a file too large are refused (exit 3), no page left.
"$promyk" render --scene s.json --w 8 --traces t.jsonl --trace-pixel 3,4 -o t.png 2>/dev/null
if "$promyk" export --scene s.json --w 8 --traces t.jsonl -o with.html 2>err.txt && [ -s with.html ]; then ok
else bad "--traces of the same scene: $(cat err.txt)"; fi
refused() {
  local name=$1 pattern=$2; shift 2
  rm -f out.html
  "$promyk" export "$@" -o out.html 2>err.txt
  local code=$?
  if [ "$code" = 3 ] && j err.txt | grep -q -- "$pattern" && [ ! -e out.html ] && [ -z "$(ls -A | grep -v -e "^[a-z0-9]*\.\(json\|jsonl\|png\|html\|txt\)$")" ]; then ok
  else bad "$name: exit $code, stderr: $(cat err.txt)"; fi
}
refused "another w" "t.jsonl: line 1: traces at w = 8, but the export is at --w 16; export with --w 8" \
  --scene s.json --w 16 --traces t.jsonl
refused "another scene" "t.jsonl: line 1: traces of scene two (fnv1a64:.*), but the exported scene is article" \
  --w 8 --traces t.jsonl
echo '{"not": "a trace"}' >bad.jsonl
refused "not a trace" "bad.jsonl: line 1: not a trace from promyk render --traces" --w 8 --traces bad.jsonl
truncate -s 17M big.jsonl
refused "too large" "big.jsonl: the trace file is 17.8 MB, and the page embeds at most 16.8 MB.*--trace-region" \
  --w 8 --traces big.jsonl
"$promyk" --lang pl export --w 8 --traces big.jsonl 2>err.txt
if j err.txt | grep -q "plik śladów ma 17,8 MB, a strona osadza najwyżej 16,8 MB"; then ok
else bad "too large, in Polish: $(cat err.txt)"; fi
rm -f big.jsonl
# Polish sizes have a decimal comma.
if "$promyk" --lang pl export --w 256 -o pl.html 2>err.txt &&
   j err.txt | grep -qE "zapisano pl.html \(strona sceny article przy w = 256, [0-9]+,[0-9] MB\)"; then ok
else bad "export's size in Polish: $(cat err.txt)"; fi
"$promyk" --lang pl export --w 16 --scene s.json --traces t.jsonl -o out.html 2>err.txt
if j err.txt | grep -q "ślady przy w = 8, a eksport jest przy --w 16"; then ok; else bad "Polish: $(cat err.txt)"; fi

# Output rules: the scene may not be overwritten; a missing folder is exit 4.
"$promyk" export --scene s.json -o s.json 2>err.txt
code=$?
if [ "$code" = 2 ] && grep -q '"name": "two"' s.json; then ok; else bad "-o the scene: exit $code"; fi
"$promyk" export --w 8 -o no/such/page.html 2>err.txt
code=$?
if [ "$code" = 4 ] && [ ! -e no ]; then ok; else bad "missing folder: exit $code"; fi
"$promyk" export --w 4096 2>err.txt
code=$?
if [ "$code" = 2 ] && grep -q "at most 2048" err.txt; then ok; else bad "--w 4096: exit $code $(cat err.txt)"; fi
summary
