#!/usr/bin/env bash
# An empty value is an error that names its option (exit 2), never a
# silent "none": --scene '' must not mean the built-in scene, --traces ''
# must not mean no traces, --threads '' must not mean all cores.
# usage: empty_values_test.sh PROMYK WORKDIR
set -u
promyk=$1 dir=$2
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1
passed=0 failed=0
check() {  # check OPTION-NAME ARGS...
  local option=$1; shift
  "$promyk" "$@" >out.txt 2>err.txt
  local code=$?
  local left
  left=$(ls -A | grep -vE '^(out|err)\.txt$')
  if [ "$code" = 2 ] && grep -q "^promyk: $option: needs a value" err.txt && [ -z "$left" ] && [ ! -s out.txt ]; then
    passed=$((passed + 1))
  else
    echo "promyk $*: exit $code, files: [$left]"; cat err.txt; failed=$((failed + 1))
  fi
}
check --w trace --w ''
check --w render --w ''
check --threads render --w 8 --threads ''
check --scene trace --scene ''
check --scene render --w 8 --scene ''
check --traces render --w 8 --traces ''
check --output render --w 8 -o ''
check --repetitions bench speed --repetitions ''
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
