#!/usr/bin/env bash
# promyk export --bench (issue 17, the precision lab): the page embeds the
# JSON of `promyk bench accuracy --json` exactly as the file holds it; a file
# that is not such JSON is refused with exit 3, naming the file and the JSON
# pointer of the fault (English and Polish), and nothing is written (an
# existing page stays as it was).
# usage: export_bench_test.sh PROMYK WORKDIR BENCH_JSON
set -u
promyk=$1 dir=$2 good=$3
. "$(dirname "$0")/lib.sh"
j() { sed ':a;N;$!ba;s/\n    / /g' "$1"; }
data() { sed -n 's/.*<script id="promyk-data" type="application\/json">\({.*}\)<\/script>.*/\1/p' "$1"; }
cp "$good" acc.json

# A good file: embedded, equal to the file as JSON, with its name.
if "$promyk" export --w 8 --bench acc.json -o p.html 2>err.txt && data p.html | python3 -c '
import json, sys
d = json.load(sys.stdin)
assert d["bench"] == json.load(open("acc.json")), "the embedded JSON differs from the file"
assert d["bench_file"] == "acc.json" and len(d["bench"]["results"]) == 48'; then ok
else bad "a good file: $(cat err.txt)"; fi
# Without --bench: no bench (null); the maps of the image's settings are there up to w = 256.
if "$promyk" export --w 8 -o q.html 2>err.txt && data q.html | python3 -c '
import base64, json, struct, sys
d = json.load(sys.stdin)
assert d["bench"] is None and d["bench_file"] == ""
m = d["maps"]
assert (m["real"], m["formula"], m["spp"], m["max_w"]) == ("double", "article", 1, 256), m
error = struct.unpack("<64d", base64.b64decode(m["error"]))
digits = struct.unpack("<64d", base64.b64decode(m["digits_lost"]))
assert error[0] == 0, error[0]               # (0, 0) misses: 1/2 in every type, exact
assert any(v > 0 for v in error)             # the sphere: some error
assert all(v >= 0 for v in error + digits)   # the article scene: no branch differs, nothing non-finite
assert any(v > 0 for v in digits)'; then ok
else bad "the maps: $(cat err.txt)"; fi
if "$promyk" export --w 300 -o big.html 2>err.txt && data big.html | python3 -c '
import json, sys
d = json.load(sys.stdin)
assert d["maps"] == {"max_w": 256}, d["maps"]'; then ok
else bad "no maps above w = 256: $(cat err.txt)"; fi
rm -f big.html

# Bad files: exit 3, the file and where, nothing written; an old page stays.
echo "old page" >out.html
refused() {
  local name=$1 file=$2 pattern=$3; shift 3
  "$promyk" "$@" export --w 8 --bench "$file" -o out.html 2>err.txt
  local code=$?
  if [ "$code" = 3 ] && j err.txt | grep -q -- "$pattern" && [ "$(cat out.html)" = "old page" ] &&
     [ -z "$(ls -A | grep -v -e '^[a-z0-9_]*\.\(json\|html\|txt\)$')" ]; then ok
  else bad "$name: exit $code, stderr: $(cat err.txt)"; fi
}
edit() { python3 -c "import json, sys; d = json.load(open('acc.json')); $1; json.dump(d, open('$2', 'w'))"; }
printf '{"bench": "accuracy",\n  "schema": 1,,}' >syntax.json
refused "not JSON" syntax.json "syntax.json: not JSON: the parser stopped at line 2, column 15"
echo '{"bench": "speed", "schema": 1}' >speed.json
refused "another bench" speed.json "speed.json: not the JSON of promyk bench accuracy --json"
echo '[1, 2]' >array.json
refused "an array" array.json "array.json: not the JSON of promyk bench accuracy --json"
edit 'd["results"][3]["ratio"] = -1' ratio.json
refused "a negative ratio" ratio.json "ratio.json: /results/3/ratio: expected a number ≥ 0 or null"
edit 'del d["results"][0]["real"]' missing.json
refused "a missing key" missing.json 'missing.json: /results/0: the key "real" is missing'
edit 'd["results"][5]["scene"] = "nowhere"' scene.json
refused "an unknown scene" scene.json "scene.json: /results/5/scene: expected the name of a scene in /scenes"
edit 'd["results"][2]["real"] = "half"' real.json
refused "an unknown type" real.json "real.json: /results/2/real: expected float, double, long-double or quad"
edit 'd["results"][1]["spp"] = 0' spp.json
refused "spp 0" spp.json "spp.json: /results/1/spp: expected a whole number ≥ 1"
edit 'd["scenes"] = []' scenes.json
refused "no scenes" scenes.json "scenes.json: /scenes: expected a non-empty array"
python3 -c "print('{\"bench\": \"accuracy\", \"schema\": 1, \"x\": ' + '[' * 100000 + ']' * 100000 + '}')" >deep.json
refused "deep nesting" deep.json "deep.json: not the JSON of promyk bench accuracy --json"
refused "Polish" ratio.json "ratio.json: /results/3/ratio: oczekiwano: liczba ≥ 0 lub null" --lang pl
refused "Polish, not JSON" syntax.json "syntax.json: to nie jest JSON: parser zatrzymał się w wierszu 2, kolumnie 15" --lang pl
"$promyk" export --w 8 --bench no_such.json -o out.html 2>err.txt
code=$?
if [ "$code" = 3 ] && grep -q "no_such.json" err.txt && [ "$(cat out.html)" = "old page" ]; then ok
else bad "a missing file: exit $code, $(cat err.txt)"; fi
# The page may not overwrite the bench file (exit 2, the file kept).
"$promyk" export --w 8 --bench acc.json -o acc.json 2>err.txt
code=$?
if [ "$code" = 2 ] && cmp -s acc.json "$good"; then ok; else bad "-o the bench file: exit $code"; fi
# The help says what --bench takes and does.
if "$promyk" export --help | grep -A2 -- "--bench FILE" | tr -s ' \n' ' ' |
   grep -q "Embed the results of promyk bench accuracy --json FILE and plot them in the page"; then ok
else bad "--help: $("$promyk" export --help)"; fi
summary
