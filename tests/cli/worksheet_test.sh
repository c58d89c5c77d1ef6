#!/bin/sh
# promyk lesson --answers FILE with the files a student would write: all
# right (exit 0), one wrong (exit 1, named), malformed (exit 3 with the line),
# JSON; and a worksheet's own form filled in from its key.
# usage: worksheet_test.sh PROMYK WORKDIR
set -u
promyk=$1 dir=$2
. "$(dirname "$0")/lib.sh"

cat >right.txt <<'END'
# pixel (3, 4), Polish and English styles mixed
[3,4]
EE = 4,0313
C = 6.4
delta = 4,5578
t = 1.058
P = (0,132; 0,132; 2,116)
N = [0.132, 0.132, -1.084]
D = 1,50539
[0,0]
delta = −8,99
END
"$promyk" lesson sphere --lang en --answers right.txt >out.txt 2>err.txt; code=$?
[ "$code" = 0 ] && grep -q "^Right: 8 of 8; wrong: 0" out.txt && [ ! -s err.txt ] && ok || bad "right answers: exit $code; $(cat out.txt err.txt)"

sed 's/^delta = 4,5578/delta = 4,5579/; s/^t = 1.058/t = 1.06/' right.txt >wrong.txt
"$promyk" lesson sphere --lang pl --answers wrong.txt >out.txt 2>err.txt; code=$?
[ "$code" = 1 ] && grep -q "^piksel (3, 4): " out.txt &&
  grep -q "✗ Δ/4 (delta) = 4,5579: źle zaokrąglone; 4,557812500000004 zaokrągla się do 4,5578" out.txt &&
  grep -q "✓ t = 1.06: dobrze" out.txt && grep -q "^Dobrze: 7 z 8; źle: 1" out.txt && ok ||
  bad "one wrong: exit $code; $(cat out.txt err.txt)"

# A miss has no t: wrong, with a note.
printf '[0,0]\nt = 1,2\n' >miss.txt
"$promyk" lesson sphere --lang en --answers miss.txt >out.txt 2>err.txt; code=$?
[ "$code" = 1 ] && grep -q "✗ t = 1,2: pixel (0, 0) has no such value" out.txt && ok || bad "t of a miss: exit $code; $(cat out.txt)"

printf 'C = 6,4\n\n# a point with decimal commas needs semicolons\nP = (0,132, 0,132, 2,116)\n' >malformed.txt
"$promyk" lesson sphere --lang en --pixel 3,4 --answers malformed.txt >out.txt 2>err.txt; code=$?
[ "$code" = 3 ] && grep -q "^promyk: malformed.txt: line 4: " err.txt && [ ! -s out.txt ] && ok ||
  bad "malformed: exit $code; $(cat err.txt)"
printf 'C = 6,4\nEPS = 1\n' >unknown.txt
"$promyk" lesson sphere --lang pl --pixel 3,4 --answers unknown.txt >out.txt 2>err.txt; code=$?
[ "$code" = 3 ] && grep -q "^promyk: unknown.txt: linia 2: nieznany klucz „EPS”" err.txt && ok || bad "unknown key: exit $code; $(cat err.txt)"

# JSON: a flat object, and a whole trace as promyk trace prints it.
printf '{"C": 6.40, "delta": "4,5578", "P": [0.132, 0.132, 2.116]}\n' >flat.json
"$promyk" lesson sphere --lang en --pixel 3,4 --answers flat.json >out.txt 2>err.txt; code=$?
[ "$code" = 0 ] && grep -q "✓ E·S (C) = 6.40: right" out.txt && ok || bad "flat JSON: exit $code; $(cat out.txt err.txt)"
"$promyk" trace --pixel 5,1 --format json >trace.json &&
  "$promyk" lesson sphere --lang en --answers trace.json >out.txt 2>err.txt; code=$?
[ "$code" = 0 ] && grep -q "^pixel (5, 1): " out.txt && grep -q "wrong: 0" out.txt && ok || bad "whole trace: exit $code; $(cat out.txt err.txt)"
printf '{"C": 6.4,\n "EE": }\n' >broken.json
"$promyk" lesson sphere --lang en --answers broken.json >out.txt 2>err.txt; code=$?
[ "$code" = 3 ] && grep -q "broken.json: line 2" err.txt && ok || bad "broken JSON: exit $code; $(cat err.txt)"

# The worksheet's own form, filled in from its key, is all right.
"$promyk" lesson lambert --lang en --worksheet --key >sheet.txt 2>err.txt || bad "worksheet: $(cat err.txt)"
awk '
  /^── The file / { form = 1; next }
  /^── Answer key/ { form = 0; key = 1; next }
  form && /^    / { sub(/^    /, ""); lines[++n] = $0 }
  key && /^  \([0-9]+\) / {
    number = $1; gsub(/[()]/, "", number)
    value = $0; sub(/^[^=]*= /, "", value); sub(/   \[[^]]*\]$/, "", value); values[number] = value
  }
  END {
    for (k = 1; k <= n; ++k) {
      line = lines[k]
      if (line ~ /# \([0-9]+\)$/) {
        number = line; sub(/.*# \(/, "", number); sub(/\)$/, "", number)
        sub(/ *#.*/, "", line); line = line " " values[number]
      }
      print line
    }
  }' sheet.txt >filled.txt
"$promyk" lesson lambert --lang en --answers filled.txt >out.txt 2>err.txt; code=$?
[ "$code" = 0 ] && grep -q "wrong: 0; left blank: 0" out.txt && ok || bad "the worksheet's form filled from its key: exit $code; $(cat filled.txt out.txt err.txt)"
grep -q "\.\.\.\.\.\.\.\.\.\.(1)" sheet.txt && ! grep -q "^Answer:" sheet.txt && ok || bad "the worksheet has blanks and no answers"

summary
