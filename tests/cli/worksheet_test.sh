#!/bin/sh
# promyk lesson --answers FILE with the files a student would write: all
# right (exit 0), one wrong (exit 1, named), unreadable lines (exit 1, each
# marked), nothing readable or not UTF-8 (exit 3 with the line), fractions,
# more digits than a double holds, JSON; and a worksheet's own form filled in from its key.
# usage: worksheet_test.sh PROMYK WORKDIR
set -u
# reports are wrapped to 80 columns (continuation lines indented by 4): join them
j() { sed ':a;N;$!ba;s/\n    / /g' "$1"; }
promyk=$1 dir=$2
. "$(dirname "$0")/lib.sh"
# The report with each long line joined again (it goes on, indented by four, on the next).
joined() { awk '/^    /{ sub(/^ +/, ""); printf " %s", $0; next } NR > 1 { print "" } { printf "%s", $0 } END { print "" }' "$1"; }

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
[ "$code" = 0 ] && j out.txt | grep -q "^Right: 8 of 8; wrong: 0" && [ ! -s err.txt ] && ok || bad "right answers: exit $code; $(cat out.txt err.txt)"

sed 's/^delta = 4,5578/delta = 4,5579/; s/^t = 1.058/t = 1.06/' right.txt >wrong.txt
"$promyk" lesson sphere --lang pl --answers wrong.txt >out.txt 2>err.txt; code=$?
[ "$code" = 1 ] && j out.txt | grep -q "^piksel (3, 4): " &&
  j out.txt | grep -q "✗ Δ/4 (delta) = 4,5579: źle zaokrąglone; 4,557812500000004 zaokrągla się do 4,5578" &&
  j out.txt | grep -q "✓ t = 1.06: dobrze" && j out.txt | grep -q "^Dobrze: 7 z 8; źle: 1" && ok ||
  bad "one wrong: exit $code; $(cat out.txt err.txt)"

# A miss has no t: wrong, with a note.
printf '[0,0]\nt = 1,2\n' >miss.txt
"$promyk" lesson sphere --lang en --answers miss.txt >out.txt 2>err.txt; code=$?
[ "$code" = 1 ] && j out.txt | grep -q "✗ t = 1,2: pixel (0, 0) has no such value" && ok || bad "t of a miss: exit $code; $(cat out.txt)"

# A bad line is one unreadable answer: the rest are checked, exit 1.
printf 'C = 6,4\n\n# a point with decimal commas needs semicolons\nP = (0,132, 0,132, 2,116)\n' >malformed.txt
"$promyk" lesson sphere --lang en --pixel 3,4 --answers malformed.txt >wrapped.txt 2>err.txt; code=$?
joined wrapped.txt >out.txt
[ "$code" = 1 ] && j out.txt | grep -q "✓ E·S (C) = 6,4: right" &&
  j out.txt | grep -q '✗ line 4: P = (0,132, 0,132, 2,116): unreadable: "(0,132, 0,132, 2,116)" is not a number' &&
  j out.txt | grep -q "Unreadable: 1\.$" && [ ! -s err.txt ] && ok ||
  bad "malformed: exit $code; $(cat out.txt err.txt)"
printf 'C = 6,4\nEPS = 1\n' >unknown.txt
"$promyk" lesson sphere --lang pl --pixel 3,4 --answers unknown.txt >wrapped.txt 2>err.txt; code=$?
joined wrapped.txt >out.txt
[ "$code" = 1 ] && j out.txt | grep -q "✗ linia 2: EPS = 1: nieczytelne: nieznany klucz „EPS”; czy chodziło o „.*”? Klucze tej lekcji: .*delta" &&
  ! j out.txt | grep -q "t_plane" && ok || bad "unknown key: exit $code; $(cat out.txt err.txt)"
