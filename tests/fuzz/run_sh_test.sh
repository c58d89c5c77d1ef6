#!/usr/bin/env bash
# tests/fuzz/run.sh, the fuzz step of CI, before it runs a fuzzer: it runs
# every target the build makes (its table against tests/fuzz/CMakeLists.txt's
# list, given as arguments), and it refuses a target or a job count it cannot
# honour (exit 2, saying what is wrong) instead of running less than asked.
#   run_sh_test.sh RUN_SH TARGET...
set -uo pipefail
run_sh=$1
shift
failed=0
fail() {
  echo "FAIL: $*"
  failed=1
}

listed=$(bash "$run_sh" --list | sort)
built=$(printf '%s\n' "$@" | sort)
[ "$listed" = "$built" ] || fail "run.sh runs [$(echo $listed)], the build makes [$(echo $built)]"

# expect_refusal WHAT ENV... -- ARGS...: exit 2 and a message naming WHAT.
expect_refusal() {
  local what=$1 err status=0
  shift
  local env=()
  while [ "$1" != "--" ]; do env+=("$1"); shift; done
  shift
  err=$(env "${env[@]}" bash "$run_sh" "$@" 2>&1 >/dev/null) || status=$?
  [ "$status" = 2 ] || fail "run.sh $* (${env[*]}): exit $status, expected 2"
  [[ "$err" == *"$what"* ]] || fail "run.sh $* (${env[*]}): said '$err', expected it to name '$what'"
}
expect_refusal "no fuzz target 'nosuch'" -- --no-build nosuch
expect_refusal "no fuzz target 'scen'" -- --no-build scene scen
expect_refusal "not '0'" PROMYK_FUZZ_JOBS=0 -- --no-build scene
expect_refusal "not 'two'" PROMYK_FUZZ_JOBS=two -- --no-build scene
expect_refusal "not '-1'" PROMYK_FUZZ_JOBS=-1 -- --no-build scene

# The verdicts, from stand-ins for three targets (PROMYK_FUZZ_BIN): one
# that passes (and records how it was called), one that crashes and one
# whose coverage is below its floor. Each verdict in the table's order,
# whatever order the runs end in; exit 1 when any failed, 0 when none did.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/bin"
stand_in() {  # stand_in NAME EXIT LINE...: a fuzz_NAME that prints the lines
  local name=$1 status=$2 file="$tmp/bin/fuzz_$1"
  shift 2
  {
    echo '#!/bin/sh'
    [ "$name" = scene ] && echo "sleep 0.5; echo \"\$@\" >'$tmp/scene_args'"
    printf "echo '%s'\n" "$@"
    echo "exit $status"
  } >"$file"
  chmod +x "$file"
}
stand_in scene 0 "#11000 DONE cov: 99999 ft: 1 corp: 1/1b exec/s: 1 rss: 1Mb"
stand_in lesson 1 "==1==ERROR: AddressSanitizer: heap-buffer-overflow" \
  "artifact_prefix=x; Test unit written to $tmp/crash-abc"
stand_in answers 0 "#6000 DONE cov: 12 ft: 1 corp: 1/1b exec/s: 1 rss: 1Mb"
mkdir -p "$tmp/out" && touch "$tmp/out/not_a_target"  # the scratch folder's other files stay
expected="fuzz_scene: ok|fuzz_lesson: FAILED|fuzz_lesson: reproducer|fuzz_lesson: rerun|fuzz_answers: FAILED|"
for jobs in 1 3; do
  status=0
  got=$(PROMYK_FUZZ_BIN="$tmp/bin" PROMYK_FUZZ_OUT="$tmp/out" PROMYK_FUZZ_JOBS=$jobs \
    bash "$run_sh" --no-build answers scene lesson 2>&1) || status=$?
  [ "$status" = 1 ] || fail "three stand-ins, $jobs at once: exit $status, expected 1"
  verdicts=$(grep -o '^fuzz_[a-z]*: [a-zA-Z]*' <<<"$got" | tr '\n' '|')
  [ "$verdicts" = "$expected" ] || fail "three stand-ins, $jobs at once: verdicts [$verdicts] in: $got"
  [[ "$got" == *"fuzz_lesson: reproducer: $tmp/crash-abc"* ]] || fail "no reproducer's path in: $got"
  [[ "$got" == *"coverage 12 edges, expected at least 5800"* ]] || fail "no coverage floor in: $got"
done
[ -f "$tmp/out/not_a_target" ] || fail "run.sh removed a file of PROMYK_FUZZ_OUT that is not a target's"
args=$(cat "$tmp/scene_args" 2>/dev/null)
[[ "$args" == "-seed=1 -runs=11000 "*" tests/fuzz/corpus/scene" ]] || fail "fuzz_scene was called with [$args]"
status=0
PROMYK_FUZZ_BIN="$tmp/bin" PROMYK_FUZZ_OUT="$tmp/out" PROMYK_FUZZ_SCALE=0 bash "$run_sh" --no-build scene \
  >/dev/null 2>&1 || status=$?
[ "$status" = 0 ] || fail "a passing stand-in alone: exit $status, expected 0"
[[ "$(cat "$tmp/scene_args")" == "-seed=1 -runs=0 "* ]] || fail "PROMYK_FUZZ_SCALE=0: fuzz_scene called with [$(cat "$tmp/scene_args")]"

[ "$failed" = 0 ] && echo "run.sh: every target listed, bad targets and job counts refused, verdicts right"
exit "$failed"
