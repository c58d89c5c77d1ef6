#!/usr/bin/env bash
# Inputs without an end (/dev/zero, /dev/urandom, an endless pipe) are
# refused at their limit with exit 3 and the limit named, within seconds:
# they used to grow until the out-of-memory killer.
# usage: input_limits_test.sh PROMYK WORKDIR
set -u
promyk=$1 dir=$2
. "$(dirname "$0")/lib.sh"
# messages are wrapped to 80 columns (continuation lines indented by 4): join them
j() { sed ':a;N;$!ba;s/\n    / /g' "$1"; }

"$promyk" trace --format json >a.json 2>/dev/null || bad "set-up: a trace"

# limited NAME MIB COMMAND...: exit 3 within 10 s, the limit in the message.
limited() {
  local name=$1 mib=$2; shift 2
  local start=$SECONDS
  # Bounded here too (1.5 GB of address space, 20 s), so that a promyk
  # without the limit fails the test instead of filling the machine.
  (ulimit -v 1500000; exec timeout -s KILL 20 "$promyk" "$@") >out.txt 2>err.txt
  local code=$?
  if [ "$code" = 3 ] && j err.txt | grep -q "reads at most $mib MiB" && [ $((SECONDS - start)) -le 10 ] && [ ! -s out.txt ]; then ok
  else bad "$name: exit $code after $((SECONDS - start)) s: $(head -c 300 err.txt)"; fi
}

# diff reads each side up to the trace limit (250 MB, 238 MiB; docs/commands.md).
limited "diff a.json /dev/zero" 238 diff a.json /dev/zero
limited "diff - a.json < /dev/zero" 238 diff - a.json </dev/zero
limited "lesson --answers /dev/zero" 64 lesson sphere --answers /dev/zero
limited "lesson --answers /dev/urandom" 64 lesson sphere --answers /dev/urandom
limited "lesson --answers - < /dev/zero" 64 lesson sphere --answers - </dev/zero
# An endless pipe, not a device.
start=$SECONDS
yes 'C = 6.4' | (ulimit -v 1500000; exec timeout -s KILL 20 "$promyk" lesson sphere --answers -) >out.txt 2>err.txt
code=${PIPESTATUS[1]}
if [ "$code" = 3 ] && j err.txt | grep -q "reads at most 64 MiB"; then ok; else bad "endless pipe: exit $code: $(head -c 300 err.txt)"; fi

(ulimit -v 1500000; exec timeout -s KILL 20 "$promyk" --lang pl diff a.json /dev/zero) >out.txt 2>err.txt
code=$?
if [ "$code" = 3 ] && j err.txt | grep -q "diff czyta najwyżej 238 MiB"; then ok; else bad "Polish: exit $code: $(cat err.txt)"; fi

summary