# One right, one unknown key, one key given twice, one wrong: each marked.
printf '[3,4]\nC = 6,4\ndetla = 4,5578\nt = 1.058\nt = 1,06\nEE = 9\n' >mixed.txt
"$promyk" lesson sphere --lang en --answers mixed.txt >wrapped.txt 2>err.txt; code=$?
joined wrapped.txt >out.txt
[ "$code" = 1 ] && j out.txt | grep -q "✓ E·S (C) = 6,4: right" &&
  j out.txt | grep -q "✗ line 3: detla = 4,5578: unreadable: unknown key 'detla'; did you mean 'delta'? This lesson's keys: " &&
  j out.txt | grep -q "✗ line 4: t = 1.058: unreadable: \"t\" for pixel (3, 4) is given more than once (lines 4, 5)" &&
  j out.txt | grep -q "✗ line 5: t = 1,06: unreadable: " && j out.txt | grep -q "✗ |E|² (EE) = 9: wrong" &&
  j out.txt | grep -q "^Right: 1 of 5; wrong: 1; left blank: 0. Unreadable: 3.$" && ok ||
  bad "mixed: exit $code; $(cat out.txt err.txt)"
# Nothing readable, or not text: the file is refused (exit 3, with the line).
printf '# only typos\ndetla = 4,5578\n' >typos.txt
"$promyk" lesson sphere --lang en --answers typos.txt >out.txt 2>err.txt; code=$?
# (errors are wrapped to 80 columns: join the lines before matching)
[ "$code" = 3 ] && sed ':a;N;$!ba;s/\n    / /g' err.txt | grep -q "^promyk: typos.txt: line 2: unknown key 'detla'; did you mean 'delta'?.*no answer in the file can be read" &&
  [ ! -s out.txt ] && ok || bad "nothing readable: exit $code; $(cat out.txt err.txt)"
printf 'C = 6,4\n# caf\351\n' >latin1.txt
"$promyk" lesson sphere --lang en --answers latin1.txt >out.txt 2>err.txt; code=$?
[ "$code" = 3 ] && grep -q "^promyk: latin1.txt: line 2: the file is not UTF-8 text" err.txt && ok ||
  bad "not UTF-8: exit $code; $(cat out.txt err.txt)"
# Fractions, and more digits than a double holds (t of pixel (5, 1) is 1.36675049556621551840... exactly).
printf '[3,4]\nE.x = 1/8\nE = (1/8; 0,125; 4/2)\n[5,1]\nE.y = \342\210\2223/8\nt = 1.3667504955662156\n' >exact.txt
"$promyk" lesson sphere --lang en --answers exact.txt >out.txt 2>err.txt; code=$?
[ "$code" = 0 ] && j out.txt | grep -q "✓ t = 1.3667504955662156: right, and more digits than a double holds" &&
  j out.txt | grep -q "^Right: 4 of 4" && ok || bad "fractions and digits: exit $code; $(cat out.txt err.txt)"

# JSON: a flat object, and a whole trace as promyk trace prints it.
printf '{"C": 6.40, "delta": "4,5578", "P": [0.132, 0.132, 2.116]}\n' >flat.json
"$promyk" lesson sphere --lang en --pixel 3,4 --answers flat.json >out.txt 2>err.txt; code=$?
[ "$code" = 0 ] && j out.txt | grep -q "✓ E·S (C) = 6.40: right" && ok || bad "flat JSON: exit $code; $(cat out.txt err.txt)"
"$promyk" trace --pixel 5,1 --format json >trace.json &&
  "$promyk" lesson sphere --lang en --answers trace.json >out.txt 2>err.txt; code=$?
[ "$code" = 0 ] && j out.txt | grep -q "^pixel (5, 1): " && j out.txt | grep -q "wrong: 0" && ok || bad "whole trace: exit $code; $(cat out.txt err.txt)"
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
      if (line ~ /# \([0-9]+\)/) {
        number = line; sub(/.*# \(/, "", number); sub(/\).*$/, "", number)
        sub(/ *#.*/, "", line); line = line " " values[number]
      }
      print line
    }
  }' sheet.txt >filled.txt
"$promyk" lesson lambert --lang en --answers filled.txt >out.txt 2>err.txt; code=$?
[ "$code" = 0 ] && j out.txt | grep -q "wrong: 0; left blank: 0" && ok || bad "the worksheet's form filled from its key: exit $code; $(cat filled.txt out.txt err.txt)"
grep -q "\.\.\.\.\.\.\.\.\.\.(1)" sheet.txt && ! grep -q "^Answer:" sheet.txt && ok || bad "the worksheet has blanks and no answers"

summary
