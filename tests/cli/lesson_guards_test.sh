#!/bin/sh
# promyk lesson on any pixel: a misspelt placeholder stops the lesson as
# --check reports it (exit 3, file and line); step mode's q quits and b goes
# back a step; a step whose needs no chosen pixel has names one that does.
# usage: lesson_guards_test.sh PROMYK WORKDIR
set -u
promyk=$1 dir=$2
. "$(dirname "$0")/lib.sh"
joined() { tr '\n' ' ' <"$1" | tr -s ' '; }

mkdir -p lessons/en lessons/pl
for l in en pl; do
  cat >lessons/$l/99-typo.md <<'END'
---
name: typo
title: T
summary: S
---

## [a] A

::: lit
t = {tt}
:::
END
done
"$promyk" lesson typo --lessons lessons --lang en >out.txt 2>err.txt; code=$?
[ "$code" = 3 ] && grep -q "99-typo.md.*line 10.*tt" err.txt && ! grep -q "—" out.txt && ok ||
  bad "misspelt placeholder: exit $code; $(cat out.txt err.txt)"

# Step mode: q and Enter quits at once (the sphere lesson has 8 steps).
printf 'q\n' | "$promyk" lesson sphere --step --lang en >out.txt 2>err.txt; code=$?
steps=$(grep -c "^── Step" out.txt)
[ "$code" = 0 ] && [ "$steps" = 1 ] && grep -q "q and Enter: quit" err.txt && ok || bad "q quits: exit $code, $steps steps"
# b and Enter goes back: step 1, (Enter) step 2, (b) step 1 again, (q).
printf '\nb\nq\n' | "$promyk" lesson sphere --step --lang en >out.txt 2>err.txt; code=$?
order=$(grep "^── Step" out.txt | sed 's/^── Step \([0-9]*\) .*/\1/' | tr '\n' ' ')
[ "$code" = 0 ] && [ "$order" = "1 2 1 " ] && ok || bad "b goes back: exit $code, steps $order"
# Enter alone goes through every step (stdin closed: it goes on).
"$promyk" lesson sphere --step --lang en </dev/null >out.txt 2>err.txt; code=$?
[ "$code" = 0 ] && [ "$(grep -c '^── Step' out.txt)" = "$(promyk_steps=$("$promyk" lesson sphere --lang en | grep -c '^── Step'); echo $promyk_steps)" ] && ok ||
  bad "closed stdin: exit $code"

# lambert at a pixel that misses: its exercise names the first lit pixel of the pane instead of printing —.
"$promyk" lesson lambert --pixel 0,0 --lang en >out.txt 2>err.txt; code=$?
[ "$code" = 0 ] && joined out.txt | grep -q "promyk lesson lambert --pixel [0-9],[0-9]" && ! grep -q "max(0, cos α) = 0.5" out.txt && ok ||
  bad "lambert 0,0: exit $code; $(cat out.txt)"
summary
