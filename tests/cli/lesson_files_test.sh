#!/usr/bin/env bash
# A teacher's copy of the lessons: --dump writes them (and never over an
# existing file), --lessons reads an edited one, --check finds a broken one
# with its file and line (exit 1), --step waits for Enter.
# usage: lesson_files_test.sh PROMYK WORKDIR
set -u
promyk=$1 dir=$2
. "$(dirname "$0")/lib.sh"

"$promyk" lesson --dump mine 2>err.txt && [ -f mine/pl/03-sphere.md ] && [ -f mine/en/05-program.md ] &&
  [ -f mine/messages.json ] && [ -f mine/scenes/article.json ] && ok || bad "--dump writes the lessons"
"$promyk" lesson --dump mine >/dev/null 2>err.txt; code=$?
[ "$code" = 2 ] && grep -q "exists" err.txt && ok || bad "--dump over an existing folder: exit $code"

# An edited lesson is read from the folder; the others come from the built-in set.
sed -i 's/^title: .*/title: My own sphere lesson/' mine/en/03-sphere.md
"$promyk" lesson sphere --lessons mine --lang en >out.txt 2>err.txt && grep -q "^Lesson: My own sphere lesson" out.txt &&
  ok || bad "--lessons reads the edited lesson"
"$promyk" lesson pane --lessons mine --lang en >out.txt 2>err.txt && grep -q "^Lesson: " out.txt && ok || bad "built-in fill-in"

# A broken lesson: an unknown key on a known line, and a step missing in Polish.
printf '\n= EE nope\n' >> mine/en/03-sphere.md
line=$(grep -n '^= EE nope$' mine/en/03-sphere.md | cut -d: -f1)
"$promyk" lesson --check --lessons mine --lang en >out.txt 2>err.txt; code=$?
[ "$code" = 1 ] && grep -q "mine/en/03-sphere.md:$line: unknown key \"nope\"" err.txt && ok ||
  bad "--check finds the unknown key at line $line: exit $code; $(cat err.txt)"
sed -i 's/^## \[exercise\]/## [cwiczenie]/' mine/pl/01-vectors.md
"$promyk" lesson --check --lessons mine --lang pl >out.txt 2>err.txt; code=$?
[ "$code" = 1 ] && grep -q "mine/pl/01-vectors.md:[0-9]*: kroki różnią się od wersji en" err.txt && ok ||
  bad "--check finds the step missing in one language: exit $code; $(cat err.txt)"

# Step mode waits for Enter: with three lines of input it shows three steps and stops waiting at the end of input.
printf '\n\n\n' | "$promyk" lesson vectors --step --lang en >out.txt 2>err.txt && grep -q "\[Enter: next step · b: back · q: quit\]" err.txt &&
  [ "$(grep -c '^── Step' out.txt)" = 7 ] && ok || bad "--step: $(grep -c '^── Step' out.txt) steps"
summary
