#!/usr/bin/env bash
# A render interrupted by SIGINT or SIGTERM exits with 128 + signal and
# leaves no file behind (no image, no traces, no temporary).
# usage: interrupt_test.sh PROMYK WORKDIR
set -u
promyk=$1 dir=$2
status=0
for signal in INT TERM; do
  rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1
  # The largest pane (about 6 s in a release build): still running when the signal comes.
  "$promyk" render --w 32768 -o big.png --traces big.jsonl --trace-region 0,0,32767,3 >out.txt 2>err.txt &
  pid=$!
  sleep 0.5
  kill -s "$signal" "$pid"
  wait "$pid"
  code=$?
  expected=$([ "$signal" = INT ] && echo 130 || echo 143)
  left=$(ls -A | grep -vE '^(out|err)\.txt$')
  if [ "$code" != "$expected" ]; then echo "SIG$signal: exit $code, expected $expected"; cat err.txt; status=1; fi
  if [ -n "$left" ]; then echo "SIG$signal: files left behind: $left"; status=1; fi
  if ! grep -q interrupted err.txt; then echo "SIG$signal: no message on stderr"; status=1; fi
done
[ $status = 0 ] && echo "interrupt test: 2 passed, 0 failed"
exit $status
