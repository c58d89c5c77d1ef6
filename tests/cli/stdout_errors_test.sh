#!/usr/bin/env bash
# Every command that prints to standard output notices when the printing
# fails, whatever the size of the output (stdio keeps a failed write only as
# a flag; an output past its 4 KiB buffer used to be lost with exit 0):
#   - into /dev/full (a full disk): exit 4 and "cannot write standard output";
#   - into a closed standard output: exit 4;
#   - into a pipe whose reader has quit: exit 141, quietly.
# usage: stdout_errors_test.sh PROMYK WORKDIR
set -u
promyk=$1 dir=$2
. "$(dirname "$0")/lib.sh"

# A scene of 4000 spheres and 20 lights: scene check and dump print more
# than a pipe holds (64 KiB).
awk 'BEGIN {
  printf "{\"name\": \"many\", \"spheres\": ["
  for (k = 1; k <= 4000; k++) printf "%s{\"S\": [%d, %d, 40], \"r\": 0.25}", (k > 1 ? ", " : ""), k % 50 - 25, int(k / 50) - 20
  printf "], \"lights\": ["
  for (k = 1; k <= 20; k++) printf "%s{\"L\": [%d, 5, 0]}", (k > 1 ? ", " : ""), k
  printf "]}\n"
}' >many.json
"$promyk" trace --format json >a.json 2>/dev/null && "$promyk" trace --real float --format json >b.json 2>/dev/null ||
  bad "set-up: traces for diff"

# Each line: a command that prints to standard output (small and big ones).
commands=(
  "--help"
  "--version"
  "trace --help"
  "help render"
  "trace"
  "trace --format json"
  "trace --spp 4 --format json"
  "trace --spp 64 --format json"
  "trace --compare float,double,quad"
  "trace --compare float,quad --spp 16 --format json"
  "trace --scene many.json --pixel 4,4 --format json"
  "scene check many.json"
  "scene dump"
  "scene dump --scene many.json --all"
  "diff a.json b.json"
  "diff a.json b.json --format json"
  "lesson sphere"
  "lesson --list"
  "lesson sphere --format markdown"
  "lesson --check"
  "lesson sphere --worksheet"
)

for command in "${commands[@]}"; do
  # shellcheck disable=SC2086  # the words of the command
  "$promyk" $command >/dev/full 2>err.txt
  code=$?
  # diff exits 1 for a divergence: the output failing still wins (4).
  if [ "$code" = 4 ] && grep -q "cannot write standard output" err.txt; then ok
  else bad "promyk $command >/dev/full: exit $code, stderr: $(head -c 300 err.txt)"; fi

  "$promyk" $command >&- 2>err.txt
  code=$?
  if [ "$code" = 4 ] && grep -q "cannot write standard output" err.txt; then ok
  else bad "promyk $command >&-: exit $code, stderr: $(head -c 300 err.txt)"; fi

  # A pipe whose reader has already quit (waited for): exit 141 and nothing
  # on stderr, whatever the output's size.
  exec {gone}> >(true)
  wait $!
  "$promyk" $command >&$gone 2>err.txt
  code=$?
  exec {gone}>&-
  if [ "$code" = 141 ] && [ ! -s err.txt ]; then ok
  else bad "promyk $command | (reader gone): exit $code, stderr: $(head -c 300 err.txt)"; fi
done

# A reader that quits after 10 bytes of a big output (bigger than a pipe holds).
for command in "trace --spp 256 --format json" "scene dump --scene many.json --all"; do
  "$promyk" $command 2>err.txt | head -c 10 >/dev/null
  code=${PIPESTATUS[0]}
  if [ "$code" = 141 ] && [ ! -s err.txt ]; then ok
  else bad "promyk $command | head -c 10: exit $code, stderr: $(head -c 300 err.txt)"; fi
done

# In Polish too.
"$promyk" --lang pl trace --spp 4 --format json >/dev/full 2>err.txt
code=$?
if [ "$code" = 4 ] && grep -q "nie można pisać na standardowe wyjście" err.txt; then ok; else bad "--lang pl >/dev/full: exit $code: $(cat err.txt)"; fi

summary
